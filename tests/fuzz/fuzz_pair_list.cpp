// OpenMVG pair lists, 'I J K ...' per line (ReadPairList, for a scene of 100 views).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/pair_list.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadPairList(fuzz::WriteInput("pairs.txt", fuzz::WholeInput(data, size)), 100); });
}
