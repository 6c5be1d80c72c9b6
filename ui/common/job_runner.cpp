// SPDX-License-Identifier: MIT
#include "ui/common/job_runner.h"

#include <QThread>
#include <chrono>
#include <cmath>
#include <exception>

#include "util/error.h"

namespace layermod::ui {
namespace {

// Progress signals are throttled: a training run reports thousands of steps.
constexpr auto kProgressInterval = std::chrono::milliseconds(50);

}  // namespace

JobRunner::JobRunner(QObject* parent) : QObject(parent) {}

JobRunner::~JobRunner() {
  if (thread_ == nullptr) return;
  cancel_->Cancel();
  thread_->wait();
  delete thread_;
}

bool JobRunner::Start(const QString& name, Work work) {
  if (busy()) return false;
  name_ = name;
  cancel_ = std::make_unique<CancelToken>();
  clock_.start();
  thread_ = QThread::create([this, work = std::move(work)] { RunOnWorker(work); });
  emit BusyChanged(true);
  emit Started(name_);
  thread_->start();
  return true;
}

void JobRunner::Cancel() {
  if (cancel_ != nullptr) cancel_->Cancel();
}

void JobRunner::RunOnWorker(const Work& work) {
  struct Throttle {
    std::chrono::steady_clock::time_point last{};
  };
  auto throttle = std::make_shared<Throttle>();
  const JobControl job(
      [this, throttle](std::size_t done, std::size_t total, std::string_view stage) {
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - throttle->last < kProgressInterval) return;
        throttle->last = now;
        const QString stage_text = QString::fromUtf8(stage.data(), static_cast<int>(stage.size()));
        const double elapsed_s = static_cast<double>(clock_.elapsed()) / 1000.0;
        QMetaObject::invokeMethod(
            this,
            [this, done, total, stage_text, elapsed_s] {
              emit Progress(static_cast<qint64>(done), static_cast<qint64>(total), stage_text,
                            elapsed_s);
            },
            Qt::QueuedConnection);
      },
      cancel_.get());
  Outcome outcome = Outcome::kSucceeded;
  Commit commit;
  QString message;
  try {
    commit = work(job);
  } catch (const layermod::Cancelled&) {
    outcome = Outcome::kCancelled;
  } catch (const std::exception& error) {  // layermod::Error and anything else from the core
    outcome = Outcome::kFailed;
    message = QString::fromStdString(error.what());
  } catch (...) {
    outcome = Outcome::kFailed;
    message = tr("unknown error");
  }
  QMetaObject::invokeMethod(
      this, [this, outcome, commit, message] { Finish(outcome, commit, message); },
      Qt::QueuedConnection);
}

void JobRunner::Finish(Outcome outcome, const Commit& commit, const QString& message) {
  thread_->wait();
  delete thread_;
  thread_ = nullptr;
  cancel_.reset();
  const QString name = name_;
  emit BusyChanged(false);
  if (outcome == Outcome::kCancelled) {
    emit Cancelled(name);
    return;
  }
  if (outcome == Outcome::kFailed) {
    emit Failed(name, message);
    return;
  }
  try {
    if (commit) commit();
  } catch (const std::exception& error) {
    emit Failed(name, QString::fromStdString(error.what()));
    return;
  }
  emit Succeeded(name);
}

QString JobRunner::FormatEta(double elapsed_s, qint64 done, qint64 total) {
  if (done <= 0 || total <= done || elapsed_s < 0.5) return {};
  const double left_s = elapsed_s * static_cast<double>(total - done) / static_cast<double>(done);
  const auto seconds = static_cast<qint64>(std::ceil(left_s));
  if (seconds < 60) return tr("about %1 s left").arg(seconds);
  return tr("about %1 min %2 s left").arg(seconds / 60).arg(seconds % 60);
}

}  // namespace layermod::ui
