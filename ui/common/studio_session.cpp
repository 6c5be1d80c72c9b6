// SPDX-License-Identifier: MIT
#include "ui/common/studio_session.h"

namespace layermod::ui {

StudioSession::StudioSession(QObject* parent) : QObject(parent) {}

void StudioSession::SetModel(std::shared_ptr<const Model> model) {
  model_ = std::move(model);
  emit ModelChanged();
}

void StudioSession::SetArchive(std::shared_ptr<const TemplateArchive> archive,
                               const QString& path) {
  archive_ = std::move(archive);
  archive_path_ = path;
  emit ArchiveChanged();
}

void StudioSession::ClearArchive() { SetArchive(nullptr, QString()); }

void StudioSession::MarkArchiveSaved(const QString& path) { archive_path_ = path; }

}  // namespace layermod::ui
