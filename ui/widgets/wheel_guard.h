// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>

namespace layermod::ui {

// Application-wide: a spin box or combo box changes on the mouse wheel only when it has the
// keyboard focus; otherwise the wheel scrolls whatever holds it (the dock's scroll area), so
// scrolling a form never edits the fields the pointer passes over. Such boxes also stop taking
// the focus from the wheel (Qt::StrongFocus): a click or Tab focuses them.
class WheelGuard : public QObject {
  Q_OBJECT

 public:
  // Installs the guard on the application once; later calls do nothing.
  static void Install();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  using QObject::QObject;
};

}  // namespace layermod::ui
