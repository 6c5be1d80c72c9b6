// SPDX-License-Identifier: MIT
#include "ui/templates/template_browser.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QItemSelectionModel>
#include <QLabel>
#include <QListView>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>
#include <exception>

#include "templates/archive_mesh.h"
#include "templates/template_picture.h"
#include "ui/common/image_convert.h"
#include "ui/common/studio_session.h"
#include "ui/templates/template_list_model.h"

namespace layermod::ui {
namespace {

constexpr int kDetailPx = 180;  // the Templates dock is ~200 px tall on a 1280x800 screen
constexpr int kDetailTextWidthPx = 220;

QDoubleSpinBox* AngleBox(double min_deg, double max_deg, double value_deg, const char* name) {
  auto* box = new QDoubleSpinBox;
  box->setObjectName(name);
  box->setRange(min_deg, max_deg);
  box->setValue(value_deg);
  box->setDecimals(0);
  box->setSuffix("°");
  return box;
}

}  // namespace

TemplateBrowser::TemplateBrowser(StudioSession* session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      model_(new TemplateListModel(this)),
      list_(new QListView),
      count_(new QLabel),
      mesh_banner_(new QWidget),
      mesh_banner_text_(new QLabel),
      detail_image_(new QLabel),
      detail_text_(new QLabel) {
  list_->setObjectName("templateList");
  list_->setModel(model_);
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(TemplateListModel::kThumbnailPx, TemplateListModel::kThumbnailPx));
  list_->setGridSize(
      QSize(TemplateListModel::kThumbnailPx + 12, TemplateListModel::kThumbnailPx + 24));
  list_->setUniformItemSizes(true);
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setLayoutMode(QListView::Batched);  // stays responsive with 20k templates
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  count_->setObjectName("templateCount");

  auto* open_mesh = new QPushButton(tr("Open mesh…"));
  auto* banner_layout = new QHBoxLayout(mesh_banner_);
  banner_layout->setContentsMargins(4, 4, 4, 4);
  mesh_banner_text_->setWordWrap(true);
  banner_layout->addWidget(mesh_banner_text_, 1);
  banner_layout->addWidget(open_mesh);
  // Light amber with dark text: readable under light and dark palettes alike.
  mesh_banner_->setObjectName("meshBanner");
  mesh_banner_->setAttribute(Qt::WA_StyledBackground);
  mesh_banner_->setStyleSheet(
      "#meshBanner { background: #fff3cd; border: 1px solid #d9b44a; } "
      "#meshBanner QLabel { color: #3d3000; }");

  detail_image_->setObjectName("detailImage");
  detail_image_->setFixedSize(kDetailPx, kDetailPx);
  detail_image_->setAlignment(Qt::AlignCenter);
  detail_image_->setStyleSheet("background: black;");
  detail_text_->setObjectName("detailText");
  detail_text_->setWordWrap(true);
  detail_text_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  detail_text_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  detail_text_->setFixedWidth(kDetailTextWidthPx);
  // The dock is wide and short: the enlarged template sits beside the thumbnails.
  auto* list_and_detail = new QHBoxLayout;
  list_and_detail->addWidget(list_, 1);
  list_and_detail->addWidget(detail_image_, 0, Qt::AlignTop);
  list_and_detail->addWidget(detail_text_);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(BuildFilterRow());
  layout->addWidget(mesh_banner_);
  layout->addLayout(list_and_detail, 1);

  connect(open_mesh, &QPushButton::clicked, this, &TemplateBrowser::OpenMeshRequested);
  // Clicks and arrow keys alike move the current template; the detail pane follows.
  connect(list_->selectionModel(), &QItemSelectionModel::currentChanged, this,
          [this](const QModelIndex& index) { ShowCurrent(index.row()); });
  connect(session_, &StudioSession::ArchiveChanged, this, &TemplateBrowser::Refresh);
  connect(session_, &StudioSession::ModelChanged, this, &TemplateBrowser::Refresh);
  Refresh();
}

QWidget* TemplateBrowser::BuildFilterRow() {
  layer_ = new QComboBox;
  layer_->setObjectName("layerFilter");
  elevation_min_ = AngleBox(-90, 90, -90, "elevationMinFilter");
  elevation_max_ = AngleBox(-90, 90, 90, "elevationMaxFilter");
  azimuth_min_ = AngleBox(0, 360, 0, "azimuthMinFilter");
  azimuth_max_ = AngleBox(0, 360, 360, "azimuthMaxFilter");
  azimuth_min_->setToolTip(
      tr("Azimuths from the first to the second box, counter-clockwise "
         "(300 to 60 is the 120° around 0)"));
  azimuth_max_->setToolTip(azimuth_min_->toolTip());
  roll_min_ = AngleBox(-180, 180, -180, "rollMinFilter");
  roll_max_ = AngleBox(-180, 180, 180, "rollMaxFilter");
  auto* row = new QWidget;
  auto* grid = new QGridLayout(row);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(new QLabel(tr("Layer")), 0, 0);
  grid->addWidget(layer_, 0, 1, 1, 4);
  grid->addWidget(count_, 0, 5, 1, 4);
  const std::pair<QString, std::pair<QDoubleSpinBox*, QDoubleSpinBox*>> ranges[] = {
      {tr("Elev."), {elevation_min_, elevation_max_}},
      {tr("Az."), {azimuth_min_, azimuth_max_}},
      {tr("Roll"), {roll_min_, roll_max_}}};
  for (int i = 0; i < 3; ++i) {
    grid->addWidget(new QLabel(ranges[i].first), 1, 3 * i, Qt::AlignRight);
    grid->addWidget(ranges[i].second.first, 1, 3 * i + 1);
    grid->addWidget(ranges[i].second.second, 1, 3 * i + 2);
  }
  connect(layer_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          &TemplateBrowser::ApplyFilter);
  for (QDoubleSpinBox* box :
       {elevation_min_, elevation_max_, azimuth_min_, azimuth_max_, roll_min_, roll_max_}) {
    box->setKeyboardTracking(false);
    connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            &TemplateBrowser::ApplyFilter);
  }
  return row;
}

