#include "sfm_pruning/features/descriptor_matching.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/flann.hpp>

#include "sfm_pruning/util/blas_product.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The two nearest neighbours of one descriptor, squared L2 distances.
struct NearestTwo {
  int best = -1;
  float d1 = kInfinity;
  float d2 = kInfinity;
  void Offer(int index, float distance) {
    if (distance < d1) {
      d2 = d1;
      d1 = distance;
      best = index;
    } else if (distance < d2) {
      d2 = distance;
    }
  }
};

cv::Mat ToFloatMat(const std::vector<Descriptor>& descriptors) {
  cv::Mat mat(static_cast<int>(descriptors.size()), kDescriptorSize, CV_32F);
  for (int r = 0; r < mat.rows; ++r) {
    float* row = mat.ptr<float>(r);
    for (int d = 0; d < kDescriptorSize; ++d) row[d] = descriptors[static_cast<size_t>(r)][d];
  }
  return mat;
}

// A kd-tree forest over one view's descriptors (the index refers to `data`, which it keeps).
struct FlannView {
  cv::Mat data;
  std::unique_ptr<cv::flann::Index> index;
};

std::vector<NearestTwo> FlannQuery(const FlannView& target, const cv::Mat& queries, int checks) {
  std::vector<NearestTwo> result(static_cast<size_t>(queries.rows));
  if (queries.rows == 0 || target.data.rows == 0) return result;
  const int knn = std::min(2, target.data.rows);
  cv::Mat indices(queries.rows, knn, CV_32S);
  cv::Mat distances(queries.rows, knn, CV_32F);
  target.index->knnSearch(queries, indices, distances, knn, cv::flann::SearchParams(checks));
  for (int q = 0; q < queries.rows; ++q) {
    for (int k = 0; k < knn; ++k) {
      const int index = indices.at<int>(q, k);
      if (index >= 0) result[static_cast<size_t>(q)].Offer(index, distances.at<float>(q, k));
    }
  }
  return result;
}

// Exact nearest two in both directions from all squared distances |a|^2 + |b|^2 - 2 a.b. The dot
// products come from BLAS a block of rows at a time, so that memory stays at block x |b| floats.
void BruteForceNearest(const cv::Mat& a, const cv::Mat& b, std::vector<NearestTwo>* a_to_b,
                       std::vector<NearestTwo>* b_to_a) {
  a_to_b->assign(static_cast<size_t>(a.rows), {});
  b_to_a->assign(static_cast<size_t>(b.rows), {});
  if (a.rows == 0 || b.rows == 0) return;
  const auto squared_norms = [](const cv::Mat& m) {
    std::vector<float> norms(static_cast<size_t>(m.rows));
    for (int r = 0; r < m.rows; ++r) norms[static_cast<size_t>(r)] = static_cast<float>(m.row(r).dot(m.row(r)));
    return norms;
  };
  const std::vector<float> a_norms = squared_norms(a);
  const std::vector<float> b_norms = squared_norms(b);
  constexpr int kBlock = 512;
  std::vector<float> dots(static_cast<size_t>(std::min(kBlock, a.rows)) * static_cast<size_t>(b.rows));
  for (int start = 0; start < a.rows; start += kBlock) {
    const int rows = std::min(kBlock, a.rows - start);
    MultiplyByTranspose(a.ptr<float>(start), rows, b.ptr<float>(0), b.rows, kDescriptorSize, dots.data());
    for (int r = 0; r < rows; ++r) {
      const int i = start + r;
      const float* row = dots.data() + static_cast<size_t>(r) * static_cast<size_t>(b.rows);
      const float a_norm = a_norms[static_cast<size_t>(i)];
      NearestTwo& forward = (*a_to_b)[static_cast<size_t>(i)];
      for (int c = 0; c < b.rows; ++c) {
        const float distance = std::max(0.f, a_norm + b_norms[static_cast<size_t>(c)] - 2.f * row[c]);
        forward.Offer(c, distance);
        (*b_to_a)[static_cast<size_t>(c)].Offer(i, distance);
      }
    }
  }
}

bool PassesRatio(const NearestTwo& n, float max_ratio_squared) {
  return n.best >= 0 && (n.d2 == kInfinity || n.d1 < max_ratio_squared * n.d2);
}

