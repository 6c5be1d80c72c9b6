// SPDX-License-Identifier: MIT
#include "render/rasterizer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "render/test_meshes.h"
#include "util/error.h"

namespace layermod {
namespace {

using test::AnalyticHit;
using test::KinectCamera;
using test::LookAtPose;
using test::PixelRay;

using Intersector = std::function<std::optional<AnalyticHit>(const Eigen::Vector3d& ray)>;

// The analytic answer for every pixel centre of the camera image.
struct AnalyticImage {
  int width = 0;
  int height = 0;
  std::vector<std::optional<AnalyticHit>> hits;

  const std::optional<AnalyticHit>& at(int x, int y) const { return hits[y * width + x]; }
  // True when all 3x3 neighbours agree on hit/miss (and face): the analytic boundary is then
  // farther than one pixel, so the renderer must agree exactly.
  bool Interior(int x, int y) const {
    const auto& centre = at(x, y);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx;
        const int ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        const auto& other = at(nx, ny);
        if (other.has_value() != centre.has_value()) return false;
        if (centre && other->face != centre->face) return false;
      }
    }
    return true;
  }
};

AnalyticImage Analytic(const PinholeCamera& camera, const Intersector& intersect) {
  AnalyticImage image;
  image.width = camera.width;
  image.height = camera.height;
  image.hits.reserve(static_cast<std::size_t>(camera.width) * camera.height);
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) image.hits.push_back(intersect(PixelRay(camera, x, y)));
  }
  return image;
}

struct Comparison {
  int interior_mask_errors = 0;  // disagreements farther than 1 px from the analytic boundary
  int boundary_mask_errors = 0;
  int interior_hits = 0;  // pixels where depth and normal were compared
  double max_depth_error_mm = 0.0;
  double max_normal_error_deg = 0.0;
};

// Compares a kFullImage render with the analytic image.
Comparison Compare(const RenderedView& view, const AnalyticImage& analytic) {
  Comparison result;
  for (int y = 0; y < analytic.height; ++y) {
    for (int x = 0; x < analytic.width; ++x) {
      const auto& hit = analytic.at(x, y);
      const bool covered = view.mask.at<std::uint8_t>(y, x) == 255;
      const bool interior = analytic.Interior(x, y);
      if (covered != hit.has_value())
        ++(interior ? result.interior_mask_errors : result.boundary_mask_errors);
      if (!covered || !hit || !interior) continue;
      ++result.interior_hits;
      const double depth = view.depth_mm.at<float>(y, x);
      result.max_depth_error_mm =
          std::max(result.max_depth_error_mm, std::abs(depth - hit->depth_mm));
      const cv::Vec3f n = view.normals.at<cv::Vec3f>(y, x);
      const Eigen::Vector3d normal(n[0], n[1], n[2]);
      // atan2 keeps small angles accurate, where acos of a cosine near 1 does not.
      const double angle = std::atan2(normal.cross(hit->normal).norm(), normal.dot(hit->normal));
      result.max_normal_error_deg = std::max(result.max_normal_error_deg, RadToDeg(angle));
    }
  }
  return result;
}

cv::Rect NonZeroBounds(const cv::Mat& mask) {
  int x0 = mask.cols, y0 = mask.rows, x1 = -1, y1 = -1;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (mask.at<std::uint8_t>(y, x) == 0) continue;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  }
  return x1 < 0 ? cv::Rect() : cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
}

RenderOptions FullImage() {
  RenderOptions options;
  options.window = RenderWindow::kFullImage;
  return options;
}

double MaxAbsDifference(const cv::Mat& a, const cv::Mat& b) { return cv::norm(a, b, cv::NORM_INF); }

bool Identical(const RenderedView& a, const RenderedView& b) {
  return a.roi == b.roi && MaxAbsDifference(a.depth_mm, b.depth_mm) == 0.0 &&
         MaxAbsDifference(a.mask, b.mask) == 0.0 && MaxAbsDifference(a.normals, b.normals) == 0.0 &&
         MaxAbsDifference(a.color, b.color) == 0.0;
}

