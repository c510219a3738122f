// PLY point clouds, ASCII and binary (ReadPlyPoints).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/ply.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadPlyPoints(fuzz::WriteInput("cloud.ply", fuzz::WholeInput(data, size))); });
}
