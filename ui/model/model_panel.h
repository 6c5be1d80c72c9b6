// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

#include "geometry/units.h"

class QComboBox;
class QLabel;
class QPushButton;

namespace layermod::ui {

class JobRunner;
class StudioSession;

// The model: open a mesh, choose its units, read its sphere and size, fix its origin.
class ModelPanel : public QWidget {
  Q_OBJECT

 public:
  ModelPanel(StudioSession* session, JobRunner* runner, QWidget* parent = nullptr);

  // Loads `path` on the worker thread with the selected units. False while another job runs.
  bool OpenMesh(const QString& path);
  LengthUnit units() const;
  void SetUnits(LengthUnit units);  // without reloading

 public slots:
  void Recentre();

 signals:
  void MeshOpened(const QString& path);
  void OpenRequested();  // the panel's "Open mesh…" button

 private:
  void OnUnitsChanged();
  void ShowModel();

  StudioSession* session_ = nullptr;
  JobRunner* runner_ = nullptr;
  QLabel* file_ = nullptr;
  QComboBox* units_ = nullptr;
  QLabel* radius_ = nullptr;
  QLabel* diameter_ = nullptr;
  QLabel* centre_ = nullptr;
  QLabel* counts_ = nullptr;
  QLabel* bbox_ = nullptr;
  QLabel* colours_ = nullptr;
  QLabel* warnings_ = nullptr;
  QPushButton* recentre_ = nullptr;
};

}  // namespace layermod::ui
