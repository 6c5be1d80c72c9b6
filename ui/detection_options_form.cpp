// SPDX-License-Identifier: MIT
#include "ui/detection_options_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSettings>
#include <QSpinBox>

namespace layermod::ui {
namespace {

constexpr DetectionMode kModes[] = {DetectionMode::kScenePatch, DetectionMode::kExhaustive,
                                    DetectionMode::kColorOnly};

}  // namespace

DetectionOptionsForm::DetectionOptionsForm(QWidget* parent)
    : QWidget(parent),
      mode_(new QComboBox),
      threshold_(new QDoubleSpinBox),
      instances_(new QSpinBox),
      blocks_(new QSpinBox),
      edge_upper_(new QDoubleSpinBox),
      refinements_(new QSpinBox) {
  mode_->setObjectName("detectionMode");
  threshold_->setObjectName("detectionThreshold");
  instances_->setObjectName("detectionInstances");
  blocks_->setObjectName("detectionBlocks");
  edge_upper_->setObjectName("detectionEdgeUpper");
  refinements_->setObjectName("detectionRefinements");
  for (DetectionMode mode : kModes) {
    mode_->addItem(
        QString::fromUtf8(ModeName(mode).data(), static_cast<int>(ModeName(mode).size())));
  }
  mode_->setToolTip(
      tr("scene-patch: regions, coarse positioning, then the block's layer; "
         "exhaustive: every template everywhere; color-only: no depth"));
  threshold_->setRange(1.0, 100.0);
  threshold_->setDecimals(1);
  threshold_->setSuffix(QStringLiteral(" %"));
  instances_->setRange(1, 50);
  blocks_->setRange(0, 100);
  blocks_->setSpecialValueText(tr("all"));
  edge_upper_->setRange(0.8, 100.0);
  edge_upper_->setDecimals(2);
  edge_upper_->setSingleStep(0.1);
  edge_upper_->setSuffix(tr(" × N_max"));
  edge_upper_->setToolTip(
      tr("Coarse positioning keeps a point with at most this many times the layer's largest "
         "template depth-edge count (the paper uses 1.5)"));
  refinements_->setRange(1, 1000000);
  refinements_->setSingleStep(100);
  refinements_->setToolTip(
      tr("Top-level matches refined down the pyramid per object and frame, best first"));
  auto* layout = new QFormLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addRow(tr("Mode"), mode_);
  layout->addRow(tr("Threshold"), threshold_);
  layout->addRow(tr("Instances"), instances_);
  layout->addRow(tr("Blocks kept"), blocks_);
  layout->addRow(tr("Edge bound"), edge_upper_);
  layout->addRow(tr("Refinements"), refinements_);
  SetOptions(DetectorOptions{});
}

DetectorOptions DetectionOptionsForm::options() const {
  DetectorOptions options;
  options.mode = kModes[std::max(0, mode_->currentIndex())];
  options.match.threshold_percent = static_cast<float>(threshold_->value());
  options.max_instances = instances_->value();
  options.coarse.max_blocks = blocks_->value();
  options.coarse.upper_factor = static_cast<float>(edge_upper_->value());
  options.match.max_refinements = refinements_->value();
  return options;
}

void DetectionOptionsForm::SetOptions(const DetectorOptions& options) {
  for (int i = 0; i < static_cast<int>(std::size(kModes)); ++i) {
    if (kModes[i] == options.mode) mode_->setCurrentIndex(i);
  }
  threshold_->setValue(options.match.threshold_percent);
  instances_->setValue(options.max_instances);
  blocks_->setValue(options.coarse.max_blocks);
  edge_upper_->setValue(options.coarse.upper_factor);
  refinements_->setValue(options.match.max_refinements);
}

void DetectionOptionsForm::SaveSettings() const {
  QSettings settings;
  settings.setValue("detection/mode", mode_->currentIndex());
  settings.setValue("detection/threshold", threshold_->value());
  settings.setValue("detection/instances", instances_->value());
  settings.setValue("detection/blocks", blocks_->value());
  settings.setValue("detection/edge_upper", edge_upper_->value());
  settings.setValue("detection/refinements", refinements_->value());
}

void DetectionOptionsForm::RestoreSettings() {
  QSettings settings;
  if (!settings.contains("detection/mode")) return;
  mode_->setCurrentIndex(settings.value("detection/mode").toInt());
  threshold_->setValue(settings.value("detection/threshold").toDouble());
  instances_->setValue(settings.value("detection/instances").toInt());
  blocks_->setValue(settings.value("detection/blocks").toInt());
  // Settings saved before these fields existed keep the defaults.
  if (settings.contains("detection/edge_upper")) {
    edge_upper_->setValue(settings.value("detection/edge_upper").toDouble());
  }
  if (settings.contains("detection/refinements")) {
    refinements_->setValue(settings.value("detection/refinements").toInt());
  }
}

}  // namespace layermod::ui
