// SPDX-License-Identifier: MIT
#include "ui/window_menus.h"

#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>

#include "ui/detection_panel.h"
#include "ui/job_runner.h"
#include "ui/scene_view.h"
#include "ui/studio_dialogs.h"
#include "ui/studio_files.h"
#include "util/version.h"

namespace layermod::ui {
namespace {

constexpr int kStatusMs = 5000;

void ShowAbout(QWidget* parent) {
  QMessageBox::about(parent, QObject::tr("About LayerMOD Studio"),
                     QObject::tr("<h3>LayerMOD Studio %1</h3><p>Authoring of multi-scale LineMOD "
                                 "template sets for texture-less objects: depth layers spaced by "
                                 "the object's circumscribing sphere.</p><p>MIT licence.</p>")
                         .arg(QString::fromStdString(ToolVersion())));
}

void BuildFileMenu(QMainWindow* window, StudioFiles* files, QMenu* recent_menu,
                   DetectionPanel* detection, QToolBar* tools) {
  QMenu* file = window->menuBar()->addMenu(QObject::tr("&File"));
  auto add = [file, files, tools](const QString& text, const QKeySequence& keys, auto slot,
                                  bool on_toolbar) {
    QAction* action = file->addAction(text, files, slot, keys);
    if (on_toolbar) tools->addAction(action);
  };
  add(QObject::tr("Open &mesh…"), QKeySequence::Open, &StudioFiles::OpenMeshDialog, true);
  add(QObject::tr("Open &archive…"), QKeySequence(QObject::tr("Ctrl+Shift+O")),
      &StudioFiles::OpenArchiveDialog, true);
  file->addMenu(recent_menu);
  file->addSeparator();
  tools->addAction(file->addAction(QObject::tr("Open &BOP frame…"), detection,
                                   &DetectionPanel::OpenBopFrameDialog));
  file->addAction(QObject::tr("Open &colour + depth capture…"), detection,
                  &DetectionPanel::OpenCaptureFilesDialog);
  file->addSeparator();
  add(QObject::tr("&Load training profile…"), QKeySequence(), &StudioFiles::LoadProfileDialog,
      false);
  add(QObject::tr("&Save training profile…"), QKeySequence(), &StudioFiles::SaveProfileDialog,
      false);
  add(QObject::tr("&Export archive…"), QKeySequence(QObject::tr("Ctrl+E")),
      &StudioFiles::ExportArchiveDialog, true);
  file->addSeparator();
  file->addAction(QObject::tr("&Quit"), window, &QWidget::close, QKeySequence::Quit);
}

void BuildViewMenu(QMainWindow* window, SceneView* scene, QToolBar* tools) {
  QMenu* view = window->menuBar()->addMenu(QObject::tr("&View"));
  tools->addAction(view->addAction(QObject::tr("&Reset camera"), scene, &SceneView::ResetCamera,
                                   QKeySequence(QObject::tr("Ctrl+R"))));
  QAction* coverage =
      view->addAction(QObject::tr("Show view &coverage"), scene, &SceneView::SetCoverageVisible);
  QAction* sphere =
      view->addAction(QObject::tr("Show &sphere"), scene, &SceneView::SetSphereVisible);
  for (QAction* toggle : {coverage, sphere}) {
    toggle->setCheckable(true);
    toggle->setChecked(true);
  }
  view->addSeparator();
  for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
    view->addAction(dock->toggleViewAction());
  }
}

}  // namespace

void BuildWindowMenus(QMainWindow* window, StudioFiles* files, QMenu* recent_menu, SceneView* scene,
                      DetectionPanel* detection) {
  QToolBar* tools = window->addToolBar(QObject::tr("Main"));
  tools->setObjectName("MainToolBar");
  BuildFileMenu(window, files, recent_menu, detection, tools);
  BuildViewMenu(window, scene, tools);
  QMenu* help = window->menuBar()->addMenu(QObject::tr("&Help"));
  help->addAction(QObject::tr("&About LayerMOD Studio"), window, [window] { ShowAbout(window); });
}

void ShowJobFeedback(QMainWindow* window, JobRunner* runner) {
  QStatusBar* status = window->statusBar();
  QObject::connect(runner, &JobRunner::Started, status,
                   [status](const QString& name) { status->showMessage(name + "…"); });
  QObject::connect(runner, &JobRunner::Succeeded, status, [status](const QString& name) {
    status->showMessage(QObject::tr("%1: done").arg(name), kStatusMs);
  });
  QObject::connect(runner, &JobRunner::Cancelled, status, [status](const QString& name) {
    status->showMessage(QObject::tr("%1: cancelled").arg(name), kStatusMs);
  });
  QObject::connect(runner, &JobRunner::Failed, window,
                   [window, status](const QString& name, const QString& message) {
                     status->showMessage(QObject::tr("%1: failed").arg(name), kStatusMs);
                     ShowError(window, name, message);
                   });
  QObject::connect(runner, &JobRunner::BusyChanged, window, [](bool busy) {
    if (busy) {
      QApplication::setOverrideCursor(Qt::BusyCursor);
    } else {
      QApplication::restoreOverrideCursor();
    }
  });
}

}  // namespace layermod::ui
