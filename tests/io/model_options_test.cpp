// The io options structs' Check(): none of them holds a value that could be out of range (bools,
// pointers that may be null), so the defaults and every other value pass.
#include <gtest/gtest.h>

#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/sfm/features.hpp"

namespace sfm_pruning {
namespace {

TEST(IoOptions, DefaultsPass) {
  EXPECT_NO_THROW(PlyWriteOptions().Check());
  EXPECT_NO_THROW(MatchReadOptions().Check());
  EXPECT_NO_THROW(ModelWriteOptions().Check());
}

TEST(IoOptions, EveryValuePasses) {
  for (const bool binary : {false, true}) {
    for (const bool cameras : {false, true}) {
      for (const bool control_points : {false, true}) {
        PlyWriteOptions options;
        options.binary = binary;
        options.include_cameras = cameras;
        options.include_control_points = control_points;
        EXPECT_NO_THROW(options.Check());
      }
    }
  }
  const SfmData scene;
  const FeaturesPerView features;
  MatchReadOptions matches;
  matches.sfm_data = &scene;
  EXPECT_NO_THROW(matches.Check());
  matches.features = &features;
  EXPECT_NO_THROW(matches.Check());
  ModelWriteOptions model;
  model.colmap_text = true;
  EXPECT_NO_THROW(model.Check());
}

}  // namespace
}  // namespace sfm_pruning
