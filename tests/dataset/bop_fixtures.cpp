// SPDX-License-Identifier: MIT
#include "bop_fixtures.h"

#include <cstdint>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace layermod::test {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> SplitIds(const std::string& ids_csv) {
  std::vector<std::string> ids;
  std::stringstream stream(ids_csv);
  for (std::string id; std::getline(stream, id, ',');) ids.push_back(id);
  return ids;
}

// {"id": entry, ...} for every id.
std::string PerImage(const std::string& ids_csv, const std::string& entry) {
  std::string json = "{";
  for (const std::string& id : SplitIds(ids_csv)) {
    if (json.size() > 1) json += ",";
    json += "\"" + id + "\": " + entry;
  }
  return json + "}";
}

}  // namespace

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string SceneCameraJson(const std::string& ids_csv, const std::string& cam_k,
                            const std::string& depth_scale) {
  const std::string k = cam_k.empty() ? "[60.0, 0, 31.5, 0, 61.0, 23.5, 0, 0, 1]" : cam_k;
  return PerImage(ids_csv, "{\"cam_K\": " + k + ", \"depth_scale\": " + depth_scale + "}");
}

std::string SceneGtJson(const std::string& ids_csv, const std::string& r, const std::string& t) {
  const std::string rotation = r.empty() ? "[1, 0, 0, 0, 1, 0, 0, 0, 1]" : r;
  const std::string translation = t.empty() ? "[1.5, -2.25, 700.125]" : t;
  return PerImage(ids_csv, "[{\"cam_R_m2c\": " + rotation + ", \"cam_t_m2c\": " + translation +
                               ", \"obj_id\": 7}]");
}

std::string SceneGtInfoJson(const std::string& ids_csv) {
  return PerImage(ids_csv,
                  "[{\"bbox_obj\": [10, 11, 12, 13], \"bbox_visib\": [10, 11, 6, 7], "
                  "\"px_count_all\": 100, \"px_count_valid\": 90, \"px_count_visib\": 50, "
                  "\"visib_fract\": 0.5}]");
}

fs::path WriteTinyScene(const fs::path& root) {
  const fs::path scene = root / "test" / "000002";
  fs::create_directories(scene / "rgb");
  fs::create_directories(scene / "depth");
  WriteText(scene / "scene_camera.json", SceneCameraJson("0,5"));
  WriteText(scene / "scene_gt.json", SceneGtJson("0,5"));
  WriteText(scene / "scene_gt_info.json", SceneGtInfoJson("0,5"));
  for (const char* stem : {"000000", "000005"}) {
    const cv::Mat color(48, 64, CV_8UC3, cv::Scalar(10, 20, 30));
    cv::Mat depth(48, 64, CV_16U);
    for (int y = 0; y < depth.rows; ++y) {
      for (int x = 0; x < depth.cols; ++x) {
        depth.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(500 + x + y);
      }
    }
    cv::imwrite((scene / "rgb" / (std::string(stem) + ".png")).string(), color);
    cv::imwrite((scene / "depth" / (std::string(stem) + ".png")).string(), depth);
  }
  return scene;
}

}  // namespace layermod::test
