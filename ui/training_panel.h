// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>
#include <functional>

#include "pipeline/training.h"

class QLabel;
class QProgressBar;
class QPushButton;

namespace layermod::ui {

class JobRunner;
class StudioSession;

// Runs TrainTemplates on the worker thread (progress, ETA, cancel) and exports the result.
class TrainingPanel : public QWidget {
  Q_OBJECT

 public:
  using RequestSource = std::function<TrainingRequest()>;
  TrainingPanel(StudioSession* session, JobRunner* runner, RequestSource request,
                QWidget* parent = nullptr);

  // False when there is no model, another job runs, or the user keeps an unexported set.
  bool StartTraining();
  bool training() const { return training_; }
  // Writes the session's template set to `path` (atomically); an error box names the file.
  bool ExportArchive(const QString& path);

 public slots:
  void CancelTraining();

 signals:
  void TrainingSucceeded();
  void TrainingStopped();  // failed or cancelled
  void ArchiveExported(const QString& path);
  void ExportRequested();  // the panel's "Export archive…" button

 private:
  void OnProgress(qint64 done, qint64 total, const QString& stage, double elapsed_s);
  void OnJobEnded(bool succeeded);
  void UpdateButtons();

  StudioSession* session_;
  JobRunner* runner_;
  RequestSource request_;
  bool training_ = false;
  QPushButton* train_;
  QPushButton* cancel_;
  QPushButton* export_;
  QProgressBar* progress_;
  QLabel* eta_;
  QLabel* summary_;
};

}  // namespace layermod::ui
