// OpenMVG match files: cereal binary (.bin) and text (.txt), the two parts of one input.
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  const auto parts = fuzz::SplitParts(data, size, 2);
  fuzz::Parse([&]() { ReadOpenMvgMatches(fuzz::WriteInput("matches.bin", parts[0])); });
  return fuzz::Parse([&]() { ReadOpenMvgMatches(fuzz::WriteInput("matches.txt", parts[1])); });
}
