// SPDX-License-Identifier: MIT
#include "ui/window/main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QResizeEvent>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/detection/detection_panel.h"
#include "ui/model/model_panel.h"
#include "ui/scene3d/scene_view.h"
#include "ui/templates/template_browser.h"
#include "ui/templates/template_list_model.h"
#include "ui/training/training_panel.h"
#include "ui/views/views_panel.h"
#include "ui/widgets/wheel_guard.h"
#include "ui/window/dock_layout.h"
#include "ui/window/log_dock.h"
#include "ui/window/recent_files.h"
#include "ui/window/studio_files.h"
#include "ui/window/window_menus.h"
#include "util/log.h"

// Q_INIT_RESOURCE must be used outside any namespace; the icons live in a static library.
static void InitStudioResources() { Q_INIT_RESOURCE(icons); }

namespace layermod::ui {
namespace {

constexpr QSize kPreferredSize(1600, 1000);
constexpr int kStatusMs = 6000;

}  // namespace

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
  WheelGuard::Install();
  setWindowTitle(tr("LayerMOD Studio"));
  setWindowIcon(QIcon(":/icons/layermod-studio.svg"));
  setAcceptDrops(true);
  tabs_->setObjectName("centralTabs");
  tabs_->addTab(scene_, tr("3D view"));
  tabs_->addTab(detection_panel_, tr("Detection preview"));
  setCentralWidget(tabs_);
  BuildDocks();
  auto* recent_menu = new QMenu(tr("Recent &files"), this);
  files_ = new StudioFiles(this, session_, runner_, {model_panel_, views_panel_, training_panel_},
                           new RecentFiles(recent_menu, this));
  BuildWindowMenus(this, {files_, recent_menu, scene_, detection_panel_, training_panel_, runner_,
                          session_, docks_, tabs_});
  Wire();
  const QRect available = screen()->availableGeometry();
  resize(InitialSize(available));
  move(available.topLeft());
  // The 3D view gets most of the window until the user arranges the docks (restored below).
  docks_->Reset();
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  // A geometry saved on a larger screen must not push the status bar off this one.
  if (width() > available.width() || height() > available.height()) {
    resize(size().boundedTo(available.size()));
    move(available.topLeft());
  }
  views_panel_->RestoreSettings();
  statusBar()->showMessage(tr("Open a mesh (File ▸ Open mesh…, or drop it here) to start."));
}

MainWindow::~MainWindow() = default;

QSize MainWindow::InitialSize(const QRect& available) {
  return kPreferredSize.boundedTo(available.size());
}

QDockWidget* MainWindow::MakeDock(QWidget* panel, const QString& title, const char* name) {
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setWidget(scroll);
  return dock;
}

void MainWindow::BuildDocks() {
  docks_ = new DockLayout(this);
  // Side docks about half the window together; on 1280 px the central view keeps ~600 px.
  docks_->Add(MakeDock(model_panel_, tr("Model"), "ModelDock"), Qt::LeftDockWidgetArea, 0.22, 360);
  docks_->Add(MakeDock(training_panel_, tr("Training"), "TrainingDock"), Qt::LeftDockWidgetArea,
              0.22, 360);
  docks_->Add(MakeDock(views_panel_, tr("Views"), "ViewsDock"), Qt::RightDockWidgetArea, 0.29, 420);
  QDockWidget* browser_dock = MakeDock(browser_, tr("Templates"), "TemplatesDock");
  docks_->Add(browser_dock, Qt::BottomDockWidgetArea, 0.28, 330);
  docks_->Tabify(browser_dock, log_dock_);
}

void MainWindow::Wire() {
  auto show_coverage = [this] {
    const auto& plan = views_panel_->plan();
    scene_->SetCoverage(plan ? plan->layer_depths_mm : std::vector<double>{},
                        plan ? plan->views : std::vector<ViewAngles>{},
                        views_panel_->profile().views.upright_from_model);
    scene_->SetGroundTruthViews(detection_panel_->ground_truth_coverage());
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
  connect(detection_panel_, &DetectionPanel::CoverageChanged, this,
          [this] { scene_->SetGroundTruthViews(detection_panel_->ground_truth_coverage()); });
  // The preview gets the whole window; the authoring docks return with the 3D view.
  connect(tabs_, &QTabWidget::currentChanged, docks_,
          [this] { docks_->SetPreviewShown(tabs_->currentWidget() == detection_panel_); });
  ShowJobFeedback(this, runner_);
  WireTraining();
  connect(session_, &StudioSession::ArchiveChanged, this, [this] {
    scene_->ClearHighlight();
    scene_->ClearDetection();
    scene_->Render();
  });
}

void MainWindow::WireTraining() {
  // The run trains what the form showed when it started; the form cannot change until it ends.
  connect(training_panel_, &TrainingPanel::TrainingStarted, this, [this] {
    views_panel_->SetLocked(true);
    model_panel_->setEnabled(false);
  });
  for (auto ended : {&TrainingPanel::TrainingSucceeded, &TrainingPanel::TrainingStopped}) {
    connect(training_panel_, ended, this, [this] {
      views_panel_->SetLocked(false);
      model_panel_->setEnabled(true);
    });
  }
  connect(views_panel_, &ViewsPanel::PlanChanged, training_panel_,
          [this] { training_panel_->SetFormProblem(views_panel_->problem()); });
  connect(training_panel_, &TrainingPanel::ArchiveExported, this,
          [this](const QString& path, int templates) {
            statusBar()->showMessage(tr("Exported %1 templates to %2")
                                         .arg(QLocale().toString(templates))
                                         .arg(QFileInfo(path).absoluteFilePath()),
                                     kStatusMs);
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
  if (!ConfirmCancelRunningJob() || !ConfirmDiscardUnsaved(this, *session_)) {
    event->ignore();
    return;
  }
  SaveWindowSettings();
  event->accept();
}

bool MainWindow::ConfirmCancelRunningJob() {
  if (!runner_->busy()) return true;
  const bool training = training_panel_->training();
  bool cancel = BatchMode();
  if (!cancel) {
    QMessageBox box(QMessageBox::Question, tr("LayerMOD Studio"),
                    training ? tr("Cancel training and quit?")
                             : tr("Cancel “%1” and quit?").arg(runner_->job_name()),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setObjectName("quitWhileBusyDialog");
    box.setInformativeText(training ? tr("The templates trained so far are discarded.")
                                    : QString());
    box.button(QMessageBox::Yes)
        ->setText(training ? tr("Cancel training and quit") : tr("Cancel and quit"));
    box.button(QMessageBox::No)->setText(tr("Keep running"));
    box.setDefaultButton(QMessageBox::No);
    cancel = box.exec() == QMessageBox::Yes;
  }
  if (!cancel) return false;
  // The runner's destructor waits for the worker, which stops at its next cancellation check.
  LogInfo((runner_->job_name() + tr(": cancelled to quit")).toStdString());
  runner_->Cancel();
  return true;
}

void MainWindow::SaveWindowSettings() {
  docks_->SetPreviewShown(false);  // the arrangement of the authoring docks is what is kept
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  views_panel_->SaveSettings();
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  const QSize old_size = event->oldSize();
  if (old_size.isValid() &&
      (event->size().width() > old_size.width() || event->size().height() > old_size.height())) {
    // After the layout has taken the new size.
    QTimer::singleShot(0, docks_, &DockLayout::RestoreCollapsed);
  }
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
