// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "eval/envelope_coverage.h"
#include "pipeline/overlay_stack.h"
#include "ui/detection/capture_source.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace layermod::ui {

class DetectionOptionsForm;
class ImageView;
class JobRunner;
class StudioSession;

// Detection preview: a capture (BOP frame, or colour + depth + camera file) and the session's
// template set; runs Detector on the worker thread and shows the capture with the stage overlays
// (each toggleable), the detections and the per-stage timings. Jobs asked for while another runs
// wait for it.
class DetectionPanel : public QWidget {
  Q_OBJECT

 public:
  DetectionPanel(StudioSession* session, JobRunner* runner, QWidget* parent = nullptr);
  ~DetectionPanel() override;

  // Reads the frame on the worker thread; detection follows when a template set is open and
  // "Detect on load" is on. Failures show an error box naming the file.
  void OpenCapture(const CaptureSource& source);
  // Runs detection now (or once the running job ends); false without a capture or templates.
  bool Detect();
  // A BOP split folder (e.g. dropped on the window): the scene and frame in the form.
  void OpenBopFolder(const QString& split_dir);
  // The frame after (`step` > 0) or before the one in the form, among the loaded BOP scene's
  // frames; false at either end or without a BOP capture.
  bool StepFrame(int step);
  bool can_step_frames() const { return source_.is_bop() && !frame_ids_.empty(); }
  bool can_detect() const;
  void SetOverlays(const OverlayToggles& toggles);
  OverlayToggles overlays() const;

  bool has_capture() const { return capture_ != nullptr; }
  bool has_result() const { return result_ != nullptr; }
  const DetectionResult* result() const { return result_.get(); }
  const Capture* capture() const { return capture_.get(); }
  const Detector* result_detector() const { return result_detector_.get(); }
  bool has_pending_work() const { return !pending_.empty(); }
  ImageView* image_view() const { return image_; }
  DetectionOptionsForm* options_form() const { return options_; }
  QTableWidget* table() const { return table_; }
  QCheckBox* overlay_toggle(int index) const { return toggles_[index]; }  // pipeline order
  int frame_in_form() const;
  // The BOP frame's ground-truth instances against the template set's envelope (empty without
  // ground truth or templates).
  const std::vector<GroundTruthCoverage>& ground_truth_coverage() const { return coverage_; }

 public slots:
  void OpenBopFrameDialog();
  void OpenCaptureFilesDialog();
  // The BOP folder, scene and frame of the form (Enter in any of them, "Load frame").
  void LoadFrameFromForm();
  void NextFrame() { StepFrame(1); }
  void PreviousFrame() { StepFrame(-1); }

 signals:
  void CaptureOpened();
  void DetectionFinished();
  // ground_truth_coverage() changed (another frame or template set).
  void CoverageChanged();
  // Whether Detect and frame stepping are possible may have changed.
  void StateChanged();
  void OpenArchiveRequested();
  // A detection row was double-clicked: show it in the 3D view.
  void DetectionActivated(int index);

 private:
  QWidget* BuildCaptureBox();
  QWidget* BuildDetectBox();
  QWidget* BuildOverlayBox();
  QWidget* BuildControls();
  QWidget* BuildResultsArea();
  void RunWhenFree(std::function<bool()> start);
  void RunPending();
  bool StartLoad(const CaptureSource& source);
  bool StartDetect();
  void ShowCapture(const CaptureSource& source, std::shared_ptr<const Capture> capture,
                   LoadedCapture loaded);
  void UpdateCoverage();
  void ShowResult(std::shared_ptr<const Detector> detector,
                  std::shared_ptr<const DetectionResult> result);
  void OnArchiveChanged();
  void RefreshImage();
  void UpdateLegend();
  void UpdateState();
  QString ArchiveText() const;

  StudioSession* session_ = nullptr;
  JobRunner* runner_ = nullptr;
  std::vector<std::function<bool()>> pending_;
  CaptureSource source_;
  std::vector<int> frame_ids_;                                // of the loaded BOP scene
  std::vector<BopGroundTruth> ground_truth_;                  // of the loaded BOP frame
  std::shared_ptr<const TemplateArchive> envelopes_archive_;  // what envelopes_ describes
  ObjectEnvelopes envelopes_;
  std::vector<GroundTruthCoverage> coverage_;
  // The capture to load next; a newer request replaces it (fast frame stepping loads the last).
  std::optional<CaptureSource> queued_capture_;
  std::shared_ptr<const Capture> capture_;
  // The detector is built once per template set; its archive copy outlives session changes.
  std::shared_ptr<const TemplateArchive> detector_archive_;
  std::shared_ptr<const Detector> detector_;
  std::shared_ptr<const Detector> result_detector_;
  std::shared_ptr<const DetectionResult> result_;

  QLineEdit* bop_dir_ = nullptr;
  QSpinBox* scene_ = nullptr;
  QSpinBox* frame_ = nullptr;
  QLabel* capture_label_ = nullptr;
  QLabel* archive_label_ = nullptr;
  QLabel* coverage_label_ = nullptr;
  DetectionOptionsForm* options_ = nullptr;
  QCheckBox* detect_on_load_ = nullptr;
  QPushButton* detect_ = nullptr;
  QCheckBox* toggles_[4] = {};
  QLabel* legend_ = nullptr;
  ImageView* image_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* timings_ = nullptr;
};

}  // namespace layermod::ui
