// SPDX-License-Identifier: MIT
#include "ui/views/views_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStringList>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <exception>
#include <memory>
#include <nlohmann/json.hpp>

#include "geometry/up_axis.h"
#include "mesh/model_resting_poses.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/views/camera_form.h"
#include "ui/views/object_form.h"
#include "ui/widgets/fold_header.h"

namespace layermod::ui {
namespace {

// Long enough to let someone type "1500" without four re-plans and glyph rebuilds.
constexpr int kDebounceMs = 200;

// The up-axis entry of a rotation that is none of the six axes.
constexpr char kCustomUpAxis[] = "tilted";

// Narrow enough for the three-column angle grid in a ~370 px dock.
constexpr int kNumberBoxMinWidthPx = 64;

QDoubleSpinBox* NumberBox(double min, double max, const QString& suffix, int decimals = 1) {
  auto* box = new QDoubleSpinBox;
  box->setMinimumWidth(kNumberBoxMinWidthPx);
  box->setRange(min, max);
  box->setDecimals(decimals);
  box->setSuffix(suffix);
  return box;
}

QSpinBox* CountBox(const char* name) {
  auto* box = new QSpinBox;
  box->setObjectName(name);
  box->setRange(0, 4096);
  return box;
}

AngleRange* RangeOf(ViewSamplingOptions& views, int row) {
  return row == 0 ? &views.azimuth : row == 1 ? &views.elevation : &views.roll;
}

}  // namespace

ViewsPanel::ViewsPanel(StudioSession* session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      camera_(new CameraForm),
      object_(new ObjectForm),
      debounce_(new QTimer(this)) {
  plan_label_ = new QLabel;
  plan_label_->setObjectName("planLabel");
  plan_label_->setWordWrap(true);
  plan_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* lock_note = new QLabel(tr("Training: the form is locked until the run ends."));
  lock_note->setObjectName("formLockedNote");
  lock_note->setWordWrap(true);
  lock_note->setStyleSheet("QLabel { background: #fff3cd; color: #4a3b00; padding: 3px; }");
  lock_note->hide();
  lock_note_ = lock_note;
  auto* object_box = new QGroupBox(tr("Object"));
  (new QVBoxLayout(object_box))->addWidget(object_);
  QWidget* camera_box = BuildCameraBox();
  auto* save = new QPushButton(tr("Save profile…"));
  auto* load = new QPushButton(tr("Load profile…"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(load);
  buttons->addWidget(save);

  // The count and any validation error first: they stay in sight on a short screen.
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(plan_label_);
  layout->addWidget(lock_note_);
  layout->addWidget(object_box);
  layout->addWidget(BuildDepthBox());
  layout->addWidget(BuildOrientationBox());
  layout->addWidget(BuildViewsBox());
  layout->addWidget(BuildFeaturesBox());
  layout->addWidget(camera_box);
  layout->addLayout(buttons);
  layout->addStretch();
  SetProfile(TrainingProfile{});

  debounce_->setSingleShot(true);
  debounce_->setInterval(kDebounceMs);
  connect(debounce_, &QTimer::timeout, this, &ViewsPanel::UpdatePlan);
  connect(camera_, &CameraForm::Changed, this, &ViewsPanel::ScheduleUpdate);
  connect(object_, &ObjectForm::Changed, this, &ViewsPanel::ScheduleUpdate);
  connect(session_, &StudioSession::ModelChanged, this, &ViewsPanel::OnModelChanged);
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path =
        AskSavePath(this, "profile", tr("Save training profile"), JsonFileFilter(), "profile.json");
    if (!path.isEmpty()) SaveProfile(path);
  });
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path =
        AskOpenPath(this, "profile", tr("Load training profile"), JsonFileFilter());
    if (!path.isEmpty()) LoadProfile(path);
  });
  UpdatePlan();
}

