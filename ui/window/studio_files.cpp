// SPDX-License-Identifier: MIT
#include "ui/window/studio_files.h"

#include <QFileInfo>
#include <QWidget>
#include <exception>

#include "templates/archive_mesh.h"
#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/model/model_panel.h"
#include "ui/training/training_panel.h"
#include "ui/views/views_panel.h"
#include "ui/window/recent_files.h"
#include "util/log.h"

namespace layermod::ui {

StudioFiles::StudioFiles(QWidget* window, StudioSession* session, JobRunner* runner, Panels panels,
                         RecentFiles* recent)
    : QObject(window),
      window_(window),
      session_(session),
      runner_(runner),
      panels_(panels),
      recent_(recent) {
  connect(runner_, &JobRunner::BusyChanged, this, [this](bool busy) {
    if (!busy) OpenNextQueued();
  });
  connect(panels_.model, &ModelPanel::MeshOpened, recent_, &RecentFiles::Add);
  connect(panels_.model, &ModelPanel::MeshOpened, this, &StudioFiles::DropArchiveOfOtherMesh);
  connect(panels_.training, &TrainingPanel::ArchiveExported, recent_, &RecentFiles::Add);
  connect(recent_, &RecentFiles::OpenRequested, this,
          [this](const QString& path) { OpenFiles({path}); });
}

void StudioFiles::OpenFiles(const QStringList& paths) {
  queue_ << paths;
  if (!runner_->busy()) OpenNextQueued();
}

void StudioFiles::OpenNextQueued() {
  // A file that cannot start (the user kept an unsaved set) is skipped, not retried forever.
  while (!queue_.isEmpty() && !runner_->busy()) {
    if (OpenOne(queue_.takeFirst())) return;
  }
}

bool StudioFiles::OpenOne(const QString& path) {
  if (path.endsWith(QLatin1String(".layermod"), Qt::CaseInsensitive)) return OpenArchive(path);
  // Another mesh ends the shown set unless it is that set's own mesh (DropArchiveOfOtherMesh).
  if (!ConfirmDiscardUnsaved(window_, *session_)) return false;
  return panels_.model->OpenMesh(path);
}

void StudioFiles::DropArchiveOfOtherMesh() {
  const auto archive = session_->archive();
  const auto model = session_->model();
  if (archive == nullptr || model == nullptr) return;
  const auto& objects = archive->manifest().objects;
  // A set trained from another mesh can be neither exported nor browsed as this mesh's set.
  if (objects.empty() || !ModelMatchesObject(*model, objects.front())) session_->ClearArchive();
}

bool StudioFiles::OpenArchive(const QString& path) {
  if (!ConfirmDiscardUnsaved(window_, *session_)) return false;
  const auto current = session_->model();
  return runner_->Start(tr("Open archive “%1”").arg(path), [=, this](const JobControl&) {
    auto archive = std::make_shared<const TemplateArchive>(ReadArchive(path.toStdString()));
    std::shared_ptr<const Model> model;
    const auto& objects = archive->manifest().objects;
    if (!objects.empty() && (current == nullptr || !ModelMatchesObject(*current, objects[0]))) {
      if (const auto mesh_path = MeshBesideArchive(path.toStdString(), objects[0])) {
        try {
          model = std::make_shared<const Model>(LoadModelForObject(*mesh_path, objects[0]));
        } catch (const std::exception& error) {
          LogWarning(std::string("mesh beside the archive not usable: ") + error.what());
        }
      }
    }
    return JobRunner::Commit([=, this] {
      if (!objects.empty()) {
        panels_.views->SetProfile(objects[0].profile);
        panels_.views->SetCamera(archive->camera());
      }
      if (model != nullptr) session_->SetModel(model);
      // After SetModel, which defaults the object from the mesh file name.
      if (!objects.empty()) {
        panels_.views->SetObject(objects[0].obj_id, QString::fromStdString(objects[0].name));
      }
      session_->SetArchive(archive, path);
      recent_->Add(path);
    });
  });
}

void StudioFiles::OpenMeshDialog() {
  const QString path = AskOpenPath(window_, "mesh", tr("Open mesh"), MeshFileFilter());
  if (!path.isEmpty()) OpenFiles({path});
}

void StudioFiles::OpenArchiveDialog() {
  const QString path = AskOpenPath(window_, "archive", tr("Open archive"), ArchiveFileFilter());
  if (!path.isEmpty()) OpenFiles({path});
}

void StudioFiles::OpenMeshForArchiveDialog() {
  const auto archive = session_->archive();
  if (archive == nullptr || archive->manifest().objects.empty()) return OpenMeshDialog();
  const ArchiveObject object = archive->manifest().objects.front();
  const QString path = AskOpenPath(
      window_, "mesh", tr("Open the mesh “%1”").arg(QString::fromStdString(object.mesh_file)),
      MeshFileFilter());
  if (path.isEmpty()) return;
  runner_->Start(tr("Open mesh “%1”").arg(path), [=, this](const JobControl&) {
    auto model = std::make_shared<const Model>(LoadModelForObject(path.toStdString(), object));
    return JobRunner::Commit([=, this] { session_->SetModel(model); });
  });
}

void StudioFiles::SaveProfileDialog() {
  const QString path = AskSavePath(window_, "profile", tr("Save training profile"),
                                   JsonFileFilter(), "profile.json");
  if (!path.isEmpty()) panels_.views->SaveProfile(path);
}

void StudioFiles::LoadProfileDialog() {
  const QString path =
      AskOpenPath(window_, "profile", tr("Load training profile"), JsonFileFilter());
  if (!path.isEmpty()) panels_.views->LoadProfile(path);
}

void StudioFiles::ExportArchiveDialog() {
  if (session_->archive() == nullptr) return;
  if (panels_.training->stale() && !ConfirmExportStale(window_)) return;
  const auto model = session_->model();
  const QString name =
      (model != nullptr ? QString::fromStdString(model->source.stem().string()) : "templates") +
      ".layermod";
  const QString path =
      AskSavePath(window_, "archive", tr("Export archive"), ArchiveFileFilter(), name);
  if (!path.isEmpty()) panels_.training->ExportArchive(path);
}

}  // namespace layermod::ui
