// SPDX-License-Identifier: MIT
#include "match_test_util.h"

#include <algorithm>
#include <numeric>

namespace layermod::test {

cv::Mat RandomQuantized(const cv::Size& size, double density, cv::RNG& rng) {
  cv::Mat image = cv::Mat::zeros(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      if (rng.uniform(0.0, 1.0) < density) image.at<std::uint8_t>(y, x) = 1 << rng.uniform(0, 8);
    }
  }
  return image;
}

cv::Mat RandomBytes(const cv::Size& size, cv::RNG& rng) {
  cv::Mat image(size, CV_8UC1);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

cv::Mat NaiveSpread(const cv::Mat& quantized, int spread_px) {
  cv::Mat spread = cv::Mat::zeros(quantized.size(), CV_8UC1);
  for (int y = 0; y < quantized.rows; ++y) {
    for (int x = 0; x < quantized.cols; ++x) {
      std::uint8_t bits = 0;
      for (int dy = 0; dy < spread_px && y + dy < quantized.rows; ++dy) {
        for (int dx = 0; dx < spread_px && x + dx < quantized.cols; ++dx) {
          bits |= quantized.at<std::uint8_t>(y + dy, x + dx);
        }
      }
      spread.at<std::uint8_t>(y, x) = bits;
    }
  }
  return spread;
}

int NaiveOrientationSimilarity(int label, int scene_label) {
  static const int kTable[8][8] = {
      {4, 1, 0, 0, 0, 0, 0, 1}, {1, 4, 1, 0, 0, 0, 0, 0}, {0, 1, 4, 1, 0, 0, 0, 0},
      {0, 0, 1, 4, 1, 0, 0, 0}, {0, 0, 0, 1, 4, 1, 0, 0}, {0, 0, 0, 0, 1, 4, 1, 0},
      {0, 0, 0, 0, 0, 1, 4, 1}, {1, 0, 0, 0, 0, 0, 1, 4},
  };
  return kTable[label][scene_label];
}

cv::Mat NaiveResponse(const cv::Mat& spread, int label) {
  cv::Mat response = cv::Mat::zeros(spread.size(), CV_8UC1);
  for (int y = 0; y < spread.rows; ++y) {
    for (int x = 0; x < spread.cols; ++x) {
      int best = 0;
      for (int bit = 0; bit < 8; ++bit) {
        if (spread.at<std::uint8_t>(y, x) & (1 << bit)) {
          best = std::max(best, NaiveOrientationSimilarity(label, bit));
        }
      }
      response.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(best);
    }
  }
  return response;
}

NaiveResponses NaiveSceneResponses(const std::array<cv::Mat, 2>& quantized, int spread_px) {
  NaiveResponses responses;
  for (int m = 0; m < 2; ++m) {
    if (quantized[m].empty()) continue;
    const cv::Mat spread = NaiveSpread(quantized[m], spread_px);
    for (int label = 0; label < 8; ++label) responses[m][label] = NaiveResponse(spread, label);
  }
  return responses;
}

int NaiveScore(const TemplateLevel& level, const NaiveResponses& responses,
               const cv::Point& position) {
  int score = 0;
  for (const Feature& f : level.features) {
    const cv::Mat& map = responses[static_cast<int>(f.modality)][f.label];
    if (map.empty()) continue;
    score += map.at<std::uint8_t>(position.y + f.y, position.x + f.x);
  }
  return score;
}

TemplateLevel TemplateFromPatch(const std::array<cv::Mat, 2>& quantized, const cv::Rect& box,
                                int per_modality, int pyramid_level, cv::RNG& rng) {
  TemplateLevel level;
  level.pyramid_level = pyramid_level;
  level.width = box.width;
  level.height = box.height;
  for (int m = 0; m < 2; ++m) {
    if (quantized[m].empty()) continue;
    std::vector<Feature> labelled;
    for (int y = 0; y < box.height; ++y) {
      for (int x = 0; x < box.width; ++x) {
        const int bits = quantized[m].at<std::uint8_t>(box.y + y, box.x + x);
        if (bits == 0) continue;
        int label = 0;
        while ((bits >> label) != 1) ++label;
        labelled.push_back({static_cast<std::int16_t>(x), static_cast<std::int16_t>(y),
                            static_cast<std::uint8_t>(label), static_cast<Modality>(m)});
      }
    }
    for (int i = static_cast<int>(labelled.size()) - 1; i > 0; --i) {
      std::swap(labelled[i], labelled[rng.uniform(0, i + 1)]);
    }
    labelled.resize(std::min<std::size_t>(labelled.size(), per_modality));
    level.features.insert(level.features.end(), labelled.begin(), labelled.end());
  }
  return level;
}

TestScene RandomScene(const cv::Size& size, double density, cv::RNG& rng) {
  TestScene scene;
  const cv::Size level1((size.width + 1) / 2, (size.height + 1) / 2);
  for (const cv::Size& level_size : {size, level1}) {
    scene.quantized.push_back(
        {RandomQuantized(level_size, density, rng), RandomQuantized(level_size, density, rng)});
  }
  return scene;
}

namespace {
cv::Rect LevelBox(const cv::Rect& box, int level) {
  return {box.x >> level, box.y >> level, std::max(box.width >> level, 1),
          std::max(box.height >> level, 1)};
}
}  // namespace

TemplateRecord TemplateFromScene(const TestScene& scene, const cv::Rect& box, int per_modality,
                                 std::uint32_t id, cv::RNG& rng) {
  TemplateRecord record;
  record.id = id;
  record.bbox_px = box;
  for (int level = 0; level < static_cast<int>(scene.quantized.size()); ++level) {
    record.levels.push_back(
        TemplateFromPatch(scene.quantized[level], LevelBox(box, level), per_modality, level, rng));
  }
  return record;
}

void CopyPatch(TestScene& scene, const cv::Rect& box, const cv::Point& to) {
  for (int level = 0; level < static_cast<int>(scene.quantized.size()); ++level) {
    const cv::Rect source = LevelBox(box, level);
    const cv::Rect target(cv::Point(to.x >> level, to.y >> level), source.size());
    for (cv::Mat& image : scene.quantized[level]) {
      if (!image.empty()) image(source).clone().copyTo(image(target));
    }
  }
}

}  // namespace layermod::test
