// OpenMVG features: a .feat text file and a .desc binary file (ReadFeatFile, ReadDescFile), the
// two parts of one input, each read on its own.
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  const auto parts = fuzz::SplitParts(data, size, 2);
  fuzz::Parse([&]() { ReadFeatFile(fuzz::WriteInput("view.feat", parts[0])); });
  return fuzz::Parse([&]() { ReadDescFile(fuzz::WriteInput("view.desc", parts[1])); });
}
