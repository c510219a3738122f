#include "sfm_pruning/util/atomic_file.hpp"

#include <unistd.h>

#include <sstream>
#include <system_error>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

namespace {

fs::path TemporarySibling(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  return tmp;
}

void EnsureParentExists(const fs::path& path) {
  const fs::path parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw FileError(parent.string(), "cannot create directory: " + ec.message());
}

}  // namespace

void WriteFileAtomically(const fs::path& path, bool binary,
                         const std::function<void(std::ostream&)>& write) {
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

void WriteDirectoryAtomically(const fs::path& dir,
                              const std::function<void(const fs::path&)>& write) {
  EnsureParentExists(dir);
  const fs::path tmp = TemporarySibling(dir);
  std::error_code ec;
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp, ec);
  if (ec) throw FileError(tmp.string(), "cannot create directory: " + ec.message());
  try {
    write(tmp);
    fs::path old;
    if (fs::exists(dir)) {
      old = dir;
      old += ".old." + std::to_string(::getpid());
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
