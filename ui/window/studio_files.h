// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

class QWidget;

namespace layermod::ui {

class JobRunner;
class ModelPanel;
class RecentFiles;
class StudioSession;
class TrainingPanel;
class ViewsPanel;

// Every file the studio opens or writes, from menus, drops, recent files and the command line:
// dialogs, queueing (one job at a time) and the unsaved-set prompt. Panels do the work.
class StudioFiles : public QObject {
  Q_OBJECT

 public:
  struct Panels {
    ModelPanel* model;
    ViewsPanel* views;
    TrainingPanel* training;
  };
  StudioFiles(QWidget* window, StudioSession* session, JobRunner* runner, Panels panels,
              RecentFiles* recent);

  // Opens meshes and *.layermod archives one after the other.
  void OpenFiles(const QStringList& paths);
  bool has_queued_files() const { return !queue_.isEmpty(); }
  // Reads an archive on the worker thread, with its mesh when it lies beside it.
  bool OpenArchive(const QString& path);

 public slots:
  void OpenMeshDialog();
  void OpenArchiveDialog();
  void OpenMeshForArchiveDialog();  // the browser's "mesh not loaded" banner
  void SaveProfileDialog();
  void LoadProfileDialog();
  void ExportArchiveDialog();

 private:
  bool OpenOne(const QString& path);
  void DropArchiveOfOtherMesh();
  void OpenNextQueued();

  QWidget* window_ = nullptr;
  StudioSession* session_ = nullptr;
  JobRunner* runner_ = nullptr;
  Panels panels_;
  RecentFiles* recent_ = nullptr;
  QStringList queue_;
};

}  // namespace layermod::ui
