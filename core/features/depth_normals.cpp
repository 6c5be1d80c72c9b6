// SPDX-License-Identifier: MIT
#include "features/depth_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "util/error.h"

namespace layermod {
namespace {

// 1 / (1 + sqrt(1 + s)) for s = xn^2 + yn^2: a fit of degree 5, within 4e-4 over s in [0, 4]
// (up to about 127 degrees across the image's diagonal; past that the value at 4, so the turn is
// only near the ray's there), with no square root or division, so that the per-pixel loop stays as
// cheap as in the camera frame. Templates and scenes are turned by the same function.
float RayFactor(float s) {
  s = std::min(s, 4.0f);
  return 0.499606835f +
         s * (-0.120093392f +
              s * (0.0464887011f +
                   s * (-0.0142436575f + s * (0.00254756807f + s * -0.000190246117f))));
}

// The normal (nx, ny, nz), of any length, turned into the viewing-ray frame of the pixel at
// normalized image coordinates (xn, yn) and scaled by L = |(xn, yn, 1)|: with the unit ray
// r = (xn, yn, 1) / L, Rodrigues' formula for the rotation taking r to +Z, axis r x z, gives
// L R n = (nx - xn nz + yn d k, ny - yn nz - xn d k, nz + xn nx + yn ny), d = yn nx - xn ny,
// k = 1 / (1 + L). Callers normalize the result, so the scale costs nothing.
void TurnToViewingRay(float xn, float yn, float& nx, float& ny, float& nz) {
  const float along = (yn * nx - xn * ny) * RayFactor(xn * xn + yn * yn);
  const float x = nx - xn * nz + yn * along;
  const float y = ny - yn * nz - xn * along;
  const float z = nz + xn * nx + yn * ny;
  nx = x, ny = y, nz = z;
}

// The fit. Per pixel, the samples of the 5x5 window are (du, dv, q) with q = z0 / z - 1
// (dimensionless and small, so float sums stay accurate). On a plane n . X = d with
// X = z (xn, yn, 1) and xn = (u - cx) / fx, 1 / z = (n / d) . (xn, yn, 1) is affine in the pixel
// offsets, so fitting q = A du + B dv + C gives n ~ -(A fx, B fy, 1 + C - A fx xn0 - B fy yn0),
// which faces the camera by construction (n . X0 ~ -(1 + C) < 0).
constexpr int kRadius = 2;  // 5x5 window
constexpr int kMinSamples = 6;
constexpr int kWindowSamples = (2 * kRadius + 1) * (2 * kRadius + 1);
// Sum of du^2 (= sum of dv^2) over a complete window: 5 rows x (4 + 1 + 0 + 1 + 4).
constexpr float kCompleteSumSq = 50.0f;

// The 5 rows of depth and inverse depth around the current row, each padded by kRadius columns,
// invalid depth (<= 0, NaN, inf) and rows outside the image set to 0, so window reads need neither
// bounds nor NaN checks. A ring of row buffers instead of padded copies of the whole map: no large
// temporaries, whose page faults cost more than the fit on scene-sized maps.
class RowRing {
 public:
  static constexpr int kRows = 2 * kRadius + 1;

  explicit RowRing(const cv::Mat& depth_mm) : depth_mm_(depth_mm) {
    const size_t padded_width = static_cast<size_t>(depth_mm.cols) + size_t{2} * kRadius;
    for (int k = 0; k < kRows; ++k) {
      z_[k].assign(padded_width, 0.0f);
      w_[k].assign(padded_width, 0.0f);
      Load(k - kRadius, k);
    }
  }

  // Row v - kRadius + k of the map, as padded pointers (index kRadius is column 0).
  const float* Z(int v, int k) const { return z_[(v + k) % kRows].data(); }
  const float* W(int v, int k) const { return w_[(v + k) % kRows].data(); }

  // Moves from row v to v + 1: row v + kRadius + 1 replaces row v - kRadius.
  void Advance(int v) { Load(v + kRadius + 1, v % kRows); }

