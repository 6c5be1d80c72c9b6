// SPDX-License-Identifier: MIT
#include "cli/image_output.h"

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod::cli {

void WritePng(const std::filesystem::path& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (image.empty() || !cv::imencode(".png", image, bytes)) {
    throw IoError(Quoted(path) + ": cannot encode the image as PNG");
  }
  WriteFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace layermod::cli
