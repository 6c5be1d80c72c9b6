// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

class QMenu;

namespace layermod::ui {

// The File ▸ Recent files menu, persisted in QSettings (most recent first).
class RecentFiles : public QObject {
  Q_OBJECT

 public:
  static constexpr int kMaxFiles = 10;
  RecentFiles(QMenu* menu, QObject* parent = nullptr);

  void Add(const QString& path);
  const QStringList& files() const { return files_; }

 signals:
  void OpenRequested(const QString& path);

 private:
  void Rebuild();

  QMenu* menu_ = nullptr;
  QStringList files_;
};

}  // namespace layermod::ui
