// SPDX-License-Identifier: MIT
// layermod-studio: the authoring GUI. Parses arguments and hands over to ui::MainWindow.
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <cstdio>

#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/detection/capture_source.h"
#include "ui/detection/detection_panel.h"
#include "ui/templates/template_browser.h"
#include "ui/widgets/focus_ring_style.h"
#include "ui/window/main_window.h"
#include "ui/window/screenshot.h"
#include "util/version.h"

namespace {

struct CaptureOptions {
  QCommandLineOption bop{"bop", "Detection preview: BOP split folder of the capture.", "dir"};
  QCommandLineOption scene{"scene", "BOP scene id (with --bop or a BOP folder among the files).",
                           "id", "1"};
  QCommandLineOption frame{"frame", "BOP image id (with --bop or a BOP folder among the files).",
                           "id", "0"};
  QCommandLineOption color{"color", "Detection preview: colour image of the capture.", "png"};
  QCommandLineOption depth{"depth", "16-bit depth PNG in mm (with --color).", "png"};
  QCommandLineOption camera{"camera", "BOP camera.json (with --color).", "json"};
  QCommandLineOption show_detection{
      "show-detection", "Once detected, show detection INDEX (0: best) in the 3D view.", "index"};
  QCommandLineOption select_template{
      "select-template", "Once an archive is open, select row ROW of the template browser.", "row"};
  QCommandLineOption overlays{
      "overlays", "Overlays shown: any of regions,coarse,matches,poses (default: poses).", "list"};

  void AddTo(QCommandLineParser& parser) const {
    parser.addOptions(
        {bop, scene, frame, color, depth, camera, overlays, show_detection, select_template});
  }
};

// A BOP folder given among the files, when --scene or --frame says which frame of it to open
// (without them the folder opens at its first frame, as a dropped folder does).
QString BopFolderAmongFiles(const QCommandLineParser& parser, const CaptureOptions& options) {
  if (parser.isSet(options.bop) || !(parser.isSet(options.scene) || parser.isSet(options.frame))) {
    return {};
  }
  for (const QString& path : parser.positionalArguments()) {
    if (QFileInfo(path).isDir()) return path;
  }
  return {};
}

// The capture asked for on the command line, if any. `folder_among_files`: BopFolderAmongFiles.
bool CaptureFromArguments(const QCommandLineParser& parser, const CaptureOptions& options,
                          const QString& folder_among_files, layermod::ui::CaptureSource* source) {
  if (parser.isSet(options.bop) || !folder_among_files.isEmpty()) {
    *source = {parser.isSet(options.bop) ? parser.value(options.bop) : folder_among_files,
               parser.value(options.scene).toInt(),
               parser.value(options.frame).toInt(),
               {},
               {},
               {}};
    return true;
  }
  if (!parser.isSet(options.color)) return false;
  *source = {{},
             0,
             0,
             parser.value(options.color),
             parser.value(options.depth),
             parser.value(options.camera)};
  return true;
}

layermod::OverlayToggles OverlaysFromArgument(const QString& list) {
  const QStringList names = list.split(',', Qt::SkipEmptyParts);
  return {names.contains("regions"), names.contains("coarse"), names.contains("matches"),
          names.contains("poses")};
}

}  // namespace

int main(int argc, char** argv) {
  // VTK's OpenGL widget needs its surface format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setStyle(new layermod::ui::FocusRingStyle);  // the application owns it
  QApplication::setOrganizationName("LayerMOD");
  QApplication::setApplicationName("layermod-studio");
  QApplication::setApplicationVersion(QString::fromStdString(layermod::ToolVersion()));

  QCommandLineParser parser;
  parser.setApplicationDescription("LayerMOD Studio: author multi-scale LineMOD template sets.");
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption screenshot(
      "screenshot", "Open FILES, wait until everything is shown, save the window to PNG and exit.",
      "png");
  parser.addOption(screenshot);
  const CaptureOptions capture_options;
  capture_options.AddTo(parser);
  parser.addPositionalArgument(
      "files", "Meshes and *.layermod archives to open; a BOP split folder opens a capture.",
      "[files...]");
  parser.process(app);

  const bool batch = parser.isSet(screenshot);
  layermod::ui::SetBatchMode(batch);
  layermod::ui::MainWindow window;
  window.show();
  const QString folder_among_files = BopFolderAmongFiles(parser, capture_options);
  QStringList files = parser.positionalArguments();
  files.removeAll(folder_among_files);  // opened as the capture below
  window.OpenFiles(files);
  if (parser.isSet(capture_options.overlays)) {
    window.detection_panel()->SetOverlays(
        OverlaysFromArgument(parser.value(capture_options.overlays)));
  }
  layermod::ui::CaptureSource capture;
  if (parser.isSet(capture_options.select_template)) {
    const int row = parser.value(capture_options.select_template).toInt();
    QObject::connect(window.session(), &layermod::ui::StudioSession::ArchiveChanged, &window,
                     [&window, row] {
                       if (window.session()->archive() != nullptr) window.browser()->SelectRow(row);
                     });
  }
  if (parser.isSet(capture_options.show_detection)) {
    const int index = parser.value(capture_options.show_detection).toInt();
    QObject::connect(window.detection_panel(), &layermod::ui::DetectionPanel::DetectionFinished,
                     &window, [&window, index] { window.ShowDetectionInScene(index); });
  }
  if (CaptureFromArguments(parser, capture_options, folder_among_files, &capture)) {
    window.detection_panel()->OpenCapture(capture);
  }
  if (batch) {
    const QString path = parser.value(screenshot);
    layermod::ui::SaveScreenshotWhenIdle(&window, path, [&app, path](bool ok) {
      if (!ok) std::fprintf(stderr, "layermod-studio: cannot write \"%s\"\n", qUtf8Printable(path));
      app.exit(ok && layermod::ui::BatchErrorCount() == 0 ? 0 : 1);
    });
  }
  return app.exec();
}
