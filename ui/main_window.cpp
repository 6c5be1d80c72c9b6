// SPDX-License-Identifier: MIT
#include "ui/main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>

#include "ui/detection_panel.h"
#include "ui/job_runner.h"
#include "ui/log_dock.h"
#include "ui/model_panel.h"
#include "ui/recent_files.h"
#include "ui/scene_view.h"
#include "ui/studio_dialogs.h"
#include "ui/studio_files.h"
#include "ui/studio_session.h"
#include "ui/template_browser.h"
#include "ui/template_list_model.h"
#include "ui/training_panel.h"
#include "ui/views_panel.h"
#include "ui/window_menus.h"

// Q_INIT_RESOURCE must be used outside any namespace; the icons live in a static library.
static void InitStudioResources() { Q_INIT_RESOURCE(icons); }

namespace layermod::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      session_(new StudioSession(this)),
      runner_(new JobRunner(this)),
      scene_(new SceneView),
      log_dock_(new LogDock(this)),
      model_panel_(new ModelPanel(session_, runner_)),
      views_panel_(new ViewsPanel(session_)),
      training_panel_(
          new TrainingPanel(session_, runner_, [this] { return views_panel_->request(); })),
      browser_(new TemplateBrowser(session_)),
      detection_panel_(new DetectionPanel(session_, runner_)),
      tabs_(new QTabWidget) {
  InitStudioResources();
  setWindowTitle(tr("LayerMOD Studio"));
  setWindowIcon(QIcon(":/icons/layermod-studio.svg"));
  setAcceptDrops(true);
  tabs_->setObjectName("centralTabs");
  tabs_->addTab(scene_, tr("3D view"));
  tabs_->addTab(detection_panel_, tr("Detection preview"));
  setCentralWidget(tabs_);
  QDockWidget* model_dock = AddDock(model_panel_, tr("Model"), "ModelDock", Qt::LeftDockWidgetArea);
  AddDock(training_panel_, tr("Training"), "TrainingDock", Qt::LeftDockWidgetArea);
  QDockWidget* views_dock =
      AddDock(views_panel_, tr("Views"), "ViewsDock", Qt::RightDockWidgetArea);
  QDockWidget* browser_dock =
      AddDock(browser_, tr("Templates"), "TemplatesDock", Qt::BottomDockWidgetArea);
  addDockWidget(Qt::BottomDockWidgetArea, log_dock_);
  tabifyDockWidget(browser_dock, log_dock_);
  browser_dock->raise();
  auto* recent_menu = new QMenu(tr("Recent &files"), this);
  files_ = new StudioFiles(this, session_, runner_, {model_panel_, views_panel_, training_panel_},
                           new RecentFiles(recent_menu, this));
  BuildWindowMenus(this, files_, recent_menu, scene_, detection_panel_);
  Wire();
  resize(1600, 1000);
  // The 3D view gets most of the window until the user arranges the docks (restored below).
  resizeDocks({model_dock, views_dock}, {360, 400}, Qt::Horizontal);
  resizeDocks({browser_dock}, {330}, Qt::Vertical);
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  views_panel_->RestoreSettings();
  statusBar()->showMessage(tr("Open a mesh (File ▸ Open mesh…, or drop it here) to start."));
}

MainWindow::~MainWindow() = default;

QDockWidget* MainWindow::AddDock(QWidget* panel, const QString& title, const char* name,
                                 Qt::DockWidgetArea area) {
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setWidget(scroll);
  addDockWidget(area, dock);
  return dock;
}

void MainWindow::Wire() {
  auto show_coverage = [this] {
    const auto& plan = views_panel_->plan();
    scene_->SetCoverage(plan ? plan->layer_depths_mm : std::vector<double>{},
                        plan ? plan->views : std::vector<ViewAngles>{});
  };
  // The views panel re-plans on ModelChanged before this runs; the glyphs follow the new sphere.
  connect(session_, &StudioSession::ModelChanged, this, [this, show_coverage] {
    scene_->SetModel(session_->model());
    show_coverage();
    scene_->ResetCamera();
  });
  connect(views_panel_, &ViewsPanel::PlanChanged, this, show_coverage);
  connect(browser_, &TemplateBrowser::TemplateSelected, this, &MainWindow::ShowSelectedCamera);
  connect(browser_, &TemplateBrowser::OpenMeshRequested, files_,
          &StudioFiles::OpenMeshForArchiveDialog);
  connect(model_panel_, &ModelPanel::OpenRequested, files_, &StudioFiles::OpenMeshDialog);
  connect(training_panel_, &TrainingPanel::ExportRequested, files_,
          &StudioFiles::ExportArchiveDialog);
  connect(detection_panel_, &DetectionPanel::OpenArchiveRequested, files_,
          &StudioFiles::OpenArchiveDialog);
  connect(detection_panel_, &DetectionPanel::DetectionActivated, this,
          &MainWindow::ShowDetectionInScene);
  connect(detection_panel_, &DetectionPanel::CaptureOpened, this,
          [this] { tabs_->setCurrentWidget(detection_panel_); });
  ShowJobFeedback(this, runner_);
  connect(session_, &StudioSession::ArchiveChanged, this, [this] {
    scene_->ClearHighlight();
    scene_->ClearDetection();
    scene_->Render();
  });
}

void MainWindow::ShowSelectedCamera(int template_index) {
  const auto archive = session_->archive();
  if (archive == nullptr || template_index < 0) return;
  const TemplateRecord& record = archive->templates()[static_cast<std::size_t>(template_index)];
  scene_->ShowTemplateCamera(record, archive->camera(),
                             archive->Object(record.obj_id).layer_depths_mm);
}

void MainWindow::ShowDetectionInScene(int detection_index) {
  const DetectionResult* result = detection_panel_->result();
  if (result == nullptr || detection_index < 0 ||
      detection_index >= static_cast<int>(result->detections.size())) {
    return;
  }
  const Detection& detection = result->detections[static_cast<std::size_t>(detection_index)];
  scene_->ShowDetection(*detection_panel_->capture(),
                        detection_panel_->result_detector()->Object(detection.obj_id), detection);
  tabs_->setCurrentWidget(scene_);
}

void MainWindow::OpenFiles(const QStringList& paths) {
  // Folders are BOP captures for the detection preview; files are meshes and archives.
  QStringList files;
  for (const QString& path : paths) {
    if (QFileInfo(path).isDir()) {
      detection_panel_->OpenBopFolder(path);
    } else {
      files << path;
    }
  }
  files_->OpenFiles(files);
}

bool MainWindow::IsIdle() const {
  return !runner_->busy() && !files_->has_queued_files() && !detection_panel_->has_pending_work() &&
         browser_->list_model()->pending_thumbnails() == 0;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (runner_->busy() || !ConfirmDiscardUnsaved(this, *session_)) {
    if (runner_->busy())
      statusBar()->showMessage(tr("Cancel the running job before quitting."), 5000);
    event->ignore();
    return;
  }
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  views_panel_->SaveSettings();
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList paths;
  for (const QUrl& url : event->mimeData()->urls()) {
    if (url.isLocalFile()) paths << url.toLocalFile();
  }
  OpenFiles(paths);
  event->acceptProposedAction();
}

}  // namespace layermod::ui
