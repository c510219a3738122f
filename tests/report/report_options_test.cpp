// Every report options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "report_test_run.hpp"
#include "sfm_pruning/report/epipolar_check.hpp"
#include "sfm_pruning/report/epipolar_image.hpp"
#include "sfm_pruning/report/graph_layout.hpp"
#include "sfm_pruning/report/top_view.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning::testing {
namespace {

TEST(ReportOptions, DefaultsPass) {
  EXPECT_NO_THROW(EpipolarCheckOptions().Check());
  EXPECT_NO_THROW(EpipolarImageOptions().Check());
  EXPECT_NO_THROW(GraphLayoutOptions().Check());
  EXPECT_NO_THROW(TopViewOptions().Check());
}

TEST(ReportOptions, EachStructNamesItsBadField) {
  ExpectEachCaseNamesItsField<EpipolarCheckOptions>({
      {[](EpipolarCheckOptions* o) { o->region_fraction = -0.08; }, "EpipolarCheckOptions::region_fraction"},
      {[](EpipolarCheckOptions* o) { o->region_fraction = kNan; }, "EpipolarCheckOptions::region_fraction"},
      {[](EpipolarCheckOptions* o) { o->feature_radius_px = -1.0; },
       "EpipolarCheckOptions::feature_radius_px"},
  });
  ExpectEachCaseNamesItsField<EpipolarImageOptions>({
      {[](EpipolarImageOptions* o) { o->panel_height = 0; }, "EpipolarImageOptions::panel_height"},
  });
  ExpectEachCaseNamesItsField<GraphLayoutOptions>({
      {[](GraphLayoutOptions* o) { o->iterations = -1; }, "GraphLayoutOptions::iterations"},
      {[](GraphLayoutOptions* o) { o->gravity = -0.3; }, "GraphLayoutOptions::gravity"},
      {[](GraphLayoutOptions* o) { o->gravity = kInf; }, "GraphLayoutOptions::gravity"},
  });
  ExpectEachCaseNamesItsField<TopViewOptions>({
      {[](TopViewOptions* o) { o->width = 0.0; }, "TopViewOptions::width"},
      {[](TopViewOptions* o) { o->height = kNan; }, "TopViewOptions::height"},
      {[](TopViewOptions* o) { o->max_points = 0; }, "TopViewOptions::max_points"},
      {[](TopViewOptions* o) { o->point_quantile = 1.5; }, "TopViewOptions::point_quantile"},
  });
}

TEST(ReportOptions, EdgeValuesThatMeanSomethingPass) {
  EpipolarCheckOptions check;
  check.max_other_views = 0;  // no other image chosen
  check.region_fraction = 0.0;
  check.feature_radius_px = 0.0;
  EXPECT_EQ(CheckMessage(check), "");
  GraphLayoutOptions layout;
  layout.iterations = 0;  // the seeded random positions
  layout.gravity = 0.0;
  EXPECT_EQ(CheckMessage(layout), "");
  TopViewOptions top;
  top.point_quantile = 1.0;
  EXPECT_EQ(CheckMessage(top), "");
}

TEST(ReportOptions, EntryFunctionsRefuseBadOptionsBeforeAnyWork) {
  const SfmData scene = RingScene(8);
  const std::string image = scene.views.begin()->second.RelativeImagePath();
  EpipolarCheckOptions check;
  check.feature_radius_px = -12.0;
  EXPECT_THROW(ImagesSeeingRegion(scene, image, Eigen::Vector2d(10, 10), check), std::invalid_argument);
  EXPECT_THROW(ComputeEpipolarCheck(scene, image, Eigen::Vector2d(10, 10), {}, nullptr, check),
               std::invalid_argument);

  EpipolarImageOptions drawing;
  drawing.panel_height = -320;
  EXPECT_THROW(RenderEpipolarCheck(EpipolarCheck(), scene, drawing, ".png"), std::invalid_argument);

  GraphLayoutOptions layout;
  layout.gravity = kNan;
  EXPECT_THROW(ForceDirectedLayout(3, {{0, 1, 1.0}}, layout), std::invalid_argument);

  TopViewOptions top;
  top.width = -520.0;
  EXPECT_THROW(DrawTopViewSvg(TopViewScene(), TopViewFrame(), top), std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning::testing
