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
      blocks_(new QSpinBox) {
  mode_->setObjectName("detectionMode");
  threshold_->setObjectName("detectionThreshold");
  instances_->setObjectName("detectionInstances");
  blocks_->setObjectName("detectionBlocks");
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
  auto* layout = new QFormLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addRow(tr("Mode"), mode_);
  layout->addRow(tr("Threshold"), threshold_);
  layout->addRow(tr("Instances"), instances_);
  layout->addRow(tr("Blocks kept"), blocks_);
  SetOptions(DetectorOptions{});
}

DetectorOptions DetectionOptionsForm::options() const {
  DetectorOptions options;
  options.mode = kModes[std::max(0, mode_->currentIndex())];
  options.match.threshold_percent = static_cast<float>(threshold_->value());
  options.max_instances = instances_->value();
  options.coarse.max_blocks = blocks_->value();
  return options;
}

void DetectionOptionsForm::SetOptions(const DetectorOptions& options) {
  for (int i = 0; i < static_cast<int>(std::size(kModes)); ++i) {
    if (kModes[i] == options.mode) mode_->setCurrentIndex(i);
  }
  threshold_->setValue(options.match.threshold_percent);
  instances_->setValue(options.max_instances);
  blocks_->setValue(options.coarse.max_blocks);
}

void DetectionOptionsForm::SaveSettings() const {
  QSettings settings;
  settings.setValue("detection/mode", mode_->currentIndex());
  settings.setValue("detection/threshold", threshold_->value());
  settings.setValue("detection/instances", instances_->value());
  settings.setValue("detection/blocks", blocks_->value());
}

void DetectionOptionsForm::RestoreSettings() {
  QSettings settings;
  if (!settings.contains("detection/mode")) return;
  mode_->setCurrentIndex(settings.value("detection/mode").toInt());
  threshold_->setValue(settings.value("detection/threshold").toDouble());
  instances_->setValue(settings.value("detection/instances").toInt());
  blocks_->setValue(settings.value("detection/blocks").toInt());
}

}  // namespace layermod::ui
