// SPDX-License-Identifier: MIT
#include "mesh/model.h"
#include "support/thrown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <thread>
#include <vector>

#include "mesh_files.h"
#include "support/matchers.h"
#include "support/test_paths.h"
#include "util/error.h"
#include "util/log.h"

namespace layermod {
namespace {

using test::MatrixNear;
using ::testing::HasSubstr;

const double kHalfDiagonal = 0.5 * std::sqrt(3.0);

// How messages name a file: in single quotes. Built piecewise: GCC 12 -O3 raises a false
// -Wrestrict on "'" + string + "'".
std::string InQuotes(const std::filesystem::path& path) {
  std::string quoted = path.string();
  quoted.insert(quoted.begin(), '\'');
  quoted.push_back('\'');
  return quoted;
}

using test::ThrownMessage;

class ModelTest : public ::testing::Test {
 protected:
  std::filesystem::path Write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    test::WriteTextFile(path, text);
    return path;
  }

  test::TempDir dir_;
};

TEST_F(ModelTest, LoadsCubeInEveryTextFormatWithMergedVertices) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"cube.ply", test::CubePly(20)},
      {"cube.obj", test::CubeObj(20)},
      {"cube.off", test::CubeOff(20)},
      {"cube.stl", test::CubeStl(20)},
  };
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    const Model model = LoadModel(Write(name, text));
    EXPECT_EQ(model.mesh.n_vertices(), 8u);
    EXPECT_EQ(model.mesh.n_faces(), 12u);
    EXPECT_NEAR(model.sphere.radius_mm, 20 * kHalfDiagonal, 1e-9);
    EXPECT_THAT(model.sphere.centre, MatrixNear(Eigen::Vector3d(10, 10, 10), 1e-9));
    EXPECT_THAT(model.bbox_min, MatrixNear(Eigen::Vector3d::Zero(), 1e-12));
    EXPECT_THAT(model.bbox_max, MatrixNear(Eigen::Vector3d(20, 20, 20), 1e-12));
    EXPECT_FALSE(model.has_vertex_colors);
    EXPECT_EQ(model.source, dir_ / name);
    EXPECT_EQ(model.source_units, LengthUnit::kMillimetre);
    for (const auto vh : model.mesh.vertices()) {
      EXPECT_EQ(model.mesh.color(vh), OpenMesh::Vec3uc(kDefaultGrey, kDefaultGrey, kDefaultGrey));
    }
  }
}

TEST_F(ModelTest, ComputesOutwardUnitNormals) {
  const Model model = LoadModel(Write("cube.ply", test::CubePly(10)));
  for (const auto fh : model.mesh.faces()) EXPECT_NEAR(model.mesh.normal(fh).norm(), 1.0, 1e-9);
  for (const auto vh : model.mesh.vertices()) {
    const auto& n = model.mesh.normal(vh);
    const auto& p = model.mesh.point(vh);
    EXPECT_NEAR(n.norm(), 1.0, 1e-9);
    EXPECT_GT(OpenMesh::dot(n, p - TriMesh::Point(5, 5, 5)), 0.0);
  }
}

TEST_F(ModelTest, KeepsPlyVertexColours) {
  const Model model = LoadModel(Write("coloured.ply", test::CubePly(10, 0.0, true)));
  ASSERT_TRUE(model.has_vertex_colors);
  // Corner i was written with colour (30 i, 255 - 10 i, 7).
  for (const auto vh : model.mesh.vertices()) {
    const auto& p = model.mesh.point(vh);
    const int i = (p[0] > 5 ? 1 : 0) + (p[1] > 5 ? 2 : 0) + (p[2] > 5 ? 4 : 0);
    EXPECT_EQ(model.mesh.color(vh), OpenMesh::Vec3uc(30 * i, 255 - 10 * i, 7)) << "corner " << i;
  }
}

TEST_F(ModelTest, AppliesNodeTransformsToEveryInstance) {
  // One triangle instanced twice: as is, and scaled by 2 and lifted by 5.
  const std::string dae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_geometries><geometry id="tri"><mesh>
    <source id="pos"><float_array id="pos-array" count="9">0 0 0 10 0 0 0 10 0</float_array>
      <technique_common><accessor source="#pos-array" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="vtx"><input semantic="POSITION" source="#pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#vtx" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="a"><instance_geometry url="#tri"/></node>
    <node id="b"><translate>0 0 5</translate><scale>2 2 2</scale><instance_geometry url="#tri"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
  const Model model = LoadModel(Write("two.dae", dae));
  EXPECT_EQ(model.mesh.n_vertices(), 6u);
  EXPECT_EQ(model.mesh.n_faces(), 2u);
  EXPECT_THAT(model.bbox_min, MatrixNear(Eigen::Vector3d(0, 0, 0), 1e-9));
  EXPECT_THAT(model.bbox_max, MatrixNear(Eigen::Vector3d(20, 20, 5), 1e-9));
}

