// SPDX-License-Identifier: MIT
#include "ui/window/window_menus.h"

#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>

#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/detection/detection_options_form.h"
#include "ui/detection/detection_panel.h"
#include "ui/scene3d/scene_view.h"
#include "ui/training/training_panel.h"
#include "ui/window/dock_layout.h"
#include "ui/window/studio_files.h"
#include "util/log.h"
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
  file->addAction(QObject::tr("Open &capture files (colour, depth, camera)…"), detection,
                  &DetectionPanel::OpenCaptureFilesDialog);
  file->addAction(QObject::tr("Load &detection settings…"), detection->options_form(),
                  &DetectionOptionsForm::LoadProfileDialog);
  file->addAction(QObject::tr("Sa&ve detection settings…"), detection->options_form(),
                  &DetectionOptionsForm::SaveProfileDialog);
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

// Train, Cancel and Detect as menu items with shortcuts, and frame stepping for the preview;
// each is enabled only when it can run.
void BuildRunMenu(QMainWindow* window, const WindowParts& parts, QToolBar* tools) {
  QMenu* run = window->menuBar()->addMenu(QObject::tr("&Run"));
  QAction* train =
      run->addAction(QObject::tr("&Train templates"), parts.training, &TrainingPanel::StartTraining,
                     QKeySequence(QObject::tr("Ctrl+T")));
  QAction* cancel = run->addAction(QObject::tr("&Cancel running job"), parts.runner,
                                   &JobRunner::Cancel, QKeySequence(Qt::Key_Escape));
  run->addSeparator();
  QAction* detect = run->addAction(QObject::tr("&Detect"), parts.detection, &DetectionPanel::Detect,
                                   QKeySequence(QObject::tr("Ctrl+D")));
  QAction* previous = run->addAction(QObject::tr("&Previous frame"), parts.detection,
                                     &DetectionPanel::PreviousFrame, QKeySequence(Qt::Key_PageUp));
  QAction* next = run->addAction(QObject::tr("&Next frame"), parts.detection,
                                 &DetectionPanel::NextFrame, QKeySequence(Qt::Key_PageDown));
  train->setObjectName("trainAction");
  cancel->setObjectName("cancelAction");
  detect->setObjectName("detectAction");
  previous->setObjectName("previousFrameAction");
  next->setObjectName("nextFrameAction");
  tools->addAction(detect);
  const WindowParts p = parts;
  auto update = [p, train, cancel, detect, previous, next] {
    train->setEnabled(!p.runner->busy() && p.session->model() != nullptr);
    cancel->setEnabled(p.runner->busy());
    detect->setEnabled(p.detection->can_detect());
    // Only over the preview: elsewhere PgUp/PgDn keep paging lists.
    const bool stepping = p.tabs->currentWidget() == p.detection && p.detection->can_step_frames();
    previous->setEnabled(stepping);
    next->setEnabled(stepping);
  };
  QObject::connect(p.runner, &JobRunner::BusyChanged, window, update);
  QObject::connect(p.session, &StudioSession::ModelChanged, window, update);
  QObject::connect(p.session, &StudioSession::ArchiveChanged, window, update);
  QObject::connect(p.detection, &DetectionPanel::StateChanged, window, update);
  QObject::connect(p.tabs, &QTabWidget::currentChanged, window, update);
  update();
}

void BuildViewMenu(QMainWindow* window, SceneView* scene, DockLayout* docks, QToolBar* tools) {
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
  view->addSeparator();
  QAction* reset = view->addAction(QObject::tr("Reset &layout"), docks, &DockLayout::Reset);
  reset->setObjectName("resetLayoutAction");
  reset->setToolTip(QObject::tr("Every panel back in its place and size"));
}

}  // namespace

void BuildWindowMenus(QMainWindow* window, const WindowParts& parts) {
  QToolBar* tools = window->addToolBar(QObject::tr("Main"));
  tools->setObjectName("MainToolBar");
  BuildFileMenu(window, parts.files, parts.recent_menu, parts.detection, tools);
  BuildRunMenu(window, parts, tools);
  BuildViewMenu(window, parts.scene, parts.docks, tools);
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
    LogInfo(QObject::tr("%1: cancelled").arg(name).toStdString());
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
