// SPDX-License-Identifier: MIT
#include "ui/views/object_form.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QSpinBox>
#include <limits>

namespace layermod::ui {

std::int32_t ObjectIdFromFileName(const QString& path) {
  static const QRegularExpression trailing_digits(QStringLiteral("(\\d+)$"));
  const QRegularExpressionMatch match = trailing_digits.match(QFileInfo(path).completeBaseName());
  if (!match.hasMatch()) return 1;
  bool ok = false;
  const qlonglong id = match.captured(1).toLongLong(&ok);
  if (!ok || id > std::numeric_limits<std::int32_t>::max()) return 1;
  return static_cast<std::int32_t>(id);
}

ObjectForm::ObjectForm(QWidget* parent) : QWidget(parent), id_(new QSpinBox), name_(new QLineEdit) {
  id_->setObjectName("objIdBox");
  id_->setRange(0, std::numeric_limits<std::int32_t>::max());
  id_->setValue(1);
  id_->setToolTip(
      tr("BOP object id: detections and ground truth are matched by it (obj_000008.ply: 8)"));
  name_->setObjectName("objNameEdit");
  name_->setToolTip(tr("Name shown with each detection"));
  // One row: the id is short, the name takes the rest.
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(new QLabel(tr("Id")));
  row->addWidget(id_);
  row->addWidget(new QLabel(tr("Name")));
  row->addWidget(name_, 1);
  connect(id_, qOverload<int>(&QSpinBox::valueChanged), this, &ObjectForm::Changed);
  connect(name_, &QLineEdit::textChanged, this, &ObjectForm::Changed);
}

std::int32_t ObjectForm::obj_id() const { return id_->value(); }

QString ObjectForm::name() const { return name_->text().trimmed(); }

void ObjectForm::SetObject(std::int32_t obj_id, const QString& name) {
  {
    const QSignalBlocker id_blocker(id_);
    const QSignalBlocker name_blocker(name_);
    id_->setValue(obj_id);
    name_->setText(name);
  }
  emit Changed();
}

void ObjectForm::DefaultFromMesh(const QString& mesh_path) {
  const QString absolute = QFileInfo(mesh_path).absoluteFilePath();
  if (absolute == defaulted_from_) return;
  defaulted_from_ = absolute;
  SetObject(ObjectIdFromFileName(mesh_path), QFileInfo(mesh_path).completeBaseName());
}

}  // namespace layermod::ui
