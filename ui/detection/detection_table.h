// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

#include "pipeline/detector.h"

class QTableWidget;

namespace layermod::ui {

// Column titles of the detections table, and one row's texts (object, confidence, score, the
// verification's main checks, layer, position, rotation, ICP residual).
QStringList DetectionColumnTitles();
QStringList DetectionRowTexts(const Detection& detection);
// What the confidence was worked out from, one measure per line: the row's tooltip.
QString VerificationTooltip(const Detection& detection);
// Replaces the table's rows with `detections`, best first.
void FillDetectionTable(QTableWidget* table, const std::vector<Detection>& detections);

// "prepare 57.6 · regions 11.4 · coarse 13.7 · match 121.1 · pose 111.3 · total 315.2 ms".
QString FormatStageTimings(const StageTimings& timings);

}  // namespace layermod::ui
