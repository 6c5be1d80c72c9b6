// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>
#include <memory>

#include "mesh/model.h"
#include "templates/archive.h"

namespace layermod::ui {

// What the studio is working on: the loaded model and the template set (trained here or opened
// from a file). Panels read it and listen to its signals; only the GUI thread touches it.
class StudioSession : public QObject {
  Q_OBJECT

 public:
  explicit StudioSession(QObject* parent = nullptr);

  std::shared_ptr<const Model> model() const { return model_; }
  void SetModel(std::shared_ptr<const Model> model);

  std::shared_ptr<const TemplateArchive> archive() const { return archive_; }
  // Where the archive lives on disk; empty for a freshly trained, not yet exported set.
  const QString& archive_path() const { return archive_path_; }
  bool archive_unsaved() const { return archive_ != nullptr && archive_path_.isEmpty(); }
  void SetArchive(std::shared_ptr<const TemplateArchive> archive, const QString& path);
  void ClearArchive();
  void MarkArchiveSaved(const QString& path);

 signals:
  void ModelChanged();
  void ArchiveChanged();

 private:
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const TemplateArchive> archive_;
  QString archive_path_;
};

}  // namespace layermod::ui
