// SPDX-License-Identifier: MIT
#include "ui/views/camera_form.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <exception>

#include "ui/common/studio_dialogs.h"

namespace layermod::ui {
namespace {

// Two columns of boxes must fit a ~370 px dock.
constexpr int kBoxMinWidthPx = 70;

QDoubleSpinBox* PixelBox(const char* name) {
  auto* box = new QDoubleSpinBox;
  box->setObjectName(name);
  box->setRange(0.0, 100000.0);
  box->setDecimals(2);
  box->setSuffix(" px");
  box->setMinimumWidth(kBoxMinWidthPx);
  return box;
}

QSpinBox* SizeBox(const char* name) {
  auto* box = new QSpinBox;
  box->setObjectName(name);
  box->setRange(1, 16384);
  box->setSuffix(" px");
  box->setMinimumWidth(kBoxMinWidthPx);
  return box;
}

// The sample capture's camera (resources/sample/camera.json), a Kinect-like VGA sensor.
PinholeCamera DefaultCamera() { return {572.0, 572.0, 319.5, 239.5, 640, 480}; }

}  // namespace

CameraForm::CameraForm(QWidget* parent)
    : QWidget(parent),
      fx_(PixelBox("fxBox")),
      fy_(PixelBox("fyBox")),
      cx_(PixelBox("cxBox")),
      cy_(PixelBox("cyBox")),
      width_(SizeBox("widthBox")),
      height_(SizeBox("heightBox")) {
  auto* load = new QPushButton(tr("Load BOP camera.json…"));
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(new QLabel("fx"), 0, 0);
  grid->addWidget(fx_, 0, 1);
  grid->addWidget(new QLabel("fy"), 0, 2);
  grid->addWidget(fy_, 0, 3);
  grid->addWidget(new QLabel("cx"), 1, 0);
  grid->addWidget(cx_, 1, 1);
  grid->addWidget(new QLabel("cy"), 1, 2);
  grid->addWidget(cy_, 1, 3);
  grid->addWidget(new QLabel(tr("width")), 2, 0);
  grid->addWidget(width_, 2, 1);
  grid->addWidget(new QLabel(tr("height")), 2, 2);
  grid->addWidget(height_, 2, 3);
  grid->addWidget(load, 3, 0, 1, 4);
  SetCamera(DefaultCamera());

  for (QDoubleSpinBox* box : {fx_, fy_, cx_, cy_}) {
    connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &CameraForm::Changed);
  }
  for (QSpinBox* box : {width_, height_}) {
    connect(box, qOverload<int>(&QSpinBox::valueChanged), this, &CameraForm::Changed);
  }
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = AskOpenPath(this, "camera", tr("Load camera"), JsonFileFilter());
    if (!path.isEmpty()) LoadCameraFile(path);
  });
}

PinholeCamera CameraForm::camera() const {
  return {fx_->value(), fy_->value(),    cx_->value(),
          cy_->value(), width_->value(), height_->value()};
}

void CameraForm::SetCamera(const PinholeCamera& camera) {
  {
    const QSignalBlocker blockers[] = {QSignalBlocker(fx_),    QSignalBlocker(fy_),
                                       QSignalBlocker(cx_),    QSignalBlocker(cy_),
                                       QSignalBlocker(width_), QSignalBlocker(height_)};
    fx_->setValue(camera.fx);
    fy_->setValue(camera.fy);
    cx_->setValue(camera.cx);
    cy_->setValue(camera.cy);
    width_->setValue(camera.width);
    height_->setValue(camera.height);
  }
  emit Changed();
}

bool CameraForm::LoadCameraFile(const QString& path) {
  try {
    SetCamera(LoadCameraJson(path.toStdString()));
    return true;
  } catch (const std::exception& error) {
    ShowError(this, tr("Load camera “%1”").arg(path), QString::fromStdString(error.what()));
    return false;
  }
}

}  // namespace layermod::ui
