#include "sfm_pruning/util/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <sstream>
#include <system_error>
#include <vector>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

namespace {

// "<name>.prunesfm-tmp.<pid>" and "<name>.prunesfm-old.<pid>": names no user file is likely to
// have, so that the cleaning of leftovers (RemoveStaleTemporaries) only ever touches ours.
constexpr char kTemporaryTag[] = "prunesfm-tmp";
constexpr char kMovedAsideTag[] = "prunesfm-old";
// Linux never gives a pid above this (PID_MAX_LIMIT): a larger number is not one of our suffixes.
constexpr long long kMaxPid = 4194304;

fs::path Sibling(const fs::path& path, const char* tag) {
  fs::path sibling = path;
  sibling += std::string(".") + tag + "." + std::to_string(::getpid());
  return sibling;
}

fs::path TemporarySibling(const fs::path& path) { return Sibling(path, kTemporaryTag); }

void EnsureParentExists(const fs::path& path) {
  const fs::path parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw FileError(parent.string(), "cannot create directory: " + ec.message());
}

// The pid in "<name>.<tag>.<pid>" when `entry` is such a sibling of `name`.
bool ParseTemporaryPid(const std::string& entry, const std::string& name, const char* tag, pid_t* pid) {
  const std::string prefix = name + "." + tag + ".";
  if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return false;
  long long value = 0;
  for (size_t k = prefix.size(); k < entry.size(); ++k) {
    if (entry[k] < '0' || entry[k] > '9') return false;
    value = value * 10 + (entry[k] - '0');
    if (value > kMaxPid) return false;
  }
  *pid = static_cast<pid_t>(value);
  return true;
}

bool ProcessIsRunning(pid_t pid) {
  if (pid <= 0) return false;
  if (pid == ::getpid()) return true;
  return ::kill(pid, 0) == 0 || errno == EPERM;
}

}  // namespace

void RemoveStaleTemporaries(const fs::path& given) {
  const fs::path path = WithoutTrailingSeparator(given);
  const fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  const std::string name = path.filename().string();
  if (name.empty()) return;
  std::error_code ec;
  std::vector<fs::path> stale_tmp, stale_old;
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, ec)) {
    const std::string entry_name = entry.path().filename().string();
    pid_t pid = 0;
    if (ParseTemporaryPid(entry_name, name, kTemporaryTag, &pid) && !ProcessIsRunning(pid)) {
      stale_tmp.push_back(entry.path());
    }
    if (ParseTemporaryPid(entry_name, name, kMovedAsideTag, &pid) && !ProcessIsRunning(pid)) {
      stale_old.push_back(entry.path());
    }
  }
  for (const fs::path& tmp : stale_tmp) fs::remove_all(tmp, ec);
  for (const fs::path& old : stale_old) {
    if (!fs::exists(path, ec)) {
      fs::rename(old, path, ec);
    } else {
      fs::remove_all(old, ec);
    }
  }
}

void WriteFileAtomically(const fs::path& path, bool binary,
                         const std::function<void(std::ostream&)>& write) {
  if (path.empty()) throw Error("output file: the path is empty");
  EnsureParentExists(path);
  const fs::path tmp = TemporarySibling(path);
  try {
    {
      std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                    : std::ios::out | std::ios::trunc);
      if (!out) throw FileError(path.string(), "cannot open for writing");
      write(out);
      out.flush();
      if (!out) throw FileError(path.string(), "write failed (disk full?)");
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw FileError(path.string(), "cannot move the finished file into place: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void WriteDirectoryAtomically(const fs::path& given, OutputFolderKind kind,
                              const std::function<void(const fs::path&)>& write) {
  if (given.empty()) throw Error("output folder: the path is empty");
  const fs::path dir = WithoutTrailingSeparator(given);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw FileError(dir.string(), "exists and is not a folder; a file is not replaced by a folder");
  }
  EnsureParentExists(dir);
  RemoveStaleTemporaries(dir);
  const fs::path tmp = TemporarySibling(dir);
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp, ec);
  if (ec) throw FileError(tmp.string(), "cannot create directory: " + ec.message());
  try {
    write(tmp);
    ClaimOutputFolder(tmp, kind);
    fs::path old;
    if (fs::exists(dir)) {
      old = Sibling(dir, kMovedAsideTag);
      fs::rename(dir, old, ec);
      if (ec) throw FileError(dir.string(), "cannot replace existing directory: " + ec.message());
    }
    fs::rename(tmp, dir, ec);
    if (ec) {
      if (!old.empty()) fs::rename(old, dir, ec);
      throw FileError(dir.string(), "cannot move the finished directory into place");
    }
    if (!old.empty()) fs::remove_all(old, ec);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    throw;
  }
}

std::string ReadFileToString(const fs::path& path, bool binary) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw FileError(path.string(), "file not found");
  if (fs::is_directory(path, ec)) throw FileError(path.string(), "is a directory, expected a file");
  std::ifstream in(path, binary ? std::ios::in | std::ios::binary : std::ios::in);
  if (!in) throw FileError(path.string(), "cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FileError(path.string(), "read failed");
  return buffer.str();
}

}  // namespace sfm_pruning
