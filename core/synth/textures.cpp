// SPDX-License-Identifier: MIT
#include "synth/textures.h"
#include "util/quoted.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "dataset/bop_images.h"
#include "geometry/pose.h"
#include "synth/random_draws.h"
#include "util/error.h"
#include "util/file_names.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

constexpr int kMipLevels = 7;  // 512 .. 8 texels

bool IsImageFile(const fs::path& path) {
  const std::string extension = LowercaseExtension(path);
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg" || extension == ".bmp";
}

// Smooth noise: a small random image resized up (values of about +-1).
cv::Mat SmoothNoise(int cells, cv::RNG& cv_rng) {
  cv::Mat small(cells, cells, CV_32F);
  cv_rng.fill(small, cv::RNG::NORMAL, 0.0, 1.0);
  cv::Mat large;
  cv::resize(small, large, cv::Size(kTextureSize, kTextureSize), 0, 0, cv::INTER_CUBIC);
  return large;
}

// A BGR offset with each channel uniform in its range, drawn last channel first (one draw per
// statement, synth/random_draws.h).
cv::Scalar UniformTint(std::mt19937_64& rng, std::pair<double, double> blue,
                       std::pair<double, double> green, std::pair<double, double> red) {
  const double r = Uniform(rng, red.first, red.second);
  const double g = Uniform(rng, green.first, green.second);
  const double b = Uniform(rng, blue.first, blue.second);
  return {b, g, r};
}

// Base grey level and tint (BGR offsets) of a surface kind.
void BaseColour(SurfaceKind kind, std::mt19937_64& rng, double& grey, cv::Scalar& tint) {
  switch (kind) {
    case SurfaceKind::kTable:
      grey = Uniform(rng, 80.0, 200.0);
      tint = UniformTint(rng, {-30.0, 15.0}, {-10.0, 10.0}, {-15.0, 35.0});
      break;
    case SurfaceKind::kFloor:
      grey = Uniform(rng, 40.0, 110.0);
      tint = UniformTint(rng, {-15.0, 10.0}, {-5.0, 5.0}, {-10.0, 20.0});
      break;
    case SurfaceKind::kWall:
      grey = Uniform(rng, 150.0, 225.0);
      tint = UniformTint(rng, {-15.0, 5.0}, {-5.0, 5.0}, {-5.0, 15.0});
      break;
  }
}

void AddGrain(cv::Mat& shade, std::mt19937_64& rng, cv::RNG& cv_rng) {
  const cv::Mat phase = SmoothNoise(6, cv_rng);
  const double period = Uniform(rng, 6.0, 20.0);
  const double amplitude = Uniform(rng, 3.0, 8.0);
  for (int y = 0; y < kTextureSize; ++y) {
    for (int x = 0; x < kTextureSize; ++x) {
      shade.at<float>(y, x) += static_cast<float>(
          amplitude * std::sin(2.0 * kPi * y / period + 3.0 * phase.at<float>(y, x)));
    }
  }
}

void AddLines(cv::Mat& texture, double grey, const cv::Scalar& tint, std::mt19937_64& rng) {
  const int lines = static_cast<int>(Uniform(rng, 1.0, 5.0));
  for (int i = 0; i < lines; ++i) {
    cv::Point a(static_cast<int>(Uniform(rng, 0, kTextureSize)), 0);
    cv::Point b(static_cast<int>(Uniform(rng, 0, kTextureSize)), kTextureSize);
    if (Uniform(rng, 0.0, 1.0) < 0.5) {
      a = cv::Point(a.y, a.x);
      b = cv::Point(b.y, b.x);
    }
    const double offset =
        Uniform(rng, 0.0, 1.0) < 0.7 ? -Uniform(rng, 20, 60) : Uniform(rng, 20, 50);
    cv::line(texture, a, b, cv::Scalar::all(grey + offset) + tint,
             static_cast<int>(Uniform(rng, 1.0, 4.0)), cv::LINE_AA);
  }
}

// A random square crop of a photo, resized to the texture size.
cv::Mat PhotoTexture(const fs::path& path, std::mt19937_64& rng) {
  const cv::Mat photo = ReadBopColor(path);
  const int max_side = std::min(photo.cols, photo.rows);
  const int side = std::max(8, static_cast<int>(max_side * Uniform(rng, 0.5, 1.0)));
  const int x = static_cast<int>(Uniform(rng, 0.0, photo.cols - side + 1));
  const int y = static_cast<int>(Uniform(rng, 0.0, photo.rows - side + 1));
  cv::Mat crop = photo(cv::Rect(x, y, side, side));
  if (Uniform(rng, 0.0, 1.0) < 0.5) cv::flip(crop, crop, 1);
  cv::Mat texture;
  cv::resize(crop, texture, cv::Size(kTextureSize, kTextureSize), 0, 0, cv::INTER_AREA);
  return texture;
}

