// SPDX-License-Identifier: MIT
#include "ui/recent_files.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace layermod::ui {
namespace {

constexpr char kSettingsKey[] = "recentFiles";

}  // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent)
    : QObject(parent), menu_(menu), files_(QSettings().value(kSettingsKey).toStringList()) {
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
    QAction* action =
        menu_->addAction(QStringLiteral("&%1  %2").arg(i + 1).arg(QFileInfo(path).fileName()));
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
