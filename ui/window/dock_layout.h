// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>
#include <QSize>
#include <vector>

class QDockWidget;
class QMainWindow;

namespace layermod::ui {

// The studio's default dock arrangement, sized for the window: the side docks run the full
// height (the bottom dock sits under the central view only), so a 1280×800 screen shows every
// panel's main controls. Reset() puts every dock back; RestoreCollapsed() gives docks that a
// small window squeezed their size back once the window grows again. While the detection
// preview is shown, the authoring docks step aside (SetPreviewShown) so that the preview gets
// the whole window; they come back with the 3D view.
class DockLayout : public QObject {
  Q_OBJECT

 public:
  explicit DockLayout(QMainWindow* window);

  // `fraction` of the window's width (side areas) or height (bottom), at most `max_px`.
  void Add(QDockWidget* dock, Qt::DockWidgetArea area, double fraction, int max_px);
  // `dock` shares `with`'s place as a tab (added after `with`).
  void Tabify(QDockWidget* with, QDockWidget* dock);

  // The size a dock of this layout gets in a window of `window_size`.
  int DefaultSize(const QDockWidget* dock, QSize window_size) const;

 public slots:
  void Reset();
  void RestoreCollapsed();
  // True: hide the visible docks (remembered); false: show those again.
  void SetPreviewShown(bool shown);

 private:
  struct Entry {
    QDockWidget* dock = nullptr;
    Qt::DockWidgetArea area = Qt::LeftDockWidgetArea;
    double fraction = 0.0;
    int max_px = 0;
    QDockWidget* tab_of = nullptr;
  };
  const Entry* Find(const QDockWidget* dock) const;
  void ResizeAll(bool only_collapsed);

  QMainWindow* window_ = nullptr;
  std::vector<Entry> entries_;
  QList<QPointer<QDockWidget>> hidden_for_preview_;
};

}  // namespace layermod::ui
