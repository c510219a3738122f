#include "sfm_pruning/util/output_folder.hpp"

#include <fstream>
#include <string>
#include <system_error>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

namespace {

constexpr char kMarkerPrefix[] = "prunesfm output: ";

// The kind named by the marker in `dir`; empty when there is no marker.
std::string MarkedKind(const fs::path& dir) {
  std::ifstream in(dir / kOutputFolderMarker);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  const std::string prefix = kMarkerPrefix;
  return line.compare(0, prefix.size(), prefix) == 0 ? line.substr(prefix.size()) : "unknown";
}

bool IsEarlierRunWithoutMarker(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "run_manifest.json", ec) || fs::exists(dir / "view_graph.json", ec);
}

}  // namespace

const char* OutputFolderKindName(OutputFolderKind kind) {
  switch (kind) {
    case OutputFolderKind::kRun:
      return "run";
    case OutputFolderKind::kSyntheticScene:
      return "synthetic scene";
    case OutputFolderKind::kColmapModel:
      return "COLMAP model";
    case OutputFolderKind::kOpenMvsWorkspace:
      return "OpenMVS workspace";
    case OutputFolderKind::kColmapDenseWorkspace:
      return "COLMAP dense workspace";
  }
  return "unknown";
}

fs::path WithoutTrailingSeparator(const fs::path& dir) {
  return !dir.empty() && !dir.has_filename() ? dir.parent_path() : dir;
}

bool CheckOutputFolder(const fs::path& path, OutputFolderKind kind, bool overwrite) {
  if (path.empty()) throw Error("output folder: the path is empty");
  const fs::path dir = WithoutTrailingSeparator(path);
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return true;
  if (!fs::is_directory(status)) {
    throw FileError(dir.string(), "exists and is not a folder; give the path of a folder to write");
  }
  const std::string marked = MarkedKind(dir);
  if (marked == OutputFolderKindName(kind)) return true;
  if (marked.empty() && kind == OutputFolderKind::kRun && IsEarlierRunWithoutMarker(dir)) return true;
  if (marked.empty() && fs::directory_iterator(dir, ec) == fs::directory_iterator()) {
    if (ec) throw FileError(dir.string(), "cannot list the folder: " + ec.message());
    return true;
  }
  if (overwrite) return false;
  const std::string what = marked.empty() ? "is not empty and is not an earlier prunesfm output"
                                          : "holds a prunesfm " + marked + ", not a " + OutputFolderKindName(kind);
  throw FileError(dir.string(), "folder " + what + "; choose another folder or pass --overwrite");
}

void ClaimOutputFolder(const fs::path& path, OutputFolderKind kind) {
  const fs::path dir = WithoutTrailingSeparator(path);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(dir.string(), "cannot create directory: " + ec.message());
  if (MarkedKind(dir) == OutputFolderKindName(kind)) return;
  WriteFileAtomically(dir / kOutputFolderMarker, false, [&](std::ostream& out) {
    out << kMarkerPrefix << OutputFolderKindName(kind) << "\n"
        << "A later prunesfm command that writes a " << OutputFolderKindName(kind)
        << " here may replace the files of this folder.\n";
  });
}

}  // namespace sfm_pruning
