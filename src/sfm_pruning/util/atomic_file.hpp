// Atomic output: every file the tools write goes to "<path>.prunesfm-tmp.<pid>" first and is renamed over
// the destination only once it is complete, so a crash or a full disk never leaves a
// half-written sfm_data.json or model behind.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "sfm_pruning/util/output_folder.hpp"

namespace sfm_pruning {

// Calls `write` with a stream opened on a temporary file beside `path`, checks the stream,
// then renames the temporary over `path`. Throws Error naming `path` on any failure and removes
// the temporary. `binary` selects std::ios::binary.
void WriteFileAtomically(const std::filesystem::path& path, bool binary,
                         const std::function<void(std::ostream&)>& write);

// Writes a whole directory atomically: `write` fills a temporary sibling directory, which then
// replaces `dir` (an existing `dir` is moved aside and deleted only after the rename succeeded).
// The new directory carries the output-folder marker of `kind` (output_folder.hpp). Leftovers of
// an interrupted earlier write of `dir` are cleaned first (RemoveStaleTemporaries). Throws Error
// when `dir` is an existing file: a file is never replaced by a folder.
void WriteDirectoryAtomically(const std::filesystem::path& dir, OutputFolderKind kind,
                              const std::function<void(const std::filesystem::path&)>& write);

// Cleans what an interrupted write of `path` left beside it: "<path>.prunesfm-tmp.<pid>" of a
// process that no longer runs is removed; "<path>.prunesfm-old.<pid>" (the previous version, moved
// aside just before the new one was to move in) is moved back when `path` is missing and removed
// otherwise. Processes are looked up in this machine's pid namespace only: a folder shared with
// another machine must not be written by two runs at once.
void RemoveStaleTemporaries(const std::filesystem::path& path);

// Reads a whole file into a string; throws Error naming the file when it cannot be opened.
std::string ReadFileToString(const std::filesystem::path& path, bool binary = true);

}  // namespace sfm_pruning
