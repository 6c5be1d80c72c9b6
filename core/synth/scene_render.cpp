// SPDX-License-Identifier: MIT
#include "synth/scene_render.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace layermod {
namespace {

// The shadow map: a top view of the table around the target.
constexpr double kShadowHalfSizeMm = 1500.0;
constexpr double kShadowMmPerCell = 4.0;
constexpr int kShadowSubpixelBits = 4;
constexpr double kCastShadowBlurMm = 14.0;
constexpr double kCastShadowStrength = 0.4;
constexpr double kContactShadowBlurMm = 6.0;
constexpr double kContactShadowStrength = 0.3;

// Marks the triangles of `item` projected along `direction` (towards the light) onto z = 0
// in `map` (cells of kShadowMmPerCell around `centre_xy`). Triangles within a cell only mark
// their corners: dense meshes stay cheap, and the blur that follows hides the difference.
void DrawShadow(const PlacedItem& item, const Eigen::Vector3d& direction,
                const Eigen::Vector2d& centre_xy, cv::Mat& map) {
  const double scale = (1 << kShadowSubpixelBits) / kShadowMmPerCell;
  const Eigen::Vector2d slope = direction.head<2>() / direction.z();
  std::vector<cv::Point> projected(item.mesh->positions.size());
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const Eigen::Vector3d p = item.world_from_item * item.mesh->positions[i].cast<double>();
    const Eigen::Vector2d cell =
        (p.head<2>() - p.z() * slope - centre_xy + Eigen::Vector2d::Constant(kShadowHalfSizeMm)) *
        scale;
    projected[i] =
        cv::Point(static_cast<int>(std::lround(cell.x())), static_cast<int>(std::lround(cell.y())));
  }
  const cv::Rect inside(0, 0, map.cols, map.rows);
  constexpr int kOneCell = 1 << kShadowSubpixelBits;
  for (const auto& triangle : item.mesh->triangles) {
    const cv::Point corners[3] = {projected[triangle[0]], projected[triangle[1]],
                                  projected[triangle[2]]};
    const int width = std::max({corners[0].x, corners[1].x, corners[2].x}) -
                      std::min({corners[0].x, corners[1].x, corners[2].x});
    const int height = std::max({corners[0].y, corners[1].y, corners[2].y}) -
                       std::min({corners[0].y, corners[1].y, corners[2].y});
    if (width <= kOneCell && height <= kOneCell) {
      for (const cv::Point& corner : corners) {
        const cv::Point cell(corner.x >> kShadowSubpixelBits, corner.y >> kShadowSubpixelBits);
        if (inside.contains(cell)) map.at<float>(cell) = 1.0f;
      }
      continue;
    }
    cv::fillConvexPoly(map, corners, 3, cv::Scalar(1.0), cv::LINE_8, kShadowSubpixelBits);
  }
}

// How much each table point is darkened (0 none .. 1), on the shadow-map grid.
cv::Mat ShadowMap(const SceneLayout& layout) {
  const int cells = static_cast<int>(2.0 * kShadowHalfSizeMm / kShadowMmPerCell);
  const Eigen::Vector2d centre = layout.items.front().footprint_centre;
  cv::Mat cast = cv::Mat::zeros(cells, cells, CV_32F);
  cv::Mat contact = cv::Mat::zeros(cells, cells, CV_32F);
  for (const PlacedItem& item : layout.items) {
    DrawShadow(item, layout.light_to_world, centre, cast);
    DrawShadow(item, Eigen::Vector3d::UnitZ(), centre, contact);
  }
  cv::GaussianBlur(cast, cast, cv::Size(), kCastShadowBlurMm / kShadowMmPerCell);
  cv::GaussianBlur(contact, contact, cv::Size(), kContactShadowBlurMm / kShadowMmPerCell);
  return cast * kCastShadowStrength + contact * kContactShadowStrength;
}

// The shadow at every table pixel (0 elsewhere), looked up from the map. The table's plane
// coordinates are world x, y.
cv::Mat ShadowAtPixels(const SceneLayout& layout, const BackdropPixels& pixels) {
  const cv::Mat map = ShadowMap(layout);
  const Eigen::Vector2d centre = layout.items.front().footprint_centre;
  cv::Mat lookup(pixels.plane_xy.size(), CV_32FC2);
  const auto offset_x = static_cast<float>(kShadowHalfSizeMm - centre.x());
  const auto offset_y = static_cast<float>(kShadowHalfSizeMm - centre.y());
  const auto inverse_cell = static_cast<float>(1.0 / kShadowMmPerCell);
  pixels.plane_xy.forEach<cv::Vec2f>([&](const cv::Vec2f& xy, const int* position) {
    // Cell centres are at integer map coordinates: cell k covers [k, k + 1) * cell size.
    lookup.at<cv::Vec2f>(position[0], position[1]) = cv::Vec2f(
        (xy[0] + offset_x) * inverse_cell - 0.5f, (xy[1] + offset_y) * inverse_cell - 0.5f);
  });
  cv::Mat shadow;
  cv::remap(map, shadow, lookup, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0.0);
  shadow.setTo(0.0f, pixels.plane_index != kTablePlane);
  return shadow;
}

cv::Rect BoundingBoxOr(const cv::Mat& mask) {
  if (cv::countNonZero(mask) == 0) return {-1, -1, -1, -1};  // BOP's "no pixel"
  return cv::boundingRect(mask);
}

}  // namespace

RenderOptions SceneRenderOptions(const SceneLayout& layout) {
  RenderOptions options;
  options.window = RenderWindow::kFullImage;
  options.light_dir_in_cam = (layout.camera.cam_from_world.R * layout.light_to_world).cast<float>();
  options.ambient = static_cast<float>(layout.ambient);
  return options;
}