std::vector<FeatureMatch> Combine(const std::vector<NearestTwo>& forward, const std::vector<NearestTwo>& backward,
                                  const DescriptorMatchingOptions& options) {
  const float ratio2 = static_cast<float>(options.max_ratio * options.max_ratio);
  std::vector<FeatureMatch> matches;
  for (size_t i = 0; i < forward.size(); ++i) {
    const NearestTwo& f = forward[i];
    if (!PassesRatio(f, ratio2)) continue;
    if (options.mutual_check) {
      const NearestTwo& back = backward[static_cast<size_t>(f.best)];
      if (!PassesRatio(back, ratio2) || back.best != static_cast<int>(i)) continue;
    }
    matches.push_back({static_cast<IndexT>(i), static_cast<IndexT>(f.best)});
  }
  return matches;
}

bool UseBruteForce(const DescriptorMatchingOptions& options, size_t n_a, size_t n_b) {
  if (options.matcher != DescriptorMatcher::kAuto) return options.matcher == DescriptorMatcher::kBruteForce;
  return static_cast<double>(n_a) * static_cast<double>(n_b) <= kAutoBruteForceBalance * static_cast<double>(n_a + n_b);
}

}  // namespace

PairwiseMatches MatchDescriptors(const FeaturesPerView& features, const PairSet& pairs,
                                 const DescriptorMatchingOptions& options, const ProgressCallback& progress) {
  options.Check();
  std::vector<ViewPair> jobs;
  for (const ViewPair& pair : pairs) {
    const auto a = features.find(pair.first);
    const auto b = features.find(pair.second);
    if (a == features.end() || b == features.end() || a->second.descriptors.empty() ||
        b->second.descriptors.empty()) {
      continue;
    }
    jobs.push_back(pair);
  }

  const auto brute_force = [&](const ViewPair& pair) {
    return UseBruteForce(options, features.at(pair.first).size(), features.at(pair.second).size());
  };
  std::map<IndexT, FlannView> flann;
  {
    std::vector<IndexT> views;  // the views of the pairs FLANN matches
    for (const ViewPair& pair : jobs) {
      if (brute_force(pair)) continue;
      views.push_back(pair.first);
      views.push_back(pair.second);
    }
    std::sort(views.begin(), views.end());
    views.erase(std::unique(views.begin(), views.end()), views.end());
    for (const IndexT view : views) flann[view];  // all slots exist before the workers write them
    ParallelFor(
        views.size(), options.num_threads,
        [&](size_t k) {
          FlannView& entry = flann.at(views[k]);
          entry.data = ToFloatMat(features.at(views[k]).descriptors);
          // The kd-trees' random choices use this thread's cv::theRNG(): seeded per view, so the
          // trees do not depend on the thread that builds them.
          cv::theRNG() = cv::RNG(options.seed * 1000003ULL + views[k] + 1);
          entry.index = std::make_unique<cv::flann::Index>(entry.data, cv::flann::KDTreeIndexParams(options.flann_trees));
        },
        progress, "indexing descriptors");
  }

  std::vector<std::vector<FeatureMatch>> results(jobs.size());
  ParallelFor(
      jobs.size(), options.num_threads,
      [&](size_t k) {
        const ViewPair& pair = jobs[k];
        std::vector<NearestTwo> forward;
        std::vector<NearestTwo> backward;
        if (!brute_force(pair)) {
          const FlannView& a = flann.at(pair.first);
          const FlannView& b = flann.at(pair.second);
          forward = FlannQuery(b, a.data, options.flann_checks);
          if (options.mutual_check) backward = FlannQuery(a, b.data, options.flann_checks);
        } else {
          BruteForceNearest(ToFloatMat(features.at(pair.first).descriptors),
                            ToFloatMat(features.at(pair.second).descriptors), &forward, &backward);
        }
        results[k] = Combine(forward, backward, options);
      },
      progress, "matching pairs");

  PairwiseMatches matches;
  for (size_t k = 0; k < jobs.size(); ++k) {
    if (static_cast<int>(results[k].size()) >= std::max(options.min_num_matches, 1)) {
      matches[jobs[k]] = std::move(results[k]);
    }
  }
  return matches;
}

void DescriptorMatchingOptions::Check() const {
  // The nearest distance over the second nearest is at most 1; a bound of 0 would keep no match.
  RequirePositiveAtMost(max_ratio, 1.0, "DescriptorMatchingOptions::max_ratio");
  RequireAtLeast(flann_trees, 1, "DescriptorMatchingOptions::flann_trees");
  RequireAtLeast(flann_checks, 1, "DescriptorMatchingOptions::flann_checks");
  // 0 and 1 both keep every pair with a match (a pair without one is never kept).
  RequireAtLeast(min_num_matches, 0, "DescriptorMatchingOptions::min_num_matches");
  RequireAtLeast(num_threads, 1, "DescriptorMatchingOptions::num_threads");
}

}  // namespace sfm_pruning
