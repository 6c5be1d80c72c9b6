// SPDX-License-Identifier: MIT
#pragma once

#include <QProxyStyle>

namespace layermod::ui {

// The platform style with a focus ring that is easy to see: a 2 px outline in the palette's
// highlight colour around the focused field, box or button (Fusion's own ring is a faint 1 px
// tint, hard to follow when working from the keyboard).
class FocusRingStyle : public QProxyStyle {
 public:
  FocusRingStyle();

  void drawPrimitive(PrimitiveElement element, const QStyleOption* option, QPainter* painter,
                     const QWidget* widget = nullptr) const override;
  void drawComplexControl(ComplexControl control, const QStyleOptionComplex* option,
                          QPainter* painter, const QWidget* widget = nullptr) const override;
};

}  // namespace layermod::ui
