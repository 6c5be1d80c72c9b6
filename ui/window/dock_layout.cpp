// SPDX-License-Identifier: MIT
#include "ui/window/dock_layout.h"

#include <QDockWidget>
#include <QMainWindow>
#include <algorithm>

namespace layermod::ui {
namespace {

// The central view keeps at least this much when collapsed docks are given room again.
constexpr int kCentralMinPx = 360;

bool IsSide(Qt::DockWidgetArea area) {
  return area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea;
}

}  // namespace

DockLayout::DockLayout(QMainWindow* window) : QObject(window), window_(window) {
  window_->setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  window_->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
}

void DockLayout::Add(QDockWidget* dock, Qt::DockWidgetArea area, double fraction, int max_px) {
  entries_.push_back({dock, area, fraction, max_px});
  window_->addDockWidget(area, dock);
}

void DockLayout::Tabify(QDockWidget* with, QDockWidget* dock) {
  const Entry* first = Find(with);
  if (first == nullptr) return;
  entries_.push_back({dock, first->area, first->fraction, first->max_px, with});
  window_->addDockWidget(first->area, dock);
  window_->tabifyDockWidget(with, dock);
  with->raise();
}

const DockLayout::Entry* DockLayout::Find(const QDockWidget* dock) const {
  for (const Entry& entry : entries_) {
    if (entry.dock == dock) return &entry;
  }
  return nullptr;
}

int DockLayout::DefaultSize(const QDockWidget* dock, QSize window_size) const {
  const Entry* entry = Find(dock);
  if (entry == nullptr) return 0;
  const int extent = IsSide(entry->area) ? window_size.width() : window_size.height();
  return std::min(entry->max_px, static_cast<int>(entry->fraction * extent));
}

void DockLayout::SetPreviewShown(bool shown) {
  if (shown) {
    if (!hidden_for_preview_.isEmpty()) return;
    for (const Entry& entry : entries_) {
      if (entry.dock->isVisible() && !entry.dock->isFloating()) {
        hidden_for_preview_ << entry.dock;
        entry.dock->hide();
      }
    }
    return;
  }
  for (const QPointer<QDockWidget>& dock : hidden_for_preview_) {
    if (dock != nullptr) dock->show();
  }
  hidden_for_preview_.clear();
}

void DockLayout::Reset() {
  hidden_for_preview_.clear();
  for (const Entry& entry : entries_) {
    entry.dock->setFloating(false);
    if (entry.tab_of == nullptr) window_->addDockWidget(entry.area, entry.dock);
    entry.dock->show();
  }
  for (const Entry& entry : entries_) {
    if (entry.tab_of != nullptr) window_->tabifyDockWidget(entry.tab_of, entry.dock);
  }
  for (const Entry& entry : entries_) {
    if (entry.tab_of != nullptr) entry.tab_of->raise();
  }
  ResizeAll(false);
}

void DockLayout::RestoreCollapsed() { ResizeAll(true); }

void DockLayout::ResizeAll(bool only_collapsed) {
  QList<QDockWidget*> side_docks;
  QList<int> side_sizes;
  QList<QDockWidget*> bottom_docks;
  QList<int> bottom_sizes;
  int side_growth = 0;
  const QWidget* central = window_->centralWidget();
  for (const Entry& entry : entries_) {
    QDockWidget* dock = entry.dock;
    if (dock->isFloating() || dock->isHidden() || entry.tab_of != nullptr) continue;
    const Qt::DockWidgetArea area = window_->dockWidgetArea(dock);
    const bool side = IsSide(area);
    const int target = DefaultSize(dock, window_->size());
    const int current = side ? dock->width() : dock->height();
    if (only_collapsed && current >= target) continue;
    if (side) {
      side_growth += std::max(0, target - current);
      side_docks << dock;
      side_sizes << target;
    } else {
      bottom_docks << dock;
      bottom_sizes << target;
    }
  }
  // Growing the side docks must leave the central view usable; else wait for a wider window.
  if (only_collapsed && central != nullptr && central->width() - side_growth < kCentralMinPx) {
    side_docks.clear();
  }
  if (!side_docks.isEmpty()) window_->resizeDocks(side_docks, side_sizes, Qt::Horizontal);
  if (!bottom_docks.isEmpty()) window_->resizeDocks(bottom_docks, bottom_sizes, Qt::Vertical);
}

}  // namespace layermod::ui
