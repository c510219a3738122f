// OpenMVS scene.mvs (ReadOpenMvsScene, then the conversion to a model as `prunesfm convert` does).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() {
    const auto path = fuzz::WriteInput("scene.mvs", fuzz::WholeInput(data, size));
    SfmDataFromOpenMvsScene(ReadOpenMvsScene(path), path.string());
  });
}
