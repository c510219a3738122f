// The top view of a reconstruction: camera centres (triangles pointing along the viewing
// direction), the trajectory in image-name order and the points, seen from "above".
//
// "Above" is the normal of the plane of the camera centres when they spread over one (rings,
// orbits: whichever way the images were held), else the mean up vector of the cameras (-y of each
// camera in the world, images being usually upright: streets); the horizontal axes are the
// principal directions of the camera centres in that plane. With ground truth the
// estimate is first moved into the truth's frame (the evaluation's similarity), the true centres
// are drawn as green rings and each camera is joined to its true centre.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct TopViewCamera {
  std::string label;  // image name
  Pose pose;
  Rgb color;
  std::optional<Eigen::Vector3d> true_center;  // in the same frame as `pose`
};

struct TopViewPoint {
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  Rgb color;
};

struct TopViewScene {
  std::vector<TopViewCamera> cameras;  // in trajectory (image name) order
  std::vector<TopViewPoint> points;
};

// The plane the scene is seen in: screen right = axis_x, screen up = axis_y (axis_x x axis_y is
// the up vector, so the view is not mirrored).
struct TopViewFrame {
  Eigen::Vector3d axis_x = Eigen::Vector3d::UnitX();
  Eigen::Vector3d axis_y = Eigen::Vector3d::UnitY();
};

// From the camera rotations and centres (true centres when every camera has one, so that two
// panels aligned to the same truth share their frame).
TopViewFrame TopViewFrameOf(const TopViewScene& scene);

struct TopViewOptions {
  double width = 520.0;
  double height = 420.0;
  size_t max_points = 15000;  // evenly strided subsample beyond this
  // The plotted extent covers the cameras and this central fraction of the points (per axis),
  // so a few far-away points do not shrink the scene to a dot.
  double point_quantile = 0.96;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

std::string DrawTopViewSvg(const TopViewScene& scene, const TopViewFrame& frame, const TopViewOptions& options = {});

}  // namespace sfm_pruning
