// SPDX-License-Identifier: MIT
#include "ui/detection/detection_table.h"

#include <QHeaderView>
#include <QObject>
#include <QTableWidget>

#include "geometry/pose.h"

namespace layermod::ui {
namespace {

QString Number(double value, int decimals = 1) { return QString::number(value, 'f', decimals); }

// Axis-angle reads better than a matrix in one cell: "37.2° about (0.12, -0.98, 0.16)".
QString RotationText(const Eigen::Matrix3d& rotation) {
  const Eigen::AngleAxisd axis_angle(rotation);
  const Eigen::Vector3d& axis = axis_angle.axis();
  return QObject::tr("%1° about (%2, %3, %4)")
      .arg(Number(RadToDeg(axis_angle.angle())), Number(axis.x(), 2), Number(axis.y(), 2),
           Number(axis.z(), 2));
}

// Whether the pose was checked against depth: without depth there is no ICP and no depth
// measure, only colour and outline.
bool CheckedAgainstDepth(const Detection& detection) { return detection.icp.iterations > 0; }

// The checks that tell right poses from wrong ones best, in one cell: "depth 0.91 · colour 1.00
// · outline 0.97".
QString ChecksText(const Detection& detection) {
  const Verification& v = detection.verification;
  QString colour_and_outline =
      QObject::tr("colour %1 · outline %2")
          .arg(Number(v.color_agreement, 2), Number(v.outline_agreement, 2));
  if (!CheckedAgainstDepth(detection)) return colour_and_outline;
  return QObject::tr("depth %1 · ").arg(Number(v.depth_fit, 2)) + colour_and_outline;
}

}  // namespace

QStringList DetectionColumnTitles() {
  return {QObject::tr("Object"),   QObject::tr("Confidence"), QObject::tr("Score"),
          QObject::tr("Checks"),   QObject::tr("Layer"),      QObject::tr("Position (mm)"),
          QObject::tr("Rotation"), QObject::tr("ICP")};
}

QString VerificationTooltip(const Detection& detection) {
  const Verification& v = detection.verification;
  QStringList lines;
  lines << QObject::tr("Confidence %1, from:").arg(Number(detection.confidence, 2))
        << QObject::tr("match score %1 %").arg(Number(detection.score));
  if (CheckedAgainstDepth(detection)) {
    lines << QObject::tr("depth fit %1, depth inliers %2")
                 .arg(Number(v.depth_fit, 2), Number(v.depth_inlier_ratio, 2))
          << QObject::tr("silhouette: visible %1, occluded %2, contradicted %3")
                 .arg(Number(v.visible_ratio, 2), Number(v.occluded_ratio, 2),
                      Number(v.contradicted_ratio, 2))
          << QObject::tr("surface continuing past the outline %1")
                 .arg(Number(v.surface_continuation, 2))
          << QObject::tr("ICP %1 mm rms, %2 of the samples fit")
                 .arg(Number(detection.icp.rmse_mm, 2), Number(detection.icp.inlier_ratio, 2));
  }
  lines << QObject::tr("colour agreement %1").arg(Number(v.color_agreement, 2))
        << QObject::tr("outline on scene edges %1").arg(Number(v.outline_agreement, 2));
  return lines.join('\n');
}

QStringList DetectionRowTexts(const Detection& detection) {
  const Eigen::Vector3d& t = detection.cam_from_model.t;
  const QString object =
      QStringLiteral("%1 (%2)").arg(QString::fromStdString(detection.name)).arg(detection.obj_id);
  const QString icp = CheckedAgainstDepth(detection)
                          ? QObject::tr("%1 mm rms").arg(Number(detection.icp.rmse_mm, 2))
                          : QObject::tr("not refined");
  return {
      object,
      Number(detection.confidence, 2),
      QStringLiteral("%1 %").arg(Number(detection.score)),
      ChecksText(detection),
      QObject::tr("%1: %2 mm").arg(detection.layer_index).arg(Number(detection.layer_depth_mm, 0)),
      QStringLiteral("(%1, %2, %3)").arg(Number(t.x()), Number(t.y()), Number(t.z())),
      RotationText(detection.cam_from_model.R),
      icp};
}

void FillDetectionTable(QTableWidget* table, const std::vector<Detection>& detections) {
  table->clearContents();
  table->setColumnCount(static_cast<int>(DetectionColumnTitles().size()));
  table->setHorizontalHeaderLabels(DetectionColumnTitles());
  table->setRowCount(static_cast<int>(detections.size()));
  for (int row = 0; row < table->rowCount(); ++row) {
    const Detection& detection = detections[static_cast<std::size_t>(row)];
    const QStringList texts = DetectionRowTexts(detection);
    const QString tooltip = VerificationTooltip(detection);
    for (int column = 0; column < texts.size(); ++column) {
      auto* item = new QTableWidgetItem(texts[column]);
      item->setToolTip(tooltip);
      table->setItem(row, column, item);
    }
  }
  table->resizeColumnsToContents();
  table->horizontalHeader()->setStretchLastSection(true);
}

QString FormatStageTimings(const StageTimings& timings) {
  return QObject::tr("prepare %1 · regions %2 · coarse %3 · match %4 · pose %5 · total %6 ms")
      .arg(Number(timings.prepare_ms), Number(timings.regions_ms), Number(timings.coarse_ms),
           Number(timings.match_ms), Number(timings.pose_ms), Number(timings.total_ms));
}

}  // namespace layermod::ui
