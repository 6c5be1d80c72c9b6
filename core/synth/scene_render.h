// SPDX-License-Identifier: MIT
#pragma once

// Rendering a synthetic scene: every item through the training rasterizer (whole image), the
// backdrop analytically, composited by z-buffer; backdrop textures and soft shadows on the
// table; ground-truth visibility from the composite.

#include <opencv2/core.hpp>
#include <vector>

#include "dataset/bop.h"
#include "render/rasterizer.h"
#include "synth/backdrop.h"
#include "synth/scene_layout.h"

namespace layermod {

// item_index values that are not an item.
inline constexpr short kNoSurface = -1;
inline constexpr short kTableSurface = -2;
inline constexpr short kBackdropSurface = -3;  // floor or wall

struct SceneRender {
  std::vector<RenderedView> item_views;  // one per layout item, full image
  BackdropPixels backdrop;
  cv::Mat depth_mm;    // CV_32F: nearest surface (items and backdrop), 0 where nothing
  cv::Mat color;       // CV_8UC3: colour of the nearest item; backdrop black until painted
  cv::Mat item_index;  // CV_16S: index of the nearest item, or a negative k...Surface
};

// Render options for the layout's light, seen from its camera.
RenderOptions SceneRenderOptions(const SceneLayout& layout);

// Renders one item in the whole image.
RenderedView RenderItem(const PlacedItem& item, const PinholeCamera& camera,
                        const SceneLayout& layout);

// Renders the items that have no view yet (item_views shorter than layout.items), intersects
// the backdrop when not done yet, and composites everything.
void RenderScene(const SceneLayout& layout, const Backdrop& backdrop, const PinholeCamera& camera,
                 SceneRender& render);

// Recomposites after items were removed from the layout and their views from item_views.
void Composite(SceneRender& render);

// Fraction of item `index`'s silhouette that is not hidden by another surface (1 when the item
// covers no pixel at all is not meaningful: 0 then).
double VisibleFraction(const SceneRender& render, std::size_t index);

// Paints the backdrop into render.color: textures shaded by the light, the table darkened by
// the items' soft shadows (cast by the light and contact shadows beneath them).
void PaintBackdrop(const SceneLayout& layout, const Backdrop& backdrop, SceneRender& render);

// An item's whole silhouette, the part outside the image included: BOP counts px_count_all on a
// canvas three times the image's size with the image in its middle (bop_toolkit's
// calc_gt_info), so a part cut by the image border is not "fully visible".
struct WholeSilhouette {
  int pixels_outside_image = 0;  // the part of the silhouette the image does not show
  cv::Rect box{-1, -1, -1, -1};  // in image coordinates; may reach outside the image
};

// Renders item `index` of `layout` alone on that canvas (only the item's box of it).
WholeSilhouette ItemWholeSilhouette(const SceneLayout& layout, const PinholeCamera& camera,
                                    std::size_t index);

// BOP visibility of item `index`: px_count_all (its in-image silhouette and the part outside)
// and bbox_obj from its whole silhouette,
// px_count_visib and bbox_visib from the composite, px_count_valid the in-image silhouette pixels
// where `sensor_depth_mm` > 0. visib_fract = px_count_visib / px_count_all.
BopGtInfo ItemGtInfo(const SceneRender& render, std::size_t index, const WholeSilhouette& whole,
                     const cv::Mat& sensor_depth_mm);

}  // namespace layermod
