#include "sfm_pruning/eval/synthetic_descriptors.hpp"

#include <algorithm>
#include <cmath>

namespace sfm_pruning {
namespace {

// Fraction of empty bins in a random appearance (real SIFT: roughly a third of bins are zero).
constexpr double kEmptyBinProbability = 0.35;
// SIFT's clipping threshold on the unit-norm histogram (Lowe 2004, section 6.1).
constexpr float kSiftClip = 0.2f;
// SIFT's scale from unit norm to bytes.
constexpr float kSiftByteScale = 512.f;

void NormalizeL2(DescriptorHistogram& h) {
  double norm2 = 0.0;
  for (float v : h) norm2 += static_cast<double>(v) * v;
  if (norm2 <= 0.0) return;  // an all-zero histogram stays zero, as in SIFT
  const float inv = static_cast<float>(1.0 / std::sqrt(norm2));
  for (float& v : h) v *= inv;
}

}  // namespace

DescriptorHistogram RandomDescriptorHistogram(std::mt19937_64& rng) {
  std::bernoulli_distribution empty(kEmptyBinProbability);
  std::exponential_distribution<float> magnitude(1.f);
  DescriptorHistogram h{};
  for (float& v : h) {
    const bool is_empty = empty(rng);
    const float m = magnitude(rng);  // drawn even for empty bins: a fixed number of draws per bin
    v = is_empty ? 0.f : m;
  }
  NormalizeL2(h);
  return h;
}

Descriptor ObserveDescriptor(const DescriptorHistogram& base, double noise, std::mt19937_64& rng) {
  if (noise <= 0.0) return QuantizeSiftHistogram(base);
  // Per-bin sigma such that the noise vector has expected norm `noise`.
  std::normal_distribution<float> gauss(0.f, static_cast<float>(noise / std::sqrt(double(kDescriptorSize))));
  DescriptorHistogram h = base;
  // Gradient histograms cannot be negative: noise that would push a bin below zero empties it.
  for (float& v : h) v = std::max(0.f, v + gauss(rng));
  return QuantizeSiftHistogram(h);
}

Descriptor QuantizeSiftHistogram(DescriptorHistogram h) {
  NormalizeL2(h);
  for (float& v : h) v = std::min(v, kSiftClip);
  NormalizeL2(h);
  Descriptor d{};
  for (int k = 0; k < kDescriptorSize; ++k) {
    d[k] = static_cast<uint8_t>(std::min(255.f, std::round(h[k] * kSiftByteScale)));
  }
  return d;
}

int SquaredDescriptorDistance(const Descriptor& a, const Descriptor& b) {
  // Written as a plain loop over a fixed size so the compiler vectorises it (SSE2 pmaddwd); this
  // is the inner loop of the brute-force matcher.
  int sum = 0;
  for (int k = 0; k < kDescriptorSize; ++k) {
    const int d = static_cast<int>(a[k]) - static_cast<int>(b[k]);
    sum += d * d;
  }
  return sum;
}

}  // namespace sfm_pruning
