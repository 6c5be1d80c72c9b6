// SPDX-License-Identifier: MIT
#include "ui/model/model_panel.h"

#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"

namespace layermod::ui {
namespace {

QString Mm(double value_mm) { return QStringLiteral("%1 mm").arg(value_mm, 0, 'f', 2); }

QString Vector(const Eigen::Vector3d& v) {
  return QStringLiteral("(%1, %2, %3)")
      .arg(v.x(), 0, 'f', 1)
      .arg(v.y(), 0, 'f', 1)
      .arg(v.z(), 0, 'f', 1);
}

QLabel* ValueLabel(const char* name) {
  auto* label = new QLabel(QStringLiteral("–"));
  label->setObjectName(name);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setWordWrap(true);
  return label;
}

}  // namespace

ModelPanel::ModelPanel(StudioSession* session, JobRunner* runner, QWidget* parent)
    : QWidget(parent),
      session_(session),
      runner_(runner),
      file_(ValueLabel("fileValue")),
      units_(new QComboBox),
      radius_(ValueLabel("radiusValue")),
      diameter_(ValueLabel("diameterValue")),
      centre_(ValueLabel("centreValue")),
      counts_(ValueLabel("countsValue")),
      bbox_(ValueLabel("bboxValue")),
      colours_(ValueLabel("coloursValue")),
      warnings_(ValueLabel("warningsValue")),
      recentre_(new QPushButton(tr("Re-centre on sphere centre"))) {
  auto* open = new QPushButton(tr("Open mesh…"));
  units_->setObjectName("unitsCombo");
  units_->addItem(tr("millimetres (mm)"), static_cast<int>(LengthUnit::kMillimetre));
  units_->addItem(tr("metres (m)"), static_cast<int>(LengthUnit::kMetre));
  units_->setToolTip(tr("Units of the mesh file; the model is converted to mm (reloads)"));
  recentre_->setObjectName("recentreButton");
  recentre_->setToolTip(
      tr("Move the model so that its sphere centre is the origin: poses then refer to the "
         "object's centre.\nLeave the origin as it is when ground truth is given in the mesh's "
         "own frame (BOP datasets): re-centred poses no longer match it."));
  warnings_->setStyleSheet("QLabel { background: #5a4a12; color: #ffe9a8; padding: 4px; }");

  auto* form = new QFormLayout;
  form->addRow(tr("File"), file_);
  form->addRow(tr("Units"), units_);
  form->addRow(tr("Sphere radius r"), radius_);
  form->addRow(tr("Diameter R = 2r"), diameter_);
  form->addRow(tr("Sphere centre"), centre_);
  form->addRow(tr("Mesh"), counts_);
  form->addRow(tr("Bounding box"), bbox_);
  form->addRow(tr("Vertex colours"), colours_);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(open);
  layout->addLayout(form);
  layout->addWidget(warnings_);
  layout->addWidget(recentre_);
  layout->addStretch();

  connect(open, &QPushButton::clicked, this, &ModelPanel::OpenRequested);
  connect(units_, qOverload<int>(&QComboBox::activated), this, &ModelPanel::OnUnitsChanged);
  connect(recentre_, &QPushButton::clicked, this, &ModelPanel::Recentre);
  connect(session_, &StudioSession::ModelChanged, this, &ModelPanel::ShowModel);
  connect(runner_, &JobRunner::BusyChanged, open, &QWidget::setDisabled);
  ShowModel();
}

LengthUnit ModelPanel::units() const {
  return static_cast<LengthUnit>(units_->currentData().toInt());
}

void ModelPanel::SetUnits(LengthUnit units) {
  units_->setCurrentIndex(units_->findData(static_cast<int>(units)));
}

bool ModelPanel::OpenMesh(const QString& path) {
  LoadModelOptions options;
  options.units = units();
  const QString action = tr("Open mesh “%1”").arg(path);
  return runner_->Start(action, [this, path, options](const JobControl&) -> JobRunner::Commit {
    auto model = std::make_shared<const Model>(LoadModel(path.toStdString(), options));
    return [this, model, path] {
      session_->SetModel(model);
      emit MeshOpened(path);
    };
  });
}

void ModelPanel::OnUnitsChanged() {
  const auto model = session_->model();
  if (model == nullptr || model->source_units == units()) return;
  // Other units make another model: a set trained from this one no longer fits it.
  if (!ConfirmDiscardUnsaved(this, *session_)) return SetUnits(model->source_units);
  if (!OpenMesh(QString::fromStdString(model->source.string()))) SetUnits(model->source_units);
}

void ModelPanel::Recentre() {
  const auto model = session_->model();
  if (model == nullptr) return;
  auto recentred = std::make_shared<Model>(*model);
  RecentreOnSphere(*recentred);
  session_->SetModel(std::move(recentred));
}

void ModelPanel::ShowModel() {
  const auto model = session_->model();
  recentre_->setVisible(model != nullptr && OriginFarFromCentre(*model));
  if (model == nullptr) {
    for (QLabel* label : {file_, radius_, diameter_, centre_, counts_, bbox_, colours_}) {
      label->setText(QStringLiteral("–"));
    }
    warnings_->hide();
    return;
  }
  SetUnits(model->source_units);
  file_->setText(QFileInfo(QString::fromStdString(model->source.string())).fileName());
  file_->setToolTip(QString::fromStdString(model->source.string()));
  radius_->setText(Mm(model->sphere.radius_mm));
  diameter_->setText(Mm(model->DiameterMm()));
  centre_->setText(Vector(model->sphere.centre) + tr(" mm"));
  counts_->setText(
      tr("%1 vertices, %2 triangles").arg(model->mesh.n_vertices()).arg(model->mesh.n_faces()));
  const Eigen::Vector3d size = model->bbox_max - model->bbox_min;
  bbox_->setText(tr("%1 × %2 × %3 mm\nfrom %4 to %5")
                     .arg(size.x(), 0, 'f', 1)
                     .arg(size.y(), 0, 'f', 1)
                     .arg(size.z(), 0, 'f', 1)
                     .arg(Vector(model->bbox_min), Vector(model->bbox_max)));
  colours_->setText(model->has_vertex_colors ? tr("yes") : tr("no (rendered grey)"));
  QStringList warnings;
  for (const std::string& warning : model->warnings) warnings << QString::fromStdString(warning);
  warnings_->setText(warnings.join("\n"));
  warnings_->setVisible(!warnings.isEmpty());
}

}  // namespace layermod::ui
