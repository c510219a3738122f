#include "software/commands/run_manifest.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>

#include "sfm_pruning/util/atomic_file.hpp"

namespace prunesfm {
namespace fs = std::filesystem;

std::string HashKey(const std::string& text) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::string FolderFingerprint(const fs::path& dir) {
  std::vector<std::string> lines;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    const auto size = entry.file_size(ec);
    const auto time = entry.last_write_time(ec).time_since_epoch().count();
    lines.push_back(entry.path().filename().string() + " " + std::to_string(size) + " " + std::to_string(time));
  }
  std::sort(lines.begin(), lines.end());
  std::string text = fs::absolute(dir).lexically_normal().string() + "\n";
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

std::string FileFingerprint(const fs::path& path) {
  std::error_code ec;
  if (path.empty() || !fs::exists(path, ec)) return {};
  return sfm_pruning::ReadFileToString(path);
}

RunManifest::RunManifest(fs::path path) : path_(std::move(path)) {
  std::error_code ec;
  if (!fs::exists(path_, ec)) return;
  try {
    const nlohmann::json json = nlohmann::json::parse(sfm_pruning::ReadFileToString(path_, false));
    for (const auto& [stage, entry] : json.at("stages").items()) {
      stages_[stage] = {entry.at("key").get<std::string>(), entry.at("seconds").get<double>()};
    }
  } catch (const std::exception&) {
    stages_.clear();  // a damaged manifest only costs a rerun
  }
}

bool RunManifest::IsDone(const std::string& stage, const std::string& key, const std::vector<fs::path>& outputs) const {
  const auto it = stages_.find(stage);
  if (it == stages_.end() || it->second.key != key) return false;
  std::error_code ec;
  return std::all_of(outputs.begin(), outputs.end(), [&](const fs::path& p) { return fs::exists(p, ec); });
}

double RunManifest::Seconds(const std::string& stage) const {
  const auto it = stages_.find(stage);
  return it == stages_.end() ? 0.0 : it->second.seconds;
}

void RunManifest::MarkDone(const std::string& stage, const std::string& key, double seconds) {
  stages_[stage] = {key, seconds};
  nlohmann::json json;
  json["stages"] = nlohmann::json::object();
  for (const auto& [name, entry] : stages_) json["stages"][name] = {{"key", entry.key}, {"seconds", entry.seconds}};
  sfm_pruning::WriteFileAtomically(path_, false, [&](std::ostream& out) { out << json.dump(2) << "\n"; });
}

}  // namespace prunesfm
