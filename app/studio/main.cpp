// SPDX-License-Identifier: MIT
// layermod-studio: the authoring GUI. Parses arguments and hands over to ui::MainWindow.
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <cstdio>

#include "ui/main_window.h"
#include "ui/screenshot.h"
#include "ui/studio_dialogs.h"
#include "util/version.h"

int main(int argc, char** argv) {
  // VTK's OpenGL widget needs its surface format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
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
  parser.addPositionalArgument("files", "Meshes and *.layermod archives to open.", "[files...]");
  parser.process(app);

  const bool batch = parser.isSet(screenshot);
  layermod::ui::SetBatchMode(batch);
  layermod::ui::MainWindow window;
  window.show();
  window.OpenFiles(parser.positionalArguments());
  if (batch) {
    const QString path = parser.value(screenshot);
    layermod::ui::SaveScreenshotWhenIdle(&window, path, [&app, path](bool ok) {
      if (!ok) std::fprintf(stderr, "layermod-studio: cannot write \"%s\"\n", qUtf8Printable(path));
      app.exit(ok && layermod::ui::BatchErrorCount() == 0 ? 0 : 1);
    });
  }
  return app.exec();
}
