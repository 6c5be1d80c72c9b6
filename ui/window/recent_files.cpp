// SPDX-License-Identifier: MIT
#include "ui/window/recent_files.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace layermod::ui {
namespace {

constexpr char kSettingsKey[] = "recentFiles";
constexpr int kMaxShownChars = 90;

// The whole path, its middle elided when very long (the tooltip keeps all of it).
QString ShownPath(const QString& path) {
  if (path.size() <= kMaxShownChars) return path;
  const int keep = (kMaxShownChars - 1) / 2;
  return path.left(keep) + QStringLiteral("…") + path.right(keep);
}

}  // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent)
    : QObject(parent), menu_(menu), files_(QSettings().value(kSettingsKey).toStringList()) {
  menu_->setToolTipsVisible(true);
  Rebuild();
}

void RecentFiles::Add(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files_.removeAll(absolute);
  files_.prepend(absolute);
  while (files_.size() > kMaxFiles) files_.removeLast();
  QSettings().setValue(kSettingsKey, files_);
  Rebuild();
}

void RecentFiles::Rebuild() {
  menu_->clear();
  for (int i = 0; i < files_.size(); ++i) {
    const QString path = files_[i];
    QAction* action = menu_->addAction(QStringLiteral("&%1  %2").arg(i + 1).arg(ShownPath(path)));
    action->setToolTip(path);
    action->setStatusTip(path);
    connect(action, &QAction::triggered, this, [this, path] { emit OpenRequested(path); });
  }
  if (files_.isEmpty()) menu_->addAction(tr("(none)"))->setEnabled(false);
  menu_->addSeparator();
  QAction* clear = menu_->addAction(tr("Clear list"));
  clear->setEnabled(!files_.isEmpty());
  connect(clear, &QAction::triggered, this, [this] {
    files_.clear();
    QSettings().setValue(kSettingsKey, files_);
    Rebuild();
  });
}

}  // namespace layermod::ui
