// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QWidget>
#include <cstdint>

class QLineEdit;
class QSpinBox;

namespace layermod::ui {

// The object id from a mesh file name, BOP style: the digits that end the name's stem
// ("obj_000008.ply" -> 8, "part12.stl" -> 12); 1 when the stem does not end in digits.
std::int32_t ObjectIdFromFileName(const QString& path);

// The object a training run describes: its id (the BOP obj_id detections and ground truth are
// matched by) and its name, both written into the archive. Defaulted from the mesh file name.
class ObjectForm : public QWidget {
  Q_OBJECT

 public:
  explicit ObjectForm(QWidget* parent = nullptr);

  std::int32_t obj_id() const;
  QString name() const;
  void SetObject(std::int32_t obj_id, const QString& name);
  // Id and name from `mesh_path`, unless the form already holds the defaults of that same file
  // (a reload keeps what the user typed).
  void DefaultFromMesh(const QString& mesh_path);

 signals:
  void Changed();

 private:
  QSpinBox* id_ = nullptr;
  QLineEdit* name_ = nullptr;
  QString defaulted_from_;
};

}  // namespace layermod::ui
