// SPDX-License-Identifier: MIT
#pragma once

#include <QImage>
#include <QWidget>

namespace layermod::ui {

// Shows one image scaled to fit, aspect kept, centred on a dark background.
class ImageView : public QWidget {
  Q_OBJECT

 public:
  explicit ImageView(QWidget* parent = nullptr);

  void SetImage(const QImage& image);
  const QImage& image() const { return image_; }
  QSize sizeHint() const override { return {640, 480}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QImage image_;
};

}  // namespace layermod::ui
