// SPDX-License-Identifier: MIT
#pragma once

// Image files of a BOP scene: 8-bit colour and 16-bit depth PNGs.

#include <filesystem>
#include <opencv2/core.hpp>

namespace layermod {

// Reads a colour image as BGR8 (grey images are expanded). Throws IoError naming the file when
// it is missing or cannot be decoded.
cv::Mat ReadBopColor(const std::filesystem::path& path);

// Reads a 16-bit depth PNG and converts it to mm (CV_32F, value x depth_scale, 0 = invalid).
// Throws IoError when missing/undecodable, FormatError when it is not single-channel 16-bit.
cv::Mat ReadBopDepth(const std::filesystem::path& path, double depth_scale);

// Converts depth in mm to BOP's 16-bit encoding (round(mm / depth_scale), saturated at 65535;
// 0, negative and non-finite values become 0).
cv::Mat EncodeBopDepth(const cv::Mat& depth_mm, double depth_scale);

// Encodes `image` as PNG and writes it atomically. Throws IoError naming the file.
void WritePngAtomically(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace layermod