// Folds a texel coordinate into [-0.5, n - 0.5]: the texture tiled by mirroring, without seams.
float Fold(double texel, int n) {
  double y = std::fmod(texel + 0.5, 2.0 * n);
  if (y < 0.0) y += 2.0 * n;
  if (y > n) y = 2.0 * n - y;
  return static_cast<float>(y - 0.5);
}

// Squared texels per pixel along the image axes (the larger of the two), from the texel
// coordinates of neighbouring pixels on the same plane.
float FootprintSquared(const cv::Mat& texel_uv, const cv::Mat& mask, int x, int y) {
  const cv::Vec2f& here = texel_uv.at<cv::Vec2f>(y, x);
  const auto valid = [&mask](int u, int v) {
    return u >= 0 && v >= 0 && u < mask.cols && v < mask.rows && mask.at<uchar>(v, u) != 0;
  };
  float footprint = 1.0f;
  for (const cv::Point step : {cv::Point(1, 0), cv::Point(0, 1)}) {
    cv::Point other(x + step.x, y + step.y);
    if (!valid(other.x, other.y)) other = cv::Point(x - step.x, y - step.y);
    if (!valid(other.x, other.y)) continue;
    const cv::Vec2f d = texel_uv.at<cv::Vec2f>(other) - here;
    footprint = std::max(footprint, d[0] * d[0] + d[1] * d[1]);
  }
  return footprint;
}

// Mirrors an index just outside [0, n) back inside (OpenCV's BORDER_REFLECT).
int Reflect(int index, int n) {
  if (index < 0) return std::min(-index - 1, n - 1);
  if (index >= n) return std::max(2 * n - index - 1, 0);
  return index;
}

// Bilinear sample of mip `level` at the folded level-0 coordinates `texel`.
cv::Vec3f Bilinear(const cv::Mat& image, const cv::Vec2f& texel, int level) {
  const float scale = 1.0f / static_cast<float>(1 << level);
  const float u = (texel[0] + 0.5f) * scale - 0.5f;
  const float v = (texel[1] + 0.5f) * scale - 0.5f;
  const int u0 = static_cast<int>(std::floor(u));
  const int v0 = static_cast<int>(std::floor(v));
  const float fu = u - static_cast<float>(u0);
  const float fv = v - static_cast<float>(v0);
  const int columns[2] = {Reflect(u0, image.cols), Reflect(u0 + 1, image.cols)};
  const cv::Vec3b* rows[2] = {image.ptr<cv::Vec3b>(Reflect(v0, image.rows)),
                              image.ptr<cv::Vec3b>(Reflect(v0 + 1, image.rows))};
  cv::Vec3f value;
  for (int c = 0; c < 3; ++c) {
    const float top = (1.0f - fu) * rows[0][columns[0]][c] + fu * rows[0][columns[1]][c];
    const float bottom = (1.0f - fu) * rows[1][columns[0]][c] + fu * rows[1][columns[1]][c];
    value[c] = (1.0f - fv) * top + fv * bottom;
  }
  return value;
}

// The level-0 texel coordinates of every masked pixel.
cv::Mat TexelCoordinates(const cv::Mat& plane_xy, const cv::Mat& mask,
                         const TextureMapping& mapping) {
  const double c = std::cos(mapping.angle_rad) / mapping.mm_per_texel;
  const double s = std::sin(mapping.angle_rad) / mapping.mm_per_texel;
  cv::Mat texel_uv(mask.size(), CV_32FC2, cv::Scalar(0, 0));
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (mask.at<uchar>(y, x) == 0) continue;
      const cv::Vec2f& p = plane_xy.at<cv::Vec2f>(y, x);
      texel_uv.at<cv::Vec2f>(y, x) =
          cv::Vec2f(static_cast<float>(c * p[0] - s * p[1] + mapping.offset_texels.x()),
                    static_cast<float>(s * p[0] + c * p[1] + mapping.offset_texels.y()));
    }
  }
  return texel_uv;
}

}  // namespace

