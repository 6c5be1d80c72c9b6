// SPDX-License-Identifier: MIT
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include "ui/common/job_runner.h"
#include "ui/common/studio_session.h"
#include "ui/model/model_panel.h"
#include "ui_test_support.h"

namespace layermod::ui::test {

class ModelPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    session_ = std::make_unique<StudioSession>();
    runner_ = std::make_unique<JobRunner>();
    panel_ = std::make_unique<ModelPanel>(session_.get(), runner_.get());
    panel_->show();
  }
  void cleanup() {
    panel_.reset();
    runner_.reset();
    session_.reset();
  }

  void LoadingTheSampleShowsTheCoreSphere() {
    const Model expected = LoadModel(SampleMeshPath().toStdString());
    QSignalSpy opened(panel_.get(), &ModelPanel::MeshOpened);
    QVERIFY(panel_->OpenMesh(SampleMeshPath()));
    QTRY_VERIFY_WITH_TIMEOUT(session_->model() != nullptr, 20000);
    QCOMPARE(opened.count(), 1);
    QCOMPARE(session_->model()->sphere.radius_mm, expected.sphere.radius_mm);
    QCOMPARE(Label("radiusValue"),
             QStringLiteral("%1 mm").arg(expected.sphere.radius_mm, 0, 'f', 2));
    QCOMPARE(Label("diameterValue"), QStringLiteral("%1 mm").arg(expected.DiameterMm(), 0, 'f', 2));
    QVERIFY(Label("countsValue").contains(QString::number(expected.mesh.n_faces())));
    QVERIFY(!panel_->findChild<QPushButton*>("recentreButton")->isVisible());
  }

  void ChangingUnitsReloadsTheMesh() {
    QVERIFY(panel_->OpenMesh(SampleMeshPath()));
    QTRY_VERIFY_WITH_TIMEOUT(session_->model() != nullptr, 20000);
    const double radius_mm = session_->model()->sphere.radius_mm;
    auto* units = panel_->findChild<QComboBox*>("unitsCombo");
    units->setCurrentIndex(units->findData(static_cast<int>(LengthUnit::kMetre)));
    emit units->activated(units->currentIndex());
    QTRY_VERIFY_WITH_TIMEOUT(session_->model()->source_units == LengthUnit::kMetre, 20000);
    QVERIFY(qAbs(session_->model()->sphere.radius_mm - 1000.0 * radius_mm) <
            1e-6 * radius_mm * 1000);
    QVERIFY(Label("warningsValue").contains("millimetres"));
  }

  void OffCentreMeshOffersRecentring() {
    QVERIFY(panel_->OpenMesh(OffCentreMeshPath()));
    QTRY_VERIFY_WITH_TIMEOUT(session_->model() != nullptr, 20000);
    auto* recentre = panel_->findChild<QPushButton*>("recentreButton");
    QVERIFY(recentre->isVisible());
    QVERIFY(Label("warningsValue").contains("far from"));
    recentre->click();
    QVERIFY(session_->model()->sphere.centre.norm() < 1e-9);
    QVERIFY(!OriginFarFromCentre(*session_->model()));
    QVERIFY(!recentre->isVisible());
  }

  void AnotherJobRunningRefusesToOpen() {
    QVERIFY(runner_->Start("hold", [](const JobControl& job) {
      while (!job.IsCancelled()) QThread::msleep(5);
      return JobRunner::Commit();
    }));
    QVERIFY(!panel_->OpenMesh(SampleMeshPath()));
    runner_->Cancel();
    QTRY_VERIFY(!runner_->busy());
    QVERIFY(session_->model() == nullptr);
  }

 private:
  QString Label(const char* name) const { return panel_->findChild<QLabel*>(name)->text(); }

  std::unique_ptr<StudioSession> session_;
  std::unique_ptr<JobRunner> runner_;
  std::unique_ptr<ModelPanel> panel_;
};

LAYERMOD_UI_TEST(ModelPanelTest);

}  // namespace layermod::ui::test

#include "model_panel_test.moc"