QWidget* ViewsPanel::BuildCameraBox() {
  // Folded to one line: set once per sensor, it need not take a short screen's height.
  QToolButton* toggle = MakeFoldHeader(camera_, false);
  toggle->setObjectName("cameraToggle");
  toggle->setToolTip(tr("The pinhole camera every template is rendered with (as the sensor)"));
  auto update_summary = [this, toggle] {
    const PinholeCamera cam = camera_->camera();
    toggle->setText(tr("Camera: f %1 / %2 px, %3×%4")
                        .arg(cam.fx, 0, 'f', 1)
                        .arg(cam.fy, 0, 'f', 1)
                        .arg(cam.width)
                        .arg(cam.height));
  };
  update_summary();
  connect(camera_, &CameraForm::Changed, toggle, update_summary);
  auto* box = new QWidget;
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(toggle);
  layout->addWidget(camera_);
  return box;
}

QWidget* ViewsPanel::BuildDepthBox() {
  depth_min_ = NumberBox(1.0, 1e6, " mm");
  depth_max_ = NumberBox(1.0, 1e6, " mm");
  depth_min_->setObjectName("depthMinBox");
  depth_max_->setObjectName("depthMaxBox");
  auto* box = new QGroupBox(tr("Depth range"));
  box->setToolTip(tr("Depth layers are spaced by the sphere radius r"));
  auto* row = new QHBoxLayout(box);
  row->addWidget(new QLabel(tr("D_min")));
  row->addWidget(depth_min_, 1);
  row->addWidget(new QLabel(tr("D_max")));
  row->addWidget(depth_max_, 1);
  for (QDoubleSpinBox* spin : {depth_min_, depth_max_}) {
    connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            &ViewsPanel::ScheduleUpdate);
  }
  return box;
}

QWidget* ViewsPanel::BuildOrientationBox() {
  up_axis_ = new QComboBox;
  up_axis_->setObjectName("upAxisCombo");
  for (const std::string& name : UpAxisNames()) up_axis_->addItem(QString::fromStdString(name));
  up_axis_->setToolTip(
      tr("The model axis that points up when the part stands as used (yellow arrow in the 3D "
         "view). Elevation and roll are measured from it; poses stay in the mesh's frame."));
  auto* tabletop = new QPushButton(tr("Tabletop"));
  auto* full = new QPushButton(tr("Full sphere"));
  tabletop->setObjectName("tabletopPresetButton");
  full->setObjectName("fullPresetButton");
  tabletop->setToolTip(tr("The part stands on its base: elevation 0–90°, roll ±45°"));
  full->setToolTip(
      tr("Any orientation (bin picking): the whole view sphere, roll all round; about 7× the "
         "templates of tabletop"));
  resting_ = new QLabel;
  resting_->setObjectName("restingPosesLabel");
  resting_->setWordWrap(true);
  resting_->setToolTip(
      tr("How the part comes to rest when put down, from its convex hull and centre of mass "
         "(the share of random drops). Click one to make it the up axis."));
  connect(resting_, &QLabel::linkActivated, this,
          [this](const QString& index) { UseRestingPose(index.toInt()); });
  auto* box = new QGroupBox(tr("Orientation and views preset"));
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Up")));
  row->addWidget(up_axis_);
  row->addSpacing(8);
  row->addWidget(tabletop, 1);
  row->addWidget(full, 1);
  auto* column = new QVBoxLayout(box);
  column->addLayout(row);
  column->addWidget(resting_);
  connect(up_axis_, qOverload<int>(&QComboBox::activated), this, [this] {
    const QString name = up_axis_->currentText();
    if (name == kCustomUpAxis) return;  // the profile's own rotation, kept
    SetUpright(UprightFromUpAxis(name.toStdString()));
  });
  connect(tabletop, &QPushButton::clicked, this, [this] { ApplyViewPreset("tabletop"); });
  connect(full, &QPushButton::clicked, this, [this] { ApplyViewPreset("full"); });
  return box;
}

std::vector<RestingPose> ViewsPanel::resting_poses() const {
  return LikelyRestingPoses(resting_all_);
}

void ViewsPanel::UseRestingPose(int index) {
  const std::vector<RestingPose> poses = resting_poses();
  if (index < 0 || index >= static_cast<int>(poses.size())) return;
  const RestingPose& pose = poses[static_cast<std::size_t>(index)];
  SetUpright(pose.axis_name ? UprightFromUpAxis(*pose.axis_name)
                            : UprightFromUpDirection(pose.up_in_model));
}

