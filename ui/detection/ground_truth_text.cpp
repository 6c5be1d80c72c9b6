// SPDX-License-Identifier: MIT
#include "ui/detection/ground_truth_text.h"

#include <QObject>
#include <QStringList>

namespace layermod::ui {
namespace {

QString InstanceLine(const GroundTruthCoverage& instance) {
  const QString object = QObject::tr("obj %1").arg(instance.obj_id);
  if (!instance.check.has_value()) {
    return QObject::tr("%1: not in the template set").arg(object);
  }
  const EnvelopeCheck& check = *instance.check;
  const QString where = QObject::tr("%1 at %2 mm").arg(object).arg(check.depth_mm, 0, 'f', 0);
  if (check.inside) {
    return QObject::tr("%1: covered (%2° from a template view)")
        .arg(where)
        .arg(check.view_gap_deg, 0, 'f', 1);
  }
  return QObject::tr("<span style='color:#d32f2f'><b>%1: outside the envelope</b>, %2</span>")
      .arg(where, QString::fromStdString(check.reason).toHtmlEscaped());
}

}  // namespace

QString CoverageHtml(const std::vector<GroundTruthCoverage>& coverage) {
  if (coverage.empty()) return {};
  QStringList lines;
  for (const GroundTruthCoverage& instance : coverage) lines << InstanceLine(instance);
  return QObject::tr("Ground truth: %1").arg(lines.join("<br>"));
}

}  // namespace layermod::ui