TEST_F(ModelTest, ConvertsMetresToMillimetres) {
  const auto path = Write("cube_m.ply", test::CubePly(0.05, -0.025));
  LoadModelOptions options;
  options.units = LengthUnit::kMetre;
  const Model model = LoadModel(path, options);
  EXPECT_EQ(model.source_units, LengthUnit::kMetre);
  EXPECT_THAT(model.bbox_max, MatrixNear(Eigen::Vector3d(25, 25, 25), 1e-5));
  EXPECT_NEAR(model.sphere.radius_mm, 50 * kHalfDiagonal, 1e-5);
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();

  // The same file read as mm is 0.09 mm across: say it looks like metres, in the log too.
  std::vector<std::string> logged;
  const LogSink previous = SetLogSink([&](LogLevel level, std::string_view message) {
    if (level == LogLevel::kWarning) logged.emplace_back(message);
  });
  const Model as_mm = LoadModel(path);
  SetLogSink(previous);
  EXPECT_EQ(logged, as_mm.warnings);
  ASSERT_EQ(as_mm.warnings.size(), 1u);
  EXPECT_THAT(as_mm.warnings[0], HasSubstr("looks like metres; use units m"));
  EXPECT_THAT(as_mm.warnings[0], HasSubstr(path.string()));
}

TEST_F(ModelTest, WarnsWhenMetreUnitsGiveAHugeModel) {
  LoadModelOptions options;
  options.units = LengthUnit::kMetre;
  const Model model = LoadModel(Write("big.ply", test::CubePly(30, -15.0)), options);
  EXPECT_NEAR(model.DiameterMm(), 60000 * kHalfDiagonal, 1e-6);
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_THAT(model.warnings[0], HasSubstr("looks like millimetres; use units mm"));
}

TEST_F(ModelTest, WarnsAboutFarOriginAndRecentres) {
  Model model = LoadModel(Write("offset.ply", test::CubePly(10, 100.0)));
  EXPECT_TRUE(OriginFarFromCentre(model));
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_THAT(model.warnings[0], HasSubstr("origin"));

  RecentreOnSphere(model);
  EXPECT_FALSE(OriginFarFromCentre(model));
  EXPECT_TRUE(model.warnings.empty());
  EXPECT_THAT(model.sphere.centre, MatrixNear(Eigen::Vector3d::Zero(), 0.0));
  EXPECT_NEAR(model.sphere.radius_mm, 10 * kHalfDiagonal, 1e-9);
  EXPECT_THAT(model.bbox_min, MatrixNear(Eigen::Vector3d::Constant(-5), 1e-9));
  EXPECT_THAT(model.bbox_max, MatrixNear(Eigen::Vector3d::Constant(5), 1e-9));
  for (const auto vh : model.mesh.vertices()) {
    EXPECT_NEAR(std::abs(model.mesh.point(vh)[0]), 5.0, 1e-9);
  }
}

TEST_F(ModelTest, CentredModelHasNoOriginWarning) {
  const Model model = LoadModel(Write("centred.ply", test::CubePly(10, -5.0)));
  EXPECT_FALSE(OriginFarFromCentre(model));
  EXPECT_TRUE(model.warnings.empty());
}

TEST_F(ModelTest, DropsDegenerateFacesAndUnusedVertices) {
  // The cube plus an edge midpoint used only by a zero-area triangle, three vertices no face
  // uses and a triangle with a repeated index.
  const std::string vertices = test::CubeVertexLines(10) + "5 0 0\n50 50 50\n60 60 60\n70 70 70\n";
  const std::string faces = test::CubeFaceLines() + "3 0 8 1\n3 2 2 3\n";
  const Model model = LoadModel(Write("dirty.ply", test::PlainPly(vertices, 12, faces, 14)));
  EXPECT_EQ(model.mesh.n_vertices(), 8u);
  EXPECT_EQ(model.mesh.n_faces(), 12u);
  EXPECT_NEAR(model.sphere.radius_mm, 10 * kHalfDiagonal, 1e-9);
}

