// SPDX-License-Identifier: MIT
#include "dataset/bop_images.h"
#include "dataset/image_header.h"

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "dataset/bop_json.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

using bop_internal::Quoted;

// Decodes a file read into memory: imread cannot tell "missing" from "undecodable".
cv::Mat DecodeFile(const fs::path& path, int flags) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw IoError(Quoted(path) + ": image is missing");
  const std::string bytes = ReadFileBytes(path);
  CheckDeclaredImageSize(path, bytes, std::nullopt, "");
  const cv::Mat image = DecodeImageBytes(bytes, flags);
  if (image.empty()) throw IoError(Quoted(path) + ": cannot decode the image");
  return image;
}

}  // namespace

cv::Mat ReadBopColor(const fs::path& path) {
  cv::Mat image = DecodeFile(path, cv::IMREAD_COLOR);
  if (image.depth() != CV_8U) image.convertTo(image, CV_8U, 1.0 / 257.0);
  return image;
}

cv::Mat ReadBopDepth(const fs::path& path, double depth_scale) {
  const cv::Mat raw = DecodeFile(path, cv::IMREAD_UNCHANGED);
  if (raw.channels() != 1 || raw.depth() != CV_16U) {
    throw FormatError(Quoted(path) + ": depth must be a single-channel 16-bit PNG (found " +
                      std::to_string(raw.channels()) + " channel(s) of " +
                      (raw.depth() == CV_8U ? "8" : "non-16") + "-bit data)");
  }
  cv::Mat depth_mm;
  raw.convertTo(depth_mm, CV_32F, depth_scale);
  return depth_mm;
}

cv::Mat EncodeBopDepth(const cv::Mat& depth_mm, double depth_scale) {
  CV_Assert(depth_mm.type() == CV_32F && depth_scale > 0.0);
  cv::Mat encoded(depth_mm.size(), CV_16U);
  for (int y = 0; y < depth_mm.rows; ++y) {
    const float* in = depth_mm.ptr<float>(y);
    auto* out = encoded.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_mm.cols; ++x) {
      const double value = std::isfinite(in[x]) ? in[x] / depth_scale : 0.0;
      out[x] = static_cast<std::uint16_t>(std::clamp(std::round(value), 0.0, 65535.0));
    }
  }
  return encoded;
}

void WritePngAtomically(const fs::path& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  bool encoded = false;
  try {
    encoded = cv::imencode(".png", image, bytes);
  } catch (const cv::Exception&) {
    encoded = false;
  }
  if (!encoded) throw IoError(Quoted(path) + ": cannot encode the image as PNG");
  WriteFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace layermod
