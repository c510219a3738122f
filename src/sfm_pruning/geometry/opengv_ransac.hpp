// Running OpenGV's Ransac reproducibly, shared by the OpenGV-based estimators (include only from
// geometry/opengv_*.cpp: it pulls in OpenGV's sac templates).
#pragma once

// OpenGV's sac headers use INT_MAX, pow and std::numeric_limits without including them.
#include <climits>
#include <cmath>
#include <limits>

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>

#include <opengv/sac/Ransac.hpp>

#include "sfm_pruning/geometry/opengv_boundary.hpp"
#include "sfm_pruning/geometry/ransac_options.hpp"

namespace sfm_pruning {

// Re-seeds an OpenGV SampleConsensusProblem. OpenGV seeds its sampler either from the clock
// (randomSeed = true, not reproducible) or with the constant 12345 (false); to make the seed an
// option we construct with false, then replace the engine and the bound generator, both public
// members. rng_gen_ binds a *copy* of the engine, so it must be rebuilt after seeding.
template <typename SacProblem>
void SeedOpenGVSampler(uint64_t seed, SacProblem* problem) {
  std::seed_seq sequence{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};
  problem->rng_alg_.seed(sequence);
  problem->rng_gen_ = std::make_shared<std::function<int()>>(std::bind(*problem->rng_dist_, problem->rng_alg_));
}

struct OpenGVRansacOutcome {
  bool found = false;  // a finite model was found
  OpenGVTransformation model = OpenGVTransformation::Zero();  // in OpenGV's convention
  int num_iterations = 0;
};

// Seeds `problem`, runs OpenGV's Ransac with the threshold `1 - cos(max_error_rad)` and returns
// the best model. The caller must have checked that the problem has at least getSampleSize()
// correspondences (OpenGV prints to stderr instead of failing otherwise).
template <typename SacProblem>
OpenGVRansacOutcome RunOpenGVRansac(const std::shared_ptr<SacProblem>& problem, double max_error_rad,
                                    const RansacOptions& options) {
  SeedOpenGVSampler(options.seed, problem.get());
  opengv::sac::Ransac<SacProblem> ransac;
  ransac.sac_model_ = problem;
  ransac.threshold_ = OpenGVThresholdFromAngle(max_error_rad);
  ransac.max_iterations_ = options.max_iterations;
  ransac.probability_ = options.confidence;
  OpenGVRansacOutcome outcome;
  outcome.found = ransac.computeModel(/*debug_verbosity_level=*/0) && ransac.model_coefficients_.allFinite();
  outcome.model = ransac.model_coefficients_;
  outcome.num_iterations = ransac.iterations_;
  return outcome;
}

// A result struct with success = false and the given reason.
template <typename Result>
Result FailedResult(const std::string& reason) {
  Result result;
  result.reason = reason;
  return result;
}

}  // namespace sfm_pruning