TEST_F(ModelTest, KeepsNonManifoldAndFlippedTriangles) {
  // Three triangles on one edge, and a fourth wound against its neighbour: the half-edge mesh
  // cannot join them, yet they are part of the object and must still be rendered.
  const std::string vertices = "0 0 0\n10 0 0\n5 5 0\n5 -5 0\n5 0 5\n15 5 0\n";
  const std::string faces = "3 0 1 2\n3 1 0 3\n3 0 1 4\n3 1 2 5\n";
  const Model model = LoadModel(Write("fan.ply", test::PlainPly(vertices, 6, faces, 4)));
  EXPECT_EQ(model.mesh.n_faces(), 4u);
  EXPECT_GE(model.mesh.n_vertices(), 6u);
  for (const auto vh : model.mesh.vertices()) EXPECT_FALSE(model.mesh.is_isolated(vh));
}

TEST_F(ModelTest, NonManifoldMeshesLoadSilentlyOnSeveralThreads) {
  // OpenMesh reports each face it cannot join on one error stream for the process; models load
  // on several threads at once (synth), and none of them may print. A fan of triangles on one
  // edge: every one past the second is such a face.
  constexpr int kBlades = 400;
  std::string vertices = "0 0 0\n10 0 0\n";
  std::string faces;
  for (int k = 0; k < kBlades; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kBlades;
    vertices += "5 " + std::to_string(5.0 * std::cos(angle)) + " " +
                std::to_string(5.0 * std::sin(angle)) + "\n";
    faces += "3 0 1 " + std::to_string(k + 2) + "\n";
  }
  const auto path = Write("fan.ply", test::PlainPly(vertices, kBlades + 2, faces, kBlades));
  std::atomic<int> loaded{0};
  ::testing::internal::CaptureStderr();
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 10; ++i) {
        if (LoadModel(path).mesh.n_faces() == std::size_t{kBlades}) ++loaded;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(loaded.load(), 40);
}

TEST_F(ModelTest, AcceptsAFlatPlate) {
  const std::string square =
      test::PlainPly("0 0 0\n40 0 0\n40 30 0\n0 30 0\n", 4, "3 0 1 2\n3 0 2 3\n", 2);
  const Model model = LoadModel(Write("plate.ply", square));
  EXPECT_EQ(model.mesh.n_faces(), 2u);
  EXPECT_NEAR(model.sphere.radius_mm, 25.0, 1e-9);
}

TEST_F(ModelTest, HashIdentifiesFileContent) {
  const Model a = LoadModel(Write("a.ply", test::CubePly(10)));
  const Model b = LoadModel(Write("b.ply", test::CubePly(10)));
  const Model c = LoadModel(Write("c.ply", test::CubePly(11)));
  EXPECT_EQ(a.hash.size(), 16u);
  EXPECT_EQ(a.hash.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_NE(a.hash, c.hash);
}

TEST_F(ModelTest, MissingFileOrDirectoryIsAnIoError) {
  const auto missing = dir_ / "missing.ply";
  const std::string message = ThrownMessage<IoError>([&] { LoadModel(missing); });
  EXPECT_THAT(message, HasSubstr(InQuotes(missing)));
  EXPECT_THAT(message, HasSubstr("no such file"));
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadModel(dir_.path()); }), HasSubstr("directory"));
}

TEST_F(ModelTest, UnreadableFileIsAnIoError) {
  const auto path = Write("locked.ply", test::CubePly(10));
  std::filesystem::permissions(path, std::filesystem::perms::none);
  if (std::ifstream(path).is_open()) GTEST_SKIP() << "running with rights that ignore permissions";
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadModel(path); }), HasSubstr("cannot open"));
}

