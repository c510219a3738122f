// Test images with exact ground truth: a room corner (back wall, left wall, floor) covered with
// multi-scale value noise, ray-cast into pinhole cameras that move sideways and turn slightly.
// SIFT finds blobs in the noise at every scale, so the whole front end (extraction, matching,
// verification) runs on these as on photos.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning::testing {

struct RenderedCamera {
  Pose pose;
  double focal = 0.0;  // pixels; principal point at the image centre
  int width = 0;
  int height = 0;
};

// `num_views` cameras 0.35 m apart along x, each turned by a few degrees, 8-bit grey images.
std::vector<RenderedCamera> RoomCameras(int num_views, int width = 480, int height = 360, double focal = 420.0);
cv::Mat RenderRoom(const RenderedCamera& camera, uint64_t seed = 7);

// Writes view k as <dir>/view_<k>.png (or .jpg) and returns the file names.
std::vector<std::string> WriteRoomImages(const std::filesystem::path& dir, int num_views, const char* extension = ".png");

}  // namespace sfm_pruning::testing
