// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

#include "pipeline/detector.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace layermod::ui {

// The detector settings the preview exposes (the same as `layermod detect`'s flags): mode,
// similarity threshold, instances per object, blocks kept by coarse positioning, the edge test's
// upper bound and the refinement budget.
class DetectionOptionsForm : public QWidget {
  Q_OBJECT

 public:
  explicit DetectionOptionsForm(QWidget* parent = nullptr);

  DetectorOptions options() const;
  void SetOptions(const DetectorOptions& options);
  void SaveSettings() const;
  void RestoreSettings();

 private:
  QComboBox* mode_;
  QDoubleSpinBox* threshold_;
  QSpinBox* instances_;
  QSpinBox* blocks_;
  QDoubleSpinBox* edge_upper_;
  QSpinBox* refinements_;
};

}  // namespace layermod::ui
