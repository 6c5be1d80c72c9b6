// SPDX-License-Identifier: MIT
#include "eval/precision_recall.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace layermod {
namespace {

struct Judged {
  double confidence = 0.0;
  bool right = false;
};

std::vector<Judged> JudgedDetections(const std::vector<TargetOutcome>& outcomes) {
  std::vector<Judged> judged;
  for (const TargetOutcome& outcome : outcomes) {
    if (!outcome.detected) continue;
    judged.push_back({outcome.confidence, outcome.present && outcome.pose.correct});
  }
  std::sort(judged.begin(), judged.end(),
            [](const Judged& a, const Judged& b) { return a.confidence > b.confidence; });
  return judged;
}

int CountTargets(const std::vector<TargetOutcome>& outcomes) {
  return static_cast<int>(std::count_if(outcomes.begin(), outcomes.end(),
                                        [](const TargetOutcome& o) { return o.present; }));
}

PrecisionRecallPoint MakePoint(double threshold, int right, int accepted, int targets) {
  PrecisionRecallPoint point;
  point.threshold = threshold;
  point.precision = accepted > 0 ? static_cast<double>(right) / accepted : 1.0;
  point.recall = targets > 0 ? static_cast<double>(right) / targets : 0.0;
  return point;
}

double MonotoneArea(const std::vector<PrecisionRecallPoint>& points) {
  // From the highest recall down, each recall step weighted by the best precision at that
  // recall or beyond.
  double area = 0.0;
  double best_precision = 0.0;
  for (std::size_t i = points.size(); i-- > 0;) {
    best_precision = std::max(best_precision, points[i].precision);
    const double lower_recall = i == 0 ? 0.0 : points[i - 1].recall;
    area += (points[i].recall - lower_recall) * best_precision;
  }
  return area;
}

}  // namespace

PrecisionRecallCurve ComputePrecisionRecall(const std::vector<TargetOutcome>& outcomes) {
  PrecisionRecallCurve curve;
  curve.targets = CountTargets(outcomes);
  const std::vector<Judged> judged = JudgedDetections(outcomes);
  int right = 0;
  for (std::size_t i = 0; i < judged.size(); ++i) {
    right += judged[i].right ? 1 : 0;
    const bool last_of_value =
        i + 1 == judged.size() || judged[i + 1].confidence < judged[i].confidence;
    if (last_of_value) {
      curve.points.push_back(
          MakePoint(judged[i].confidence, right, static_cast<int>(i + 1), curve.targets));
    }
  }
  curve.area = MonotoneArea(curve.points);
  return curve;
}

PrecisionRecallPoint PointAt(const std::vector<TargetOutcome>& outcomes, double threshold) {
  int right = 0;
  int accepted = 0;
  for (const Judged& judged : JudgedDetections(outcomes)) {
    if (judged.confidence < threshold) break;
    ++accepted;
    right += judged.right ? 1 : 0;
  }
  return MakePoint(threshold, right, accepted, CountTargets(outcomes));
}

cv::Mat DrawPrecisionRecall(const PrecisionRecallCurve& curve, const PrecisionRecallPoint& chosen) {
  const cv::Size size(560, 440);
  const cv::Rect plot(70, 30, 460, 340);
  cv::Mat image(size, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto to_pixel = [&](double recall, double precision) {
    return cv::Point(plot.x + static_cast<int>(recall * plot.width),
                     plot.y + plot.height - static_cast<int>(precision * plot.height));
  };
  const cv::Scalar grid(225, 225, 225), ink(40, 40, 40), line(200, 110, 30), mark(40, 40, 220);
  for (int i = 0; i <= 10; ++i) {
    const double v = i / 10.0;
    cv::line(image, to_pixel(v, 0.0), to_pixel(v, 1.0), grid, 1);
    cv::line(image, to_pixel(0.0, v), to_pixel(1.0, v), grid, 1);
    if (i % 2 == 0) {
      char label[8];
      std::snprintf(label, sizeof label, "%.1f", v);
      cv::putText(image, label, to_pixel(v, 0.0) + cv::Point(-12, 18), cv::FONT_HERSHEY_SIMPLEX,
                  0.4, ink, 1, cv::LINE_AA);
      cv::putText(image, label, to_pixel(0.0, v) + cv::Point(-32, 4), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                  ink, 1, cv::LINE_AA);
    }
  }
  cv::rectangle(image, plot, ink, 1);
  cv::Point previous = to_pixel(0.0, curve.points.empty() ? 1.0 : curve.points.front().precision);
  for (const PrecisionRecallPoint& point : curve.points) {
    const cv::Point current = to_pixel(point.recall, point.precision);
    cv::line(image, previous, current, line, 2, cv::LINE_AA);
    previous = current;
  }
  cv::circle(image, to_pixel(chosen.recall, chosen.precision), 6, mark, 2, cv::LINE_AA);
  char caption[160];
  std::snprintf(caption, sizeof caption,
                "min confidence %.2f: precision %.3f, recall %.3f; area %.3f", chosen.threshold,
                chosen.precision, chosen.recall, curve.area);
  cv::putText(image, caption, cv::Point(plot.x, 20), cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1,
              cv::LINE_AA);
  cv::putText(image, "recall", cv::Point(plot.x + plot.width / 2 - 20, size.height - 20),
              cv::FONT_HERSHEY_SIMPLEX, 0.5, ink, 1, cv::LINE_AA);
  cv::putText(image, "precision", cv::Point(4, plot.y - 8), cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1,
              cv::LINE_AA);
  return image;
}

}  // namespace layermod
