// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

#include "ui/detection/capture_source.h"

class QDialogButtonBox;
class QGridLayout;
class QLabel;
class QLineEdit;

namespace layermod::ui {

// One dialog for a capture given as files: colour image, optional 16-bit depth PNG (mm) and BOP
// camera.json. Starts with the last trio used (QSettings) and remembers the accepted one.
class CaptureDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CaptureDialog(QWidget* parent = nullptr);

  CaptureSource source() const;
  void SetFiles(const QString& color, const QString& depth, const QString& camera);
  // Saves the trio for the next time (called on accept).
  void RememberFiles() const;

 private:
  QLineEdit* AddRow(QGridLayout* grid, int row, const QString& label, const char* name,
                    const QString& kind, const QString& filter);
  void Validate();

  QLineEdit* color_ = nullptr;
  QLineEdit* depth_ = nullptr;
  QLineEdit* camera_ = nullptr;
  QLabel* problem_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace layermod::ui
