// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <vector>

#include "mesh/model.h"
#include "templates/training_profile.h"

namespace layermod::ui {
class MainWindow;
class ViewsPanel;
}  // namespace layermod::ui

namespace layermod::ui::test {

// The bundled sample part: resources/sample/bracket.ply when present, else the same part written
// by the core (MakeSampleBracket) into a temporary directory.
QString SampleMeshPath();
// The sample part moved 200 mm away from its origin (triggers the centring warning).
QString OffCentreMeshPath();
// A directory that lives as long as the test process.
QString ScratchDir();

// A profile of 8 views (4 azimuths x 2 elevations, no roll) over 500-700 mm: three layers, 24
// templates for the sample part; trains in well under a second.
TrainingProfile TinyProfile();

// A template set of the sample part (TinyProfile, the bundled camera) and one RGB-D frame of
// the part rendered at the pose of one of its templates, in front of a wall, written both as a
// BOP scene and as colour + depth PNG + camera.json. Built once per process.
struct SyntheticCapture {
  QString archive;  // *.layermod
  QString bop_dir;  // split folder holding scene 000001 with frame 0
  QString color;
  QString depth;
  QString camera;
};
const SyntheticCapture& SyntheticCaptureFiles();

// Closes the next modal message box with `button` once it appears and records its texts.
class MessageBoxCloser : public QObject {
  Q_OBJECT

 public:
  explicit MessageBoxCloser(int button);
  bool seen() const { return seen_; }
  const QString& object_name() const { return object_name_; }
  const QString& text() const { return text_; }  // text + informative text

 private:
  void Poll();
  int button_;
  bool seen_ = false;
  QString object_name_;
  QString text_;
};

// Creates the test suites by class name (used by the test main).
using SuiteFactory = std::function<std::unique_ptr<QObject>()>;
std::vector<std::pair<QString, SuiteFactory>>& Suites();
struct RegisterSuite {
  RegisterSuite(const char* name, SuiteFactory factory);
};

}  // namespace layermod::ui::test

// Registers a QObject test class for the test main.
#define LAYERMOD_UI_TEST(Class)                                      \
  static const ::layermod::ui::test::RegisterSuite register_##Class( \
      #Class, [] { return std::unique_ptr<QObject>(new Class); })
