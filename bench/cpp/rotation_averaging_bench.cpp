// Scaling of EstimateGlobalRotations at the size of large collections, on the two graph shapes
// that stress its two linear solvers (global/rotation_increment_solver.hpp): an unordered
// collection (a ring plus random chords: expander-like, solved by preconditioned CG) and a video
// (each view linked to the next few: a band, solved by the exact factor). 1° of noise on every
// relative rotation, 10 % of the edges corrupted.
//
//   build/bench/bench_rotation_averaging [--views N] [--chords K] [--band B]
//
// prints one line per shape: time, iterations, error after alignment, filtered edges. Built with
// the tests (it uses their scene generator, tests/global/rotation_test_scene.hpp), not run by ctest.
#include <cstdlib>
#include <iostream>
#include <string>

#include "global/rotation_test_scene.hpp"

namespace {

int Run(const sfm_pruning::testing::RotationSceneOptions& options, const std::string& shape) {
  sfm_pruning::testing::RotationScene scene = sfm_pruning::testing::MakeRotationScene(options);
  const sfm_pruning::testing::TimedRotationAveraging run = sfm_pruning::testing::RunTimedRotationAveraging(&scene);
  if (!run.result.success) {
    std::cerr << shape << ": rotation averaging failed: " << run.result.failure_reason << "\n";
    return 1;
  }
  std::cout << shape << ": " << run.Summary(scene) << (run.result.converged ? "" : " (not converged)") << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  size_t views = 10000, chords = 4, band = 5;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string flag = argv[k];
    const long value = std::strtol(argv[k + 1], nullptr, 10);
    if (value <= 0) {
      std::cerr << "bench_rotation_averaging: " << flag << " needs a positive integer, got '" << argv[k + 1] << "'\n";
      return 2;
    }
    if (flag == "--views") {
      views = static_cast<size_t>(value);
    } else if (flag == "--chords") {
      chords = static_cast<size_t>(value);
    } else if (flag == "--band") {
      band = static_cast<size_t>(value);
    } else {
      std::cerr << "bench_rotation_averaging: unknown option " << flag << " (--views, --chords, --band)\n";
      return 2;
    }
  }
  int failures = Run(sfm_pruning::testing::SceneOptions(views, chords, 1.0, 0.1), "random chords");
  sfm_pruning::testing::RotationSceneOptions video = sfm_pruning::testing::SceneOptions(views, 0, 1.0, 0.1);
  video.ring_neighbors = band;
  failures += Run(video, "video band");
  return failures == 0 ? 0 : 1;
}