void ViewsPanel::ShowRestingPoses() {
  const std::vector<RestingPose> poses = resting_poses();
  if (poses.empty()) {
    resting_->setText(session_->model() == nullptr ? QString() : tr("Rests on: no stable face"));
    return;
  }
  QStringList links;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    links << QStringLiteral("<a href='%1'>%2</a> %3 %")
                 .arg(i)
                 .arg(QString::fromStdString(RestingPoseName(poses[i])).toHtmlEscaped())
                 .arg(100.0 * poses[i].probability, 0, 'f', 0);
  }
  QString text = tr("Rests on: %1").arg(links.join(" · "));
  if (!IsLikelyRestingUp(resting_all_, profile().views.upright_from_model)) {
    text +=
        tr("<br><span style='color:#b26a00'>The part rarely rests this way up; views are "
           "measured from this axis anyway (right for a part held in a gripper).</span>");
  }
  resting_->setText(text);
}

void ViewsPanel::SetUpright(const Eigen::Matrix3d& upright_from_model) {
  TrainingProfile changed = profile();
  changed.views.upright_from_model = upright_from_model;
  SetProfile(changed);
}

void ViewsPanel::ApplyViewPreset(const std::string& name) {
  TrainingProfile changed = profile();
  changed.views = ViewPreset(name, changed.views.upright_from_model);
  SetProfile(changed);
}

void ViewsPanel::ShowUpAxis(const Eigen::Matrix3d& upright_from_model) {
  const QSignalBlocker blocker(up_axis_);
  const int custom = up_axis_->findText(kCustomUpAxis);
  if (const auto name = UpAxisName(upright_from_model)) {
    if (custom >= 0) up_axis_->removeItem(custom);
    up_axis_->setCurrentText(QString::fromStdString(*name));
    return;
  }
  // A rotation that is none of the six axes (a profile's, or a tilted resting face).
  const Eigen::Vector3d up = UpDirectionInModel(upright_from_model);
  if (custom < 0) up_axis_->addItem(kCustomUpAxis);
  up_axis_->setCurrentText(kCustomUpAxis);
  up_axis_->setItemData(up_axis_->findText(kCustomUpAxis),
                        tr("up = (%1, %2, %3) in the model")
                            .arg(up.x(), 0, 'f', 2)
                            .arg(up.y(), 0, 'f', 2)
                            .arg(up.z(), 0, 'f', 2),
                        Qt::ToolTipRole);
}

QWidget* ViewsPanel::BuildViewsBox() {
  auto* box = new QGroupBox(tr("Views (degrees)"));
  auto* grid = new QGridLayout(box);
  const QString rows[] = {tr("Azimuth"), tr("Elevation"), tr("Roll")};
  const QString columns[] = {tr("min"), tr("step"), tr("max")};
  const char* names[] = {"azimuth", "elevation", "roll"};
  for (int column = 0; column < 3; ++column) {
    grid->addWidget(new QLabel(columns[column]), 0, column + 1);
  }
  for (int row = 0; row < 3; ++row) {
    grid->addWidget(new QLabel(rows[row]), row + 1, 0);
    for (int column = 0; column < 3; ++column) {
      auto* spin = NumberBox(column == 1 ? 0.1 : -360.0, 360.0, "°");
      spin->setObjectName(QStringLiteral("%1%2Box").arg(names[row], columns[column]));
      angles_[row][column] = spin;
      grid->addWidget(spin, row + 1, column + 1);
      connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
              &ViewsPanel::ScheduleUpdate);
    }
  }
  even_spacing_ = NumberBox(0.0, 90.0, "°");
  even_spacing_->setObjectName("evenSpacingBox");
  even_spacing_->setSpecialValueText(tr("0 (az/el grid)"));
  even_spacing_->setToolTip(
      tr("When above 0: camera directions evenly spread on the view "
         "sphere (Fibonacci), limited to the elevation range; the "
         "azimuth range is then unused"));
  grid->addWidget(new QLabel(tr("Even spacing")), 4, 0);
  grid->addWidget(even_spacing_, 4, 1, 1, 3);
  connect(even_spacing_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          &ViewsPanel::ScheduleUpdate);
  return box;
}

