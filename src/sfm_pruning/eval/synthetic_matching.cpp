#include "sfm_pruning/eval/synthetic_matching.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sfm_pruning/eval/synthetic_descriptors.hpp"
#include "sfm_pruning/util/blas_product.hpp"

namespace sfm_pruning {
namespace {

enum class MatchKind { kTrue, kTwin, kRandom };

MatchKind Classify(IndexT landmark_a, IndexT landmark_b, const std::map<IndexT, IndexT>& appearance) {
  if (landmark_a == kUndefinedIndex || landmark_b == kUndefinedIndex) return MatchKind::kRandom;
  if (landmark_a == landmark_b) return MatchKind::kTrue;
  return appearance.at(landmark_a) == appearance.at(landmark_b) ? MatchKind::kTwin : MatchKind::kRandom;
}

// Upper bound on random draws per injected match, so a pair with few free features ends.
constexpr int kDrawsPerInjectedMatch = 50;

// Rows of `a` whose distances to all of `b` are computed at once (bounds the block's memory).
constexpr size_t kDistanceBlockRows = 256;

std::vector<float> DescriptorsAsFloats(const FeatureSet& features, size_t first, size_t count) {
  std::vector<float> values(count * kDescriptorSize);
  for (size_t r = 0; r < count; ++r) {
    const Descriptor& d = features.descriptors[first + r];
    for (int k = 0; k < kDescriptorSize; ++k) values[r * kDescriptorSize + k] = static_cast<float>(d[k]);
  }
  return values;
}

int SquaredNorm(const Descriptor& d) {
  int sum = 0;
  for (const uint8_t v : d) sum += static_cast<int>(v) * static_cast<int>(v);
  return sum;
}

}  // namespace

std::vector<FeatureMatch> MatchDescriptorsBruteForce(const FeatureSet& a, const FeatureSet& b, double ratio,
                                                     bool mutual) {
  constexpr int kInf = std::numeric_limits<int>::max();
  const size_t n = a.descriptors.size(), m = b.descriptors.size();
  std::vector<int> column_best(m, kInf);
  std::vector<IndexT> column_best_index(m, kUndefinedIndex);
  std::vector<IndexT> row_best_index(n, kUndefinedIndex);
  std::vector<int> row_best(n, kInf), row_second(n, kInf);
  // |a − b|² = |a|² + |b|² − 2 a·b, the dot products by the system BLAS (a tuned, uninstrumented
  // library: this loop is most of a synthetic scene's generation, also in the sanitizer build).
  // Exact: byte descriptors of 128 values give dot products of at most 128·255² < 2²⁴, which a float
  // holds exactly whatever the order of the sums, so the distances are the integer ones.
  static_assert(kDescriptorSize * 255 * 255 < (1 << 24), "float dot products of byte descriptors must be exact");
  std::vector<int> norm_b(m);
  for (size_t j = 0; j < m; ++j) norm_b[j] = SquaredNorm(b.descriptors[j]);
  const std::vector<float> floats_b = DescriptorsAsFloats(b, 0, m);
  std::vector<float> dots;
  for (size_t i = 0; i < n; ++i) {
    const size_t row = i % kDistanceBlockRows;
    if (row == 0 && m > 0) {
      const size_t rows = std::min(kDistanceBlockRows, n - i);
      const std::vector<float> floats_a = DescriptorsAsFloats(a, i, rows);
      dots.resize(rows * m);
      MultiplyByTranspose(floats_a.data(), static_cast<int>(rows), floats_b.data(), static_cast<int>(m),
                          kDescriptorSize, dots.data());
    }
    const int norm_a = SquaredNorm(a.descriptors[i]);
    int best = kInf, second = kInf;
    IndexT best_j = kUndefinedIndex;
    for (size_t j = 0; j < m; ++j) {
      const int d = norm_a + norm_b[j] - 2 * static_cast<int>(dots[row * m + j]);
      if (d < best) {
        second = best;
        best = d;
        best_j = static_cast<IndexT>(j);
      } else if (d < second) {
        second = d;
      }
      if (d < column_best[j]) {
        column_best[j] = d;
        column_best_index[j] = static_cast<IndexT>(i);
      }
    }
    row_best[i] = best;
    row_second[i] = second;
    row_best_index[i] = best_j;
  }
  // The ratio test on distances, d1 < ratio * d2, compared on squared distances.
  const double ratio2 = ratio * ratio;
  std::vector<FeatureMatch> matches;
  for (size_t i = 0; i < n; ++i) {
    const IndexT j = row_best_index[i];
    if (j == kUndefinedIndex) continue;
    // With a single candidate there is no second neighbour: the ratio test cannot reject it.
    if (row_second[i] != kInf && !(row_best[i] < ratio2 * row_second[i])) continue;
    if (mutual && column_best_index[j] != i) continue;
    matches.push_back({static_cast<IndexT>(i), j});
  }
  return matches;
}

PairMatchStats ClassifyMatches(const std::vector<FeatureMatch>& matches, const MatchTruth& truth) {
  PairMatchStats stats;
  for (const FeatureMatch& match : matches) {
    switch (Classify((*truth.landmarks_a)[match.i], (*truth.landmarks_b)[match.j], *truth.landmark_appearance)) {
      case MatchKind::kTrue: ++stats.num_true; break;
      case MatchKind::kTwin: ++stats.num_twin; break;
      case MatchKind::kRandom: ++stats.num_random; break;
    }
  }
  return stats;
}

size_t InjectRandomWrongMatches(const PairMatchStats& stats, double outlier_ratio, size_t num_features_a,
                                size_t num_features_b, const MatchTruth& truth, std::mt19937_64& rng,
                                std::vector<FeatureMatch>* matches) {
  if (outlier_ratio <= 0.0 || num_features_a == 0 || num_features_b == 0) return 0;
  // random / (consistent + random) = r  <=>  random = r * consistent / (1 - r).
  const double consistent = static_cast<double>(stats.num_true + stats.num_twin);
  const double wanted = std::round(outlier_ratio * consistent / (1.0 - outlier_ratio));
  if (wanted <= static_cast<double>(stats.num_random)) return 0;
  const auto to_add = static_cast<size_t>(wanted) - stats.num_random;

  std::vector<bool> used_a(num_features_a, false), used_b(num_features_b, false);
  for (const FeatureMatch& match : *matches) {
    used_a[match.i] = true;
    used_b[match.j] = true;
  }
  std::uniform_int_distribution<IndexT> pick_a(0, static_cast<IndexT>(num_features_a - 1));
  std::uniform_int_distribution<IndexT> pick_b(0, static_cast<IndexT>(num_features_b - 1));
  size_t added = 0;
  for (size_t draw = 0; added < to_add && draw < to_add * kDrawsPerInjectedMatch; ++draw) {
    const IndexT i = pick_a(rng);
    const IndexT j = pick_b(rng);
    if (used_a[i] || used_b[j]) continue;
    if (Classify((*truth.landmarks_a)[i], (*truth.landmarks_b)[j], *truth.landmark_appearance) != MatchKind::kRandom) {
      continue;
    }
    used_a[i] = used_b[j] = true;
    matches->push_back({i, j});
    ++added;
  }
  std::sort(matches->begin(), matches->end(),
            [](const FeatureMatch& x, const FeatureMatch& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });
  return added;
}

}  // namespace sfm_pruning
