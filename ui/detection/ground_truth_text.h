// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <vector>

#include "eval/envelope_coverage.h"

namespace layermod::ui {

// One line per ground-truth instance: whether the template set's envelope covers its pose, and
// why not when it does not ("obj 1 at 734 mm: outside the envelope, seen from -57 deg ...").
// Rich text; empty for no instances.
QString CoverageHtml(const std::vector<GroundTruthCoverage>& coverage);

}  // namespace layermod::ui
