// SPDX-License-Identifier: MIT
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>

#include "ui/job_runner.h"
#include "ui/main_window.h"
#include "ui/studio_session.h"
#include "ui/template_browser.h"
#include "ui/template_list_model.h"
#include "ui/training_panel.h"
#include "ui/views_panel.h"
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

  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(TrainingPanelTest);

}  // namespace layermod::ui::test

#include "training_panel_test.moc"
