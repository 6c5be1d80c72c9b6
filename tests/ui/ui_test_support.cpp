// SPDX-License-Identifier: MIT
#include "ui_test_support.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>

#include "mesh/sample_part.h"

namespace layermod::ui::test {

QString ScratchDir() {
  static QTemporaryDir dir;
  return dir.path();
}

QString SampleMeshPath() {
  const QString bundled = QStringLiteral(LAYERMOD_SOURCE_DIR "/resources/sample/bracket.ply");
  if (QFileInfo::exists(bundled)) return bundled;
  const QString path = QDir(ScratchDir()).filePath("bracket.ply");
  if (!QFileInfo::exists(path)) SaveModelPly(path.toStdString(), MakeSampleBracket());
  return path;
}

QString OffCentreMeshPath() {
  const QString path = QDir(ScratchDir()).filePath("bracket_off_centre.ply");
  if (QFileInfo::exists(path)) return path;
  TriMesh mesh = MakeSampleBracket();
  for (const auto vertex : mesh.vertices()) mesh.point(vertex) += TriMesh::Point(200.0, 0.0, 0.0);
  SaveModelPly(path.toStdString(), mesh);
  return path;
}

TrainingProfile TinyProfile() {
  TrainingProfile profile;
  profile.depth_min_mm = 500.0;
  profile.depth_max_mm = 700.0;
  profile.views.azimuth = {0.0, 90.0, 270.0};
  profile.views.elevation = {30.0, 30.0, 60.0};
  profile.views.roll = {0.0, 10.0, 0.0};
  profile.views.even_spacing_deg = 0.0;
  return profile;
}

MessageBoxCloser::MessageBoxCloser(int button) : button_(button) {
  auto* timer = new QTimer(this);
  connect(timer, &QTimer::timeout, this, &MessageBoxCloser::Poll);
  timer->start(20);
}

void MessageBoxCloser::Poll() {
  if (seen_) return;
  auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
  if (box == nullptr) return;
  seen_ = true;
  object_name_ = box->objectName();
  text_ = box->text() + "\n" + box->informativeText();
  QAbstractButton* button = box->button(static_cast<QMessageBox::StandardButton>(button_));
  if (button != nullptr) {
    button->click();
  } else {
    box->reject();
  }
}

std::vector<std::pair<QString, SuiteFactory>>& Suites() {
  static std::vector<std::pair<QString, SuiteFactory>> suites;
  return suites;
}

RegisterSuite::RegisterSuite(const char* name, SuiteFactory factory) {
  Suites().emplace_back(QString::fromLatin1(name), std::move(factory));
}

}  // namespace layermod::ui::test
