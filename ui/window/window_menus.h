// SPDX-License-Identifier: MIT
#pragma once

class QMainWindow;
class QMenu;
class QTabWidget;

namespace layermod::ui {

class DetectionPanel;
class DockLayout;
class JobRunner;
class SceneView;
class StudioFiles;
class StudioSession;
class TrainingPanel;

// What the menus act on.
struct WindowParts {
  StudioFiles* files;
  QMenu* recent_menu;
  SceneView* scene;
  DetectionPanel* detection;
  TrainingPanel* training;
  JobRunner* runner;
  StudioSession* session;
  DockLayout* docks;
  QTabWidget* tabs;
};

// The studio window's menu bar and toolbar: File (files, recent files, captures), Run (Train,
// Cancel, Detect, frame stepping, with shortcuts), View (the 3D view's toggles, every dock,
// Reset layout), Help. Call after the docks exist.
void BuildWindowMenus(QMainWindow* window, const WindowParts& parts);

// For every job of `runner`: status-bar messages, a busy cursor, a log line on cancellation and
// an error box on failure.
void ShowJobFeedback(QMainWindow* window, JobRunner* runner);

}  // namespace layermod::ui
