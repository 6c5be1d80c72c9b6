// SPDX-License-Identifier: MIT
#include "eval/bop_targets.h"

#include <nlohmann/json.hpp>
#include <string>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

int RequiredInt(const nlohmann::json& entry, const char* key, const std::string& where) {
  const auto it = entry.find(key);
  if (it == entry.end() || !it->is_number_integer()) {
    throw FormatError(where + ": missing or non-integer " + Quoted(std::string_view(key)));
  }
  return it->get<int>();
}

}  // namespace

std::vector<BopTarget> LoadBopTargets(const std::filesystem::path& path) {
  const std::string bytes = ReadFileBytes(path);
  const nlohmann::json json = nlohmann::json::parse(bytes, nullptr, false);
  if (json.is_discarded() || !json.is_array()) {
    throw FormatError(Quoted(path) + ": not a JSON array of targets");
  }
  std::vector<BopTarget> targets;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const std::string where = Quoted(path) + ", entry " + std::to_string(i);
    if (!json[i].is_object()) throw FormatError(where + ": not an object");
    BopTarget target;
    target.scene_id = RequiredInt(json[i], "scene_id", where);
    target.image_id = RequiredInt(json[i], "im_id", where);
    target.obj_id = RequiredInt(json[i], "obj_id", where);
    target.instance_count =
        json[i].contains("inst_count") ? RequiredInt(json[i], "inst_count", where) : 1;
    targets.push_back(target);
  }
  return targets;
}

}  // namespace layermod
