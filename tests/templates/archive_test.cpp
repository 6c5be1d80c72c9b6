// SPDX-License-Identifier: MIT
#include "templates/archive.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "archive_fixtures.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(TemplateArchiveTest, TemplatesOfObjectAndLayerAreTheRightSpans) {
  const TemplateArchive archive = test::MakeSyntheticArchive();  // objects 3 (3 layers), 7 (2)
  const auto all3 = archive.TemplatesOf(3);
  const auto all7 = archive.TemplatesOf(7);
  ASSERT_EQ(all3.size(), 12u);
  ASSERT_EQ(all7.size(), 8u);
  EXPECT_EQ(all3.data(), archive.templates().data());  // a view, not a copy
  EXPECT_EQ(all7.front().id, 12u);
  for (int layer = 0; layer < 3; ++layer) {
    const auto span = archive.TemplatesOf(3, layer);
    ASSERT_EQ(span.size(), 4u);
    EXPECT_EQ(span.front().id, static_cast<std::uint32_t>(4 * layer));
    for (const TemplateRecord& record : span) {
      EXPECT_EQ(record.obj_id, 3);
      EXPECT_EQ(record.layer_index, layer);
    }
  }
  EXPECT_EQ(archive.TemplatesOf(7, 1).front().id, 16u);
}

TEST(TemplateArchiveTest, UnknownObjectOrLayerGivesEmptySpan) {
  const TemplateArchive archive = test::MakeSyntheticArchive();
  EXPECT_TRUE(archive.TemplatesOf(5).empty());
  EXPECT_TRUE(archive.TemplatesOf(7, 2).empty());
  EXPECT_TRUE(archive.TemplatesOf(3, 99).empty());
  const TemplateArchive empty;
  EXPECT_TRUE(empty.TemplatesOf(0).empty());
  EXPECT_TRUE(empty.templates().empty());
}

TEST(TemplateArchiveTest, ObjectLookup) {
  const TemplateArchive archive = test::MakeSyntheticArchive();
  EXPECT_EQ(archive.Object(7).obj_id, 7);
  EXPECT_EQ(archive.Object(7).layer_depths_mm.size(), 2u);
  EXPECT_THROW(archive.Object(4), Error);
  EXPECT_EQ(archive.camera().width, 640);
}

TEST(TemplateArchiveTest, ObjectWithoutTemplatesHasEmptySpan) {
  const TemplateArchive source = test::MakeSyntheticArchive();
  ArchiveManifest manifest = source.manifest();
  manifest.objects.push_back(manifest.objects.front());
  manifest.objects.back().obj_id = 42;
  const TemplateArchive archive(manifest, source.templates());
  EXPECT_TRUE(archive.TemplatesOf(42).empty());
  EXPECT_EQ(archive.Object(42).obj_id, 42);
}

void ExpectConstructorRejects(std::vector<TemplateRecord> templates, const std::string& phrase) {
  const TemplateArchive source = test::MakeSyntheticArchive();
  try {
    const TemplateArchive archive(source.manifest(), std::move(templates));
    ADD_FAILURE() << "accepted, expected: " << phrase;
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find(phrase), std::string::npos) << error.what();
  }
}

TEST(TemplateArchiveTest, IdsMustBeTheirIndex) {
  auto templates = test::MakeSyntheticArchive().templates();
  templates[5].id = 6;
  ExpectConstructorRejects(templates, "ids must be 0..n-1");
}

TEST(TemplateArchiveTest, ObjectsMustBeContiguous) {
  auto templates = test::MakeSyntheticArchive().templates();
  // Object 7's layer 0, then object 3, then object 7's layer 1: layers intact, object split.
  std::rotate(templates.begin(), templates.begin() + 12, templates.begin() + 16);
  for (std::size_t i = 0; i < templates.size(); ++i)
    templates[i].id = static_cast<std::uint32_t>(i);
  ExpectConstructorRejects(templates, "object 7 are not contiguous");
}

TEST(TemplateArchiveTest, LayersMustBeContiguous) {
  auto templates = test::MakeSyntheticArchive().templates();
  std::swap(templates[1], templates[5]);  // object 3: layer 0 and layer 1 interleave
  for (std::size_t i = 0; i < templates.size(); ++i)
    templates[i].id = static_cast<std::uint32_t>(i);
  ExpectConstructorRejects(templates, "layer 0 are not contiguous");
}

TEST(TemplateArchiveTest, TemplatesMustBelongToAKnownObject) {
  auto templates = test::MakeSyntheticArchive().templates();
  for (std::size_t i = 12; i < templates.size(); ++i) templates[i].obj_id = 8;
  ExpectConstructorRejects(templates, "object 8, which is not in the manifest");
}

}  // namespace
}  // namespace layermod
