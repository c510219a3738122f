// SIFT-like descriptors for synthetic scenes.
//
// A real SIFT descriptor is a 4x4x8 histogram of gradient orientations: non-negative, sparse
// (a few strong bins, many weak ones), L2-normalised, clipped at 0.2 to damp strong edges,
// renormalised and stored as uint8 after scaling by 512. We produce descriptors through the
// same final steps, so squared-L2 distances and Lowe's ratio test behave as on real images: two
// observations of one surface point differ by their noise only, unrelated points are far apart.
#pragma once

#include <array>
#include <random>

#include "sfm_pruning/sfm/features.hpp"

namespace sfm_pruning {

// The noise-free appearance of a surface point: a unit-norm, non-negative histogram.
using DescriptorHistogram = std::array<float, kDescriptorSize>;

// A random appearance: exponential bin magnitudes with about a third of the bins empty, as in
// the sparse histograms of real image patches.
DescriptorHistogram RandomDescriptorHistogram(std::mt19937_64& rng);

// One observation of `base`: Gaussian noise whose expected norm is `noise` (relative to the
// unit-norm histogram; 0 gives the base itself), then SIFT's normalise-clip-renormalise-quantise.
Descriptor ObserveDescriptor(const DescriptorHistogram& base, double noise, std::mt19937_64& rng);

// SIFT's final steps on a histogram: L2-normalise, clip at 0.2, renormalise, scale by 512,
// round, clip to 255.
Descriptor QuantizeSiftHistogram(DescriptorHistogram histogram);

// Squared L2 distance between two descriptors (what FLANN's L2 and OpenMVG's matchers compare).
int SquaredDescriptorDistance(const Descriptor& a, const Descriptor& b);

}  // namespace sfm_pruning
