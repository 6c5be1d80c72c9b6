// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

namespace layermod::cli {

// Encodes `image` as PNG and writes it atomically. Throws IoError naming the file.
void WritePng(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace layermod::cli
