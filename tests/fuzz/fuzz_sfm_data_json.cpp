// OpenMVG sfm_data.json (ReadSfmData: the cereal JSON parser, then the reference and value checks).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadSfmData(fuzz::WriteInput("sfm_data.json", fuzz::WholeInput(data, size))); });
}
