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

// The plot's frame: a caption line at the top, the axis name "precision" on its own line under
// it (above the vertical axis), the plot area, the tick labels and "recall" under it.
constexpr int kCaptionBaselinePx = 20;
const cv::Size kPlotImageSize(560, 460);
const cv::Rect kPlotArea(70, 50, 460, 340);
const cv::Scalar kInk(40, 40, 40);

cv::Point ToPixel(double recall, double precision) {
  return {kPlotArea.x + static_cast<int>(recall * kPlotArea.width),
          kPlotArea.y + kPlotArea.height - static_cast<int>(precision * kPlotArea.height)};
}

void PutLabel(cv::Mat& image, const std::string& text, cv::Point at, double scale) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, kInk, 1, cv::LINE_AA);
}

void DrawGridAndAxes(cv::Mat& image) {
  const cv::Scalar grid(225, 225, 225);
  for (int i = 0; i <= 10; ++i) {
    const double v = i / 10.0;
    cv::line(image, ToPixel(v, 0.0), ToPixel(v, 1.0), grid, 1);
    cv::line(image, ToPixel(0.0, v), ToPixel(1.0, v), grid, 1);
    if (i % 2 == 0) {
      char label[8];
      std::snprintf(label, sizeof label, "%.1f", v);
      PutLabel(image, label, ToPixel(v, 0.0) + cv::Point(-12, 18), 0.4);
      PutLabel(image, label, ToPixel(0.0, v) + cv::Point(-32, 4), 0.4);
    }
  }
  cv::rectangle(image, kPlotArea, kInk, 1);
  PutLabel(image, "recall",
           cv::Point(kPlotArea.x + kPlotArea.width / 2 - 20, kPlotImageSize.height - 20), 0.5);
  PutLabel(image, "precision", cv::Point(4, kPlotArea.y - 12), 0.45);
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
  cv::Mat image(kPlotImageSize, CV_8UC3, cv::Scalar(255, 255, 255));
  DrawGridAndAxes(image);
  const cv::Scalar line(200, 110, 30), mark(40, 40, 220);
  cv::Point previous = ToPixel(0.0, curve.points.empty() ? 1.0 : curve.points.front().precision);
  for (const PrecisionRecallPoint& point : curve.points) {
    const cv::Point current = ToPixel(point.recall, point.precision);
    cv::line(image, previous, current, line, 2, cv::LINE_AA);
    previous = current;
  }
  cv::circle(image, ToPixel(chosen.recall, chosen.precision), 6, mark, 2, cv::LINE_AA);
  char caption[160];
  std::snprintf(caption, sizeof caption,
                "min confidence %.2f: precision %.3f, recall %.3f; area %.3f", chosen.threshold,
                chosen.precision, chosen.recall, curve.area);
  PutLabel(image, caption, cv::Point(kPlotArea.x, kCaptionBaselinePx), 0.45);
  return image;
}

}  // namespace layermod