 private:
  void Load(int source_row, int slot) {
    float* z = z_[slot].data() + kRadius;
    float* w = w_[slot].data() + kRadius;
    if (source_row < 0 || source_row >= depth_mm_.rows) {
      std::fill_n(z, depth_mm_.cols, 0.0f);
      std::fill_n(w, depth_mm_.cols, 0.0f);
      return;
    }
    const auto* in = depth_mm_.ptr<float>(source_row);
    for (int u = 0; u < depth_mm_.cols; ++u) {
      const bool valid = (in[u] > 0.0f) & (in[u] < std::numeric_limits<float>::infinity());
      z[u] = valid ? in[u] : 0.0f;
      w[u] = valid ? 1.0f / (valid ? in[u] : 1.0f) : 0.0f;
    }
  }

  const cv::Mat& depth_mm_;
  std::vector<float> z_[kRows];
  std::vector<float> w_[kRows];
};

// Least-squares sums of the usable samples of one window.
struct PlaneSums {
  float n = 0, su = 0, sv = 0, suu = 0, svv = 0, suv = 0, sq = 0, suq = 0, svq = 0;
};

struct Intrinsics {
  float fx, fy, cx, cy;  // cx, cy in the depth map's own pixels
};

cv::Vec3f SolvePlane(const PlaneSums& s, const Intrinsics& k, int u, int v) {
  if (s.n < static_cast<float>(kMinSamples)) return {0.0f, 0.0f, 0.0f};
  const float cuu = s.suu - s.su * s.su / s.n, cvv = s.svv - s.sv * s.sv / s.n;
  const float cuv = s.suv - s.su * s.sv / s.n;
  const float cuq = s.suq - s.su * s.sq / s.n, cvq = s.svq - s.sv * s.sq / s.n;
  const float det = cuu * cvv - cuv * cuv;
  if (!(det > 1.0f)) return {0.0f, 0.0f, 0.0f};  // samples on (nearly) one line
  const float a = (cvv * cuq - cuv * cvq) / det;
  const float b = (cuu * cvq - cuv * cuq) / det;
  const float c = (s.sq - a * s.su - b * s.sv) / s.n;
  const float xn0 = (static_cast<float>(u) - k.cx) / k.fx;
  const float yn0 = (static_cast<float>(v) - k.cy) / k.fy;
  const cv::Vec3f normal(-a * k.fx, -b * k.fy, -(1.0f + c - a * k.fx * xn0 - b * k.fy * yn0));
  const float length = std::sqrt(normal.dot(normal));
  if (!(length > 0.0f) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};
  return normal / length;
}

// Any window: samples with invalid depth or a depth step beyond `max_step_mm` are left out.
cv::Vec3f GeneralFit(const RowRing& ring, const Intrinsics& k, int u, int v, float max_step_mm) {
  const float z0 = ring.Z(v, kRadius)[u + kRadius];
  PlaneSums s;
  for (int r = 0; r < RowRing::kRows; ++r) {
    const float* z = ring.Z(v, r) + u;
    const float* w = ring.W(v, r) + u;
    const auto dv = static_cast<float>(r - kRadius);
    for (int col = 0; col <= 2 * kRadius; ++col) {
      if (!(w[col] > 0.0f) || std::abs(z[col] - z0) > max_step_mm) continue;
      const auto du = static_cast<float>(col - kRadius);
      const float q = z0 * w[col] - 1.0f;
      s.n += 1, s.su += du, s.sv += dv, s.suu += du * du, s.svv += dv * dv, s.suv += du * dv;
      s.sq += q, s.suq += du * q, s.svq += dv * q;
    }
  }
  return SolvePlane(s, k, u, v);
}

// Column sums over the 5 rows of the window, per padded column: sum w, sum dv w, and the depth
// range (0 as minimum when a depth is invalid).
struct ColumnSums {
  std::vector<float> w, dv_w, min_z, max_z;

  explicit ColumnSums(int padded_width)
      : w(padded_width), dv_w(padded_width), min_z(padded_width), max_z(padded_width) {}

