// SfmData <-> OpenMVS scene (openmvs_scene.hpp).
//
// Export (as OpenMVG's openMVG2openMVS lays a scene out): one platform per intrinsic holding one
// camera (K, width, height; R = I, C = 0 relative to the platform) and one pose per posed view of
// that intrinsic; one image per posed view (name = image_prefix / the view's relative path, id =
// view id); one vertex per landmark seen by at least one exported view, its views sorted by image
// index with confidence 0, and the landmark colours as vertex colours. OpenMVS reads pinhole
// images only, so every exported intrinsic must be an undistorted pinhole (undistort first,
// export/undistortion.hpp).
//
// Import: one intrinsic per (platform, camera), one view and pose per posed image, landmarks
// from the vertices. The scene stores no 2D positions, so each observation gets the reprojection
// of its vertex and id_feat = kUndefinedIndex.
#pragma once

#include <string>

#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// Throws Error for a posed view whose intrinsic is distorted or spherical.
OpenMvsScene OpenMvsSceneFromSfmData(const SfmData& data, const std::string& image_prefix,
                                     uint32_t version = kOpenMvsExportVersion);

// View ids are the images' ids when every image has a distinct one (version >= 3 files written
// by OpenMVG or by us), else the image indices. Throws Error starting with `source` for what
// SfmData cannot hold: a camera without resolution (normalized K), a skewed K.
SfmData SfmDataFromOpenMvsScene(const OpenMvsScene& scene, const std::string& source);

}  // namespace sfm_pruning
