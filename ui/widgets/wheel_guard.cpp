// SPDX-License-Identifier: MIT
#include "ui/widgets/wheel_guard.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>

namespace layermod::ui {
namespace {

QWidget* GuardedBox(QObject* object) {
  if (auto* spin = qobject_cast<QAbstractSpinBox*>(object)) return spin;
  if (auto* combo = qobject_cast<QComboBox*>(object)) return combo;
  return nullptr;
}

}  // namespace

void WheelGuard::Install() {
  static WheelGuard* guard = nullptr;
  if (guard != nullptr || qApp == nullptr) return;
  guard = new WheelGuard(qApp);
  qApp->installEventFilter(guard);
  // Boxes that already exist were polished before the guard could see them.
  for (QWidget* widget : QApplication::allWidgets()) {
    if (QWidget* box = GuardedBox(widget)) box->setFocusPolicy(Qt::StrongFocus);
  }
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
  QWidget* box = GuardedBox(watched);
  if (box == nullptr) return false;
  if (event->type() == QEvent::Polish) {
    // Qt::WheelFocus (the boxes' default) would focus them on the first wheel step.
    box->setFocusPolicy(Qt::StrongFocus);
    return false;
  }
  if (event->type() != QEvent::Wheel || box->hasFocus()) return false;
  // Filtered but not accepted: QApplication hands the wheel on to the parent widgets.
  event->ignore();
  return true;
}

}  // namespace layermod::ui
