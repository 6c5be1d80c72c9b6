// SPDX-License-Identifier: MIT
#include <cmath>

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>
#include <nlohmann/json.hpp>

#include "geometry/up_axis.h"
#include "ui/common/studio_session.h"
#include "ui/views/object_form.h"
#include "ui/views/views_panel.h"
#include "ui_test_support.h"

namespace layermod::ui::test {

class ViewsPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    model_ = std::make_shared<const Model>(LoadModel(SampleMeshPath().toStdString()));
  }
  void init() {
    session_ = std::make_unique<StudioSession>();
    panel_ = std::make_unique<ViewsPanel>(session_.get());
    panel_->show();
  }
  void cleanup() {
    panel_.reset();
    session_.reset();
  }

  void WithoutModelThereIsNoPlan() {
    QVERIFY(!panel_->plan().has_value());
    QVERIFY(panel_->plan_text().contains("Open a mesh"));
  }

  void CountsFollowTheFormAndMatchPlanTraining() {
    session_->SetModel(model_);
    SetBox("depthMinBox", 600.0);
    SetBox("depthMaxBox", 1000.0);
    SetBox("azimuthminBox", 0.0);
    SetBox("azimuthstepBox", 30.0);
    SetBox("azimuthmaxBox", 330.0);
    SetBox("elevationminBox", 10.0);
    SetBox("elevationstepBox", 20.0);
    SetBox("elevationmaxBox", 70.0);
    SetBox("rollminBox", -20.0);
    SetBox("rollstepBox", 20.0);
    SetBox("rollmaxBox", 20.0);
    SetBox("evenSpacingBox", 0.0);

    // Computed here from the same numbers, not from the panel's own request.
    TrainingRequest request;
    request.camera = panel_->camera();
    request.profile.depth_min_mm = 600.0;
    request.profile.depth_max_mm = 1000.0;
    request.profile.views.azimuth = {0.0, 30.0, 330.0};
    request.profile.views.elevation = {10.0, 20.0, 70.0};
    request.profile.views.roll = {-20.0, 20.0, 20.0};
    request.profile.views.even_spacing_deg = 0.0;
    const TrainingPlan expected = PlanTraining(*model_, request);
    QCOMPARE(expected.views.size(), std::size_t{12 * 4 * 3});

    // The debounce timer updates the count without any explicit call.
    QTRY_VERIFY(panel_->plan().has_value() &&
                panel_->plan()->TemplateCount() == expected.TemplateCount());
    QCOMPARE(panel_->plan()->layer_depths_mm, expected.layer_depths_mm);
    const QLocale locale;
    QVERIFY(panel_->plan_text().contains(
        QStringLiteral("<b>%1</b> layers").arg(expected.layer_depths_mm.size())));
    QVERIFY(panel_->plan_text().contains(
        QStringLiteral("<b>%1</b> templates")
            .arg(locale.toString(static_cast<qulonglong>(expected.TemplateCount())))));
  }

  void EvenSpacingReplacesTheGrid() {
    session_->SetModel(model_);
    SetBox("evenSpacingBox", 10.0);
    panel_->UpdatePlan();
    TrainingRequest request = panel_->request();
    QCOMPARE(request.profile.views.even_spacing_deg, 10.0);
    QCOMPARE(panel_->plan()->views.size(), SampleViews(request.profile.views).size());
  }

  void EvenSpacingGreysTheUnusedGridBoxes() {
    auto* azimuth_step = panel_->findChild<QDoubleSpinBox*>("azimuthstepBox");
    auto* elevation_min = panel_->findChild<QDoubleSpinBox*>("elevationminBox");
    auto* elevation_step = panel_->findChild<QDoubleSpinBox*>("elevationstepBox");
    SetBox("evenSpacingBox", 0.0);
    QVERIFY(azimuth_step->isEnabled() && elevation_step->isEnabled());
    SetBox("evenSpacingBox", 10.0);
    QVERIFY(!azimuth_step->isEnabled());
    QVERIFY(!elevation_step->isEnabled());
    QVERIFY(elevation_min->isEnabled());  // the elevation range still limits the directions
  }

  void InvalidRangeSaysWhy() {
    session_->SetModel(model_);
    SetBox("depthMinBox", 900.0);
    SetBox("depthMaxBox", 800.0);
    panel_->UpdatePlan();
    QVERIFY(!panel_->plan().has_value());
    // In the form's words, not a profile file's field names.
    QCOMPARE(panel_->problem(), QString("D_min (900.0 mm) must be below D_max (800.0 mm)"));
    QVERIFY2(panel_->plan_text().contains("Cannot train: D_min (900.0 mm) must be below"),
             qPrintable(panel_->plan_text()));
    QVERIFY(!panel_->plan_text().contains("depth_min_mm"));
    SetBox("depthMaxBox", 1000.0);
    panel_->UpdatePlan();
    QVERIFY(panel_->problem().isEmpty());
    QVERIFY(panel_->plan().has_value());
  }

  void UpAxisAndPresetsSetTheEnvelope() {
    session_->SetModel(model_);
    auto* up_axis = panel_->findChild<QComboBox*>("upAxisCombo");
    QCOMPARE(up_axis->currentText(), QString("+z"));
    // The keyboard picks the next axis: -z, as the original LineMOD meshes need.
    up_axis->setFocus();
    QTest::keyClick(up_axis, Qt::Key_Down);
    QCOMPARE(up_axis->currentText(), QString("-z"));
    QVERIFY(panel_->profile().views.upright_from_model.isApprox(UprightFromUpAxis("-z")));

    panel_->findChild<QPushButton*>("fullPresetButton")->click();
    const ViewSamplingOptions full = panel_->profile().views;
    QCOMPARE(full.elevation.min_deg, -90.0);
    QCOMPARE(full.roll.max_deg - full.roll.min_deg, 345.0);
    QVERIFY(full.upright_from_model.isApprox(UprightFromUpAxis("-z")));  // kept by the preset
    panel_->UpdatePlan();
    const std::size_t full_templates = panel_->plan()->TemplateCount();
    panel_->findChild<QPushButton*>("tabletopPresetButton")->click();
    QCOMPARE(panel_->profile().views.elevation.min_deg, 0.0);
    panel_->UpdatePlan();
    QVERIFY(panel_->plan()->TemplateCount() * 6 < full_templates);

    // A profile's rotation that is none of the six axes shows as tilted and is kept.
    TrainingProfile tilted = panel_->profile();
    tilted.views.upright_from_model = UprightFromUpDirection({0.3, -0.6, 0.74});
    panel_->SetProfile(tilted);
    QCOMPARE(up_axis->currentText(), QString("tilted"));
    QVERIFY(panel_->profile().views.upright_from_model.isApprox(tilted.views.upright_from_model));
    panel_->SetProfile(TinyProfile());
    QCOMPARE(up_axis->currentText(), QString("+z"));
    QCOMPARE(up_axis->findText("tilted"), -1);
  }

  // The bracket rests most likely on its base (+z); the panel offers its resting poses as links
  // and says when the chosen up axis is not one of them.
  void RestingPosesAreOfferedAsUpAxes() {
    auto* label = panel_->findChild<QLabel*>("restingPosesLabel");
    session_->SetModel(model_);
    QVERIFY(!panel_->resting_poses().empty());
    QCOMPARE(panel_->resting_poses().front().axis_name.value_or(""), std::string("+z"));
    QVERIFY2(label->text().contains(">+z</a>"), qPrintable(label->text()));
    QVERIFY(!label->text().contains("rarely rests"));
    panel_->SetUpright(UprightFromUpAxis("-z"));  // not a way the bracket lies
    QVERIFY2(label->text().contains("rarely rests"), qPrintable(label->text()));
    // A link makes that pose the up axis.
    for (int i = 0; i < static_cast<int>(panel_->resting_poses().size()); ++i) {
      emit label->linkActivated(QString::number(i));
      const Eigen::Vector3d up = UpDirectionInModel(panel_->profile().views.upright_from_model);
      // Exactly the pose's direction, or the axis it is named after (within 5 degrees).
      QVERIFY(up.dot(panel_->resting_poses()[static_cast<std::size_t>(i)].up_in_model) >
              std::cos(5.01 * 3.14159265358979 / 180.0));
      QVERIFY(!label->text().contains("rarely rests"));
    }
  }

  void ObjectIdComesFromTheFileName() {
    QCOMPARE(ObjectIdFromFileName("/data/lmo/models/obj_000008.ply"), 8);
    QCOMPARE(ObjectIdFromFileName("obj_000012.stl"), 12);
    QCOMPARE(ObjectIdFromFileName("part12.obj"), 12);
    QCOMPARE(ObjectIdFromFileName("bracket.ply"), 1);
    QCOMPARE(ObjectIdFromFileName("99999999999999.ply"), 1);  // beyond int32: the default
  }

  void ModelDefaultsTheObjectFields() {
    const QString path = QDir(ScratchDir()).filePath("obj_000008.ply");
    if (!QFileInfo::exists(path)) QVERIFY(QFile::copy(SampleMeshPath(), path));
    session_->SetModel(std::make_shared<const Model>(LoadModel(path.toStdString())));
    QCOMPARE(panel_->request().obj_id, 8);
    QCOMPARE(panel_->request().name, std::string("obj_000008"));
    // Edits survive a reload of the same file.
    panel_->SetObject(3, "gear");
    session_->SetModel(std::make_shared<const Model>(LoadModel(path.toStdString())));
    QCOMPARE(panel_->request().obj_id, 3);
    QCOMPARE(panel_->request().name, std::string("gear"));
    session_->SetModel(model_);  // another file: its defaults
    QCOMPARE(panel_->request().obj_id, 1);
    QCOMPARE(panel_->request().name, std::string("bracket"));
  }

  void ProfileFileRoundTrip() {
    TrainingProfile profile = TinyProfile();
    profile.features.color_features = 40;
    profile.features.min_features = 9;  // not on the form: must survive through the panel
    panel_->SetProfile(profile);
    const QString path = QDir(ScratchDir()).filePath("profile_roundtrip.json");
    QVERIFY(panel_->SaveProfile(path));
    panel_->SetProfile(TrainingProfile{});
    QVERIFY(ToJson(panel_->profile()) != ToJson(profile));
    QVERIFY(panel_->LoadProfile(path));
    QCOMPARE(ToJson(panel_->profile()).dump(), ToJson(profile).dump());
  }

  void SettingsRestoreTheLastValues() {
    panel_->SetProfile(TinyProfile());
    panel_->SetCamera({600.0, 610.0, 320.0, 240.0, 640, 480});
    panel_->SaveSettings();
    ViewsPanel restored(session_.get());
    restored.RestoreSettings();
    QCOMPARE(ToJson(restored.profile()).dump(), ToJson(TinyProfile()).dump());
    QCOMPARE(restored.camera().fy, 610.0);
  }

 private:
  void SetBox(const char* name, double value) {
    auto* box = panel_->findChild<QDoubleSpinBox*>(name);
    QVERIFY2(box != nullptr, name);
    box->setValue(value);
  }

  std::shared_ptr<const Model> model_;
  std::unique_ptr<StudioSession> session_;
  std::unique_ptr<ViewsPanel> panel_;
};

LAYERMOD_UI_TEST(ViewsPanelTest);

}  // namespace layermod::ui::test

#include "views_panel_test.moc"