TEST(RasterizerTest, SphereMatchesAnalyticSilhouetteDepthAndNormals) {
  const double radius_mm = 100.0;
  const RenderMesh sphere = test::MakeIcosphere(radius_mm, 5);
  const PinholeCamera camera = KinectCamera();
  const std::vector<Pose> poses = {
      LookAtPose(800, 0, 0, 0), LookAtPose(600, 30, -20, 10, {80, -40}),
      LookAtPose(1200, -70, 45, 160, {-250, 120}), LookAtPose(450, 10, 80, -30, {-300, 0})};
  for (const Pose& pose : poses) {
    SCOPED_TRACE("sphere at t = " + std::to_string(pose.t.x()) + ", " + std::to_string(pose.t.y()) +
                 ", " + std::to_string(pose.t.z()));
    const RenderedView view = RenderView(sphere, camera, pose, FullImage());
    const AnalyticImage analytic = Analytic(camera, [&](const Eigen::Vector3d& ray) {
      return test::IntersectSphere(ray, pose.t, radius_mm);
    });
    const Comparison result = Compare(view, analytic);
    EXPECT_EQ(result.interior_mask_errors, 0);
    EXPECT_GT(result.interior_hits, 1000);
    EXPECT_LT(result.max_depth_error_mm, 0.5);
    EXPECT_LT(result.max_normal_error_deg, 3.0);
  }
}

TEST(RasterizerTest, BoxMatchesAnalyticProjectionExactly) {
  const Eigen::Vector3d half_size(60.0, 40.0, 25.0);
  const RenderMesh box = test::MakeBox(half_size, 3);
  const PinholeCamera camera = KinectCamera();
  const std::vector<Pose> poses = {LookAtPose(700, 0, 0, 0), LookAtPose(800, 35, 25, 10, {50, 30}),
                                   LookAtPose(1000, -120, 60, 75, {-200, -100}),
                                   LookAtPose(400, 45, -45, 0)};
  for (const Pose& pose : poses) {
    const RenderedView view = RenderView(box, camera, pose, FullImage());
    const AnalyticImage analytic = Analytic(camera, [&](const Eigen::Vector3d& ray) {
      return test::IntersectBox(ray, pose, half_size);
    });
    const Comparison result = Compare(view, analytic);
    EXPECT_EQ(result.interior_mask_errors, 0);
    EXPECT_GT(result.interior_hits, 1000);
    // Planar faces: depth and normals are exact up to float rounding.
    EXPECT_LT(result.max_depth_error_mm, 0.01);
    EXPECT_LT(result.max_normal_error_deg, 0.01);
  }
}

