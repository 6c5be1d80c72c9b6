// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>
#include <optional>

#include "geometry/resting_poses.h"
#include "pipeline/training.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QTimer;

namespace layermod::ui {

class CameraForm;
class ObjectForm;
class StudioSession;

// The training profile form: depth range, view sampling, feature counts and camera, with a live
// count of layers and templates (PlanTraining) once a model is loaded.
class ViewsPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ViewsPanel(StudioSession* session, QWidget* parent = nullptr);

  TrainingProfile profile() const;
  void SetProfile(const TrainingProfile& profile);
  PinholeCamera camera() const;
  void SetCamera(const PinholeCamera& camera);
  // The model's likely resting poses, most likely first (empty without a model).
  std::vector<RestingPose> resting_poses() const;
  // Object id and name from the form (defaulted from the mesh file name).
  TrainingRequest request() const;
  void SetObject(std::int32_t obj_id, const QString& name);
  // The up axis the view angles are measured from (the rest of the profile is kept).
  void SetUpright(const Eigen::Matrix3d& upright_from_model);
  // While a run trains, the form cannot change (the run uses the values it started with).
  void SetLocked(bool locked);
  bool locked() const { return locked_; }

  // The plan for the current model and form (nullopt without a model or with invalid values).
  const std::optional<TrainingPlan>& plan() const { return plan_; }
  QString plan_text() const;
  // Why the form cannot be trained as it stands (empty when it can, or without a model).
  const QString& problem() const { return problem_; }

  // Profile files; failures show an error box naming the file.
  bool SaveProfile(const QString& path);
  bool LoadProfile(const QString& path);
  // Last values between runs (QSettings).
  void SaveSettings() const;
  void RestoreSettings();

 public slots:
  void UpdatePlan();  // now, without waiting for the debounce

 signals:
  void PlanChanged();

 private:
  QWidget* BuildCameraBox();
  QWidget* BuildDepthBox();
  QWidget* BuildOrientationBox();
  QWidget* BuildViewsBox();
  void ApplyViewPreset(const std::string& name);
  void ShowUpAxis(const Eigen::Matrix3d& upright_from_model);
  void UseRestingPose(int index);  // of resting_poses()
  void ShowRestingPoses();
  QWidget* BuildFeaturesBox();
  void OnModelChanged();
  void ScheduleUpdate();
  void ShowUnusedGridBoxes();
  QString FormProblem() const;

  StudioSession* session_ = nullptr;
  TrainingProfile base_;  // fields the form does not show are kept from here
  QDoubleSpinBox* depth_min_ = nullptr;
  QDoubleSpinBox* depth_max_ = nullptr;
  QComboBox* up_axis_ = nullptr;
  QLabel* resting_ = nullptr;
  RestingPoses resting_all_;  // of the session's model; the likely ones are offered as links
  QDoubleSpinBox* angles_[3][3] = {};  // [azimuth, elevation, roll][min, step, max]
  QDoubleSpinBox* even_spacing_ = nullptr;
  QSpinBox* color_features_ = nullptr;
  QSpinBox* normal_features_ = nullptr;
  CameraForm* camera_ = nullptr;
  ObjectForm* object_ = nullptr;
  QWidget* lock_note_ = nullptr;
  bool locked_ = false;
  QLabel* plan_label_ = nullptr;
  QTimer* debounce_ = nullptr;
  std::optional<TrainingPlan> plan_;
  QString problem_;
};

}  // namespace layermod::ui
