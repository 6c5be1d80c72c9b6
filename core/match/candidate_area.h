// SPDX-License-Identifier: MIT
#pragma once

// Where a search restricted to candidate points looks: the level-0 pixels within a radius of
// some point ("disks"), turned once per search into what tells, for any template, which of its
// top-level grid cells come near a point (see matcher.h, MatchTemplateGroups).

#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "match/similarity.h"

namespace layermod {

struct CandidateArea {
  bool restricted = false;  // false: every position is searched
  // Per top-level cell span (level-0 pixels per cell), from the reach map: reach(q - origin) != 0
  // iff some disk pixel lies in [q.x, q.x + span) x [q.y, q.y + span). The map is kept sampled
  // every `span` pixels, once for each of the span x span phases a template's grid can have
  // against it (index ry * span + rx): cell j of phase (rx, ry) is
  // reach(j.y * span - ry, j.x * span - rx), 0 outside. A template's near cells are then a
  // shifted copy of one phase, with no pass over the map per template.
  struct Reach {
    int span = 0;
    cv::Point origin;
    // Per phase, its non-zero cells as maximal row runs, in scan order.
    std::vector<std::vector<GridRowSpan>> phase_runs;
  };
  std::vector<Reach> by_span;

  const Reach* ForSpan(int span) const;
};

// The area of `points` for each of `spans` (level-0 pixels per top-level cell; repeats are
// made once) in a scene of `image` pixels: disks far outside it are dropped (anchors lie in or
// near the template box, hence in or near the image).
CandidateArea MakeCandidateArea(const std::vector<cv::Point>& points, int radius_px, cv::Size image,
                                std::span<const int> spans);

// The top-level cells near some candidate point of a template whose cells span `span` level-0
// pixels and whose anchor lies `anchor` from its box's top-left, in a grid of `cells`: merged
// row spans in scan order, into `spans` (none when the area has no reach for `span`). Cell
// (gx, gy) puts the anchor in [gx * span, (gx + 1) * span) + anchor (both axes).
void NearCells(int span, cv::Point anchor, const cv::Size& cells, const CandidateArea& area,
               std::vector<GridRowSpan>& spans);

}  // namespace layermod
