// The geometry of a synthetic scene before any camera looks at it: textured surface points and
// camera poses. Each scene file (synthetic_*_scene.cpp) builds one SceneLayout.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

// A point on a surface. Points with one appearance id look identical (twins).
struct SurfacePoint {
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, pointing to the side it is seen from
  IndexT appearance = 0;
};

// How the image pairs to match are chosen.
enum class PairSelection {
  kExhaustive,             // every pair (small scenes)
  kSequentialAndRetrieval  // a sliding window plus retrieval-style loop candidates
};

struct SceneLayout {
  std::vector<Pose> poses;  // view i has pose i
  std::vector<SurfacePoint> points;  // landmark id = index
  IndexT num_appearances = 0;
  PairSelection pairs = PairSelection::kExhaustive;
  SceneDescription description;  // a family scene's drawn geometry
};

// A texture: points on a plane patch, in patch coordinates (u, v along the patch, w = relief
// along its normal), each with an appearance id. Placing one texture on several patches creates
// twins with identical relative geometry, so cross-copy matches are consistent with one
// (wrong) rigid motion.
struct Texture {
  std::vector<Eigen::Vector3d> uvw;
  std::vector<IndexT> appearance;
};

// Uniform random points on a width x height patch (metres) with `density_per_m2` points per
// square metre and relief uniform in [-relief_m, relief_m]. New appearance ids are taken from
// layout->num_appearances.
Texture MakeTexture(double width_m, double height_m, double density_per_m2, double relief_m,
                    SceneLayout* layout, std::mt19937_64& rng);

// Adds the texture's points at origin + u * u_axis + v * v_axis + w * normal, where
// normal = u_axis x v_axis (unit axes, orthogonal). Choose the axes so that the normal points
// towards the cameras that should see the surface.
void PlaceTexture(const Texture& texture, const Eigen::Vector3d& origin, const Eigen::Vector3d& u_axis,
                  const Eigen::Vector3d& v_axis, SceneLayout* layout);

// Wraps the texture round a vertical cylinder: u runs along the circumference (arc length,
// counter-clockwise seen from above, starting at `start_angle` radians from +x), v up from
// `base`, w outward. Normals point outward (the cylinder is seen from outside) or inward.
void PlaceTextureOnCylinder(const Texture& texture, const Eigen::Vector3d& base, double radius_m,
                            double start_angle, bool outward, SceneLayout* layout);

// A side face of an upright box: where its texture's u axis starts (at the ground), the
// direction u runs along (u x z points out of the box) and the face's width.
struct BoxSide {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u_axis = Eigen::Vector3d::UnitX();
  double width_m = 0.0;
};

// The four side faces of an upright box whose footprint is centred on `center`, its length along
// `length_axis` (a horizontal unit vector) and its depth along z x length_axis: front (the -depth
// side), right, back, left, each turned 90 degrees counter-clockwise from the one before. A
// texture placed on the front and again on the back is the front turned 180 degrees.
std::array<BoxSide, 4> BoxSideFaces(const Eigen::Vector3d& center, const Eigen::Vector3d& length_axis,
                                    double length_m, double depth_m);

// `v` turned by `angle` radians about the world's vertical axis.
Eigen::Vector3d RotateAboutZ(const Eigen::Vector3d& v, double angle);

// A camera at `center` looking at `target`, with image +y pointing down along world -z (z up).
Pose LookAtPose(const Eigen::Vector3d& center, const Eigen::Vector3d& target);

// A camera at `center` with the given heading (radians, counter-clockwise from world +x in the
// ground plane) and pitch (radians, positive looks up).
Pose HeadingPitchPose(const Eigen::Vector3d& center, double heading, double pitch);

// Scene builders. `options` carries resolved defaults (num_views etc.); `rng` is the layout stream.
SceneLayout BuildOrbitLayout(const SyntheticSceneOptions& options, bool symmetric, std::mt19937_64& rng);
SceneLayout BuildStreetLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng);
SceneLayout BuildCourtyardLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng);
SceneLayout BuildLoopLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng);

}  // namespace sfm_pruning
