// SPDX-License-Identifier: MIT
#pragma once

#include <QMainWindow>

class QTabWidget;

namespace layermod::ui {

class DetectionPanel;
class DockLayout;
class JobRunner;
class LogDock;
class ModelPanel;
class SceneView;
class StudioFiles;
class StudioSession;
class TemplateBrowser;
class TrainingPanel;
class ViewsPanel;

// Creates the panels around the 3D view and wires them; the work lives in the panels.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  StudioSession* session() const { return session_; }
  JobRunner* runner() const { return runner_; }
  SceneView* scene() const { return scene_; }
  ModelPanel* model_panel() const { return model_panel_; }
  ViewsPanel* views_panel() const { return views_panel_; }
  TrainingPanel* training_panel() const { return training_panel_; }
  TemplateBrowser* browser() const { return browser_; }
  DetectionPanel* detection_panel() const { return detection_panel_; }
  QTabWidget* tabs() const { return tabs_; }
  LogDock* log_dock() const { return log_dock_; }
  StudioFiles* files() const { return files_; }
  DockLayout* dock_layout() const { return docks_; }
  // The first window's size: the preferred size, but never more than the screen offers.
  static QSize InitialSize(const QRect& available);

  // Meshes and *.layermod archives, opened in order, and BOP split folders as detection
  // captures (command line, drops).
  void OpenFiles(const QStringList& paths);
  // The preview's detection `detection_index` in the 3D view, against the capture's points.
  void ShowDetectionInScene(int detection_index);
  // No job runs or waits, no file waits, no thumbnail is being rendered.
  bool IsIdle() const;

 protected:
  void closeEvent(QCloseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  QDockWidget* MakeDock(QWidget* panel, const QString& title, const char* name);
  void BuildDocks();
  void Wire();
  void WireTraining();
  // True when no job runs, or the user agrees to cancel it (then it is cancelled).
  bool ConfirmCancelRunningJob();
  void SaveWindowSettings();
  void ShowSelectedCamera(int template_index);

  StudioSession* session_ = nullptr;
  JobRunner* runner_ = nullptr;
  SceneView* scene_ = nullptr;
  LogDock* log_dock_ = nullptr;
  ModelPanel* model_panel_ = nullptr;
  ViewsPanel* views_panel_ = nullptr;
  TrainingPanel* training_panel_ = nullptr;
  TemplateBrowser* browser_ = nullptr;
  DetectionPanel* detection_panel_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  StudioFiles* files_ = nullptr;
  DockLayout* docks_ = nullptr;
};

}  // namespace layermod::ui
