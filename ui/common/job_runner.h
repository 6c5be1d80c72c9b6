// SPDX-License-Identifier: MIT
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <functional>
#include <memory>

#include "util/job.h"

class QThread;

namespace layermod::ui {

// Runs one core job at a time on a worker thread. The core runs synchronously there; its
// progress reaches the GUI thread through queued signals, and Cancel() trips its CancelToken.
// Exceptions stop at this boundary: layermod::Error and std::exception become Failed(),
// layermod::Cancelled becomes Cancelled().
class JobRunner : public QObject {
  Q_OBJECT

 public:
  // What to do on the GUI thread once the work succeeded (e.g. hand the result to the session).
  using Commit = std::function<void()>;
  // Runs on the worker thread.
  using Work = std::function<Commit(const JobControl& job)>;

  explicit JobRunner(QObject* parent = nullptr);
  ~JobRunner() override;  // cancels the running job and waits for it

  bool busy() const { return thread_ != nullptr; }
  const QString& job_name() const { return name_; }
  // Starts `work`; returns false and starts nothing while another job runs.
  bool Start(const QString& name, Work work);
  void Cancel();

  // "about 2 min 5 s left" from the progress so far; empty until there is a meaningful estimate.
  static QString FormatEta(double elapsed_s, qint64 done, qint64 total);

 signals:
  void BusyChanged(bool busy);
  void Started(const QString& name);
  void Progress(qint64 done, qint64 total, const QString& stage, double elapsed_s);
  void Succeeded(const QString& name);
  void Failed(const QString& name, const QString& message);
  void Cancelled(const QString& name);

 private:
  enum class Outcome { kSucceeded, kFailed, kCancelled };
  void RunOnWorker(const Work& work);
  void Finish(Outcome outcome, const Commit& commit, const QString& message);

  QThread* thread_ = nullptr;
  QString name_;
  std::unique_ptr<CancelToken> cancel_;
  QElapsedTimer clock_;
};

}  // namespace layermod::ui
