// SPDX-License-Identifier: MIT
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/image_output.h"
#include "templates/archive.h"
#include "templates/template_picture.h"
#include "util/error.h"

namespace layermod::cli {
namespace {
namespace fs = std::filesystem;

struct RenderArgs {
  std::string archive;
  std::string out_dir;
  int every = 100;
};

std::string FileName(const TemplateRecord& record) {
  char name[96];
  std::snprintf(name, sizeof(name), "obj%d_t%06u_layer%d_%.0fmm_az%.0f_el%.0f_roll%.0f.png",
                record.obj_id, record.id, record.layer_index, record.layer_depth_mm,
                record.view.azimuth_deg, record.view.elevation_deg, record.view.roll_deg);
  return name;
}

void RunRender(const RenderArgs& args) {
  const TemplateArchive archive = ReadArchive(args.archive);
  std::error_code ec;
  fs::create_directories(args.out_dir, ec);
  if (ec) throw IoError("'" + args.out_dir + "': cannot create directory (" + ec.message() + ")");
  int written = 0;
  for (std::size_t i = 0; i < archive.templates().size();
       i += static_cast<std::size_t>(args.every)) {
    const TemplateRecord& record = archive.templates()[i];
    WritePng(fs::path(args.out_dir) / FileName(record),
             RenderTemplatePicture(record, archive.camera(), &archive.Object(record.obj_id).mesh));
    ++written;
  }
  std::printf("wrote %d template image(s) to %s\n", written, args.out_dir.c_str());
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command = app.add_subcommand(
      "render", "Write template renders with their feature points drawn (for inspection)");
  command->add_option("--archive", args->archive, "Template archive (*.layermod)")->required();
  command->add_option("--out", args->out_dir, "Output directory")->required();
  command->add_option("--every", args->every, "Write every K-th template")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([args] { RunRender(*args); });
}

}  // namespace layermod::cli
