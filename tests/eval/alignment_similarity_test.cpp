// Similarity alignment: exact recovery of a known transform, with and without planted outliers.
#include <gtest/gtest.h>

#include <random>

#include "sfm_pruning/eval/similarity_alignment.hpp"

namespace sfm_pruning {
namespace {

Similarity3 KnownSimilarity() {
  Similarity3 similarity;
  similarity.scale = 2.5;
  similarity.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  similarity.translation = Eigen::Vector3d(1.0, -2.0, 3.0);
  return similarity;
}

std::vector<Eigen::Vector3d> RandomPoints(size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  std::vector<Eigen::Vector3d> points;
  for (size_t k = 0; k < count; ++k) points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  return points;
}

std::vector<Eigen::Vector3d> Transformed(const Similarity3& similarity, const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : points) out.push_back(similarity.Apply(p));
  return out;
}

void ExpectSameSimilarity(const Similarity3& actual, const Similarity3& expected) {
  EXPECT_NEAR(actual.scale, expected.scale, 1e-10);
  EXPECT_LT((actual.rotation - expected.rotation).norm(), 1e-10);
  EXPECT_LT((actual.translation - expected.translation).norm(), 1e-9);
}

TEST(SimilarityAlignment, LeastSquaresRecoversKnownTransform) {
  const std::vector<Eigen::Vector3d> source = RandomPoints(12, 1);
  const std::optional<Similarity3> fit = FitSimilarityLeastSquares(source, Transformed(KnownSimilarity(), source));
  ASSERT_TRUE(fit.has_value());
  ExpectSameSimilarity(*fit, KnownSimilarity());
}

TEST(SimilarityAlignment, RejectsCollinearAndTooFewPoints) {
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}};
  EXPECT_FALSE(FitSimilarityLeastSquares(line, Transformed(KnownSimilarity(), line)).has_value());
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_FALSE(FitSimilarityLeastSquares(two, two).has_value());
  EXPECT_FALSE(FitSimilarityRobust(two, two).has_value());
  EXPECT_FALSE(FitSimilarityRobust(line, Transformed(KnownSimilarity(), line)).has_value());
}

TEST(SimilarityAlignment, RobustFitRejectsPlantedOutliers) {
  const std::vector<Eigen::Vector3d> source = RandomPoints(20, 2);
  std::vector<Eigen::Vector3d> target = Transformed(KnownSimilarity(), source);
  // Four cameras placed far from where the transform puts them (a folded part of the model).
  const std::vector<size_t> outliers = {3, 7, 11, 16};
  for (size_t k : outliers) target[k] += Eigen::Vector3d(8.0, -6.0, 4.0 + static_cast<double>(k));

  const std::optional<Similarity3> plain = FitSimilarityLeastSquares(source, target);
  ASSERT_TRUE(plain.has_value());
  // Least squares alone is pulled off: a clean point no longer lands on its target.
  EXPECT_GT((plain->Apply(source[0]) - target[0]).norm(), 0.1);

  RobustSimilarityOptions options;
  options.seed = 42;
  const std::optional<RobustSimilarity> robust = FitSimilarityRobust(source, target, options);
  ASSERT_TRUE(robust.has_value());
  ExpectSameSimilarity(robust->transform, KnownSimilarity());
  EXPECT_EQ(robust->num_inliers, 16u);
  for (size_t k = 0; k < source.size(); ++k) {
    const bool is_outlier = std::find(outliers.begin(), outliers.end(), k) != outliers.end();
    EXPECT_EQ(robust->inliers[k], !is_outlier) << k;
  }
}

TEST(SimilarityAlignment, SameSeedSameResult) {
  const std::vector<Eigen::Vector3d> source = RandomPoints(15, 3);
  std::vector<Eigen::Vector3d> target = Transformed(KnownSimilarity(), source);
  std::mt19937_64 noise_rng(9);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (Eigen::Vector3d& p : target) p += Eigen::Vector3d(noise(noise_rng), noise(noise_rng), noise(noise_rng));
  RobustSimilarityOptions options;
  options.seed = 7;
  const auto a = FitSimilarityRobust(source, target, options);
  const auto b = FitSimilarityRobust(source, target, options);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->transform.scale, b->transform.scale);
  EXPECT_EQ(a->transform.rotation, b->transform.rotation);
  EXPECT_EQ(a->transform.translation, b->transform.translation);
  EXPECT_EQ(a->inliers, b->inliers);
}

TEST(SimilarityAlignment, MovingAPoseKeepsWhatTheCameraSees) {
  // A camera moved with its world sees every moved point where it saw the original, scaled.
  const Similarity3 similarity = KnownSimilarity();
  const Pose pose(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix(), Eigen::Vector3d(1, 2, 3));
  const Pose moved = similarity.Apply(pose);
  const Eigen::Vector3d X(-2.0, 0.5, 7.0);
  EXPECT_LT((moved.ToCamera(similarity.Apply(X)) - similarity.scale * pose.ToCamera(X)).norm(), 1e-12);
}

}  // namespace
}  // namespace sfm_pruning
