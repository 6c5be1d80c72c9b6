// SPDX-License-Identifier: MIT
#include "render/shading.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace layermod::render_internal {
namespace {

// Colour of meshes without vertex colours (RenderMesh::colors empty).
constexpr float kDefaultGrey = 0.8f;

// Plain double 3-vectors: this is the per-pixel hot path, where Eigen's fixed-size expressions
// compiled to noticeably more instructions.
struct Vec3 {
  double x, y, z;
};
inline Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 ToVec3(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

// What shading needs of one triangle, set up once per run of pixels showing it. With the corners
// p0, p1, p2 as the columns of M, a point X on the triangle's plane has barycentric coordinates
// M^-1 X, whose rows are the cross products below (over det = p0 . (p1 x p2)); along the pixel
// ray X = z * ray they sum to 1, which gives z = det / (sum of rows . ray). Depth and the
// perspective-correct colour weights so come from three dot products per pixel, in double.
struct ShadedTriangle {
  Vec3 rows[3]{};  // p1 x p2, p2 x p0, p0 x p1
  double det = 0.0;
  double min_z = 0.0;  // the triangle's z range (at least near): clamps rounding at grazing
  double max_z = 0.0;
  cv::Vec3f normal;      // unit face normal, towards the camera
  float colors[3][3]{};  // per corner: vertex colour x Lambert shading, in 0..255, RGB
};

// Fills `t` in place: returning the struct would copy it for every covered pixel.
void SetUpTriangle(const RenderMesh& mesh, const ScratchVector<Eigen::Vector3f>& in_cam,
                   std::int32_t id, const Vec3& light, double ambient, double near_mm,
                   ShadedTriangle& t) {
  const auto& triangle = mesh.triangles[static_cast<std::size_t>(id)];
  const Vec3 p0 = ToVec3(in_cam[triangle[0]]);
  const Vec3 p1 = ToVec3(in_cam[triangle[1]]);
  const Vec3 p2 = ToVec3(in_cam[triangle[2]]);
  t.rows[0] = Cross(p1, p2);
  t.rows[1] = Cross(p2, p0);
  t.rows[2] = Cross(p0, p1);
  t.det = Dot(p0, t.rows[0]);
  t.min_z = std::max(std::min({p0.z, p1.z, p2.z}), near_mm);
  t.max_z = std::max({p0.z, p1.z, p2.z, near_mm});
  // The face normal (p1 - p0) x (p2 - p0) is the sum of the rows. The camera sits at the origin,
  // so the normal facing it has normal . p0 = det < 0.
  Vec3 normal{t.rows[0].x + t.rows[1].x + t.rows[2].x, t.rows[0].y + t.rows[1].y + t.rows[2].y,
              t.rows[0].z + t.rows[1].z + t.rows[2].z};
  // One division, and a branch that does not wait for the square root.
  const double squared_length = Dot(normal, normal);
  if (squared_length > 0.0) {
    const double scale = (t.det > 0.0 ? -1.0 : 1.0) / std::sqrt(squared_length);
    normal = {normal.x * scale, normal.y * scale, normal.z * scale};
  } else {
    normal = {0.0, 0.0, -1.0};
  }
  t.normal = cv::Vec3f(static_cast<float>(normal.x), static_cast<float>(normal.y),
                       static_cast<float>(normal.z));
  const double shade = ambient + (1.0 - ambient) * std::max(0.0, Dot(normal, light));
  const auto scale = static_cast<float>(255.0 * shade);
  for (int k = 0; k < 3; ++k) {
    for (int channel = 0; channel < 3; ++channel) {
      t.colors[k][channel] =
          scale * (mesh.colors.empty() ? kDefaultGrey : mesh.colors[triangle[k]][channel]);
    }
  }
}

// Depth and colour where the ray through a pixel centre (ray.z = 1) meets the triangle.
void ShadePixel(const ShadedTriangle& t, const Vec3& ray, float& depth_mm, cv::Vec3b& bgr) {
  double w0 = Dot(t.rows[0], ray);
  double w1 = Dot(t.rows[1], ray);
  double w2 = Dot(t.rows[2], ray);
  const double sum = w0 + w1 + w2;
  double z = t.min_z;
  if (sum != 0.0) {
    const double inv_sum = 1.0 / sum;
    z = std::clamp(t.det * inv_sum, t.min_z, t.max_z);
    w0 = std::max(0.0, w0 * inv_sum);
    w1 = std::max(0.0, w1 * inv_sum);
    w2 = std::max(0.0, w2 * inv_sum);
  } else {  // the ray runs within the plane: the triangle is seen edge-on
    w0 = w1 = w2 = 1.0 / 3.0;
  }
  depth_mm = static_cast<float>(z);
  const auto b0 = static_cast<float>(w0);
  const auto b1 = static_cast<float>(w1);
  const auto b2 = static_cast<float>(w2);
  for (int channel = 0; channel < 3; ++channel) {  // RGB in, BGR out
    bgr[2 - channel] = cv::saturate_cast<std::uint8_t>(
        b0 * t.colors[0][channel] + b1 * t.colors[1][channel] + b2 * t.colors[2][channel]);
  }
}

// A view of `window`; zeroed only when the shading pass will not write all of it.
RenderedView AllocateView(const PixelWindow& window, bool zeroed) {
  RenderedView view;
  view.roi = cv::Rect(window.x0, window.y0, window.width(), window.height());
  const cv::Size size = view.roi.size();
  view.depth_mm.create(size, CV_32F);
  view.mask.create(size, CV_8U);
  view.normals.create(size, CV_32FC3);
  view.color.create(size, CV_8UC3);
  if (zeroed) {
    view.depth_mm.setTo(0);
    view.mask.setTo(0);
    view.normals.setTo(0);
    view.color.setTo(0);
  }
  return view;
}

}  // namespace

RenderedView BlankView(const PixelWindow& window) { return AllocateView(window, true); }

RenderedView ShadeVisibility(const RenderMesh& mesh, const ScratchVector<Eigen::Vector3f>& in_cam,
                             const VisibilityBuffer& buffer, const PinholeCamera& camera,
                             const RenderOptions& options, const PixelWindow& output) {
  const PixelWindow& window = buffer.window;
  // Inside the buffer's window every pixel is written, background included.
  const bool larger = output.x0 != window.x0 || output.y0 != window.y0 || output.x1 != window.x1 ||
                      output.y1 != window.y1;
  RenderedView view = AllocateView(output, larger);
  const int col_offset = window.x0 - output.x0;
  const Eigen::Vector3d light_unit = options.light_dir_in_cam.cast<double>().normalized();
  const Vec3 light{light_unit.x(), light_unit.y(), light_unit.z()};
  std::vector<double> ray_x(static_cast<std::size_t>(window.width()));
  for (int col = 0; col < window.width(); ++col) {
    ray_x[col] = (window.x0 + col - camera.cx) / camera.fx;
  }
  ShadedTriangle triangle;
  std::int32_t loaded = -1;
  for (int row = 0; row < window.height(); ++row) {
    const std::int32_t* ids =
        buffer.triangle.data() + static_cast<std::size_t>(row) * window.width();
    const int out_row = row + window.y0 - output.y0;
    auto* depth = view.depth_mm.ptr<float>(out_row) + col_offset;
    auto* mask = view.mask.ptr<std::uint8_t>(out_row) + col_offset;
    auto* normals = view.normals.ptr<cv::Vec3f>(out_row) + col_offset;
    auto* color = view.color.ptr<cv::Vec3b>(out_row) + col_offset;
    const double ray_y = (window.y0 + row - camera.cy) / camera.fy;
    for (int col = 0; col < window.width(); ++col) {
      const std::int32_t id = ids[col];
      if (id < 0) {
        depth[col] = 0.0f;
        mask[col] = 0;
        normals[col] = cv::Vec3f(0.0f, 0.0f, 0.0f);
        color[col] = cv::Vec3b(0, 0, 0);
        continue;
      }
      if (id != loaded) {
        SetUpTriangle(mesh, in_cam, id, light, options.ambient, options.near_mm, triangle);
        loaded = id;
      }
      ShadePixel(triangle, Vec3{ray_x[col], ray_y, 1.0}, depth[col], color[col]);
      mask[col] = 255;
      normals[col] = triangle.normal;
    }
  }
  return view;
}

}  // namespace layermod::render_internal
