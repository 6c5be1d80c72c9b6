// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>
#include <functional>
#include <optional>

#include "pipeline/training.h"

class QLabel;
class QProgressBar;
class QPushButton;

namespace layermod::ui {

class JobRunner;
class StudioSession;

// Runs TrainTemplates on the worker thread (progress, ETA, cancel) and exports the result. It
// remembers the request the session's template set was made with, so it can say when the form no
// longer describes that set (stale) and what Export would write.
class TrainingPanel : public QWidget {
  Q_OBJECT

 public:
  using RequestSource = std::function<TrainingRequest()>;
  TrainingPanel(StudioSession* session, JobRunner* runner, RequestSource request,
                QWidget* parent = nullptr);

  // False when there is no model, another job runs, or the user keeps an unexported set.
  bool StartTraining();
  bool training() const { return training_; }
  // A template set is shown but the form has changed since it was trained (or opened).
  bool stale() const;
  // Writes the session's template set to `path` (atomically); an error box names the file.
  bool ExportArchive(const QString& path);
  // "Export 9,576 templates (500–1500 mm)…", or a hint when there is nothing to export.
  QString export_text() const;

 public slots:
  void CancelTraining();
  // The form changed: why it cannot be trained (empty when it can; Train is then disabled and
  // says why), and whether the shown set is still what the form describes (stale).
  void SetFormProblem(const QString& problem);

 signals:
  void TrainingStarted();
  void TrainingSucceeded();
  void TrainingStopped();  // failed or cancelled
  void ArchiveExported(const QString& path, int templates);
  void ExportRequested();  // the panel's "Export archive…" button

 private:
  void OnProgress(qint64 done, qint64 total, const QString& stage, double elapsed_s);
  void OnJobEnded(bool succeeded);
  void OnArchiveChanged();
  void ResetProgress();
  void UpdateButtons();

  StudioSession* session_ = nullptr;
  JobRunner* runner_ = nullptr;
  RequestSource request_;
  bool training_ = false;
  // What the session's template set was trained (or opened) with; empty without a set.
  std::optional<TrainingRequest> basis_;
  QString form_problem_;
  QPushButton* train_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QPushButton* export_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* eta_ = nullptr;
  QLabel* summary_ = nullptr;
  QLabel* stale_ = nullptr;
  const QString train_tip_;
};

}  // namespace layermod::ui