RenderedView RenderItem(const PlacedItem& item, const PinholeCamera& camera,
                        const SceneLayout& layout) {
  return RenderView(*item.mesh, camera, layout.camera.cam_from_world * item.world_from_item,
                    SceneRenderOptions(layout));
}

void RenderScene(const SceneLayout& layout, const Backdrop& backdrop, const PinholeCamera& camera,
                 SceneRender& render) {
  while (render.item_views.size() < layout.items.size()) {
    render.item_views.push_back(RenderItem(layout.items[render.item_views.size()], camera, layout));
  }
  if (render.backdrop.depth_mm.empty()) {
    render.backdrop = IntersectBackdrop(backdrop, camera, layout.camera.cam_from_world);
  }
  Composite(render);
}

void Composite(SceneRender& render) {
  const cv::Size size = render.backdrop.depth_mm.size();
  render.depth_mm = render.backdrop.depth_mm.clone();
  render.color = cv::Mat::zeros(size, CV_8UC3);
  render.item_index = cv::Mat(size, CV_16S, cv::Scalar(kNoSurface));
  render.item_index.setTo(kBackdropSurface, render.backdrop.plane_index >= 0);
  render.item_index.setTo(kTableSurface, render.backdrop.plane_index == kTablePlane);
  for (std::size_t i = 0; i < render.item_views.size(); ++i) {
    const RenderedView& view = render.item_views[i];
    for (int y = 0; y < size.height; ++y) {
      const auto* mask = view.mask.ptr<uchar>(y);
      const auto* depth = view.depth_mm.ptr<float>(y);
      auto* best = render.depth_mm.ptr<float>(y);
      for (int x = 0; x < size.width; ++x) {
        // Ties go to the item: an object resting on the table owns its contact pixels.
        if (mask[x] == 0 || (best[x] > 0.0f && depth[x] > best[x])) continue;
        best[x] = depth[x];
        render.item_index.at<short>(y, x) = static_cast<short>(i);
        render.color.at<cv::Vec3b>(y, x) = view.color.at<cv::Vec3b>(y, x);
      }
    }
  }
}

double VisibleFraction(const SceneRender& render, std::size_t index) {
  const int all = cv::countNonZero(render.item_views[index].mask);
  if (all == 0) return 0.0;
  const int visible = cv::countNonZero(render.item_index == static_cast<short>(index));
  return static_cast<double>(visible) / all;
}

void PaintBackdrop(const SceneLayout& layout, const Backdrop& backdrop, SceneRender& render) {
  const cv::Mat shaded =
      ShadeBackdrop(backdrop, render.backdrop, layout.light_to_world, layout.ambient);
  const cv::Mat shadow = ShadowAtPixels(layout, render.backdrop);
  for (int y = 0; y < render.color.rows; ++y) {
    for (int x = 0; x < render.color.cols; ++x) {
      const short index = render.item_index.at<short>(y, x);
      if (index != kTableSurface && index != kBackdropSurface) continue;
      render.color.at<cv::Vec3b>(y, x) =
          shaded.at<cv::Vec3b>(y, x) * (1.0 - shadow.at<float>(y, x));
    }
  }
}

WholeSilhouette ItemWholeSilhouette(const SceneLayout& layout, const PinholeCamera& camera,
                                    std::size_t index) {
  const PlacedItem& item = layout.items[index];
  // The canvas: the image in the middle of one three times its size.
  PinholeCamera canvas = camera;
  canvas.cx += camera.width;
  canvas.cy += camera.height;
  canvas.width = 3 * camera.width;
  canvas.height = 3 * camera.height;
  RenderOptions options = SceneRenderOptions(layout);
  options.window = RenderWindow::kObjectOnly;  // only the item's box of the canvas is drawn
  const RenderedView view =
      RenderView(*item.mesh, canvas, layout.camera.cam_from_world * item.world_from_item, options);
  WholeSilhouette whole;
  if (view.mask.empty()) return whole;
  const cv::Rect image_in_view =
      (cv::Rect(camera.width, camera.height, camera.width, camera.height) & view.roi) -
      view.roi.tl();
  const int inside = image_in_view.empty() ? 0 : cv::countNonZero(view.mask(image_in_view));
  whole.pixels_outside_image = cv::countNonZero(view.mask) - inside;
  if (inside + whole.pixels_outside_image > 0) {
    whole.box =
        cv::boundingRect(view.mask) + view.roi.tl() - cv::Point(camera.width, camera.height);
  }
  return whole;
}

BopGtInfo ItemGtInfo(const SceneRender& render, std::size_t index, const WholeSilhouette& whole,
                     const cv::Mat& sensor_depth_mm) {
  const cv::Mat& silhouette = render.item_views[index].mask;
  const cv::Mat visible = render.item_index == static_cast<short>(index);
  BopGtInfo info;
  // The in-image part from the scene's own render, so that nothing seen exceeds it.
  info.px_count_all = cv::countNonZero(silhouette) + whole.pixels_outside_image;
  info.px_count_visib = cv::countNonZero(visible);
  info.px_count_valid = cv::countNonZero(silhouette & (sensor_depth_mm > 0.0f));
  info.visib_fract =
      info.px_count_all > 0 ? static_cast<double>(info.px_count_visib) / info.px_count_all : 0.0;
  // BOP's convention: both boxes are "no pixel" when nothing of the item is seen.
  info.bbox_obj = info.px_count_visib > 0 ? whole.box : cv::Rect(-1, -1, -1, -1);
  info.bbox_visib = BoundingBoxOr(visible);
  return info;
}

}  // namespace layermod
