// SPDX-License-Identifier: MIT
#include "ui/training/training_panel.h"

#include <QApplication>
#include <QCursor>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <exception>
#include <nlohmann/json.hpp>

#include "templates/archive_mesh.h"
#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "util/log.h"

namespace layermod::ui {
namespace {

bool SameCamera(const PinholeCamera& a, const PinholeCamera& b) {
  return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.width == b.width &&
         a.height == b.height;
}

// Whether training with `a` and `b` gives the same archive (threads and simplification are not
// on the form).
bool SameRequest(const TrainingRequest& a, const TrainingRequest& b) {
  return a.obj_id == b.obj_id && a.name == b.name && SameCamera(a.camera, b.camera) &&
         ToJson(a.profile) == ToJson(b.profile);
}

QString Count(std::size_t value) { return QLocale().toString(static_cast<qulonglong>(value)); }

}  // namespace

TrainingPanel::TrainingPanel(StudioSession* session, JobRunner* runner, RequestSource request,
                             QWidget* parent)
    : QWidget(parent),
      session_(session),
      runner_(runner),
      request_(std::move(request)),
      train_(new QPushButton(tr("Train"))),
      cancel_(new QPushButton(tr("Cancel"))),
      export_(new QPushButton),
      progress_(new QProgressBar),
      eta_(new QLabel),
      summary_(new QLabel),
      stale_(new QLabel),
      train_tip_(tr("Render every view at every depth layer and extract its template (Ctrl+T)")) {
  train_->setObjectName("trainButton");
  cancel_->setObjectName("cancelButton");
  export_->setObjectName("exportButton");
  // The label names the set and may be longer than a narrow dock; the button clips, not the dock.
  export_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  export_->setMinimumWidth(120);
  progress_->setObjectName("trainingProgress");
  eta_->setObjectName("etaLabel");
  summary_->setObjectName("summaryLabel");
  summary_->setWordWrap(true);
  stale_->setObjectName("staleLabel");
  stale_->setWordWrap(true);
  stale_->setStyleSheet("QLabel { background: #fff3cd; color: #4a3b00; padding: 3px; }");
  stale_->setText(
      tr("The form has changed since this set was made: Train again to apply it. Export writes "
         "the set as it was made."));
  stale_->hide();
  train_->setToolTip(train_tip_);
  cancel_->setToolTip(tr("Stop the running job (Esc)"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(train_);
  buttons->addWidget(cancel_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addWidget(eta_);
  layout->addWidget(summary_);
  layout->addWidget(stale_);
  layout->addWidget(export_);
  layout->addStretch();
  ResetProgress();

  connect(train_, &QPushButton::clicked, this, &TrainingPanel::StartTraining);
  connect(cancel_, &QPushButton::clicked, this, &TrainingPanel::CancelTraining);
  connect(export_, &QPushButton::clicked, this, &TrainingPanel::ExportRequested);
  connect(runner_, &JobRunner::Progress, this, &TrainingPanel::OnProgress);
  connect(runner_, &JobRunner::Succeeded, this, [this] { OnJobEnded(true); });
  connect(runner_, &JobRunner::Failed, this, [this] { OnJobEnded(false); });
  connect(runner_, &JobRunner::Cancelled, this, [this] { OnJobEnded(false); });
  connect(runner_, &JobRunner::BusyChanged, this, &TrainingPanel::UpdateButtons);
  connect(session_, &StudioSession::ModelChanged, this, &TrainingPanel::UpdateButtons);
  connect(session_, &StudioSession::ArchiveChanged, this, &TrainingPanel::OnArchiveChanged);
  UpdateButtons();
}

bool TrainingPanel::StartTraining() {
  const auto model = session_->model();
  if (model == nullptr || runner_->busy() || !form_problem_.isEmpty()) return false;
  if (!ConfirmDiscardUnsaved(this, *session_)) return false;
  // The run uses this snapshot; the form is locked until it ends (TrainingStarted).
  const TrainingRequest request = request_();
  // A new run replaces the shown set now, so a cancelled or failed run leaves no result.
  session_->ClearArchive();
  const QString action =
      tr("Train templates for “%1”").arg(QString::fromStdString(model->source.string()));
  training_ = runner_->Start(action, [this, model, request](const JobControl& job) {
    auto result = std::make_shared<TrainingResult>(TrainTemplates(*model, request, job));
    return JobRunner::Commit([this, result, request] {
      const TrainingSummary& summary = result->summary;
      summary_->setText(tr("%1 templates in %2 layers (%3 weak), %4 s, %5 templates/s")
                            .arg(summary.templates)
                            .arg(summary.layers)
                            .arg(summary.weak_templates)
                            .arg(summary.seconds, 0, 'f', 1)
                            .arg(summary.TemplatesPerSecond(), 0, 'f', 0));
      LogInfo(summary_->text().toStdString());
      session_->SetArchive(std::make_shared<const TemplateArchive>(std::move(result->archive)),
                           QString());
      basis_ = request;
    });
  });
  if (training_) {
    summary_->clear();
    eta_->setText(tr("Starting…"));
    progress_->setRange(0, 0);  // busy until the first report
    emit TrainingStarted();
  }
  UpdateButtons();
  return training_;
}

void TrainingPanel::CancelTraining() {
  if (training_) runner_->Cancel();
}

bool TrainingPanel::stale() const {
  const auto archive = session_->archive();
  if (archive == nullptr || training_) return false;
  // A model changed since (re-centred) no longer is the one the set was made from.
  const auto model = session_->model();
  const auto& objects = archive->manifest().objects;
  if (model != nullptr && !objects.empty() && !ModelMatchesObject(*model, objects.front())) {
    return true;
  }
  return basis_.has_value() && !SameRequest(*basis_, request_());
}

void TrainingPanel::SetFormProblem(const QString& problem) {
  form_problem_ = problem;
  UpdateButtons();
}

void TrainingPanel::OnProgress(qint64 done, qint64 total, const QString& stage, double elapsed_s) {
  if (!training_ || total <= 0) return;
  // QProgressBar takes int; scale to per-mille so huge runs fit.
  progress_->setRange(0, 1000);
  progress_->setValue(static_cast<int>(1000 * done / total));
  progress_->setFormat(QStringLiteral("%1 / %2").arg(done).arg(total));
  eta_->setText(QStringLiteral("%1 — %2").arg(stage, JobRunner::FormatEta(elapsed_s, done, total)));
}

void TrainingPanel::OnJobEnded(bool succeeded) {
  if (!training_) return;
  training_ = false;
  progress_->setRange(0, 1);
  progress_->setValue(succeeded ? 1 : 0);
  progress_->setFormat(succeeded ? tr("done") : tr("stopped"));
  eta_->clear();
  if (!succeeded) summary_->setText(tr("No templates: the run was cancelled or failed."));
  UpdateButtons();
  if (succeeded) {
    emit TrainingSucceeded();
  } else {
    emit TrainingStopped();
  }
}

void TrainingPanel::OnArchiveChanged() {
  // While training, the run's own ClearArchive/SetArchive: its figures are shown by the run.
  if (training_) return UpdateButtons();
  const auto archive = session_->archive();
  ResetProgress();
  // Another set (opened, or none): the last run's figures no longer describe it. The form
  // already shows the opened set's profile, so that is its basis.
  basis_.reset();
  summary_->clear();
  if (archive != nullptr) {
    basis_ = request_();
    const auto& objects = archive->manifest().objects;
    const QString file = QFileInfo(session_->archive_path()).fileName();
    summary_->setText(tr("Opened “%1”: %2 templates in %3 layers")
                          .arg(file)
                          .arg(Count(archive->templates().size()))
                          .arg(objects.empty() ? 0 : objects.front().layer_depths_mm.size()));
  }
  UpdateButtons();
}

void TrainingPanel::ResetProgress() {
  progress_->setRange(0, 1);
  progress_->setValue(0);
  progress_->setFormat(tr("not trained"));
  eta_->clear();
}

bool TrainingPanel::ExportArchive(const QString& path) {
  const auto archive = session_->archive();
  if (archive == nullptr) return false;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    WriteArchive(path.toStdString(), *archive);
  } catch (const std::exception& error) {
    QApplication::restoreOverrideCursor();
    ShowError(this, tr("Export archive “%1”").arg(path), QString::fromStdString(error.what()));
    return false;
  }
  QApplication::restoreOverrideCursor();
  session_->MarkArchiveSaved(path);
  const int templates = static_cast<int>(archive->templates().size());
  LogInfo("exported " + Count(archive->templates().size()).toStdString() + " templates to " +
          QFileInfo(path).absoluteFilePath().toStdString());
  emit ArchiveExported(path, templates);
  return true;
}

QString TrainingPanel::export_text() const {
  const auto archive = session_->archive();
  if (archive == nullptr) return tr("Export archive…");
  const auto& objects = archive->manifest().objects;
  if (objects.empty()) return tr("Export %1 templates…").arg(Count(archive->templates().size()));
  const TrainingProfile& profile = objects.front().profile;
  return tr("Export %1 templates…\n(%2–%3 mm)")
      .arg(Count(archive->templates().size()))
      .arg(profile.depth_min_mm, 0, 'f', 0)
      .arg(profile.depth_max_mm, 0, 'f', 0);
}

void TrainingPanel::UpdateButtons() {
  train_->setEnabled(!runner_->busy() && session_->model() != nullptr && form_problem_.isEmpty());
  train_->setToolTip(form_problem_.isEmpty() ? train_tip_
                                             : tr("Cannot train: %1").arg(form_problem_));
  cancel_->setEnabled(training_);
  const bool is_stale = stale();
  export_->setEnabled(!training_ && session_->archive() != nullptr);
  export_->setText(export_text());
  export_->setToolTip(is_stale ? export_->text() + "\n" + stale_->text() : export_->text());
  stale_->setVisible(is_stale);
  if (session_->archive() != nullptr && !training_ && progress_->maximum() == 1 &&
      progress_->value() == 1) {
    progress_->setFormat(is_stale ? tr("done — form changed since") : tr("done"));
  }
}

}  // namespace layermod::ui
