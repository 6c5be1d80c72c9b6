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

  StudioSession* session_;
  JobRunner* runner_;
  QLabel* file_;
  QComboBox* units_;
  QLabel* radius_;
  QLabel* diameter_;
  QLabel* centre_;
  QLabel* counts_;
  QLabel* bbox_;
  QLabel* colours_;
  QLabel* warnings_;
  QPushButton* recentre_;
};

}  // namespace layermod::ui
