// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <functional>

namespace layermod::ui {

class MainWindow;

// Once `window` has been idle for a moment (no job, no queued file, no thumbnail in flight),
// renders the 3D view, grabs the whole window to `path` (PNG) and calls `done(true)`; calls
// `done(false)` when the grab cannot be written or the window never settles within `timeout_ms`.
void SaveScreenshotWhenIdle(MainWindow* window, const QString& path,
                            const std::function<void(bool ok)>& done, int timeout_ms = 180000);

}  // namespace layermod::ui
