// SPDX-License-Identifier: MIT
#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <nlohmann/json.hpp>

#include "dataset/bop.h"
#include "dataset/bop_writer.h"
#include "pipeline/detector_options.h"
#include "ui/common/job_runner.h"
#include "ui/common/studio_session.h"
#include "ui/detection/detection_options_form.h"
#include "ui/detection/detection_panel.h"
#include "ui/detection/detection_table.h"
#include "ui/detection/ground_truth_text.h"
#include "ui/detection/image_view.h"
#include "ui/scene3d/scene_view.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

namespace layermod::ui::test {

class DetectionPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(!SyntheticCaptureFiles().archive.isEmpty()); }

  void init() {
    window_ = std::make_unique<MainWindow>();
    window_->show();
    window_->OpenFiles({SyntheticCaptureFiles().archive});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->archive() != nullptr, 20000);
    QTRY_VERIFY(!window_->runner()->busy());
  }
  void cleanup() { window_.reset(); }

  void BopFrameIsDetectedIntoTheTable() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({files.bop_dir, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QCOMPARE(window_->tabs()->currentWidget(), panel);
    QVERIFY(panel->table()->rowCount() >= 1);
    QVERIFY2(panel->table()->item(0, 0)->text().contains("bracket"),
             qPrintable(panel->table()->item(0, 0)->text()));
    // The checks the confidence came from: in their column and, in full, in the row's tooltip.
    const int checks = static_cast<int>(DetectionColumnTitles().indexOf("Checks"));
    QVERIFY(checks > 0);
    const QString checks_text = panel->table()->item(0, checks)->text();
    QVERIFY2(checks_text.contains("depth") && checks_text.contains("outline"),
             qPrintable(checks_text));
    const QString tooltip = panel->table()->item(0, 0)->toolTip();
    QVERIFY2(tooltip.contains("depth fit") && tooltip.contains("contradicted") &&
                 tooltip.contains("outline on scene edges"),
             qPrintable(tooltip));
    QVERIFY(window_->findChild<QLabel*>("timingsLabel")->text().contains("total"));
    QVERIFY(window_->findChild<QLabel*>("layerLegend")->text().contains("mm"));
  }

  void GroundTruthCoverageIsShownAndDrawn() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy covered(panel, &DetectionPanel::CoverageChanged);
    panel->OpenCapture({files.bop_dir, 1, 0, {}, {}, {}});
    QTRY_VERIFY_WITH_TIMEOUT(covered.count() >= 1, 60000);
    // The frame's ground truth is a template's own pose: inside the envelope.
    QCOMPARE(panel->ground_truth_coverage().size(), std::size_t{1});
    QVERIFY(panel->ground_truth_coverage()[0].check->inside);
    auto* label = window_->findChild<QLabel*>("groundTruthLabel");
    QVERIFY(label->isVisibleTo(panel));
    QVERIFY2(label->text().contains("obj 1 at") && label->text().contains("covered"),
             qPrintable(label->text()));
    // Its camera among the template cameras needs the model in the 3D view.
    QCOMPARE(window_->scene()->ground_truth_view_count(), 0);
    window_->OpenFiles({SampleMeshPath()});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->model() != nullptr, 20000);
    QTRY_COMPARE(window_->scene()->ground_truth_view_count(), 1);
    QVERIFY(window_->session()->archive() != nullptr);

    // A pose outside, and an object the set has no templates of, say so.
    EnvelopeCheck outside;
    outside.inside = false;
    outside.depth_mm = 734.0;
    outside.reason = "seen from -57 deg elevation, 58.1 deg from every template view";
    const QString text = CoverageHtml({{1, outside}, {5, std::nullopt}});
    QVERIFY2(text.contains("obj 1 at 734 mm: outside the envelope") &&
                 text.contains("seen from -57 deg elevation"),
             qPrintable(text));
    QVERIFY(text.contains("obj 5: not in the template set"));
  }

  // The docks step aside for the preview and come back with the 3D view. The preview's minimum
  // width outlasts it (a tab widget is as wide as its widest page), so it must leave the docks
  // their room on a laptop screen, or the window grows past it when they return.
  void BackFromThePreviewTheDocksStillFit() {
    window_->resize(1280, 760);
    QTest::qWait(50);
    const int docks_px = window_->findChild<QDockWidget*>("ModelDock")->width() +
                         window_->findChild<QDockWidget*>("ViewsDock")->width();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({SyntheticCaptureFiles().bop_dir, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QTest::qWait(50);
    const int preview_min_px = window_->tabs()->minimumSizeHint().width();
    QVERIFY2(preview_min_px + docks_px <= 1280,
             qPrintable(QString("preview %1 px + docks %2 px").arg(preview_min_px).arg(docks_px)));
    window_->tabs()->setCurrentIndex(0);
    QTest::qWait(100);
    QVERIFY(window_->width() <= 1280);
  }

  void EdgeBoundAndRefinementsReachTheDetectorAndPersist() {
    DetectionOptionsForm form;
    QCOMPARE(form.options().coarse.upper_factor, CoarsePositioningOptions{}.upper_factor);
    QCOMPARE(form.options().match.max_refinements, MatchOptions{}.max_refinements);
    form.findChild<QDoubleSpinBox*>("detectionEdgeUpper")->setValue(1.5);
    form.findChild<QSpinBox*>("detectionRefinements")->setValue(500);
    QCOMPARE(form.options().coarse.upper_factor, 1.5f);
    QCOMPARE(form.options().match.max_refinements, 500);
    form.SaveSettings();
    DetectionOptionsForm restored;
    restored.RestoreSettings();
    QCOMPARE(restored.options().coarse.upper_factor, 1.5f);
    QCOMPARE(restored.options().match.max_refinements, 500);
    restored.SetOptions(DetectorOptions{});
    restored.SaveSettings();  // leave the defaults for the other tests
  }

  void TableRowsNameTheChecksOfTheirConfidence() {
    Detection detection;
    detection.name = "part";
    detection.confidence = 0.42;
    detection.score = 81.0;
    detection.verification.depth_fit = 0.61;
    detection.verification.contradicted_ratio = 0.25;
    detection.verification.color_agreement = 0.93;
    detection.verification.outline_agreement = 0.48;
    detection.icp.iterations = 12;
    const QStringList texts = DetectionRowTexts(detection);
    QCOMPARE(texts.size(), DetectionColumnTitles().size());
    QCOMPARE(texts[DetectionColumnTitles().indexOf("Checks")],
             QString("depth 0.61 · colour 0.93 · outline 0.48"));
    const QString tooltip = VerificationTooltip(detection);
    QVERIFY2(tooltip.startsWith("Confidence 0.42, from:") &&
                 tooltip.contains("contradicted 0.25") &&
                 tooltip.contains("outline on scene edges 0.48"),
             qPrintable(tooltip));
    // Without depth (no ICP) only what the colour image tells is shown.
    detection.icp.iterations = 0;
    QCOMPARE(DetectionRowTexts(detection)[DetectionColumnTitles().indexOf("Checks")],
             QString("colour 0.93 · outline 0.48"));
    QVERIFY(!VerificationTooltip(detection).contains("depth"));
  }

  void SettingsFormIsTheFieldTable() {
    DetectionOptionsForm form;
    for (const DetectorOptionField& field : DetectorOptionFields()) {
      QVERIFY2(form.field_widget(std::string(field.key)) != nullptr, field.key.data());
    }
    // The boxes show every default exactly (no rounding to the boxes' decimals).
    QVERIFY2(SameOptions(form.options(), DetectorOptions{}), qPrintable(differences_));
    DetectorOptions options;
    options.mode = DetectionMode::kExhaustive;
    options.icp.huber_mm = 7.5;
    options.verification.min_depth_inlier_ratio = 0.4;
    options.regions.cell_size_px = 12;
    form.SetOptions(options);
    QVERIFY2(SameOptions(form.options(), options), qPrintable(differences_));
    const QString path = QDir(ScratchDir()).filePath("detector_profile.json");
    QVERIFY(form.SaveProfile(path));
    DetectionOptionsForm loaded;
    QVERIFY(loaded.LoadProfile(path));
    QVERIFY2(SameOptions(loaded.options(), options), qPrintable(differences_));
    // Settings are keyed by the table's keys, and hold only what differs from the defaults.
    form.SaveSettings();
    QCOMPARE(QSettings().value("detection/icp_huber").toString(), QStringLiteral("7.5"));
    QCOMPARE(QSettings().value("detection/mode").toString(), QStringLiteral("\"exhaustive\""));
    QVERIFY(!QSettings().contains("detection/occlusion"));
    QVERIFY(!QSettings().contains("detection/min_confidence"));
    DetectionOptionsForm restored;
    restored.RestoreSettings();
    QVERIFY2(SameOptions(restored.options(), options), qPrintable(differences_));
    // A value an older studio saved in another form keeps its default, not the others'.
    QSettings().setValue("detection/mode", 2);
    restored.RestoreSettings();
    QCOMPARE(restored.options().mode, DetectorOptions{}.mode);
    QCOMPARE(restored.options().icp.huber_mm, 7.5);
    restored.SetOptions(DetectorOptions{});
    restored.SaveSettings();  // leave the defaults for the other tests
  }

  void FieldLabelsAndDecimalsReadWell() {
    DetectionOptionsForm form;
    const auto label = [&](const char* key) {
      QWidget* box = form.field_widget(key);
      auto* layout = qobject_cast<QFormLayout*>(box->parentWidget()->layout());
      return qobject_cast<QLabel*>(layout->labelForField(box))->text();
    };
    QCOMPARE(label("nms_radius"), QStringLiteral("NMS radius"));
    QCOMPARE(label("icp_max_step_deg"), QStringLiteral("ICP max step (deg)"));
    QCOMPARE(label("min_inlier_ratio"), QStringLiteral("Min inlier ratio"));
    // A float default shows with the decimals it needs, not a float's rounding noise.
    QCOMPARE(qobject_cast<QDoubleSpinBox*>(form.field_widget("tree_descend"))->text(),
             QStringLiteral("0.150"));
  }

  void EachOverlayToggles() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({files.bop_dir, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(!panel->result()->detections.empty());
    QVERIFY(!panel->result()->diagnostics.empty());

    panel->SetOverlays({false, false, false, false});
    const QImage plain = panel->image_view()->image();
    QVERIFY(!plain.isNull());
    for (int overlay = 0; overlay < 4; ++overlay) {
      QCheckBox* toggle = panel->overlay_toggle(overlay);
      toggle->click();
      QVERIFY2(panel->image_view()->image() != plain, qPrintable(toggle->text()));
      toggle->click();
      QCOMPARE(panel->image_view()->image(), plain);
    }
  }

  void ColourDepthFilesAreDetected() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({{}, 0, 0, files.color, files.depth, files.camera});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(panel->table()->rowCount() >= 1);
    QVERIFY(window_->findChild<QLabel*>("captureLabel")->text().contains("with depth"));
  }

  void DoubleClickedDetectionShowsInThe3dView() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({files.bop_dir, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(!window_->scene()->has_detection());
    emit panel->table()->cellDoubleClicked(0, 0);
    QVERIFY(window_->scene()->has_detection());
    QVERIFY(window_->scene()->detection_cloud_points() > 100);
    QCOMPARE(window_->tabs()->currentWidget(), window_->scene());
  }

  void DroppedBopFolderOpensItsFrame() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    QSignalSpy finished(window_->detection_panel(), &DetectionPanel::DetectionFinished);
    window_->OpenFiles({files.bop_dir});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(window_->detection_panel()->has_capture());
    QVERIFY(window_->detection_panel()->table()->rowCount() >= 1);
  }

  void PageKeysStepThroughTheScenesFrames() {
    const QString split = ThreeFrameSplit();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy finished(panel, &DetectionPanel::DetectionFinished);
    panel->OpenCapture({split, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QCOMPARE(window_->tabs()->currentWidget(), panel);
    QVERIFY(panel->can_step_frames());
    // PgUp/PgDn are the Run menu's window shortcuts (Xvfb has no window manager to make the
    // window active for a simulated key, so the actions are triggered as the shortcut would).
    auto* next = window_->findChild<QAction*>("nextFrameAction");
    auto* previous = window_->findChild<QAction*>("previousFrameAction");
    QCOMPARE(next->shortcut(), QKeySequence(Qt::Key_PageDown));
    QCOMPARE(previous->shortcut(), QKeySequence(Qt::Key_PageUp));
    QVERIFY(next->isEnabled() && previous->isEnabled());
    // The scene holds frames 0, 3 and 5: steps follow the scene's ids, not +1.
    next->trigger();
    QCOMPARE(panel->frame_in_form(), 3);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QVERIFY(window_->findChild<QLabel*>("captureLabel")->text().contains("frame 3"));
    next->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 60000);
    QCOMPARE(panel->frame_in_form(), 5);
    QVERIFY(!panel->StepFrame(1));  // the last frame
    previous->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 4, 60000);
    QCOMPARE(panel->frame_in_form(), 3);
    // Over the 3D view the keys page lists again.
    window_->tabs()->setCurrentWidget(window_->scene());
    QVERIFY(!next->isEnabled());
    QVERIFY(window_->findChild<QLabel*>("captureLabel")->text().contains("frame 3"));
  }

  void EnterInTheFrameBoxLoadsTheFrame() {
    const QString split = ThreeFrameSplit();
    DetectionPanel* panel = window_->detection_panel();
    window_->findChild<QLineEdit*>("bopDir")->setText(split);
    auto* frame = panel->findChild<QSpinBox*>("frameBox");
    frame->setValue(5);
    QSignalSpy opened(panel, &DetectionPanel::CaptureOpened);
    QTest::keyClick(frame, Qt::Key_Return);
    QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 60000);
    QVERIFY(window_->findChild<QLabel*>("captureLabel")->text().contains("frame 5"));
  }

  void ColourDepthLoadClearsTheBopFolder() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy opened(panel, &DetectionPanel::CaptureOpened);
    panel->OpenCapture({files.bop_dir, 1, 0, {}, {}, {}});
    QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 60000);
    QCOMPARE(window_->findChild<QLineEdit*>("bopDir")->text(), files.bop_dir);
    panel->OpenCapture({{}, 0, 0, files.color, files.depth, files.camera});
    QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 2, 60000);
    QVERIFY(window_->findChild<QLineEdit*>("bopDir")->text().isEmpty());
    QVERIFY(!panel->can_step_frames());
  }

  void MissingFrameShowsAnErrorNamingTheFolder() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    MessageBoxCloser closer(QMessageBox::Ok);
    window_->detection_panel()->OpenCapture({files.bop_dir, 1, 7, {}, {}, {}});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 20000);
    QCOMPARE(closer.object_name(), QStringLiteral("errorDialog"));
    QVERIFY2(closer.text().contains(files.bop_dir), qPrintable(closer.text()));
    QVERIFY(!window_->detection_panel()->has_capture());
  }

  void OtherIntrinsicsShowADetectionError() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    PinholeCamera other = LoadCameraJson(files.camera.toStdString());
    other.fx *= 1.2;
    const QString camera = QDir(ScratchDir()).filePath("other_camera.json");
    WriteBopCamera(camera.toStdString(), other);
    DetectionPanel* panel = window_->detection_panel();
    QSignalSpy opened(panel, &DetectionPanel::CaptureOpened);
    MessageBoxCloser closer(QMessageBox::Ok);
    panel->OpenCapture({{}, 0, 0, files.color, files.depth, camera});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 60000);
    QCOMPARE(opened.count(), 1);
    QVERIFY2(closer.text().contains("Detect in") && closer.text().contains(files.color),
             qPrintable(closer.text()));
    QVERIFY(!panel->has_result());
    QCOMPARE(panel->table()->rowCount(), 0);
  }

  void UnreadableColourShowsAnErrorNamingTheFile() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    const QString missing = QDir(ScratchDir()).filePath("no_such_colour.png");
    MessageBoxCloser closer(QMessageBox::Ok);
    window_->detection_panel()->OpenCapture({{}, 0, 0, missing, files.depth, files.camera});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 20000);
    QVERIFY2(closer.text().contains(missing), qPrintable(closer.text()));
  }

 private:
  // Whether `a` and `b` have the same fields; the differing fields in differences_.
  bool SameOptions(const DetectorOptions& a, const DetectorOptions& b) {
    const nlohmann::json ja = DetectorOptionsToJson(a);
    const nlohmann::json jb = DetectorOptionsToJson(b);
    differences_.clear();
    for (const auto& [key, value] : ja.items()) {
      if (jb.at(key) != value) {
        differences_ +=
            QString::fromStdString(key + ": " + value.dump() + " vs " + jb.at(key).dump() + "; ");
      }
    }
    return differences_.isEmpty();
  }

  QString differences_;
  // A split whose scene 1 holds the synthetic frame three times, as images 0, 3 and 5.
  static QString ThreeFrameSplit() {
    const QString split = QDir(ScratchDir()).filePath("three_frames");
    if (QFileInfo::exists(split)) return split;
    const auto scenes = ListBopScenes(SyntheticCaptureFiles().bop_dir.toStdString());
    BopFrame frame = LoadBopFrame(scenes.front(), 0);
    BopSceneWriter writer(QDir(split).filePath("000001").toStdString());
    for (int id : {0, 3, 5}) {
      frame.image_id = id;
      writer.AddFrame(frame);
    }
    writer.Finish();
    return split;
  }

  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(DetectionPanelTest);

}  // namespace layermod::ui::test

#include "detection_panel_test.moc"
