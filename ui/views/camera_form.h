// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

#include "geometry/camera.h"

class QDoubleSpinBox;
class QSpinBox;

namespace layermod::ui {

// The pinhole camera every template is rendered with: typed in, or read from a BOP camera.json.
class CameraForm : public QWidget {
  Q_OBJECT

 public:
  explicit CameraForm(QWidget* parent = nullptr);

  PinholeCamera camera() const;
  void SetCamera(const PinholeCamera& camera);
  // Reads a BOP camera file; shows an error box naming the file when it cannot.
  bool LoadCameraFile(const QString& path);

 signals:
  void Changed();

 private:
  QDoubleSpinBox* fx_ = nullptr;
  QDoubleSpinBox* fy_ = nullptr;
  QDoubleSpinBox* cx_ = nullptr;
  QDoubleSpinBox* cy_ = nullptr;
  QSpinBox* width_ = nullptr;
  QSpinBox* height_ = nullptr;
};

}  // namespace layermod::ui
