// OUT/run_manifest.json: what `prunesfm run IMAGES OUT` has finished, so that a second run reuses
// every stage whose inputs and options did not change. Each stage has a key, a 64-bit FNV-1a hash
// of its options and of the previous stage's key (the first stage hashes the image files' names,
// sizes and modification times), so a change anywhere reruns that stage and all after it.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace prunesfm {

// FNV-1a, 64 bits, as 16 hex digits.
std::string HashKey(const std::string& text);

// Names, sizes and modification times of the files of `dir` (sorted), one per line: the
// fingerprint of an image folder without reading the images.
std::string FolderFingerprint(const std::filesystem::path& dir);

// The content of a file ("" when it does not exist).
std::string FileFingerprint(const std::filesystem::path& path);

class RunManifest {
 public:
  // Reads OUT/run_manifest.json; a missing or unreadable manifest is empty (everything reruns).
  explicit RunManifest(std::filesystem::path path);

  // True when `stage` finished with `key` and all `outputs` exist.
  bool IsDone(const std::string& stage, const std::string& key,
              const std::vector<std::filesystem::path>& outputs) const;
  double Seconds(const std::string& stage) const;
  // Records the stage and writes the manifest (atomically).
  void MarkDone(const std::string& stage, const std::string& key, double seconds);

 private:
  struct Entry {
    std::string key;
    double seconds = 0.0;
  };
  std::filesystem::path path_;
  std::map<std::string, Entry> stages_;
};

}  // namespace prunesfm
