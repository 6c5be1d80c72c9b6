// SPDX-License-Identifier: MIT
#pragma once

#include <QAbstractListModel>
#include <QCache>
#include <QPixmap>
#include <QSet>
#include <QThreadPool>
#include <memory>
#include <vector>

#include "mesh/render_mesh.h"
#include "templates/archive.h"

namespace layermod::ui {

// Which templates the browser lists.
struct TemplateFilter {
  int layer_index = -1;  // -1: every layer
  double elevation_min_deg = -90.0;
  double elevation_max_deg = 90.0;
  // Azimuths from min to max going counter-clockwise, wrapping past 360 (300..60 is the 120
  // degrees around 0).
  double azimuth_min_deg = 0.0;
  double azimuth_max_deg = 360.0;
  double roll_min_deg = -180.0;
  double roll_max_deg = 180.0;

  bool Accepts(const TemplateRecord& record) const;
};

// The templates of an archive as a list of thumbnails. Thumbnails are rendered lazily, when the
// view first asks for one, on a private thread pool, and kept in a bounded cache.
class TemplateListModel : public QAbstractListModel {
  Q_OBJECT

 public:
  static constexpr int kThumbnailPx = 112;
  static constexpr int kTemplateIdRole = Qt::UserRole;

  explicit TemplateListModel(QObject* parent = nullptr);
  ~TemplateListModel() override;  // waits for the renders in flight

  // `mesh` renders the views of object `mesh_obj_id`; templates of other objects, or all of them
  // when `mesh` is null, show their features alone on black.
  void SetArchive(std::shared_ptr<const TemplateArchive> archive,
                  std::shared_ptr<const RenderMesh> mesh, std::int32_t mesh_obj_id);
  void SetFilter(const TemplateFilter& filter);
  std::shared_ptr<const TemplateArchive> archive() const { return archive_; }
  std::shared_ptr<const RenderMesh> mesh() const { return mesh_; }
  const TemplateRecord* RecordAt(int row) const;
  int TemplateIndexAt(int row) const;          // index in archive()->templates(), or -1
  int RowOfTemplate(std::size_t index) const;  // -1 when filtered out
  // The mesh for `record`'s views, or null.
  const RenderMesh* MeshFor(const TemplateRecord& record) const;

  int pending_thumbnails() const { return pending_.size(); }
  int rendered_thumbnails() const { return rendered_; }

  int rowCount(const QModelIndex& parent = QModelIndex()) const override;
  QVariant data(const QModelIndex& index, int role) const override;

 signals:
  void ThumbnailsIdle();  // every requested thumbnail has arrived

 private:
  QVariant Thumbnail(std::size_t index) const;
  void OnThumbnail(int generation, std::size_t index, const QImage& image);
  void Rebuild();

  std::shared_ptr<const TemplateArchive> archive_;
  std::shared_ptr<const RenderMesh> mesh_;
  std::int32_t mesh_obj_id_ = 0;
  TemplateFilter filter_;
  std::vector<std::size_t> rows_;  // indices of the templates shown, ascending
  int generation_ = 0;             // results of an older archive/mesh are dropped
  int rendered_ = 0;
  QPixmap placeholder_;
  mutable QCache<std::size_t, QPixmap> cache_;
  mutable QSet<std::size_t> pending_;
  mutable QThreadPool pool_;
};

}  // namespace layermod::ui
