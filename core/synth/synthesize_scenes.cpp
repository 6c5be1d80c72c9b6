// SPDX-License-Identifier: MIT
// SynthesizeScenes: the parallel run and the dataset folder it builds.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <string>

#include "dataset/bop_writer.h"
#include "dataset/models_info.h"
#include "synth/synthesizer.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

// The dataset is built here and renamed to its final name only when complete; removed on
// failure or cancellation.
class StagingDir {
 public:
  explicit StagingDir(const fs::path& out_dir) {
    std::string name(1, '.');
    name += out_dir.filename().string();
    name += ".partial-XXXXXX";
    std::string pattern = (out_dir.parent_path() / name).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw IoError(Quoted(out_dir) + ": cannot create a folder beside it");
    }
    path_ = pattern;
  }
  ~StagingDir() {
    if (path_.empty()) return;
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  StagingDir(const StagingDir&) = delete;
  StagingDir& operator=(const StagingDir&) = delete;

  const fs::path& Path() const { return path_; }

  void Commit(const fs::path& out_dir) {
    std::error_code ec;
    fs::permissions(path_,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec,
                    ec);
    fs::rename(path_, out_dir, ec);  // replaces an empty folder
    if (ec) {
      throw IoError(Quoted(out_dir) + ": cannot move the dataset into place (" + ec.message() +
                    ")");
    }
    path_.clear();
  }

 private:
  fs::path path_;
};

// The output must be new or an empty folder: a generator never mixes two datasets.
fs::path CheckOutputDir(const fs::path& requested) {
  fs::path out_dir = fs::absolute(requested).lexically_normal();
  if (out_dir.filename().empty()) out_dir = out_dir.parent_path();
  std::error_code ec;
  if (fs::exists(out_dir, ec)) {
    if (!fs::is_directory(out_dir, ec)) {
      throw IoError(Quoted(out_dir) + ": exists and is not a folder");
    }
    if (!fs::is_empty(out_dir, ec)) {
      throw IoError(Quoted(out_dir) + ": folder is not empty; give a new or empty folder");
    }
  }
  if (!fs::is_directory(out_dir.parent_path(), ec)) {
    throw IoError(Quoted(out_dir) + ": parent folder does not exist");
  }
  return out_dir;
}

struct FrameRecord {
  std::int32_t target_id = 0;
  bool target_present = true;
  int instances = 0;  // annotated instances of the target
  double distance_mm = 0.0;
  double visibility = 0.0;
  std::vector<std::int32_t> obj_ids;  // every annotated model
};

void WriteModels(const fs::path& models_dir, const SynthContext& context,
                 const std::set<std::int32_t>& used) {
  std::error_code ec;
  fs::create_directories(models_dir, ec);
  if (ec) throw IoError(Quoted(models_dir) + ": cannot create the folder (" + ec.message() + ")");
  std::map<int, ModelInfo> infos;
  for (const std::int32_t id : used) {
    const SynthModel& model = context.models.at(id);
    const fs::path target = models_dir / BopModelFileName(id);
    fs::copy_file(model.path, target, ec);
    if (ec) throw IoError(Quoted(target) + ": cannot copy the model (" + ec.message() + ")");
    infos[id] = model.info;
  }
  WriteModelsInfo(models_dir / "models_info.json", infos);
}

void WriteTargets(const fs::path& path, const std::vector<FrameRecord>& records, int scene_id) {
  nlohmann::ordered_json targets = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!records[i].target_present) continue;  // BOP lists only objects that are there
    targets.push_back({{"im_id", static_cast<int>(i)},
                       {"inst_count", records[i].instances},
                       {"obj_id", records[i].target_id},
                       {"scene_id", scene_id}});
  }
  WriteFileAtomically(path, targets.dump(1) + "\n");
}

SynthSummary Summarise(const fs::path& out_dir, const std::vector<FrameRecord>& records) {
  SynthSummary summary;
  summary.out_dir = out_dir;
  summary.images = static_cast<int>(records.size());
  summary.min_distance_mm = summary.min_visibility = std::numeric_limits<double>::max();
  double visibility_sum = 0.0;
  int present = 0;
  for (const FrameRecord& record : records) {
    ++summary.images_per_target[record.target_id];
    if (!record.target_present) {
      ++summary.images_without_target;
      continue;
    }
    ++present;
    summary.min_distance_mm = std::min(summary.min_distance_mm, record.distance_mm);
    summary.max_distance_mm = std::max(summary.max_distance_mm, record.distance_mm);
    summary.min_visibility = std::min(summary.min_visibility, record.visibility);
    visibility_sum += record.visibility;
  }
  summary.mean_visibility = visibility_sum / std::max(1, present);
  if (present == 0) summary.min_visibility = 0.0;
  return summary;
}

}  // namespace

SynthSummary SynthesizeScenes(const SynthOptions& options, const JobControl& job) {
  const auto start = std::chrono::steady_clock::now();
  options.Validate();
  const fs::path out_dir = CheckOutputDir(options.out_dir);
  const SynthContext context = PrepareSynthesis(options);
  job.ThrowIfCancelled();

  StagingDir staging(out_dir);
  constexpr int kSceneId = 1;
  BopSceneWriter writer(staging.Path() / "test" / BopIdName(kSceneId));
  const auto count = static_cast<std::size_t>(options.scenes);
  std::vector<FrameRecord> records(count);
  std::mutex progress_mutex;
  std::size_t done = 0;
  job.Report(0, count, "synthesising images");
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
      if (job.IsCancelled()) return;
      const SynthFrame frame = SynthesizeFrame(context, static_cast<int>(i));
      writer.AddFrame(frame.frame);
      FrameRecord& record = records[i];
      record.target_id = frame.target_id;
      record.target_present = frame.target_present;
      record.distance_mm = frame.target_distance_mm;
      record.visibility = frame.target_visibility;
      for (const BopGroundTruth& gt : frame.frame.gt) {
        record.obj_ids.push_back(gt.obj_id);
        record.instances += gt.obj_id == frame.target_id;
      }
      std::lock_guard lock(progress_mutex);
      job.Report(++done, count, "synthesising images");
    });
  });
  job.ThrowIfCancelled();

  std::set<std::int32_t> used;
  for (const FrameRecord& record : records) {
    used.insert(record.obj_ids.begin(), record.obj_ids.end());
  }
  writer.Finish();
  WriteModels(staging.Path() / "models", context, used);
  WriteBopCamera(staging.Path() / "camera.json", options.camera);
  WriteTargets(staging.Path() / "test_targets_bop19.json", records, kSceneId);
  job.ThrowIfCancelled();
  staging.Commit(out_dir);

  SynthSummary summary = Summarise(out_dir, records);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace layermod
