// SPDX-License-Identifier: MIT
#include "ui/detection/capture_dialog.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

#include "ui/common/studio_dialogs.h"

namespace layermod::ui {
namespace {

QString ImageFilter() {
  return QObject::tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr);;All files (*)");
}

}  // namespace

CaptureDialog::CaptureDialog(QWidget* parent)
    : QDialog(parent),
      problem_(new QLabel),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel)) {
  setObjectName("captureDialog");
  setWindowTitle(tr("Open capture"));
  auto* grid = new QGridLayout;
  color_ = AddRow(grid, 0, tr("Colour image"), "captureColorEdit", "capture", ImageFilter());
  depth_ = AddRow(grid, 1, tr("Depth (16-bit PNG, mm; optional)"), "captureDepthEdit", "capture",
                  ImageFilter());
  camera_ = AddRow(grid, 2, tr("Camera (BOP camera.json)"), "captureCameraEdit", "camera",
                   JsonFileFilter());
  problem_->setObjectName("captureProblem");
  problem_->setStyleSheet("QLabel { color: #b00020; }");
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(grid);
  layout->addWidget(problem_);
  layout->addWidget(buttons_);
  connect(buttons_, &QDialogButtonBox::accepted, this, [this] {
    RememberFiles();
    accept();
  });
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  const QSettings settings;
  SetFiles(settings.value("capture/color").toString(), settings.value("capture/depth").toString(),
           settings.value("capture/camera").toString());
  resize(640, sizeHint().height());
}

QLineEdit* CaptureDialog::AddRow(QGridLayout* grid, int row, const QString& label, const char* name,
                                 const QString& kind, const QString& filter) {
  auto* edit = new QLineEdit;
  edit->setObjectName(name);
  auto* browse = new QPushButton(tr("Browse…"));
  grid->addWidget(new QLabel(label), row, 0);
  grid->addWidget(edit, row, 1);
  grid->addWidget(browse, row, 2);
  connect(edit, &QLineEdit::textChanged, this, &CaptureDialog::Validate);
  connect(browse, &QPushButton::clicked, this, [this, edit, label, kind, filter] {
    const QString path = AskOpenPath(this, kind, label, filter);
    if (!path.isEmpty()) edit->setText(path);
  });
  return edit;
}

CaptureSource CaptureDialog::source() const {
  return {{}, 0, 0, color_->text().trimmed(), depth_->text().trimmed(), camera_->text().trimmed()};
}

void CaptureDialog::SetFiles(const QString& color, const QString& depth, const QString& camera) {
  color_->setText(color);
  depth_->setText(depth);
  camera_->setText(camera);
  Validate();
}

void CaptureDialog::RememberFiles() const {
  QSettings settings;
  const CaptureSource files = source();
  settings.setValue("capture/color", files.color);
  settings.setValue("capture/depth", files.depth);
  settings.setValue("capture/camera", files.camera);
}

void CaptureDialog::Validate() {
  const CaptureSource files = source();
  QString problem;
  if (files.color.isEmpty()) {
    problem = tr("Choose the colour image.");
  } else if (!QFileInfo::exists(files.color)) {
    problem = tr("No colour image at “%1”.").arg(files.color);
  } else if (!files.depth.isEmpty() && !QFileInfo::exists(files.depth)) {
    problem =
        tr("No depth image at “%1” (leave empty for colour-only detection).").arg(files.depth);
  } else if (files.camera.isEmpty()) {
    problem = tr("Choose the camera file.");
  } else if (!QFileInfo::exists(files.camera)) {
    problem = tr("No camera file at “%1”.").arg(files.camera);
  }
  problem_->setText(problem);
  problem_->setVisible(!problem.isEmpty());
  buttons_->button(QDialogButtonBox::Open)->setEnabled(problem.isEmpty());
}

}  // namespace layermod::ui
