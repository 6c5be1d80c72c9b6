// SPDX-License-Identifier: MIT
// GUI test main: `layermod_ui_tests [TestClass] [QTest options]`. Settings go to a temporary
// directory and the unsaved-set prompt is switched off (one test switches it back on).
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <cstdio>
#include <opencv2/core.hpp>

#include "ui/common/studio_dialogs.h"
#include "ui_test_support.h"
#include "util/log.h"

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  qputenv(layermod::ui::kDiscardWithoutAskingEnv, "1");
  cv::theRNG().state = 12345;
  // The core's warnings are asserted on (through the log dock), not printed.
  layermod::SetLogSink([](layermod::LogLevel, std::string_view) {});
  QApplication app(argc, argv);
  QApplication::setOrganizationName("LayerMOD-tests");
  QApplication::setApplicationName("layermod-studio-tests");
  QTemporaryDir settings_dir;
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir.path());
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_dir.path());

  QStringList args = QApplication::arguments();
  QString only;
  if (args.size() > 1 && !args[1].startsWith('-')) only = args.takeAt(1);
  int failures = 0;
  bool found = false;
  for (const auto& [name, factory] : layermod::ui::test::Suites()) {
    if (!only.isEmpty() && name != only) continue;
    found = true;
    const auto suite = factory();
    failures += QTest::qExec(suite.get(), args);
  }
  if (!found) {
    std::fprintf(stderr, "no test class named %s\n", qUtf8Printable(only));
    return 2;
  }
  return failures == 0 ? 0 : 1;
}
