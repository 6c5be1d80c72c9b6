// SPDX-License-Identifier: MIT
#include "ui/window/screenshot.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QPixmap>
#include <QTimer>
#include <memory>

#include "ui/scene3d/scene_view.h"
#include "ui/window/main_window.h"

namespace layermod::ui {
namespace {

constexpr int kPollMs = 100;
// Thumbnails are only requested once the list has painted, so idleness must last a few polls.
constexpr int kIdlePollsNeeded = 5;

}  // namespace

void SaveScreenshotWhenIdle(MainWindow* window, const QString& path,
                            const std::function<void(bool ok)>& done, int timeout_ms) {
  auto* timer = new QTimer(window);
  auto clock = std::make_shared<QElapsedTimer>();
  auto idle_polls = std::make_shared<int>(0);
  clock->start();
  QObject::connect(timer, &QTimer::timeout, window, [=] {
    *idle_polls = window->IsIdle() ? *idle_polls + 1 : 0;
    const bool timed_out = clock->elapsed() > timeout_ms;
    if (*idle_polls < kIdlePollsNeeded && !timed_out) return;
    timer->stop();
    timer->deleteLater();
    if (timed_out) return done(false);
    window->scene()->Render();
    QApplication::processEvents();
    const QPixmap shot = window->grab();
    done(!shot.isNull() && shot.save(path, "PNG"));
  });
  timer->start(kPollMs);
}

}  // namespace layermod::ui