QWidget* ViewsPanel::BuildFeaturesBox() {
  color_features_ = CountBox("colorFeaturesBox");
  normal_features_ = CountBox("normalFeaturesBox");
  color_features_->setToolTip(tr("Colour-gradient features per template"));
  normal_features_->setToolTip(tr("Surface-normal features per template"));
  auto* box = new QGroupBox(tr("Features per template"));
  auto* row = new QHBoxLayout(box);
  row->addWidget(new QLabel(tr("Gradients")));
  row->addWidget(color_features_, 1);
  row->addWidget(new QLabel(tr("Normals")));
  row->addWidget(normal_features_, 1);
  for (QSpinBox* spin : {color_features_, normal_features_}) {
    connect(spin, qOverload<int>(&QSpinBox::valueChanged), this, &ViewsPanel::ScheduleUpdate);
  }
  return box;
}

TrainingProfile ViewsPanel::profile() const {
  TrainingProfile profile = base_;
  profile.depth_min_mm = depth_min_->value();
  profile.depth_max_mm = depth_max_->value();
  for (int row = 0; row < 3; ++row) {
    *RangeOf(profile.views, row) = {angles_[row][0]->value(), angles_[row][1]->value(),
                                    angles_[row][2]->value()};
  }
  profile.views.even_spacing_deg = even_spacing_->value();
  profile.features.color_features = color_features_->value();
  profile.features.normal_features = normal_features_->value();
  return profile;
}

void ViewsPanel::SetProfile(const TrainingProfile& profile) {
  base_ = profile;
  {
    // One plan update for the whole profile, not one per field.
    std::vector<std::unique_ptr<QSignalBlocker>> blockers;
    for (QAbstractSpinBox* box : findChildren<QAbstractSpinBox*>()) {
      blockers.push_back(std::make_unique<QSignalBlocker>(box));
    }
    depth_min_->setValue(profile.depth_min_mm);
    depth_max_->setValue(profile.depth_max_mm);
    ViewSamplingOptions views = profile.views;
    for (int row = 0; row < 3; ++row) {
      const AngleRange& range = *RangeOf(views, row);
      angles_[row][0]->setValue(range.min_deg);
      angles_[row][1]->setValue(range.step_deg);
      angles_[row][2]->setValue(range.max_deg);
    }
    even_spacing_->setValue(profile.views.even_spacing_deg);
    ShowUpAxis(profile.views.upright_from_model);
    color_features_->setValue(profile.features.color_features);
    normal_features_->setValue(profile.features.normal_features);
  }
  ScheduleUpdate();
}

PinholeCamera ViewsPanel::camera() const { return camera_->camera(); }

void ViewsPanel::SetCamera(const PinholeCamera& camera) { camera_->SetCamera(camera); }

TrainingRequest ViewsPanel::request() const {
  TrainingRequest request;
  request.camera = camera();
  request.profile = profile();
  request.obj_id = object_->obj_id();
  request.name = object_->name().toStdString();
  const auto model = session_->model();
  if (request.name.empty() && model != nullptr) request.name = model->source.stem().string();
  return request;
}

void ViewsPanel::SetObject(std::int32_t obj_id, const QString& name) {
  object_->SetObject(obj_id, name);
}

void ViewsPanel::SetLocked(bool locked) {
  locked_ = locked;
  for (QWidget* child : findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
    if (child != plan_label_ && child != lock_note_) child->setEnabled(!locked);
  }
  lock_note_->setVisible(locked);
}

void ViewsPanel::OnModelChanged() {
  resting_all_ = {};
  if (const auto model = session_->model()) {
    object_->DefaultFromMesh(QString::fromStdString(model->source.string()));
    resting_all_ = SuggestRestingPoses(*model);  // milliseconds, even for scanned meshes
  }
  ShowRestingPoses();
  UpdatePlan();
}

void ViewsPanel::ScheduleUpdate() {
  ShowUnusedGridBoxes();
  ShowRestingPoses();
  debounce_->start();
}

