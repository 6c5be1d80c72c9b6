// SPDX-License-Identifier: MIT
#pragma once

// Textures of the synthetic scenes' backdrop (table, floor, wall): random crops of photos or
// procedural surfaces, and their sampling on a plane seen in perspective: tiled by mirroring
// (no seams) and filtered by each pixel's footprint (mipmapping), so that a far, grazing surface
// looks like a surface, not like noise.

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace layermod {

inline constexpr int kTextureSize = 512;  // texels per side (a power of two for the mips)

// The images (png, jpg, jpeg, bmp) of a folder, sorted by name. Throws IoError when the folder
// does not exist or holds none.
std::vector<std::filesystem::path> ListBackgroundImages(const std::filesystem::path& dir);

enum class SurfaceKind { kTable, kFloor, kWall };

// A square BGR8 procedural surface: a base colour typical of `kind`, shading at a few scales,
// sometimes grain, and (tables) a few lines: seams, tape, scratches.
cv::Mat MakeProceduralTexture(SurfaceKind kind, std::mt19937_64& rng);

// A random square crop of a random `backgrounds` image, resized to the texture size; the
// procedural table texture when `backgrounds` is empty. Throws IoError when the chosen image
// cannot be read.
cv::Mat MakeTableTexture(const std::vector<std::filesystem::path>& backgrounds,
                         std::mt19937_64& rng);

// How a texture lies on its plane: texel = rotation(angle) * (plane xy) / mm_per_texel + offset.
struct TextureMapping {
  double mm_per_texel = 1.5;
  double angle_rad = 0.0;
  Eigen::Vector2d offset_texels = Eigen::Vector2d::Zero();
};

// A random placement with the texture's side covering min..max mm.
TextureMapping RandomTextureMapping(double min_side_mm, double max_side_mm, std::mt19937_64& rng);

// The texture's colour (BGR8) at every pixel of `mask` from its plane coordinates `plane_xy`
// (CV_32FC2, mm); black elsewhere.
cv::Mat SampleTexture(const cv::Mat& texture, const cv::Mat& plane_xy, const cv::Mat& mask,
                      const TextureMapping& mapping);

}  // namespace layermod
