// SPDX-License-Identifier: MIT
#include "ui/training_panel.h"

#include <QApplication>
#include <QCursor>
#include <QFileInfo>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <exception>

#include "ui/job_runner.h"
#include "ui/studio_dialogs.h"
#include "ui/studio_session.h"
#include "util/log.h"

namespace layermod::ui {

TrainingPanel::TrainingPanel(StudioSession* session, JobRunner* runner, RequestSource request,
                             QWidget* parent)
    : QWidget(parent),
      session_(session),
      runner_(runner),
      request_(std::move(request)),
      train_(new QPushButton(tr("Train"))),
      cancel_(new QPushButton(tr("Cancel"))),
      export_(new QPushButton(tr("Export archive…"))),
      progress_(new QProgressBar),
      eta_(new QLabel),
      summary_(new QLabel) {
  train_->setObjectName("trainButton");
  cancel_->setObjectName("cancelButton");
  export_->setObjectName("exportButton");
  progress_->setObjectName("trainingProgress");
  eta_->setObjectName("etaLabel");
  summary_->setObjectName("summaryLabel");
  summary_->setWordWrap(true);
  train_->setToolTip(tr("Render every view at every depth layer and extract its template"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(train_);
  buttons->addWidget(cancel_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addWidget(eta_);
  layout->addWidget(summary_);
  layout->addWidget(export_);
  layout->addStretch();
  progress_->setRange(0, 1);
  progress_->setValue(0);

  connect(train_, &QPushButton::clicked, this, &TrainingPanel::StartTraining);
  connect(cancel_, &QPushButton::clicked, this, &TrainingPanel::CancelTraining);
  connect(export_, &QPushButton::clicked, this, &TrainingPanel::ExportRequested);
  connect(runner_, &JobRunner::Progress, this, &TrainingPanel::OnProgress);
  connect(runner_, &JobRunner::Succeeded, this, [this] { OnJobEnded(true); });
  connect(runner_, &JobRunner::Failed, this, [this] { OnJobEnded(false); });
  connect(runner_, &JobRunner::Cancelled, this, [this] { OnJobEnded(false); });
  connect(runner_, &JobRunner::BusyChanged, this, &TrainingPanel::UpdateButtons);
  connect(session_, &StudioSession::ModelChanged, this, &TrainingPanel::UpdateButtons);
  connect(session_, &StudioSession::ArchiveChanged, this, &TrainingPanel::UpdateButtons);
  UpdateButtons();
}

bool TrainingPanel::StartTraining() {
  const auto model = session_->model();
  if (model == nullptr || runner_->busy()) return false;
  if (!ConfirmDiscardUnsaved(this, *session_)) return false;
  const TrainingRequest request = request_();
  // A new run replaces the shown set now, so a cancelled or failed run leaves no result.
  session_->ClearArchive();
  const QString action =
      tr("Train templates for “%1”").arg(QString::fromStdString(model->source.string()));
  training_ = runner_->Start(action, [this, model, request](const JobControl& job) {
    auto result = std::make_shared<TrainingResult>(TrainTemplates(*model, request, job));
    return JobRunner::Commit([this, result] {
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
    });
  });
  if (training_) {
    summary_->clear();
    eta_->setText(tr("Starting…"));
    progress_->setRange(0, 0);  // busy until the first report
  }
  UpdateButtons();
  return training_;
}

void TrainingPanel::CancelTraining() {
  if (training_) runner_->Cancel();
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
  LogInfo("exported " + std::to_string(archive->templates().size()) + " templates to \"" +
          path.toStdString() + "\"");
  emit ArchiveExported(path);
  return true;
}

void TrainingPanel::UpdateButtons() {
  train_->setEnabled(!runner_->busy() && session_->model() != nullptr);
  cancel_->setEnabled(training_);
  export_->setEnabled(!training_ && session_->archive() != nullptr);
}

}  // namespace layermod::ui