void ViewsPanel::ShowUnusedGridBoxes() {
  // Even spacing samples the elevation range only (geometry/views.h): the azimuth row and the
  // elevation step are unused, and look it.
  const bool grid = even_spacing_->value() <= 0.0;
  const QString unused = grid ? QString() : tr("Unused while even spacing is above 0");
  for (QDoubleSpinBox* box : {angles_[0][0], angles_[0][1], angles_[0][2], angles_[1][1]}) {
    box->setEnabled(grid);
    box->setToolTip(unused);
  }
}

void ViewsPanel::UpdatePlan() {
  debounce_->stop();
  plan_.reset();
  const auto model = session_->model();
  QString text;
  problem_ = FormProblem();
  if (model == nullptr) {
    text = tr("Open a mesh to count depth layers and templates.");
  } else if (problem_.isEmpty()) {
    try {
      plan_ = PlanTraining(*model, request());
    } catch (const std::exception& error) {
      problem_ = QString::fromStdString(error.what());
    }
  }
  if (!problem_.isEmpty()) {
    text = tr("<span style='color:#ff6b6b'>Cannot train: %1</span>").arg(problem_.toHtmlEscaped());
  }
  for (QDoubleSpinBox* box : {depth_min_, depth_max_}) {
    box->setStyleSheet(depth_min_->value() < depth_max_->value()
                           ? QString()
                           : "QDoubleSpinBox { color: #d32f2f; }");
  }
  if (plan_.has_value()) {
    const QLocale locale;
    text = tr("<b>%1</b> layers × <b>%2</b> views = <b>%3</b> templates<br>layer step r = %4 mm")
               .arg(plan_->layer_depths_mm.size())
               .arg(locale.toString(static_cast<qulonglong>(plan_->views.size())))
               .arg(locale.toString(static_cast<qulonglong>(plan_->TemplateCount())))
               .arg(plan_->radius_mm, 0, 'f', 1);
  }
  plan_label_->setText(text);
  emit PlanChanged();
}

QString ViewsPanel::plan_text() const { return plan_label_->text(); }

QString ViewsPanel::FormProblem() const {
  // Said in the form's own words; the core's messages name profile-file fields.
  if (depth_min_->value() >= depth_max_->value()) {
    return tr("D_min (%1 mm) must be below D_max (%2 mm)")
        .arg(depth_min_->value(), 0, 'f', 1)
        .arg(depth_max_->value(), 0, 'f', 1);
  }
  return {};
}

bool ViewsPanel::SaveProfile(const QString& path) {
  try {
    SaveTrainingProfile(path.toStdString(), profile());
    return true;
  } catch (const std::exception& error) {
    ShowError(this, tr("Save profile “%1”").arg(path), QString::fromStdString(error.what()));
    return false;
  }
}

bool ViewsPanel::LoadProfile(const QString& path) {
  try {
    SetProfile(LoadTrainingProfile(path.toStdString()));
    return true;
  } catch (const std::exception& error) {
    ShowError(this, tr("Load profile “%1”").arg(path), QString::fromStdString(error.what()));
    return false;
  }
}

void ViewsPanel::SaveSettings() const {
  QSettings settings;
  settings.setValue("profile/json", QString::fromStdString(ToJson(profile()).dump()));
  const PinholeCamera cam = camera();
  settings.setValue("camera/intrinsics",
                    QVariantList{cam.fx, cam.fy, cam.cx, cam.cy, cam.width, cam.height});
}

void ViewsPanel::RestoreSettings() {
  QSettings settings;
  const QString json = settings.value("profile/json").toString();
  try {
    if (!json.isEmpty()) {
      SetProfile(TrainingProfileFromJson(nlohmann::json::parse(json.toStdString())));
    }
  } catch (const std::exception&) {
    // A profile saved by another version: keep the defaults.
  }
  const QVariantList values = settings.value("camera/intrinsics").toList();
  if (values.size() == 6) {
    SetCamera({values[0].toDouble(), values[1].toDouble(), values[2].toDouble(),
               values[3].toDouble(), values[4].toInt(), values[5].toInt()});
  }
}

}  // namespace layermod::ui