TEST(RasterizerTest, EveryNthPixelCameraRendersTheFullImageSampled) {
  const Eigen::Vector3d half_size(60.0, 40.0, 25.0);
  const RenderMesh box = test::MakeBox(half_size, 3);
  const PinholeCamera camera = KinectCamera();
  const int step = 3;
  const PinholeCamera sampled = camera.EveryNthPixel(step);
  const Pose pose = LookAtPose(800, 35, 25, 10, {50, 30});
  const RenderedView view = RenderView(box, sampled, pose, FullImage());
  const AnalyticImage analytic = Analytic(
      camera, [&](const Eigen::Vector3d& ray) { return test::IntersectBox(ray, pose, half_size); });
  int compared = 0;
  for (int y = 0; y < sampled.height; ++y) {
    for (int x = 0; x < sampled.width; ++x) {
      if (!analytic.Interior(step * x, step * y)) continue;
      const auto& hit = analytic.at(step * x, step * y);
      const float depth = view.depth_mm.at<float>(y, x);
      ASSERT_EQ(hit.has_value(), depth > 0.0f) << "sampled pixel " << x << ", " << y;
      if (!hit) continue;
      EXPECT_NEAR(depth, hit->depth_mm, 0.01) << "sampled pixel " << x << ", " << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(RasterizerTest, CameraInsideSphereSeesInnerSurfaceFacingIt) {
  // No back-face culling: meshes are not guaranteed closed or outward-oriented.
  const double radius_mm = 500.0;
  const RenderMesh sphere = test::MakeIcosphere(radius_mm, 4);
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(0, 20, 30, 40, {30, -20});
  const RenderedView view = RenderView(sphere, camera, pose, FullImage());
  EXPECT_EQ(cv::countNonZero(view.mask), camera.width * camera.height);
  const AnalyticImage analytic = Analytic(camera, [&](const Eigen::Vector3d& ray) {
    return test::IntersectSphere(ray, pose.t, radius_mm);
  });
  const Comparison result = Compare(view, analytic);
  EXPECT_EQ(result.interior_mask_errors, 0);
  EXPECT_LT(result.max_depth_error_mm, 0.5 * radius_mm / 100.0);  // coarser mesh, bigger sphere
  EXPECT_LT(result.max_normal_error_deg, 5.0);
}

TEST(RasterizerTest, ObjectWindowContainsSilhouetteWithPadding) {
  const RenderMesh sphere = test::MakeIcosphere(100.0, 4);
  const PinholeCamera camera = KinectCamera();
  const cv::Rect image(0, 0, camera.width, camera.height);
  for (const int padding_px : {0, 8, 25}) {
    for (const Eigen::Vector2d& offset :
         {Eigen::Vector2d(120, -50), Eigen::Vector2d(-350, 0), Eigen::Vector2d(260, 230)}) {
      const Pose pose = LookAtPose(700, 10, 20, 30, offset);
      RenderOptions options;
      options.padding_px = padding_px;
      const RenderedView window = RenderView(sphere, camera, pose, options);
      const RenderedView full = RenderView(sphere, camera, pose, FullImage());
      ASSERT_FALSE(window.empty());
      const cv::Rect silhouette = NonZeroBounds(full.mask);
      const auto padded = [&](int pad) {
        return cv::Rect(silhouette.x - pad, silhouette.y - pad, silhouette.width + 2 * pad,
                        silhouette.height + 2 * pad) &
               image;
      };
      EXPECT_EQ(window.roi & padded(padding_px), padded(padding_px)) << "roi " << window.roi;
      EXPECT_EQ(window.roi | padded(padding_px + 1), padded(padding_px + 1))
          << "roi " << window.roi;
      EXPECT_EQ(window.mask.size(), window.roi.size());
      EXPECT_EQ(cv::countNonZero(window.mask), cv::countNonZero(full.mask));
    }
  }
}

TEST(RasterizerTest, FullImageMatchesObjectWindowInsideRoi) {
  const RenderMesh box = test::MakeBox({70, 50, 30}, 2);
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(900, 30, -40, 15, {-60, 40});
  const RenderedView window = RenderView(box, camera, pose);
  const RenderedView full = RenderView(box, camera, pose, FullImage());
  ASSERT_FALSE(window.empty());
  EXPECT_EQ(full.roi, cv::Rect(0, 0, camera.width, camera.height));
  EXPECT_EQ(MaxAbsDifference(full.depth_mm(window.roi), window.depth_mm), 0.0);
  EXPECT_EQ(MaxAbsDifference(full.mask(window.roi), window.mask), 0.0);
  EXPECT_EQ(MaxAbsDifference(full.normals(window.roi), window.normals), 0.0);
  EXPECT_EQ(MaxAbsDifference(full.color(window.roi), window.color), 0.0);
  EXPECT_EQ(cv::countNonZero(full.mask), cv::countNonZero(window.mask));
}

TEST(RasterizerTest, ObjectBehindOrBesideTheCameraGivesEmptyView) {
  const RenderMesh sphere = test::MakeIcosphere(100.0, 3);
  const PinholeCamera camera = KinectCamera();
  for (const Pose& pose : {LookAtPose(-800, 0, 0, 0), LookAtPose(800, 0, 0, 0, {2000, 0}),
                           LookAtPose(800, 0, 0, 0, {0, -1500}), LookAtPose(50, 0, 0, 0, {0, 0})}) {
    // The last pose puts the camera inside the sphere's far half: part of it is visible.
    const bool visible = pose.t.z() == 50;
    const RenderedView window = RenderView(sphere, camera, pose);
    EXPECT_EQ(window.empty(), !visible);
    if (!visible) {
      EXPECT_EQ(window.roi.area(), 0);
      EXPECT_TRUE(window.mask.empty());
    }
    const RenderedView full = RenderView(sphere, camera, pose, FullImage());
    EXPECT_EQ(full.empty(), !visible);
  }
  EXPECT_TRUE(RenderView(RenderMesh{}, camera, LookAtPose(800, 0, 0, 0)).empty());
}

TEST(RasterizerTest, TriangleCrossingNearPlaneIsClipped) {
  RenderMesh triangle;
  triangle.positions = {{-400, -300, -200}, {400, -100, 900}, {-100, 400, 700}};
  triangle.colors.assign(3, Eigen::Vector3f::Ones());
  triangle.triangles = {{0, 1, 2}};
  const Eigen::Vector3d p0 = triangle.positions[0].cast<double>();
  const Eigen::Vector3d p1 = triangle.positions[1].cast<double>();
  const Eigen::Vector3d p2 = triangle.positions[2].cast<double>();
  const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
  const PinholeCamera camera = KinectCamera();
  for (const float near_mm : {1.0f, 300.0f}) {
    RenderOptions options = FullImage();
    options.near_mm = near_mm;
    const RenderedView view = RenderView(triangle, camera, Pose{}, options);
    const AnalyticImage analytic = Analytic(camera, [&](const Eigen::Vector3d& ray) {
      std::optional<AnalyticHit> hit;
      const double s = normal.dot(p0) / normal.dot(ray);
      const Eigen::Vector3d x = s * ray;
      const bool inside = normal.dot((p1 - p0).cross(x - p0)) >= 0 &&
                          normal.dot((p2 - p1).cross(x - p1)) >= 0 &&
                          normal.dot((p0 - p2).cross(x - p2)) >= 0;
      if (s > near_mm && inside) {
        hit = AnalyticHit{s, (normal.dot(x) > 0 ? -normal : normal).normalized(), 0};
      }
      return hit;
    });
    const Comparison result = Compare(view, analytic);
    EXPECT_EQ(result.interior_mask_errors, 0) << "near " << near_mm;
    EXPECT_GT(result.interior_hits, 10000);
    EXPECT_LT(result.max_depth_error_mm, 0.5);
    EXPECT_LT(result.max_normal_error_deg, 0.01);
    double min_depth_mm = 0.0;
    cv::minMaxLoc(view.depth_mm, &min_depth_mm, nullptr, nullptr, nullptr, view.mask);
    EXPECT_GE(min_depth_mm, near_mm);
    // The object window holds every covered pixel too.
    options.window = RenderWindow::kObjectOnly;
    const RenderedView window = RenderView(triangle, camera, Pose{}, options);
    EXPECT_EQ(cv::countNonZero(window.mask), cv::countNonZero(view.mask));
  }
}

TEST(RasterizerTest, HugeSlantedPlaneBeyondTheGuardBandCoversTheImage) {
  // A 40 m square seen from 1 m: its corners project thousands of pixels outside the image, so
  // its two triangles go through the guard-band clipper.
  RenderMesh plane = test::MakeGradientSquare(40000.0, 1);
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(1000, 20, 0, 0);
  const RenderedView view = RenderView(plane, camera, pose, FullImage());
  EXPECT_EQ(cv::countNonZero(view.mask), camera.width * camera.height);
  const Eigen::Vector3d normal = pose.R.col(2);
  const double offset = normal.dot(pose.t);
  double max_error_mm = 0.0;
  for (int y = 0; y < camera.height; y += 7) {
    for (int x = 0; x < camera.width; x += 7) {
      const Eigen::Vector3d ray = PixelRay(camera, x, y);
      const double expected = offset / normal.dot(ray);
      max_error_mm = std::max(max_error_mm, std::abs(view.depth_mm.at<float>(y, x) - expected));
    }
  }
  EXPECT_LT(max_error_mm, 0.01);
}

TEST(RasterizerTest, NonFiniteVerticesDropOnlyTheirTriangles) {
  RenderMesh mesh = test::MakeBox({50, 50, 50}, 1);
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(600, 0, 0, 0);
  const int clean = cv::countNonZero(RenderView(mesh, camera, pose).mask);
  mesh.positions.push_back({std::nanf(""), 0.0f, 0.0f});
  mesh.colors.push_back(Eigen::Vector3f::Ones());
  const auto bad = static_cast<std::uint32_t>(mesh.positions.size() - 1);
  mesh.triangles.push_back({0, 1, bad});
  const RenderedView view = RenderView(mesh, camera, pose);
  EXPECT_EQ(cv::countNonZero(view.mask), clean);
}

TEST(RasterizerTest, RendersAreDeterministicAcrossRunsAndThreads) {
  const RenderMesh sphere = test::MakeIcosphere(100.0, 4, {0.9f, 0.5f, 0.2f});
  const PinholeCamera camera = KinectCamera();
  std::vector<Pose> poses;
  for (int i = 0; i < 6; ++i) poses.push_back(LookAtPose(600 + 100 * i, 15 * i, -10 * i, 25 * i));
  std::vector<RenderedView> expected;
  for (const Pose& pose : poses) expected.push_back(RenderView(sphere, camera, pose));
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_TRUE(Identical(RenderView(sphere, camera, poses[i]), expected[i]));
  }
  std::vector<std::vector<RenderedView>> per_thread(4);
  std::vector<std::thread> threads;
  for (auto& results : per_thread) {
    threads.emplace_back([&] {
      for (const Pose& pose : poses) results.push_back(RenderView(sphere, camera, pose));
    });
  }
  for (auto& thread : threads) thread.join();
  for (const auto& results : per_thread) {
    ASSERT_EQ(results.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) EXPECT_TRUE(Identical(results[i], expected[i]));
  }
}

double MeanCoveredGrey(const RenderedView& view) {
  cv::Mat grey;
  cv::extractChannel(view.color, grey, 1);
  return cv::mean(grey, view.mask)[0];
}

TEST(RasterizerTest, LambertShadingIsBrighterHeadOnAndBackgroundIsBlack) {
  RenderMesh square = test::MakeGradientSquare(200.0, 2);
  square.colors.assign(square.positions.size(), Eigen::Vector3f::Ones());  // white
  const PinholeCamera camera = KinectCamera();
  const RenderedView head_on = RenderView(square, camera, LookAtPose(800, 0, 0, 0), FullImage());
  const RenderedView grazing = RenderView(square, camera, LookAtPose(800, 0, 75, 0), FullImage());
  ASSERT_FALSE(head_on.empty());
  ASSERT_FALSE(grazing.empty());
  EXPECT_GT(MeanCoveredGrey(head_on), MeanCoveredGrey(grazing) + 50.0);
  // Head-on white with the light at the camera: full brightness.
  EXPECT_NEAR(MeanCoveredGrey(head_on), 255.0, 2.0);
  // 75 deg: ambient + (1 - ambient) cos(75 deg), about 132 of 255 (the light is along -z, the
  // pixel rays are not, so allow a little).
  EXPECT_NEAR(MeanCoveredGrey(grazing), 255.0 * (0.35 + 0.65 * std::cos(DegToRad(75))), 3.0);
  for (const RenderedView* view : {&head_on, &grazing}) {
    const cv::Mat background = view->mask == 0;
    EXPECT_EQ(cv::countNonZero(background & (view->depth_mm != 0)), 0);
    cv::Mat any_color;
    cv::transform(view->color, any_color, cv::Matx13f(1, 1, 1));
    EXPECT_EQ(cv::countNonZero(background & (any_color != 0)), 0);
  }
}

TEST(RasterizerTest, ColoursArePerspectiveCorrectAndInBgrOrder) {
  const RenderMesh square = test::MakeGradientSquare(300.0, 1);  // two big triangles
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(700, 0, 60, 0);  // strongly foreshortened
  RenderOptions options = FullImage();
  options.ambient = 1.0f;  // no Lambert term: the colour is the interpolated vertex colour
  const RenderedView view = RenderView(square, camera, pose, options);
  ASSERT_FALSE(view.empty());
  int checked = 0;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      if (view.mask.at<std::uint8_t>(y, x) == 0) continue;
      // Back-project through the rendered depth to the model square; colour is linear there.
      const Eigen::Vector3d in_cam = view.depth_mm.at<float>(y, x) * PixelRay(camera, x, y);
      const Eigen::Vector3d in_model = pose.Inverse() * in_cam;
      const cv::Vec3b bgr = view.color.at<cv::Vec3b>(y, x);
      EXPECT_NEAR(bgr[2], 255.0 * (in_model.x() / 300.0 + 0.5), 1.01);
      EXPECT_NEAR(bgr[1], 255.0 * (in_model.y() / 300.0 + 0.5), 1.01);
      EXPECT_EQ(bgr[0], 255);
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

TEST(RasterizerTest, MeshWithoutColoursRendersGrey) {
  RenderMesh box = test::MakeBox({50, 50, 50}, 1);
  box.colors.clear();
  RenderOptions options;
  options.ambient = 1.0f;
  const RenderedView view = RenderView(box, KinectCamera(), LookAtPose(600, 0, 0, 0), options);
  ASSERT_FALSE(view.empty());
  EXPECT_NEAR(MeanCoveredGrey(view), 0.8 * 255.0, 1.0);
}

TEST(RasterizerTest, InvalidInputThrows) {
  const RenderMesh box = test::MakeBox({50, 50, 50}, 1);
  const PinholeCamera camera = KinectCamera();
  const Pose pose = LookAtPose(600, 0, 0, 0);
  const auto render_with = [&](auto change) {
    RenderOptions options;
    change(options);
    return RenderView(box, camera, pose, options);
  };
  EXPECT_THROW(render_with([](RenderOptions& o) { o.padding_px = -1; }), Error);
  EXPECT_THROW(render_with([](RenderOptions& o) { o.ambient = 1.5f; }), Error);
  EXPECT_THROW(render_with([](RenderOptions& o) { o.ambient = -0.1f; }), Error);
  EXPECT_THROW(render_with([](RenderOptions& o) { o.light_dir_in_cam.x() = std::nanf(""); }),
               Error);
  EXPECT_THROW(render_with([](RenderOptions& o) { o.light_dir_in_cam.setZero(); }), Error);
  EXPECT_THROW(render_with([](RenderOptions& o) { o.near_mm = 0.0f; }), Error);
  EXPECT_NO_THROW(RenderOptions{}.Validate());

  PinholeCamera bad_camera = camera;
  bad_camera.fx = 0.0;
  EXPECT_THROW(RenderView(box, bad_camera, pose), Error);

  RenderMesh bad_index = box;
  bad_index.triangles.push_back({0, 1, static_cast<std::uint32_t>(box.positions.size())});
  EXPECT_THROW(RenderView(bad_index, camera, pose), Error);
  RenderMesh bad_colors = box;
  bad_colors.colors.pop_back();
  EXPECT_THROW(RenderView(bad_colors, camera, pose), Error);
}

}  // namespace
}  // namespace layermod
