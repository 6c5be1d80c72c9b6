// SPDX-License-Identifier: MIT
#include "ui/templates/template_list_model.h"

#include <cmath>

#include <QColor>
#include <algorithm>
#include <exception>

#include "templates/template_picture.h"
#include "ui/common/image_convert.h"

namespace layermod::ui {
namespace {

// Thumbnails kept in memory (~50 KB each): enough for several screens of scrolling.
constexpr int kCachedThumbnails = 3000;

QString Describe(const TemplateRecord& record) {
  int colour = 0;
  int normal = 0;
  if (!record.levels.empty()) {
    for (const Feature& feature : record.levels[0].features) {
      (feature.modality == Modality::kColorGradient ? colour : normal) += 1;
    }
  }
  QString text = QObject::tr(
                     "Template #%1 — layer %2 (%3 mm)\naz %4°, el %5°, roll %6°\n"
                     "%7 colour-gradient + %8 normal features")
                     .arg(record.id)
                     .arg(record.layer_index)
                     .arg(record.layer_depth_mm, 0, 'f', 0)
                     .arg(record.view.azimuth_deg, 0, 'f', 1)
                     .arg(record.view.elevation_deg, 0, 'f', 1)
                     .arg(record.view.roll_deg, 0, 'f', 1)
                     .arg(colour)
                     .arg(normal);
  if (record.status == TemplateStatus::kTooFewFeatures) {
    text += QObject::tr("\nweak: too few features, skipped by the matcher");
  }
  return text;
}

}  // namespace

bool TemplateFilter::Accepts(const TemplateRecord& record) const {
  constexpr double kEps = 1e-6;
  if (layer_index >= 0 && record.layer_index != layer_index) return false;
  const double span = azimuth_max_deg - azimuth_min_deg;
  if (span < 360.0 - kEps) {
    const double from_min =
        std::fmod(std::fmod(record.view.azimuth_deg - azimuth_min_deg, 360.0) + 360.0, 360.0);
    if (from_min > std::fmod(span + 360.0, 360.0) + kEps) return false;
  }
  return record.view.elevation_deg >= elevation_min_deg - kEps &&
         record.view.elevation_deg <= elevation_max_deg + kEps &&
         record.view.roll_deg >= roll_min_deg - kEps && record.view.roll_deg <= roll_max_deg + kEps;
}

TemplateListModel::TemplateListModel(QObject* parent)
    : QAbstractListModel(parent), placeholder_(kThumbnailPx, kThumbnailPx) {
  placeholder_.fill(QColor(40, 40, 44));
  cache_.setMaxCost(kCachedThumbnails);
  // Leave a core to the GUI thread and to training.
  pool_.setMaxThreadCount(std::max(1, QThread::idealThreadCount() - 1));
}

TemplateListModel::~TemplateListModel() {
  pool_.clear();
  pool_.waitForDone();
}

void TemplateListModel::SetArchive(std::shared_ptr<const TemplateArchive> archive,
                                   std::shared_ptr<const RenderMesh> mesh,
                                   std::int32_t mesh_obj_id) {
  archive_ = std::move(archive);
  mesh_ = std::move(mesh);
  mesh_obj_id_ = mesh_obj_id;
  Rebuild();
}

void TemplateListModel::SetFilter(const TemplateFilter& filter) {
  filter_ = filter;
  Rebuild();
}

void TemplateListModel::Rebuild() {
  beginResetModel();
  ++generation_;
  pool_.clear();  // renders not started yet are no longer wanted
  pending_.clear();
  cache_.clear();
  rendered_ = 0;
  rows_.clear();
  if (archive_ != nullptr) {
    const auto& templates = archive_->templates();
    for (std::size_t i = 0; i < templates.size(); ++i) {
      if (filter_.Accepts(templates[i])) rows_.push_back(i);
    }
  }
  endResetModel();
}

int TemplateListModel::TemplateIndexAt(int row) const {
  if (archive_ == nullptr || row < 0 || row >= static_cast<int>(rows_.size())) return -1;
  return static_cast<int>(rows_[static_cast<std::size_t>(row)]);
}

const TemplateRecord* TemplateListModel::RecordAt(int row) const {
  const int index = TemplateIndexAt(row);
  return index < 0 ? nullptr : &archive_->templates()[static_cast<std::size_t>(index)];
}

int TemplateListModel::RowOfTemplate(std::size_t index) const {
  const auto found = std::lower_bound(rows_.begin(), rows_.end(), index);
  if (found == rows_.end() || *found != index) return -1;
  return static_cast<int>(found - rows_.begin());
}

const RenderMesh* TemplateListModel::MeshFor(const TemplateRecord& record) const {
  return record.obj_id == mesh_obj_id_ ? mesh_.get() : nullptr;
}

int TemplateListModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

QVariant TemplateListModel::data(const QModelIndex& index, int role) const {
  const TemplateRecord* record = RecordAt(index.row());
  if (record == nullptr) return {};
  switch (role) {
    case Qt::DisplayRole:
      return QStringLiteral("#%1  %2 mm").arg(record->id).arg(record->layer_depth_mm, 0, 'f', 0);
    case Qt::ToolTipRole:
      return Describe(*record);
    case Qt::DecorationRole:
      return Thumbnail(static_cast<std::size_t>(TemplateIndexAt(index.row())));
    case Qt::ForegroundRole:
      if (record->status == TemplateStatus::kTooFewFeatures) return QColor(255, 140, 90);
      return {};
    case kTemplateIdRole:
      return static_cast<uint>(record->id);
    default:
      return {};
  }
}

QVariant TemplateListModel::Thumbnail(std::size_t template_index) const {
  if (const QPixmap* cached = cache_.object(template_index)) return *cached;
  if (!pending_.contains(template_index)) {
    pending_.insert(template_index);
    auto* self = const_cast<TemplateListModel*>(this);
    const TemplateRecord& record = archive_->templates()[template_index];
    std::shared_ptr<const RenderMesh> mesh = MeshFor(record) != nullptr ? mesh_ : nullptr;
    pool_.start([self, template_index, generation = generation_, archive = archive_, mesh] {
      cv::Mat image;
      try {
        image = RenderTemplatePicture(archive->templates()[template_index], archive->camera(),
                                      mesh.get());
      } catch (const std::exception&) {
        // A view the renderer refuses shows as an empty (black) thumbnail.
      }
      const QImage thumbnail = ToQImage(FitInSquare(image, kThumbnailPx));
      QMetaObject::invokeMethod(
          self,
          [self, generation, template_index, thumbnail] {
            self->OnThumbnail(generation, template_index, thumbnail);
          },
          Qt::QueuedConnection);
    });
  }
  return placeholder_;
}

void TemplateListModel::OnThumbnail(int generation, std::size_t template_index,
                                    const QImage& image) {
  if (generation != generation_) return;
  pending_.remove(template_index);
  cache_.insert(template_index, new QPixmap(QPixmap::fromImage(image)));
  ++rendered_;
  const int row = RowOfTemplate(template_index);
  if (row >= 0) emit dataChanged(index(row), index(row), {Qt::DecorationRole});
  if (pending_.isEmpty()) emit ThumbnailsIdle();
}

}  // namespace layermod::ui
