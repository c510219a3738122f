// The fuzz input of a COLMAP sparse model: its three files (cameras, images, points3D) are the
// three parts of one input, written with `extension` (".bin" or ".txt") and read as a model.
#pragma once

#include <string>

#include "fuzz_input.hpp"
#include "sfm_pruning/io/colmap_model.hpp"

namespace sfm_pruning::fuzz {

inline int ParseColmapModelInput(const uint8_t* data, size_t size, const std::string& extension) {
  const auto parts = SplitParts(data, size, 3);
  const char* names[] = {"model/cameras", "model/images", "model/points3D"};
  for (size_t k = 0; k < 3; ++k) WriteInput(names[k] + extension, parts[k]);
  return Parse([&]() { ReadColmapModel(ScratchFolder() / "model"); });
}

}  // namespace sfm_pruning::fuzz
