// COLMAP sparse model, text (ReadColmapModel on cameras.txt, images.txt, points3D.txt).
#include "colmap_model_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return sfm_pruning::fuzz::ParseColmapModelInput(data, size, ".txt");
}
