// camera_priors.json, written by `prunesfm init` and read back by later stages (ReadCameraPriors).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/camera_priors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadCameraPriors(fuzz::WriteInput("camera_priors.json", fuzz::WholeInput(data, size))); });
}
