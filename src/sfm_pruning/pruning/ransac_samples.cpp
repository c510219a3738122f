#include "sfm_pruning/pruning/ransac_samples.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sfm_pruning {

double NumSubsets(size_t n, size_t k) {
  if (k > n) return 0.0;
  k = std::min(k, n - k);
  double count = 1.0;
  for (size_t i = 0; i < k; ++i) count = count * static_cast<double>(n - i) / static_cast<double>(i + 1);
  return std::round(count);
}

RansacSamples::RansacSamples(size_t pool_size, size_t sample_size, int num_iterations, size_t max_enumerated,
                             std::mt19937_64* rng)
    : pool_size_(pool_size), sample_size_(std::min(sample_size, pool_size)), rng_(rng) {
  const double distinct = NumSubsets(pool_size_, sample_size_);
  enumerated_ = max_enumerated > 0 && distinct <= static_cast<double>(max_enumerated);
  num_samples_ = enumerated_ ? static_cast<int>(distinct) : std::max(num_iterations, 0);
  subset_.resize(sample_size_);
  std::iota(subset_.begin(), subset_.end(), size_t{0});
  order_.resize(pool_size_);
}

std::vector<size_t> RansacSamples::Next() {
  if (enumerated_) {
    std::vector<size_t> sample = subset_;
    // Advance to the next subset: the last position that can still move right moves one step,
    // and the positions after it follow it.
    for (size_t i = sample_size_; i-- > 0;) {
      if (subset_[i] < pool_size_ - sample_size_ + i) {
        ++subset_[i];
        for (size_t j = i + 1; j < sample_size_; ++j) subset_[j] = subset_[j - 1] + 1;
        break;
      }
    }
    return sample;
  }
  std::iota(order_.begin(), order_.end(), size_t{0});
  for (size_t k = 0; k < sample_size_; ++k) {  // partial Fisher–Yates
    std::uniform_int_distribution<size_t> pick(k, pool_size_ - 1);
    std::swap(order_[k], order_[pick(*rng_)]);
  }
  std::vector<size_t> sample(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(sample_size_));
  std::sort(sample.begin(), sample.end());
  return sample;
}

}  // namespace sfm_pruning
