// Strecha's K.txt calibration (ReadKFile).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/k_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadKFile(fuzz::WriteInput("K.txt", fuzz::WholeInput(data, size))); });
}
