// SPDX-License-Identifier: MIT
#include "render/screen_projection.h"

#include <algorithm>

namespace layermod::render_internal {

ScreenProjection::ScreenProjection(const PinholeCamera& camera, float near_mm)
    : fx_(static_cast<float>(camera.fx)),
      fy_(static_cast<float>(camera.fy)),
      cx_(static_cast<float>(camera.cx)),
      cy_(static_cast<float>(camera.cy)),
      near_mm_(near_mm) {
  constexpr float kScale = static_cast<float>(kSubpixelScale);
  guard_ = static_cast<float>(kGuardBandPx);
  right_ = static_cast<float>(camera.width - 1) + guard_;
  bottom_ = static_cast<float>(camera.height - 1) + guard_;
  fixed_offset_ = guard_ * kScale + 0.5f;
  max_fixed_ =
      static_cast<float>(std::max(camera.width, camera.height) + 2 * kGuardBandPx) * kScale;
  // The same sides as planes through the camera centre, for clipping in camera space:
  // u >= -guard  <=>  fx*x + (cx + guard)*z >= 0 for z > 0; likewise for the other sides.
  planes_[0] = {0.0f, 0.0f, 1.0f, -near_mm};
  planes_[1] = {fx_, 0.0f, cx_ + guard_, 0.0f};
  planes_[2] = {-fx_, 0.0f, right_ - cx_, 0.0f};
  planes_[3] = {0.0f, fy_, cy_ + guard_, 0.0f};
  planes_[4] = {0.0f, -fy_, bottom_ - cy_, 0.0f};
}

}  // namespace layermod::render_internal