std::vector<fs::path> ListBackgroundImages(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw IoError(Quoted(dir) + ": backgrounds folder does not exist");
  }
  std::vector<fs::path> images;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (IsImageFile(entry.path()) && entry.is_regular_file(ec)) images.push_back(entry.path());
  }
  if (ec) throw IoError(Quoted(dir) + ": cannot list the folder (" + ec.message() + ")");
  if (images.empty()) {
    throw IoError(Quoted(dir) + ": backgrounds folder holds no image (png, jpg, bmp)");
  }
  std::sort(images.begin(), images.end());
  return images;
}

cv::Mat MakeProceduralTexture(SurfaceKind kind, std::mt19937_64& rng) {
  cv::RNG cv_rng(rng());
  double grey = 0.0;
  cv::Scalar tint;
  BaseColour(kind, rng, grey, tint);
  const double contrast = kind == SurfaceKind::kWall ? 0.4 : 1.0;
  const double broad_gain = contrast * Uniform(rng, 2.0, 5.0);
  const cv::Mat broad = SmoothNoise(40, cv_rng);
  const double coarse_gain = contrast * Uniform(rng, 5.0, 14.0);
  const cv::Mat coarse = SmoothNoise(5, cv_rng);
  cv::Mat shade = coarse * coarse_gain + broad * broad_gain;
  cv::Mat fine(kTextureSize, kTextureSize, CV_32F);
  cv_rng.fill(fine, cv::RNG::NORMAL, 0.0, Uniform(rng, 1.0, 4.0));
  shade += fine;
  // Grain on tables only: a floor seen from afar would turn it into moire.
  if (kind == SurfaceKind::kTable && Uniform(rng, 0.0, 1.0) < 0.4) AddGrain(shade, rng, cv_rng);
  cv::Mat channels[3];
  for (int c = 0; c < 3; ++c) channels[c] = shade + (grey + tint[c]);
  cv::Mat texture;
  cv::merge(channels, 3, texture);
  if (kind == SurfaceKind::kTable) AddLines(texture, grey, tint, rng);
  cv::Mat result;
  texture.convertTo(result, CV_8UC3);
  return result;
}

cv::Mat MakeTableTexture(const std::vector<fs::path>& backgrounds, std::mt19937_64& rng) {
  if (backgrounds.empty()) return MakeProceduralTexture(SurfaceKind::kTable, rng);
  const auto index = std::uniform_int_distribution<std::size_t>(0, backgrounds.size() - 1)(rng);
  return PhotoTexture(backgrounds[index], rng);
}

TextureMapping RandomTextureMapping(double min_side_mm, double max_side_mm, std::mt19937_64& rng) {
  TextureMapping mapping;
  mapping.mm_per_texel = Uniform(rng, min_side_mm, max_side_mm) / kTextureSize;
  mapping.angle_rad = Uniform(rng, -kPi, kPi);
  mapping.offset_texels = {Uniform(rng, 0.0, 2.0 * kTextureSize),
                           Uniform(rng, 0.0, 2.0 * kTextureSize)};
  return mapping;
}

cv::Mat SampleTexture(const cv::Mat& texture, const cv::Mat& plane_xy, const cv::Mat& mask,
                      const TextureMapping& mapping) {
  CV_Assert(texture.type() == CV_8UC3 && texture.cols == kTextureSize &&
            texture.rows == kTextureSize && plane_xy.type() == CV_32FC2 && mask.type() == CV_8U &&
            mask.size() == plane_xy.size());
  const cv::Mat texel_uv = TexelCoordinates(plane_xy, mask, mapping);
  std::vector<cv::Mat> pyramid;
  cv::buildPyramid(texture, pyramid, kMipLevels - 1);
  cv::Mat color = cv::Mat::zeros(mask.size(), CV_8UC3);
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (mask.at<uchar>(y, x) == 0) continue;
      const cv::Vec2f& uv = texel_uv.at<cv::Vec2f>(y, x);
      const cv::Vec2f folded(Fold(uv[0], kTextureSize), Fold(uv[1], kTextureSize));
      // Trilinear: the two mip levels around the footprint, blended.
      const float level = std::min(0.5f * std::log2(FootprintSquared(texel_uv, mask, x, y)),
                                   static_cast<float>(kMipLevels - 1));
      const int low = std::min(static_cast<int>(level), kMipLevels - 2);
      const float blend = level - static_cast<float>(low);
      const cv::Vec3f value =
          (1.0f - blend) * Bilinear(pyramid[static_cast<std::size_t>(low)], folded, low) +
          blend * Bilinear(pyramid[static_cast<std::size_t>(low) + 1], folded, low + 1);
      color.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uchar>(value[0]), cv::saturate_cast<uchar>(value[1]),
                    cv::saturate_cast<uchar>(value[2]));
    }
  }
  return color;
}

}  // namespace layermod
