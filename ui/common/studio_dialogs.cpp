// SPDX-License-Identifier: MIT
#include "ui/common/studio_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <cstdio>

#include "ui/common/studio_session.h"

namespace layermod::ui {
namespace {

bool batch_mode = false;
int batch_errors = 0;

QString LastDirKey(const QString& kind) { return QStringLiteral("dirs/") + kind; }

QString LastDir(const QString& kind) {
  return QSettings().value(LastDirKey(kind), QDir::homePath()).toString();
}

void RememberDir(const QString& kind, const QString& path) {
  if (!path.isEmpty()) QSettings().setValue(LastDirKey(kind), QFileInfo(path).absolutePath());
}

}  // namespace

void SetBatchMode(bool batch) { batch_mode = batch; }
bool BatchMode() { return batch_mode; }
int BatchErrorCount() { return batch_errors; }

void ShowError(QWidget* parent, const QString& action, const QString& message) {
  if (batch_mode) {
    ++batch_errors;
    std::fprintf(stderr, "layermod-studio: %s failed: %s\n", qUtf8Printable(action),
                 qUtf8Printable(message));
    return;
  }
  QMessageBox box(QMessageBox::Critical, QObject::tr("LayerMOD Studio"),
                  QObject::tr("%1 failed.").arg(action), QMessageBox::Ok, parent);
  box.setObjectName("errorDialog");
  box.setInformativeText(message);
  box.exec();
}

bool ConfirmDiscardUnsaved(QWidget* parent, const StudioSession& session) {
  if (!session.archive_unsaved() || batch_mode) return true;
  if (qEnvironmentVariable(kDiscardWithoutAskingEnv) == QLatin1String("1")) return true;
  const auto count = session.archive() ? session.archive()->templates().size() : 0;
  QMessageBox box(QMessageBox::Warning, QObject::tr("LayerMOD Studio"),
                  QObject::tr("The trained set of %1 templates has not been exported.").arg(count),
                  QMessageBox::Discard | QMessageBox::Cancel, parent);
  box.setObjectName("discardDialog");
  box.setInformativeText(QObject::tr("Discard it?"));
  box.setDefaultButton(QMessageBox::Cancel);
  return box.exec() == QMessageBox::Discard;
}

bool ConfirmExportStale(QWidget* parent) {
  if (batch_mode || qEnvironmentVariable(kDiscardWithoutAskingEnv) == QLatin1String("1")) {
    return true;
  }
  QMessageBox box(QMessageBox::Warning, QObject::tr("LayerMOD Studio"),
                  QObject::tr("The form has changed since this template set was made."),
                  QMessageBox::Save | QMessageBox::Cancel, parent);
  box.setObjectName("exportStaleDialog");
  box.setInformativeText(
      QObject::tr("Export writes the set as it was made, not the form's values. Train again to "
                  "apply the form. Export anyway?"));
  box.button(QMessageBox::Save)->setText(QObject::tr("Export as made"));
  box.setDefaultButton(QMessageBox::Cancel);
  return box.exec() == QMessageBox::Save;
}

QString AskOpenPath(QWidget* parent, const QString& kind, const QString& title,
                    const QString& filter) {
  QString path = QFileDialog::getOpenFileName(parent, title, LastDir(kind), filter);
  RememberDir(kind, path);
  return path;
}

QString AskSavePath(QWidget* parent, const QString& kind, const QString& title,
                    const QString& filter, const QString& suggested_name) {
  const QString start = QDir(LastDir(kind)).filePath(suggested_name);
  QString path = QFileDialog::getSaveFileName(parent, title, start, filter);
  RememberDir(kind, path);
  return path;
}

QString MeshFileFilter() {
  return QObject::tr(
      "Meshes (*.ply *.stl *.obj *.off *.gltf *.glb *.fbx *.dae *.3ds);;"
      "All files (*)");
}

QString ArchiveFileFilter() { return QObject::tr("LayerMOD archives (*.layermod)"); }

QString JsonFileFilter() { return QObject::tr("JSON files (*.json);;All files (*)"); }

}  // namespace layermod::ui
