// SPDX-License-Identifier: MIT
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QListView>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <nlohmann/json.hpp>

#include "pipeline/training.h"
#include "ui/common/studio_session.h"
#include "ui/scene3d/scene_view.h"
#include "ui/templates/template_browser.h"
#include "ui/templates/template_list_model.h"
#include "ui/views/views_panel.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

namespace layermod::ui::test {

class TemplateBrowserTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    // One archive trained by the core, stored once beside its mesh and once alone.
    const Model model = LoadModel(SampleMeshPath().toStdString());
    TrainingRequest request;
    request.name = "bracket";
    request.camera = {572.0, 572.0, 319.5, 239.5, 640, 480};
    request.profile = TinyProfile();
    trained_ = TrainTemplates(model, request).archive;
    const QDir scratch(ScratchDir());
    scratch.mkpath("with_mesh");
    scratch.mkpath("alone");
    with_mesh_ = scratch.filePath("with_mesh/set.layermod");
    alone_ = scratch.filePath("alone/set.layermod");
    WriteArchive(with_mesh_.toStdString(), trained_);
    WriteArchive(alone_.toStdString(), trained_);
    const QString mesh_name = QString::fromStdString(trained_.manifest().objects[0].mesh_file);
    QFile::copy(SampleMeshPath(), scratch.filePath("with_mesh/" + mesh_name));
  }
  void init() {
    window_ = std::make_unique<MainWindow>();
    window_->show();
  }
  void cleanup() { window_.reset(); }

  void ArchiveOpensWithTheMeshBesideIt() {
    window_->OpenFiles({with_mesh_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    QVERIFY(window_->session()->model() != nullptr);
    QVERIFY(window_->browser()->has_mesh());
    QCOMPARE(window_->session()->archive_path(), with_mesh_);
    QVERIFY(!window_->session()->archive_unsaved());
    // The form shows what the archive was trained with.
    QCOMPARE(ToJson(window_->views_panel()->profile()).dump(),
             ToJson(trained_.manifest().objects[0].profile).dump());
    QCOMPARE(window_->browser()->list_model()->rowCount(),
             static_cast<int>(trained_.templates().size()));
  }

  void ArchiveWithoutMeshShowsFeaturesOnBlack() {
    window_->OpenFiles({alone_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    QVERIFY(window_->session()->model() == nullptr);
    QVERIFY(!window_->browser()->has_mesh());
    TemplateListModel* list = window_->browser()->list_model();
    list->data(list->index(0), Qt::DecorationRole);  // ask for one even if not painted yet
    QTRY_VERIFY_WITH_TIMEOUT(list->rendered_thumbnails() > 0 && list->pending_thumbnails() == 0,
                             20000);
    const QImage thumbnail =
        list->data(list->index(0), Qt::DecorationRole).value<QPixmap>().toImage();
    int grey = 0;
    int green = 0;
    for (int y = 0; y < thumbnail.height(); ++y) {
      for (int x = 0; x < thumbnail.width(); ++x) {
        const QColor c = thumbnail.pixelColor(x, y);
        if (c.green() > 200 && c.red() < 100) ++green;
        if (c.red() > 60 && qAbs(c.red() - c.green()) < 8 && qAbs(c.red() - c.blue()) < 8) ++grey;
      }
    }
    QVERIFY(green > 0);  // the features are drawn
    // but no rendered (grey) part behind them; a few mixed feature pixels may look grey
    QVERIFY2(grey < thumbnail.width() * thumbnail.height() / 100,
             qPrintable(QString::number(grey)));
  }

  void FiltersByLayerAndElevation() {
    window_->OpenFiles({with_mesh_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    auto* layer = window_->browser()->findChild<QComboBox*>("layerFilter");
    const int layers = static_cast<int>(trained_.manifest().objects[0].layer_depths_mm.size());
    QCOMPARE(layer->count(), layers + 1);  // "All layers" first
    layer->setCurrentIndex(2);
    TemplateListModel* list = window_->browser()->list_model();
    QCOMPARE(list->rowCount(), static_cast<int>(trained_.templates().size()) / layers);
    for (int row = 0; row < list->rowCount(); ++row)
      QCOMPARE(int{list->RecordAt(row)->layer_index}, 1);

    auto* elevation_min = window_->browser()->findChild<QDoubleSpinBox*>("elevationMinFilter");
    elevation_min->setValue(45.0);
    for (int row = 0; row < list->rowCount(); ++row) {
      QVERIFY(list->RecordAt(row)->view.elevation_deg >= 45.0);
    }
    QCOMPARE(list->rowCount(), 4);  // elevation 60 only, four azimuths

    // An azimuth range across 0: 300 to 60 degrees.
    window_->browser()->findChild<QDoubleSpinBox*>("azimuthMinFilter")->setValue(300.0);
    window_->browser()->findChild<QDoubleSpinBox*>("azimuthMaxFilter")->setValue(60.0);
    QVERIFY(list->rowCount() >= 1 && list->rowCount() < 4);
    for (int row = 0; row < list->rowCount(); ++row) {
      const double azimuth = std::fmod(list->RecordAt(row)->view.azimuth_deg + 360.0, 360.0);
      QVERIFY2(azimuth >= 300.0 - 1e-6 || azimuth <= 60.0 + 1e-6,
               qPrintable(QString::number(azimuth)));
    }
  }

  void ClickShowsTheTemplateAndItsCamera() {
    window_->OpenFiles({with_mesh_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    QVERIFY(!window_->scene()->has_highlight());
    window_->browser()->SelectRow(5);
    QVERIFY(window_->scene()->has_highlight());
    auto* image = window_->browser()->findChild<QLabel*>("detailImage");
    QVERIFY(!image->pixmap(Qt::ReturnByValue).isNull());
    const QString text = window_->browser()->findChild<QLabel*>("detailText")->text();
    QVERIFY(text.contains(QStringLiteral("Template #%1").arg(trained_.templates()[5].id)));
  }

  void ArrowKeysMoveTheDetailAndTheCamera() {
    window_->OpenFiles({with_mesh_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    TemplateBrowser* browser = window_->browser();
    QSignalSpy selected(browser, &TemplateBrowser::TemplateSelected);
    browser->SelectRow(5);
    QCOMPARE(selected.count(), 1);
    browser->list_view()->setFocus();
    QTest::keyClick(browser->list_view(), Qt::Key_Right);
    QCOMPARE(browser->list_view()->currentIndex().row(), 6);
    QCOMPARE(selected.count(), 2);
    const int template_index = browser->list_model()->TemplateIndexAt(6);
    QCOMPARE(selected.last().at(0).toInt(), template_index);
    const QString text = browser->findChild<QLabel*>("detailText")->text();
    QVERIFY2(
        text.contains(QStringLiteral("Template #%1")
                          .arg(trained_.templates()[static_cast<std::size_t>(template_index)].id)),
        qPrintable(text));
  }

  void CoverageGlyphsFollowThePlan() {
    window_->OpenFiles({with_mesh_});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    window_->views_panel()->UpdatePlan();
    const auto& plan = window_->views_panel()->plan();
    QVERIFY(plan.has_value());
    // One glyph per layer and camera direction (rolls share a position).
    QCOMPARE(window_->scene()->coverage_glyph_count(),
             static_cast<int>(plan->layer_depths_mm.size() * 8));
  }

 private:
  TemplateArchive trained_;
  QString with_mesh_;
  QString alone_;
  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(TemplateBrowserTest);

}  // namespace layermod::ui::test

#include "template_browser_test.moc"
