// SPDX-License-Identifier: MIT
#pragma once

class QToolButton;
class QWidget;

namespace layermod::ui {

// A flat header button with an arrow that shows and hides `body` (folded: right arrow, open: down
// arrow). The caller sets its text and places both in a layout.
QToolButton* MakeFoldHeader(QWidget* body, bool open);

}  // namespace layermod::ui
