// COLMAP sparse model, binary (ReadColmapModel on cameras.bin, images.bin, points3D.bin).
#include "colmap_model_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return sfm_pruning::fuzz::ParseColmapModelInput(data, size, ".bin");
}
