// OpenMVG image_describer.json (ReadImageDescriber, then the SIFT check the readers apply).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() {
    const auto path = fuzz::WriteInput("image_describer.json", fuzz::WholeInput(data, size));
    RequireSiftRegions(ReadImageDescriber(path), path);
  });
}
