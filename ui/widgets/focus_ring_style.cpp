// SPDX-License-Identifier: MIT
#include "ui/widgets/focus_ring_style.h"

#include <QPainter>
#include <QStyleFactory>
#include <QStyleOption>

namespace layermod::ui {
namespace {

constexpr int kRingWidthPx = 2;

void DrawRing(const QStyleOption& option, QPainter* painter) {
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setBrush(Qt::NoBrush);
  painter->setPen(QPen(option.palette.color(QPalette::Highlight), kRingWidthPx));
  const int inset = kRingWidthPx / 2;
  painter->drawRoundedRect(QRectF(option.rect).adjusted(inset, inset, -inset, -inset), 2.5, 2.5);
  painter->restore();
}

bool HasFocus(const QStyleOption& option) {
  return (option.state & QStyle::State_HasFocus) && (option.state & QStyle::State_Enabled);
}

}  // namespace

FocusRingStyle::FocusRingStyle() : QProxyStyle(QStyleFactory::create("Fusion")) {}

void FocusRingStyle::drawPrimitive(PrimitiveElement element, const QStyleOption* option,
                                   QPainter* painter, const QWidget* widget) const {
  if (element == PE_FrameFocusRect) {
    // Buttons, check boxes, tabs and item views: the ring replaces the style's own.
    DrawRing(*option, painter);
    return;
  }
  QProxyStyle::drawPrimitive(element, option, painter, widget);
  if ((element == PE_FrameLineEdit || element == PE_PanelButtonCommand) && HasFocus(*option)) {
    DrawRing(*option, painter);
  }
}

void FocusRingStyle::drawComplexControl(ComplexControl control, const QStyleOptionComplex* option,
                                        QPainter* painter, const QWidget* widget) const {
  QProxyStyle::drawComplexControl(control, option, painter, widget);
  if ((control == CC_SpinBox || control == CC_ComboBox) && HasFocus(*option)) {
    DrawRing(*option, painter);
  }
}

}  // namespace layermod::ui
