// AUC of hand-made error lists, each value worked out by hand from the formula in pose_auc.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sfm_pruning/eval/pose_auc.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTolerance = 1e-12;

TEST(PoseAuc, HandComputedErrorList) {
  // Errors {1, 2, 4}, N = 3: curve (0,0) (1,1/3) (2,2/3) (4,1).
  // t = 3: trapezoids 1/6 + 1/2, then recall 2/3 held from 2 to 3: 2/3. Area 4/3, AUC = 400/9.
  EXPECT_NEAR(AucPercent({4.0, 1.0, 2.0}, 3.0), 400.0 / 9.0, kTolerance);
  // t = 5: 1/6 + 1/2 + 2 * (2/3 + 1) / 2 = 7/3, then recall 1 from 4 to 5: area 10/3, AUC = 200/3.
  EXPECT_NEAR(AucPercent({1.0, 2.0, 4.0}, 5.0), 200.0 / 3.0, kTolerance);
  // t = 1.5: trapezoid 1/6, then 1/3 * 0.5: area 1/3, AUC = 100 / 4.5.
  EXPECT_NEAR(AucPercent({1.0, 2.0, 4.0}, 1.5), 100.0 / 4.5, kTolerance);
}

TEST(PoseAuc, SeveralThresholdsMatchOneByOne) {
  const std::vector<double> errors = {0.5, 7.0, 2.5, kInf, 0.0, 4.0};
  const std::vector<double> thresholds = {3.0, 5.0, 10.0};
  const std::vector<double> aucs = AucPercent(errors, thresholds);
  ASSERT_EQ(aucs.size(), 3u);
  for (size_t k = 0; k < thresholds.size(); ++k) EXPECT_EQ(aucs[k], AucPercent(errors, thresholds[k]));
}

TEST(PoseAuc, FailuresStayInTheDenominator) {
  // A failure replacing the error 4 changes nothing below t = 3, and caps recall at 2/3 above 4.
  EXPECT_NEAR(AucPercent({1.0, 2.0, kInf}, 3.0), 400.0 / 9.0, kTolerance);
  // t = 5: 1/6 + 1/2 + 3 * 2/3 = 8/3 over 5.
  EXPECT_NEAR(AucPercent({1.0, 2.0, kInf}, 5.0), 100.0 * (8.0 / 3.0) / 5.0, kTolerance);
  EXPECT_EQ(AucPercent({kInf, kInf}, 10.0), 0.0);
}

TEST(PoseAuc, PerfectErrorsGiveHundred) {
  EXPECT_NEAR(AucPercent({0.0, 0.0, 0.0, 0.0}, 3.0), 100.0, kTolerance);
}

TEST(PoseAuc, ErrorEqualToThresholdCountsAsAbove) {
  // {0, 3} at t = 3: only the 0 is below, recall 1/2 held over [0, 3].
  EXPECT_NEAR(AucPercent({0.0, 3.0}, 3.0), 50.0, kTolerance);
}

TEST(PoseAuc, EmptyListAndBadInput) {
  EXPECT_EQ(AucPercent(std::vector<double>{}, 5.0), 0.0);
  EXPECT_THROW(AucPercent({1.0}, 0.0), Error);
  EXPECT_THROW(AucPercent({1.0}, -3.0), Error);
  EXPECT_THROW(AucPercent({std::nan("")}, 3.0), Error);
  EXPECT_THROW(AucPercent({-1.0}, 3.0), Error);
}

}  // namespace
}  // namespace sfm_pruning
