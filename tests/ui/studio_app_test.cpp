// SPDX-License-Identifier: MIT
// Runs the layermod-studio executable itself (command line, --screenshot, --version).
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTest>

#include "ui_test_support.h"
#include "util/version.h"

namespace layermod::ui::test {

class StudioAppTest : public QObject {
  Q_OBJECT

 private slots:
  void VersionPrintsTheToolVersion() {
    const Run run = Studio({"--version"});
    QCOMPARE(run.exit_code, 0);
    QVERIFY2(run.output.contains(QString::fromStdString(ToolVersion())), qPrintable(run.output));
  }

  void ScreenshotOfAMeshWritesAPng() {
    const QString png = QDir(ScratchDir()).filePath("studio_screenshot.png");
    const Run run = Studio({SampleMeshPath(), "--screenshot", png});
    QCOMPARE(run.exit_code, 0);
    QVERIFY(QFileInfo(png).size() > 0);
    const QImage image(png);
    QVERIFY(image.width() >= 640 && image.height() >= 480);
    // The central 3D view is not blank: its centre holds more than one colour.
    const QImage centre =
        image.copy(image.width() / 3, image.height() / 4, image.width() / 3, image.height() / 2);
    QSet<QRgb> colours;
    for (int y = 0; y < centre.height(); y += 4) {
      for (int x = 0; x < centre.width(); x += 4) colours.insert(centre.pixel(x, y));
    }
    QVERIFY(colours.size() > 20);
  }

  void ScreenshotOfTheDetectionPreviewRunsDetection() {
    const SyntheticCapture& files = SyntheticCaptureFiles();
    const QString png = QDir(ScratchDir()).filePath("studio_detection.png");
    const Run run = Studio({files.archive, "--bop", files.bop_dir, "--scene", "1", "--frame", "0",
                            "--overlays", "regions,poses", "--screenshot", png});
    QVERIFY2(run.exit_code == 0, qPrintable(run.output));
    const QImage image(png);
    QVERIFY(image.width() >= 640 && image.height() >= 480);
  }

  void FrameFlagsChooseTheFrameOfAFolderAmongTheFiles() {
    // The folder given among the files opens at --scene/--frame, as with --bop: frame 7 is not
    // in the capture, so the run names it and fails instead of showing frame 0.
    const SyntheticCapture& files = SyntheticCaptureFiles();
    const QString png = QDir(ScratchDir()).filePath("studio_positional_frame.png");
    const Run run =
        Studio({files.archive, files.bop_dir, "--scene", "1", "--frame", "7", "--screenshot", png});
    QCOMPARE(run.exit_code, 1);
    QVERIFY2(run.output.contains("image 7 is not in scene 1"), qPrintable(run.output));
  }

  void MissingCaptureFolderFailsTheScreenshotRun() {
    const QString missing = QDir(ScratchDir()).filePath("no_such_dataset");
    const QString png = QDir(ScratchDir()).filePath("studio_no_capture.png");
    const Run run = Studio({"--bop", missing, "--screenshot", png});
    QCOMPARE(run.exit_code, 1);
    QVERIFY2(run.output.contains("no_such_dataset"), qPrintable(run.output));
  }

  void UnreadableFileFailsTheScreenshotRun() {
    const QString png = QDir(ScratchDir()).filePath("studio_bad.png");
    const Run run = Studio({QDir(ScratchDir()).filePath("missing.ply"), "--screenshot", png});
    QCOMPARE(run.exit_code, 1);
    QVERIFY2(run.output.contains("missing.ply"), qPrintable(run.output));
  }

 private:
  struct Run {
    int exit_code = -1;
    QString output;
  };

  static Run Studio(const QStringList& args) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    // Keep the user's settings out of it.
    env.insert("XDG_CONFIG_HOME", QDir(ScratchDir()).filePath("studio-config"));
    process.setProcessEnvironment(env);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(QStringLiteral(LAYERMOD_STUDIO_EXE), args);
    Run run;
    if (!process.waitForFinished(300000)) return run;
    run.exit_code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.output = QString::fromLocal8Bit(process.readAll());
    return run;
  }
};

LAYERMOD_UI_TEST(StudioAppTest);

}  // namespace layermod::ui::test

#include "studio_app_test.moc"
