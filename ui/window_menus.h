// SPDX-License-Identifier: MIT
#pragma once

class QMainWindow;
class QMenu;

namespace layermod::ui {

class DetectionPanel;
class JobRunner;
class SceneView;
class StudioFiles;

// The studio window's menu bar and toolbar: File (via `files`, with `recent_menu`, and the
// captures of `detection`), View (the 3D view's toggles and every dock), Help. Call after the
// docks exist.
void BuildWindowMenus(QMainWindow* window, StudioFiles* files, QMenu* recent_menu, SceneView* scene,
                      DetectionPanel* detection);

// For every job of `runner`: status-bar messages, a busy cursor, and an error box on failure.
void ShowJobFeedback(QMainWindow* window, JobRunner* runner);

}  // namespace layermod::ui
