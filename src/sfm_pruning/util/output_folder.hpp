// Which folders the tools may write into. A command that writes a folder (a run's outputs, a
// synthetic scene, a COLMAP model, a dense workspace) replaces files in it or the folder as a
// whole, so it must never be pointed at a folder of the user's, or at another kind of output, by
// mistake. Every folder this project writes carries a marker file naming its kind; a folder may be
// written when it does not exist, is empty, or carries the marker of the same kind, and any other
// folder only when the user says so (`--overwrite`).
#pragma once

#include <filesystem>

namespace sfm_pruning {

// The marker file inside every output folder; its first line names the kind.
inline constexpr char kOutputFolderMarker[] = ".prunesfm_output";

enum class OutputFolderKind {
  kRun,                   // prunesfm run / reconstruct: written into, file by file
  kSyntheticScene,        // prunesfm synth: replaced whole, as are the kinds below
  kColmapModel,           // cameras, images, points3D
  kOpenMvsWorkspace,      // scene.mvs + images
  kColmapDenseWorkspace,  // images + sparse + stereo
};

const char* OutputFolderKindName(OutputFolderKind kind);

// Throws Error (one line naming `dir`) unless `dir` may receive outputs of `kind`: an empty path
// and a path that is an existing file are always refused (a file is never replaced by a folder);
// an existing folder must be empty or carry the marker of `kind` (a run folder may instead hold the
// run_manifest.json or view_graph.json of a run written before markers existed), unless
// `overwrite`. Returns whether the folder is the project's to mark: false for a folder accepted
// only through `overwrite`, which stays unmarked so that no later command takes it for its own.
bool CheckOutputFolder(const std::filesystem::path& dir, OutputFolderKind kind, bool overwrite);

// Creates `dir` (and its parents) if needed and writes the marker of `kind` into it.
void ClaimOutputFolder(const std::filesystem::path& dir, OutputFolderKind kind);

// `dir` without a trailing separator ("out/" -> "out"), so that its file name is the folder's.
std::filesystem::path WithoutTrailingSeparator(const std::filesystem::path& dir);

}  // namespace sfm_pruning