bool TemplateBrowser::has_mesh() const { return model_->mesh() != nullptr; }

void TemplateBrowser::Refresh() {
  const auto archive = session_->archive();
  const auto model = session_->model();
  std::shared_ptr<const RenderMesh> mesh;
  std::int32_t mesh_obj_id = 0;
  QString missing;
  if (archive != nullptr && !archive->manifest().objects.empty()) {
    const ArchiveObject& object = archive->manifest().objects.front();
    mesh_obj_id = object.obj_id;
    if (model != nullptr && ModelMatchesObject(*model, object)) {
      mesh = std::make_shared<const RenderMesh>(ToRenderMesh(*model));
    } else {
      missing = QString::fromStdString(object.mesh_file);
    }
  }
  mesh_banner_text_->setText(
      tr("The mesh “%1” this set was trained from is not loaded: thumbnails show the features "
         "alone.")
          .arg(missing));
  mesh_banner_->setVisible(!missing.isEmpty());
  model_->SetArchive(archive, mesh, mesh_obj_id);
  FillLayers();
  ApplyFilter();
  ShowDetail(-1);
}

void TemplateBrowser::FillLayers() {
  const QSignalBlocker blocker(layer_);
  layer_->clear();
  layer_->addItem(tr("All layers"), -1);
  const auto archive = session_->archive();
  if (archive == nullptr || archive->manifest().objects.empty()) return;
  const auto& depths = archive->manifest().objects.front().layer_depths_mm;
  for (std::size_t i = 0; i < depths.size(); ++i) {
    layer_->addItem(tr("Layer %1 — %2 mm").arg(i).arg(depths[i], 0, 'f', 0), static_cast<int>(i));
  }
}

void TemplateBrowser::ApplyFilter() {
  TemplateFilter filter;
  filter.layer_index = layer_->currentData().isValid() ? layer_->currentData().toInt() : -1;
  filter.elevation_min_deg = elevation_min_->value();
  filter.elevation_max_deg = elevation_max_->value();
  filter.azimuth_min_deg = azimuth_min_->value();
  filter.azimuth_max_deg = azimuth_max_->value();
  filter.roll_min_deg = roll_min_->value();
  filter.roll_max_deg = roll_max_->value();
  model_->SetFilter(filter);
  const auto archive = model_->archive();
  const std::size_t total = archive == nullptr ? 0 : archive->templates().size();
  count_->setText(tr("%1 of %2 templates").arg(model_->rowCount()).arg(total));
}

void TemplateBrowser::SelectRow(int row) {
  if (model_->RecordAt(row) == nullptr) return;
  if (list_->currentIndex().row() == row) return ShowCurrent(row);
  list_->setCurrentIndex(model_->index(row));  // ShowCurrent through currentChanged
}

void TemplateBrowser::ShowCurrent(int row) {
  ShowDetail(row);
  if (model_->RecordAt(row) != nullptr) emit TemplateSelected(model_->TemplateIndexAt(row));
}

void TemplateBrowser::ShowDetail(int row) {
  const TemplateRecord* record = model_->RecordAt(row);
  if (record == nullptr) {
    detail_image_->clear();
    detail_text_->setText(
        tr("Click a template to enlarge it and to see its camera in the 3D "
           "view.<br><span style='color:#4cff4c'>●</span> colour-gradient feature (green "
           "tick: orientation)<br><span style='color:#ff3b3b'>●</span> normal feature (its "
           "<span style='color:#0050ff'>blue</span> tick: direction)"));
    return;
  }
  cv::Mat image;
  try {
    image = RenderTemplatePicture(*record, model_->archive()->camera(), model_->MeshFor(*record));
  } catch (const std::exception&) {
    // Shown as an empty image; the text still describes the template.
  }
  detail_image_->setPixmap(QPixmap::fromImage(ToQImage(FitInSquare(image, kDetailPx))));
  const QString tooltip = model_->data(model_->index(row), Qt::ToolTipRole).toString();
  detail_text_->setText(tooltip.toHtmlEscaped().replace("\n", "<br>") +
                        tr("<br><br><span style='color:#4cff4c'>●</span> colour gradient "
                           "(green tick: orientation)<br><span style='color:#ff3b3b'>●</span> "
                           "normal (<span style='color:#0050ff'>blue</span> tick: direction)"));
}

}  // namespace layermod::ui
