// Where `prunesfm run` without arguments finds its default input: the Middlebury templeSparseRing
// images (16 images, 640x480) in the shared datasets folder beside the project.
#pragma once

#include <filesystem>
#include <optional>

namespace prunesfm {

// The default dataset below a `shared` folder.
inline constexpr char kDefaultDatasetRelative[] = "datasets/middlebury/templeSparseRing/images";

// Looked up, in this order: $PRUNESFM_SHARED_DIR; `shared` beside the source tree the binary was
// built from; `shared` beside any parent folder of the working directory or of the executable
// (so both /work/main/../shared and a build folder's ../../../../shared are found).
std::optional<std::filesystem::path> FindDefaultDataset();

}  // namespace prunesfm
