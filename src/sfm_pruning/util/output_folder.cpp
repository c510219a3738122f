#include "sfm_pruning/util/output_folder.hpp"

#include <system_error>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

void CheckOutputFolder(const fs::path& dir, bool overwrite) {
  if (dir.empty()) throw Error("output folder: the path is empty");
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw FileError(dir.string(), "exists and is not a folder; give the path of a folder to write");
  }
  if (overwrite || fs::exists(dir / kOutputFolderMarker, ec)) return;
  if (fs::directory_iterator(dir, ec) == fs::directory_iterator()) {
    if (ec) throw FileError(dir.string(), "cannot list the folder: " + ec.message());
    return;
  }
  throw FileError(dir.string(), "folder is not empty and is not an earlier prunesfm output; "
                                "choose another folder or pass --overwrite to replace its contents");
}

void ClaimOutputFolder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(dir.string(), "cannot create directory: " + ec.message());
  if (fs::exists(dir / kOutputFolderMarker, ec)) return;
  WriteFileAtomically(dir / kOutputFolderMarker, false, [](std::ostream& out) {
    out << "This folder was written by prunesfm; a later prunesfm run may replace the files in it.\n";
  });
}

}  // namespace sfm_pruning
