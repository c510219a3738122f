// The datasets' gt_cameras.txt (ReadGroundTruthCameras).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/ground_truth_cameras.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadGroundTruthCameras(fuzz::WriteInput("gt_cameras.txt", fuzz::WholeInput(data, size))); });
}
