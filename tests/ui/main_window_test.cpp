// SPDX-License-Identifier: MIT
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QUrl>
#include <QWheelEvent>
#include <nlohmann/json.hpp>

#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/training/training_panel.h"
#include "ui/views/views_panel.h"
#include "ui/window/dock_layout.h"
#include "ui/window/log_dock.h"
#include "ui/window/main_window.h"
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

  void WheelChangesABoxOnlyWithFocus() {
    auto* depth_min = window_->findChild<QDoubleSpinBox*>("depthMinBox");
    auto* mode = window_->findChild<QComboBox*>("detectionMode");
    QVERIFY(depth_min != nullptr && mode != nullptr);
    QCOMPARE(depth_min->focusPolicy(), Qt::StrongFocus);
    depth_min->clearFocus();
    const double before = depth_min->value();
    const int mode_before = mode->currentIndex();
    SendWheel(depth_min, -120);
    SendWheel(mode, -120);
    QCOMPARE(depth_min->value(), before);
    QCOMPARE(mode->currentIndex(), mode_before);
    QVERIFY(!depth_min->hasFocus());
    // With the focus the wheel edits, as it always did.
    window_->activateWindow();
    depth_min->setFocus();
    QTRY_VERIFY(depth_min->hasFocus());
    SendWheel(depth_min, 120);
    QVERIFY(depth_min->value() > before);
  }

  void FirstWindowFitsALaptopScreen() {
    const QSize size = MainWindow::InitialSize(QRect(0, 0, 1280, 800));
    QVERIFY(size.width() <= 1280 && size.height() <= 800);
    QCOMPARE(MainWindow::InitialSize(QRect(0, 0, 2560, 1440)), QSize(1600, 1000));
    QVERIFY2(window_->minimumSizeHint().width() < 900,
             qPrintable(QString::number(window_->minimumSizeHint().width())));
  }

  void ResetLayoutRestoresTheDocks() {
    auto* views = window_->findChild<QDockWidget*>("ViewsDock");
    auto* model = window_->findChild<QDockWidget*>("ModelDock");
    auto* training = window_->findChild<QDockWidget*>("TrainingDock");
    views->hide();
    window_->addDockWidget(Qt::RightDockWidgetArea, model);
    training->setFloating(true);
    QVERIFY(!views->isVisible());
    window_->findChild<QAction*>("resetLayoutAction")->trigger();
    QVERIFY(views->isVisible());
    QVERIFY(!training->isFloating());
    QCOMPARE(window_->dockWidgetArea(model), Qt::LeftDockWidgetArea);
    QCOMPARE(window_->dockWidgetArea(training), Qt::LeftDockWidgetArea);
    QCOMPARE(window_->dockWidgetArea(views), Qt::RightDockWidgetArea);
    QTRY_VERIFY(views->width() >= window_->dock_layout()->DefaultSize(views, window_->size()) - 20);
  }

  void DocksComeBackWhenTheWindowGrows() {
    window_->resize(1280, 800);
    QTRY_COMPARE(window_->width(), 1280);
    window_->dock_layout()->Reset();
    auto* views = window_->findChild<QDockWidget*>("ViewsDock");
    const int wide = window_->dock_layout()->DefaultSize(views, window_->size());
    QVERIFY(wide > 300);
    QTRY_VERIFY2(views->width() >= wide - 20, qPrintable(QString::number(views->width())));
    window_->resize(720, 560);
    QTRY_VERIFY(window_->width() <= 760);
    QTRY_VERIFY(views->width() < wide - 50);
    window_->resize(1280, 800);
    QTRY_COMPARE(window_->width(), 1280);
    QTRY_VERIFY2(views->width() >= wide - 20, qPrintable(QString::number(views->width())));
  }

  void QuitWhileTrainingAsksToCancel() {
    window_->OpenFiles({SampleMeshPath()});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->model() != nullptr, 20000);
    QTRY_VERIFY(!window_->runner()->busy());
    TrainingProfile large = TinyProfile();
    large.depth_max_mm = 1500.0;
    large.views = TrainingProfile::DefaultEnvelopeViews();
    window_->views_panel()->SetProfile(large);
    window_->views_panel()->UpdatePlan();
    QVERIFY(window_->training_panel()->StartTraining());
    {
      MessageBoxCloser keep(QMessageBox::No);
      QVERIFY(!window_->close());
      QVERIFY(keep.seen());
      QCOMPARE(keep.object_name(), QStringLiteral("quitWhileBusyDialog"));
      QVERIFY2(keep.text().contains("Cancel training and quit?"), qPrintable(keep.text()));
      QVERIFY(window_->runner()->busy());
    }
    {
      MessageBoxCloser quit(QMessageBox::Yes);
      QVERIFY(window_->close());
      QVERIFY(quit.seen());
    }
    QTRY_VERIFY_WITH_TIMEOUT(!window_->runner()->busy(), 60000);
  }

  void AnInvalidFormCannotBeTrained() {
    window_->OpenFiles({SampleMeshPath()});
    QTRY_VERIFY_WITH_TIMEOUT(window_->session()->model() != nullptr, 20000);
    QTRY_VERIFY(!window_->runner()->busy());
    auto* train = window_->findChild<QPushButton*>("trainButton");
    TrainingProfile profile = TinyProfile();
    window_->views_panel()->SetProfile(profile);
    window_->views_panel()->UpdatePlan();
    QVERIFY(train->isEnabled());
    profile.depth_min_mm = profile.depth_max_mm + 100.0;
    window_->views_panel()->SetProfile(profile);
    window_->views_panel()->UpdatePlan();
    QVERIFY(!train->isEnabled());
    QVERIFY2(train->toolTip().contains("must be below D_max"), qPrintable(train->toolTip()));
    QVERIFY(!window_->training_panel()->StartTraining());  // Ctrl+T is refused too
    QVERIFY(!window_->runner()->busy());
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
  static void SendWheel(QWidget* widget, int delta) {
    const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent wheel(at, QPointF(widget->mapToGlobal(at.toPoint())), QPoint(), QPoint(0, delta),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
  }

  std::unique_ptr<MainWindow> window_;
};

LAYERMOD_UI_TEST(MainWindowTest);

}  // namespace layermod::ui::test

#include "main_window_test.moc"