  void Compute(const RowRing& ring, int v) {
    const int width = static_cast<int>(w.size());
    float* __restrict sum_w = w.data();
    float* __restrict sum_dv_w = dv_w.data();
    float* __restrict lo = min_z.data();
    float* __restrict hi = max_z.data();
    const float* z_rows[RowRing::kRows];
    const float* w_rows[RowRing::kRows];
    for (int r = 0; r < RowRing::kRows; ++r) z_rows[r] = ring.Z(v, r), w_rows[r] = ring.W(v, r);
    for (int x = 0; x < width; ++x) {
      sum_w[x] = w_rows[0][x] + w_rows[1][x] + w_rows[2][x] + w_rows[3][x] + w_rows[4][x];
      sum_dv_w[x] = 2.0f * (w_rows[4][x] - w_rows[0][x]) + (w_rows[3][x] - w_rows[1][x]);
      lo[x] = std::min(
          std::min(std::min(z_rows[0][x], z_rows[1][x]), std::min(z_rows[2][x], z_rows[3][x])),
          z_rows[4][x]);
      hi[x] = std::max(
          std::max(std::max(z_rows[0][x], z_rows[1][x]), std::max(z_rows[2][x], z_rows[3][x])),
          z_rows[4][x]);
    }
  }
};

// One row of complete-window fits, branch-free so that it vectorises. A window is complete when
// all 25 depths are valid (minimum > 0) and within `max_step_mm` of the centre: then n = 25,
// sum du = sum dv = sum du dv = 0, sum du^2 = sum dv^2 = 50, and the fit is diagonal; only sum w,
// sum du w and sum dv w vary. `complete[u]` tells the caller which pixels need GeneralFit. yn0 and
// xn are the row's and the columns' normalized image coordinates.
// kInRayFrame: the normals are turned into each pixel's viewing-ray frame here, where it
// vectorises.
template <bool kInRayFrame>
void CompleteRow(const ColumnSums& columns, const float* z0, float yn0, int width, const float* xn,
                 const Intrinsics& k, float max_step_mm, float* __restrict out_x,
                 float* __restrict out_y, float* __restrict out_z,
                 std::uint8_t* __restrict complete) {
  // Column index u + i is window column du = i - kRadius of pixel u.
  const float* cw = columns.w.data();
  const float* cdv = columns.dv_w.data();
  const float* lo = columns.min_z.data();
  const float* hi = columns.max_z.data();
  for (int u = 0; u < width; ++u) {
    const float sum_w = cw[u] + cw[u + 1] + cw[u + 2] + cw[u + 3] + cw[u + 4];
    const float sum_du_w = 2.0f * (cw[u + 4] - cw[u]) + (cw[u + 3] - cw[u + 1]);
    const float sum_dv_w = cdv[u] + cdv[u + 1] + cdv[u + 2] + cdv[u + 3] + cdv[u + 4];
    const float min_z =
        std::min(std::min(std::min(lo[u], lo[u + 1]), std::min(lo[u + 2], lo[u + 3])), lo[u + 4]);
    const float max_z =
        std::max(std::max(std::max(hi[u], hi[u + 1]), std::max(hi[u + 2], hi[u + 3])), hi[u + 4]);
    const float z = z0[u];
    const bool ok = (min_z > 0.0f) & (z - min_z <= max_step_mm) & (max_z - z <= max_step_mm);
    const float a = z * sum_du_w / kCompleteSumSq;
    const float b = z * sum_dv_w / kCompleteSumSq;
    const float c = z * sum_w / static_cast<float>(kWindowSamples) - 1.0f;
    const float nx = -a * k.fx, ny = -b * k.fy;
    const float nz = -(1.0f + c - a * k.fx * xn[u] - b * k.fy * yn0);
    float mx = nx, my = ny, mz = nz;
    if constexpr (kInRayFrame) TurnToViewingRay(xn[u], yn0, mx, my, mz);
    const float length_sq = mx * mx + my * my + mz * mz;
    const float scale = ok ? 1.0f / std::sqrt(ok ? length_sq : 1.0f) : 0.0f;
    out_x[u] = mx * scale;
    out_y[u] = my * scale;
    out_z[u] = mz * scale;
    complete[u] = ok ? 1 : 0;
  }
}

void CheckInputs(const cv::Mat& depth_mm, const PinholeCamera& camera, float max_depth_step_mm) {
  if (depth_mm.type() != CV_32F) throw Error("ComputeDepthNormals: expected a CV_32F depth map");
  if (!(camera.fx > 0.0 && camera.fy > 0.0 && std::isfinite(camera.fx) &&
        std::isfinite(camera.fy) && std::isfinite(camera.cx) && std::isfinite(camera.cy))) {
    throw Error("ComputeDepthNormals: camera focal lengths must be positive and finite");
  }
  if (!(max_depth_step_mm > 0.0f) || !std::isfinite(max_depth_step_mm)) {
    throw Error("ComputeDepthNormals: max_depth_step_mm must be positive and finite");
  }
}

}  // namespace

cv::Vec3f InViewingRayFrame(const cv::Vec3f& normal, float xn, float yn) {
  float x = normal[0], y = normal[1], z = normal[2];
  TurnToViewingRay(xn, yn, x, y, z);
  const float inverse_length = 1.0f / std::sqrt(xn * xn + yn * yn + 1.0f);
  return {x * inverse_length, y * inverse_length, z * inverse_length};
}

cv::Mat ComputeDepthNormals(const cv::Mat& depth_mm, const PinholeCamera& camera,
                            cv::Point roi_offset, float max_depth_step_mm, NormalFrame frame,
                            const cv::Mat& where) {
  CheckInputs(depth_mm, camera, max_depth_step_mm);
  if (!where.empty() && (where.type() != CV_8U || where.size() != depth_mm.size())) {
    throw Error("ComputeDepthNormals: `where` must be CV_8U of the depth map's size");
  }
  cv::Mat normals = cv::Mat::zeros(depth_mm.size(), CV_32FC3);
  if (depth_mm.empty()) return normals;
  const Intrinsics k{static_cast<float>(camera.fx), static_cast<float>(camera.fy),
                     static_cast<float>(camera.cx - roi_offset.x),
                     static_cast<float>(camera.cy - roi_offset.y)};
  const int width = depth_mm.cols;
  RowRing ring(depth_mm);
  ColumnSums columns(width + 2 * kRadius);
  std::vector<float> xn(width), out_x(width), out_y(width), out_z(width);
  std::vector<std::uint8_t> complete(width);
  for (int u = 0; u < width; ++u) xn[u] = (static_cast<float>(u) - k.cx) / k.fx;
  const auto complete_row =
      frame == NormalFrame::kViewingRay ? CompleteRow<true> : CompleteRow<false>;
  for (int v = 0; v < depth_mm.rows; ++v) {
    const float* z0 = ring.Z(v, kRadius) + kRadius;
    const float yn = (static_cast<float>(v) - k.cy) / k.fy;
    columns.Compute(ring, v);
    complete_row(columns, z0, yn, width, xn.data(), k, max_depth_step_mm, out_x.data(),
                 out_y.data(), out_z.data(), complete.data());
    auto* out = normals.ptr<cv::Vec3f>(v);
    const std::uint8_t* wanted = where.empty() ? nullptr : where.ptr<std::uint8_t>(v);
    for (int u = 0; u < width; ++u) {
      if (wanted != nullptr && wanted[u] == 0) continue;
      if (complete[u] != 0) {
        out[u] = {out_x[u], out_y[u], out_z[u]};
      } else if (z0[u] > 0.0f) {
        out[u] = GeneralFit(ring, k, u, v, max_depth_step_mm);
        if (frame == NormalFrame::kViewingRay) out[u] = InViewingRayFrame(out[u], xn[u], yn);
      }
    }
    ring.Advance(v);
  }
  return normals;
}

}  // namespace layermod
