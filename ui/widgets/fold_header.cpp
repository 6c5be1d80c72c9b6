// SPDX-License-Identifier: MIT
#include "ui/widgets/fold_header.h"

#include <QToolButton>

namespace layermod::ui {

QToolButton* MakeFoldHeader(QWidget* body, bool open) {
  auto* header = new QToolButton;
  header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  header->setAutoRaise(true);
  header->setCheckable(true);
  header->setChecked(open);
  header->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
  body->setVisible(open);
  QObject::connect(header, &QToolButton::toggled, body, [header, body](bool shown) {
    header->setArrowType(shown ? Qt::DownArrow : Qt::RightArrow);
    body->setVisible(shown);
  });
  return header;
}

}  // namespace layermod::ui
