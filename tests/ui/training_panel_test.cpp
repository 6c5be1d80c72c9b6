// SPDX-License-Identifier: MIT
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include "ui/common/job_runner.h"
#include "ui/common/studio_session.h"
#include "ui/model/model_panel.h"
#include "ui/templates/template_browser.h"
#include "ui/templates/template_list_model.h"
#include "ui/training/training_panel.h"
#include "ui/views/views_panel.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

namespace layermod::ui::test {

class TrainingPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    window_ = std::make_unique<MainWindow>();
    window_->show();
    window_->OpenFiles({SampleMeshPath()});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->model() != nullptr, 20000);
  }
  void cleanup() { window_.reset(); }

  void TrainExportAndBrowse() {
    window_->views_panel()->SetProfile(TinyProfile());
    window_->views_panel()->UpdatePlan();
    const std::size_t expected = window_->views_panel()->plan()->TemplateCount();
    QCOMPARE(expected, window_->views_panel()->plan()->layer_depths_mm.size() * 8);

    QSignalSpy progress(window_->runner(), &JobRunner::Progress);
    QSignalSpy succeeded(window_->training_panel(), &TrainingPanel::TrainingSucceeded);
    QVERIFY(window_->training_panel()->StartTraining());
    QVERIFY(window_->training_panel()->training());
    QTRY_COMPARE_WITH_TIMEOUT(succeeded.count(), 1, 60000);
    QVERIFY(progress.count() >= 1);  // progress reached the GUI thread while training ran

    const auto archive = window_->session()->archive();
    QVERIFY(archive != nullptr);
    QCOMPARE(archive->templates().size(), expected);
    QVERIFY(window_->session()->archive_unsaved());
    QVERIFY(window_->findChild<QLabel*>("summaryLabel")
                ->text()
                .contains(QStringLiteral("%1 templates").arg(expected)));

    const QString path = QDir(ScratchDir()).filePath("trained.layermod");
    QVERIFY(window_->training_panel()->ExportArchive(path));
    QVERIFY(QFileInfo(path).size() > 0);
    QCOMPARE(ReadArchive(path.toStdString()).templates().size(), expected);
    QVERIFY(!window_->session()->archive_unsaved());

    TemplateListModel* list = window_->browser()->list_model();
    QCOMPARE(list->rowCount(), static_cast<int>(expected));
    QVERIFY(window_->browser()->has_mesh());
    // Every thumbnail of the visible part is rendered lazily and arrives.
    QTRY_VERIFY_WITH_TIMEOUT(list->rendered_thumbnails() > 0 && list->pending_thumbnails() == 0,
                             30000);
    const QPixmap thumbnail = list->data(list->index(0), Qt::DecorationRole).value<QPixmap>();
    QCOMPARE(thumbnail.width(), TemplateListModel::kThumbnailPx);
    QVERIFY(HasGreenFeaturePixels(thumbnail.toImage()));
  }

  void CancelLeavesNoResult() {
    TrainingProfile large = TinyProfile();
    large.depth_max_mm = 1500.0;
    large.views = TrainingProfile::DefaultEnvelopeViews();
    window_->views_panel()->SetProfile(large);
    window_->views_panel()->UpdatePlan();
    QVERIFY(window_->views_panel()->plan()->TemplateCount() > 2000);

    QSignalSpy progress(window_->runner(), &JobRunner::Progress);
    QSignalSpy cancelled(window_->runner(), &JobRunner::Cancelled);
    QSignalSpy stopped(window_->training_panel(), &TrainingPanel::TrainingStopped);
    QVERIFY(window_->training_panel()->StartTraining());
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, 60000);
    window_->training_panel()->CancelTraining();
    QTRY_COMPARE_WITH_TIMEOUT(cancelled.count(), 1, 60000);
    QCOMPARE(stopped.count(), 1);
    QVERIFY(window_->session()->archive() == nullptr);
    QVERIFY(!window_->session()->archive_unsaved());
    QCOMPARE(window_->browser()->list_model()->rowCount(), 0);
    QVERIFY(!window_->training_panel()->training());
    QVERIFY(!window_->runner()->busy());
  }

  void FormIsLockedWhileTraining() {
    TrainingProfile large = TinyProfile();
    large.depth_max_mm = 1500.0;
    large.views = TrainingProfile::DefaultEnvelopeViews();
    window_->views_panel()->SetProfile(large);
    window_->views_panel()->UpdatePlan();
    auto* depth_max = window_->findChild<QDoubleSpinBox*>("depthMaxBox");
    QVERIFY(depth_max->isEnabled());
    QSignalSpy progress(window_->runner(), &JobRunner::Progress);
    QVERIFY(window_->training_panel()->StartTraining());
    QVERIFY(window_->views_panel()->locked());
    QVERIFY(!depth_max->isEnabled());
    QVERIFY(!window_->findChild<QSpinBox*>("objIdBox")->isEnabled());
    QVERIFY(!window_->model_panel()->isEnabled());
    // Typing into the locked box changes nothing.
    QTest::keyClicks(depth_max, "9");
    QCOMPARE(depth_max->value(), 1500.0);
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, 60000);
    window_->training_panel()->CancelTraining();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->runner()->busy(), 60000);
    QVERIFY(!window_->views_panel()->locked());
    QVERIFY(depth_max->isEnabled());
    QVERIFY(window_->model_panel()->isEnabled());
  }

  void ChangedFormMarksTheSetStale() {
    TrainTiny();
    TrainingPanel* panel = window_->training_panel();
    auto* export_button = window_->findChild<QPushButton*>("exportButton");
    QVERIFY(!panel->stale());
    QVERIFY2(export_button->text().contains("Export 24 templates") &&
                 export_button->text().contains(QString::fromUtf8("(500–700 mm)")),
             qPrintable(export_button->text()));
    auto* depth_max = window_->findChild<QDoubleSpinBox*>("depthMaxBox");
    depth_max->setValue(900.0);
    window_->views_panel()->UpdatePlan();
    QVERIFY(panel->stale());
    QVERIFY(window_->findChild<QLabel*>("staleLabel")->isVisible());
    // Export still names the set as trained, not the form.
    QVERIFY(export_button->text().contains(QString::fromUtf8("(500–700 mm)")));
    depth_max->setValue(700.0);
    window_->views_panel()->UpdatePlan();
    QVERIFY(!panel->stale());
    QVERIFY(!window_->findChild<QLabel*>("staleLabel")->isVisible());
    window_->findChild<QLineEdit*>("objNameEdit")->setText("renamed");
    window_->views_panel()->UpdatePlan();
    QVERIFY(panel->stale());
  }

  void AnotherMeshDropsTheSetAndItsFigures() {
    TrainTiny();
    QVERIFY(window_->findChild<QLabel*>("summaryLabel")->text().contains("24 templates"));
    window_->OpenFiles({OffCentreMeshPath()});
    QTRY_VERIFY_WITH_TIMEOUT(
        window_->session()->model() != nullptr &&
            window_->session()->model()->source.filename() == "bracket_off_centre.ply",
        20000);
    QVERIFY(window_->session()->archive() == nullptr);
    QVERIFY(!window_->findChild<QPushButton*>("exportButton")->isEnabled());
    QVERIFY(!window_->findChild<QLabel*>("summaryLabel")->text().contains("templates"));
    QVERIFY(!window_->training_panel()->stale());
  }

  void ObjectIdAndNameReachTheArchive() {
    window_->views_panel()->SetObject(8, "obj_000008");
    TrainTiny();
    const QString path = QDir(ScratchDir()).filePath("object_8.layermod");
    QVERIFY(window_->training_panel()->ExportArchive(path));
    const TemplateArchive archive = ReadArchive(path.toStdString());
    QCOMPARE(archive.manifest().objects.size(), std::size_t{1});
    QCOMPARE(archive.manifest().objects.front().obj_id, 8);
    QCOMPARE(archive.manifest().objects.front().name, std::string("obj_000008"));
    QCOMPARE(archive.templates().front().obj_id, 8);
  }

  void TrainingWithoutModelIsRefused() {
    window_->session()->SetModel(nullptr);
    QVERIFY(!window_->training_panel()->StartTraining());
    QVERIFY(!window_->runner()->busy());
  }

 private:
  static bool HasGreenFeaturePixels(const QImage& image) {
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        const QColor c = image.pixelColor(x, y);
        if (c.green() > 200 && c.red() < 100 && c.blue() < 100) return true;
      }
    }
    return false;
  }

  void TrainTiny() {
    window_->views_panel()->SetProfile(TinyProfile());
    window_->views_panel()->UpdatePlan();
    QSignalSpy succeeded(window_->training_panel(), &TrainingPanel::TrainingSucceeded);
    QVERIFY(window_->training_panel()->StartTraining());
    QTRY_COMPARE_WITH_TIMEOUT(succeeded.count(), 1, 60000);
  }

  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(TrainingPanelTest);

}  // namespace layermod::ui::test

#include "training_panel_test.moc"
