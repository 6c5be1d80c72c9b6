// SPDX-License-Identifier: MIT
#include "dataset/image_header.h"

#include <opencv2/imgcodecs.hpp>

#include <cstdint>
#include <cstring>
#include <string>

#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

std::uint32_t BigEndian(std::string_view bytes, std::size_t at, int count) {
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) value = value << 8 | static_cast<std::uint8_t>(bytes[at + i]);
  return value;
}

std::optional<cv::Size> PngSize(std::string_view bytes) {
  // Signature (8), IHDR length (4) and type (4), then width and height (4 + 4, big-endian).
  if (bytes.size() < 24 || bytes.substr(12, 4) != "IHDR") return std::nullopt;
  const std::uint32_t width = BigEndian(bytes, 16, 4);
  const std::uint32_t height = BigEndian(bytes, 20, 4);
  if (width > 1u << 30 || height > 1u << 30) return cv::Size(1 << 30, 1 << 30);
  return cv::Size(static_cast<int>(width), static_cast<int>(height));
}

bool IsStartOfFrame(std::uint8_t marker) {
  return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
}

std::optional<cv::Size> JpegSize(std::string_view bytes) {
  std::size_t at = 2;  // after SOI
  while (at + 9 <= bytes.size()) {
    if (static_cast<std::uint8_t>(bytes[at]) != 0xFF) return std::nullopt;
    const auto marker = static_cast<std::uint8_t>(bytes[at + 1]);
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    const std::uint32_t length = BigEndian(bytes, at + 2, 2);
    if (IsStartOfFrame(marker)) {
      return cv::Size(static_cast<int>(BigEndian(bytes, at + 7, 2)),
                      static_cast<int>(BigEndian(bytes, at + 5, 2)));
    }
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<cv::Size> DeclaredImageSize(std::string_view bytes) {
  if (bytes.size() >= 8 && bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) {
    return PngSize(bytes);
  }
  if (bytes.size() >= 3 && bytes.substr(0, 3) == std::string_view("\xFF\xD8\xFF", 3)) {
    return JpegSize(bytes);
  }
  return std::nullopt;
}

void CheckDeclaredImageSize(const std::filesystem::path& path, std::string_view bytes,
                            std::optional<cv::Size> expected, std::string_view what) {
  const std::optional<cv::Size> size = DeclaredImageSize(bytes);
  if (!size) return;
  const std::string text = std::to_string(size->width) + "x" + std::to_string(size->height);
  if (static_cast<long long>(size->width) * size->height > kMaxImagePixels) {
    throw FormatError(Quoted(path) + ": image declares " + text + " pixels, more than " +
                      std::to_string(kMaxImagePixels >> 20) + " Mpx; refusing to decode it");
  }
  if (expected && *size != *expected) {
    throw FormatError(Quoted(path) + ": image is " + text + " but " + std::string(what) + " says " +
                      std::to_string(expected->width) + "x" + std::to_string(expected->height));
  }
}

cv::Mat DecodeImageBytes(std::string_view bytes, int flags) {
  try {
    const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
    return cv::imdecode(buffer, flags);
  } catch (const cv::Exception&) {
    return {};
  }
}

}  // namespace layermod
