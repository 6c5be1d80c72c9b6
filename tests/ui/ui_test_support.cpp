// SPDX-License-Identifier: MIT
#include "ui_test_support.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>

#include "dataset/bop_writer.h"
#include "mesh/sample_part.h"
#include "pipeline/training.h"
#include "render/rasterizer.h"

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

namespace {

// The frame: the part at `record`'s pose over a grey wall one radius behind the sphere centre.
BopFrame RenderFrameAt(const Model& model, const TemplateRecord& record,
                       const PinholeCamera& camera) {
  RenderOptions options;
  options.window = RenderWindow::kFullImage;
  const RenderedView view = RenderView(ToRenderMesh(model), camera, record.cam_from_model, options);
  BopFrame frame;
  frame.scene_id = 1;
  frame.image_id = 0;
  frame.camera = camera;
  frame.color = cv::Mat(view.mask.size(), CV_8UC3, cv::Scalar(90, 95, 100));
  view.color.copyTo(frame.color, view.mask);
  const double wall_mm = record.layer_depth_mm + model.sphere.radius_mm;
  frame.depth_mm = cv::Mat(view.mask.size(), CV_32F, cv::Scalar(wall_mm));
  view.depth_mm.copyTo(frame.depth_mm, view.mask);
  frame.gt.push_back({record.obj_id, record.cam_from_model});
  return frame;
}

SyntheticCapture WriteSyntheticCapture() {
  const QDir dir(QDir(ScratchDir()).filePath("capture"));
  QDir().mkpath(dir.path());
  const Model model = LoadModel(SampleMeshPath().toStdString());
  TrainingRequest request;
  request.name = "bracket";
  request.camera = LoadCameraJson(LAYERMOD_SOURCE_DIR "/resources/sample/camera.json");
  request.profile = TinyProfile();
  const TrainingResult trained = TrainTemplates(model, request);
  SyntheticCapture files;
  files.archive = dir.filePath("bracket.layermod");
  WriteArchive(files.archive.toStdString(), trained.archive);

  // A template of the middle layer, so the wall lies within the trained depth range too.
  const auto& templates = trained.archive.templates();
  const TemplateRecord& record = templates[templates.size() / 2 + 1];
  files.bop_dir = dir.filePath("test");
  BopSceneWriter writer(dir.filePath("test/000001").toStdString());
  writer.AddFrame(RenderFrameAt(model, record, request.camera));
  writer.Finish();
  files.color = dir.filePath("test/000001/rgb/000000.png");
  files.depth = dir.filePath("test/000001/depth/000000.png");
  files.camera = dir.filePath("camera.json");
  WriteBopCamera(files.camera.toStdString(), request.camera);
  return files;
}

}  // namespace

const SyntheticCapture& SyntheticCaptureFiles() {
  static const SyntheticCapture files = WriteSyntheticCapture();
  return files;
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