TEST_F(ModelTest, BadContentIsAFormatErrorNamingTheFile) {
  std::string garbage;
  for (int i = 0; i < 3000; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 256));
  const std::string nan_ply = test::PlainPly("0 0 0\n1 nan 0\n0 1 0\n", 3, "3 0 1 2\n", 1);
  const std::string inf_ply = test::PlainPly("0 0 0\n1 0 0\n0 inf 0\n", 3, "3 0 1 2\n", 1);
  const std::string degenerate_ply = test::PlainPly("0 0 0\n1 0 0\n1 0 0\n", 3, "3 0 1 2\n", 1);
  const std::string collinear_ply =
      test::PlainPly("0 0 0\n1 1 1\n2 2 2\n3 3 3\n", 4, "3 0 1 2\n3 1 2 3\n3 0 1 3\n", 3);
  const std::string points_ply = test::PlainPly("0 0 0\n1 0 0\n0 1 0\n", 3, "", 0);
  const std::string bad_index_ply = test::PlainPly("0 0 0\n1 0 0\n0 1 0\n", 3, "3 0 1 7\n", 1);
  const struct {
    std::string name, text, expected;
  } cases[] = {
      {"empty.ply", "", "empty"},
      {"garbage.ply", garbage, "not a PLY file"},
      {"garbage.xyz", garbage, "cannot read as a mesh"},
      {"nan.ply", nan_ply, "non-finite"},
      {"inf.ply", inf_ply, "non-finite"},
      {"degenerate.ply", degenerate_ply, "degenerate"},
      {"collinear.ply", collinear_ply, "degenerate"},
      {"points.ply", points_ply, "no triangles"},
      {"bad_index.ply", bad_index_ply, "out of range"},
      {"bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "out of range"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto path = Write(c.name, c.text);
    const std::string message = ThrownMessage<FormatError>([&] { LoadModel(path); });
    EXPECT_THAT(message, HasSubstr(InQuotes(path)));
    EXPECT_THAT(message, HasSubstr(c.expected));
  }
}

TEST_F(ModelTest, RefusesMeshesAboveTheTriangleLimit) {
  LoadModelOptions options;
  options.max_triangles = 11;
  const auto path = Write("cube.ply", test::CubePly(10));
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModel(path, options); }),
              HasSubstr("12 faces, more than the limit of 11 triangles"));
  options.max_triangles = 12;
  EXPECT_EQ(LoadModel(path, options).mesh.n_faces(), 12u);
  EXPECT_EQ(LoadModelOptions{}.max_triangles, 20'000'000u);
  options.max_triangles = 0;
  EXPECT_THROW(LoadModel(path, options), Error);
}

TEST_F(ModelTest, RenderMeshIsAFlatCopyWithUnitColours) {
  const Model coloured = LoadModel(Write("coloured.ply", test::CubePly(10, 0.0, true)));
  const RenderMesh render = ToRenderMesh(coloured);
  ASSERT_EQ(render.positions.size(), 8u);
  ASSERT_EQ(render.colors.size(), 8u);
  ASSERT_EQ(render.triangles.size(), 12u);
  for (std::size_t i = 0; i < render.positions.size(); ++i) {
    const TriMesh::VertexHandle vh(static_cast<int>(i));
    const auto& p = coloured.mesh.point(vh);
    const auto& c = coloured.mesh.color(vh);
    EXPECT_THAT(render.positions[i], MatrixNear(Eigen::Vector3f(p[0], p[1], p[2]), 1e-6f));
    EXPECT_THAT(render.colors[i], MatrixNear(Eigen::Vector3f(c[0], c[1], c[2]) / 255.0f, 1e-6f));
  }
  for (const auto& tri : render.triangles) {
    for (auto index : tri) EXPECT_LT(index, 8u);
  }
  const RenderMesh grey = ToRenderMesh(LoadModel(Write("grey.ply", test::CubePly(10))));
  for (const auto& c : grey.colors) {
    EXPECT_THAT(c, MatrixNear(Eigen::Vector3f::Constant(kDefaultGrey / 255.0f), 1e-6f));
  }
}

TEST(ModelSharedDataTest, LoadsLineModOccludedModel) {
  const auto data = test::SharedDataDir();
  if (!data) GTEST_SKIP() << "shared data (../shared/data/lmo-dev) not found";
  const auto models = *data / "lmo-dev" / "models";
  std::ifstream info_file(models / "models_info.json");
  ASSERT_TRUE(info_file.is_open());
  const double diameter_mm = nlohmann::json::parse(info_file)["5"]["diameter"].get<double>();

  const auto start = std::chrono::steady_clock::now();
  const Model model = LoadModel(models / "obj_000005.ply");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("load_seconds", std::to_string(seconds));

  EXPECT_TRUE(model.has_vertex_colors);
  // BOP's diameter is the largest distance between two vertices; the enclosing sphere can only
  // be larger (this object: 1.7 % larger, measured against a brute-force vertex diameter).
  EXPECT_GE(model.sphere.radius_mm, 0.5 * diameter_mm * (1.0 - 1e-5));
  EXPECT_LE(model.sphere.radius_mm, 0.5 * diameter_mm * 1.03);
  EXPECT_GT(model.mesh.n_faces(), 10000u);
  // Real colours, not the uniform grey of a colourless mesh.
  std::set<int> reds;
  for (const auto vh : model.mesh.vertices()) reds.insert(model.mesh.color(vh)[0]);
  EXPECT_GT(reds.size(), 20u);
}

}  // namespace
}  // namespace layermod
