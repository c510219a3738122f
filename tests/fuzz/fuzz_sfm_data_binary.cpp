// OpenMVG sfm_data.bin (ReadSfmData: cereal's PortableBinary layout, then the checks).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadSfmData(fuzz::WriteInput("sfm_data.bin", fuzz::WholeInput(data, size))); });
}
