// What every parser fuzz target shares. The readers take paths, so the input becomes a file in a
// folder of this process; a format that spans several files (a COLMAP model) takes one input split
// at kPartSeparator. A reader may reject an input only with sfm_pruning::Error, its one-line
// message: any other exception escapes LLVMFuzzerTestOneInput and libFuzzer reports it as a crash,
// like a sanitizer finding, a hang (-timeout) or a runaway allocation (-rss_limit_mb).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::fuzz {

// Between the files of a multi-file input, as scripts/fuzz.sh writes the seeds.
inline constexpr std::string_view kPartSeparator = "\n--prunesfm-fuzz-part--\n";

// This process's folder under $TMPDIR (default /tmp), created on first use and removed at exit.
inline const std::filesystem::path& ScratchFolder() {
  static const std::filesystem::path folder = []() {
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path dir =
        std::filesystem::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") /
        ("prunesfm-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::atexit([]() {
      std::error_code ignored;
      std::filesystem::remove_all(ScratchFolder(), ignored);
    });
    return dir;
  }();
  return folder;
}

// Writes `bytes` to ScratchFolder()/name (replacing the previous input) and returns the path.
inline std::filesystem::path WriteInput(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = ScratchFolder() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

// The input split at kPartSeparator into exactly `count` parts (missing parts are empty; the last
// part keeps any further separators).
inline std::vector<std::string_view> SplitParts(const uint8_t* data, size_t size, size_t count) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < count) {
    const size_t at = rest.find(kPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(rest.substr(0, at));
    rest.remove_prefix(at + kPartSeparator.size());
  }
  parts.push_back(rest);
  parts.resize(count);
  return parts;
}

inline std::string_view WholeInput(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `read`; sfm_pruning::Error is the accepted way to refuse an input.
template <typename Read>
int Parse(Read&& read) {
  try {
    read();
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace sfm_pruning::fuzz
