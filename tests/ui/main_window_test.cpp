// SPDX-License-Identifier: MIT
#include <QApplication>
#include <QDir>
#include <QDropEvent>
#include <QFile>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QTest>
#include <QUrl>
#include <nlohmann/json.hpp>

#include "ui/job_runner.h"
#include "ui/log_dock.h"
#include "ui/main_window.h"
#include "ui/studio_dialogs.h"
#include "ui/studio_session.h"
#include "ui/views_panel.h"
#include "ui_test_support.h"
#include "util/log.h"

namespace layermod::ui::test {

class MainWindowTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    window_ = std::make_unique<MainWindow>();
    window_->show();
  }
  void cleanup() { window_.reset(); }

  void BadMeshShowsAnErrorNamingTheFile() {
    const QString path = QDir(ScratchDir()).filePath("not_a_mesh.ply");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("ply\nthis is not a mesh\n");
    file.close();
    MessageBoxCloser closer(QMessageBox::Ok);
    window_->OpenFiles({path});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 20000);
    QCOMPARE(closer.object_name(), QStringLiteral("errorDialog"));
    QVERIFY2(closer.text().contains(path), qPrintable(closer.text()));
    QVERIFY(window_->session()->model() == nullptr);
    QTRY_VERIFY(!window_->runner()->busy());
  }

  void MissingFileShowsAnError() {
    const QString path = QDir(ScratchDir()).filePath("does_not_exist.stl");
    MessageBoxCloser closer(QMessageBox::Ok);
    window_->OpenFiles({path});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 20000);
    QVERIFY(closer.text().contains(path));
    QVERIFY(closer.text().contains("no such file"));
  }

  void CorruptArchiveShowsAnErrorNamingTheFile() {
    const QString path = QDir(ScratchDir()).filePath("corrupt.layermod");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QByteArray(300, 'x'));
    file.close();
    MessageBoxCloser closer(QMessageBox::Ok);
    window_->OpenFiles({path});
    QTRY_VERIFY_WITH_TIMEOUT(closer.seen(), 20000);
    QVERIFY2(closer.text().contains(path), qPrintable(closer.text()));
    QVERIFY(window_->session()->archive() == nullptr);
  }

  void DroppedMeshOpensAndBecomesRecent() {
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(SampleMeshPath())});
    // Straight to the window's event handler: QApplication routes drops through the platform's
    // drag manager, which Xvfb has no drag in progress for.
    QDragEnterEvent enter(QPoint(100, 100), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    static_cast<QObject*>(window_.get())->event(&enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(100, 100), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    static_cast<QObject*>(window_.get())->event(&drop);
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->model() != nullptr, 20000);
    delete mime;
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    QVERIFY(!recent.isEmpty());
    QCOMPARE(recent.front(), QFileInfo(SampleMeshPath()).absoluteFilePath());
  }

  void CoreLogReachesTheLogDock() {
    LogWarning("a message from the core");
    QTRY_VERIFY(window_->log_dock()->Text().contains("warning: a message from the core"));
  }

  void QuitAsksBeforeDiscardingAnUnexportedSet() {
    window_->session()->SetArchive(std::make_shared<const TemplateArchive>(), QString());
    QVERIFY(window_->session()->archive_unsaved());
    qunsetenv(kDiscardWithoutAskingEnv);
    {
      MessageBoxCloser keep(QMessageBox::Cancel);
      QVERIFY(!window_->close());
      QVERIFY(keep.seen());
      QCOMPARE(keep.object_name(), QStringLiteral("discardDialog"));
      QVERIFY(window_->isVisible());
    }
    {
      MessageBoxCloser discard(QMessageBox::Discard);
      QVERIFY(window_->close());
      QVERIFY(discard.seen());
    }
    qputenv(kDiscardWithoutAskingEnv, "1");
  }

  void ClosingSavesTheProfileForTheNextRun() {
    TrainingProfile profile = TinyProfile();
    profile.depth_max_mm = 1234.0;
    window_->views_panel()->SetProfile(profile);
    QVERIFY(window_->close());
    MainWindow next;
    QCOMPARE(next.views_panel()->profile().depth_max_mm, 1234.0);
  }

 private:
  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(MainWindowTest);

}  // namespace layermod::ui::test

#include "main_window_test.moc"
