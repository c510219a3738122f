// COLMAP sparse models (cameras / images / points3D, .bin or .txt) <-> SfmData.
//
// Id mapping: view id = pose id = COLMAP image_id, intrinsic id = camera_id, landmark id =
// point3D_id. Poses: COLMAP's qvec (Hamilton, w first) and tvec are the world-to-camera R and
// t = -R c of pose.hpp. Pixels are shifted by 0.5 at the boundary (colmap_camera.hpp).
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

enum class ColmapModelFormat { kBinary, kText };

// Which encoding `dir` holds (cameras.bin or cameras.txt); throws Error when neither exists.
ColmapModelFormat DetectColmapModelFormat(const std::filesystem::path& dir);

// Reads a model folder, format auto-detected. Observations get id_feat = point2D index and the
// point2D position (shifted to our convention). COLMAP 4.x rigs/frames files are accepted when
// every rig has a single camera, and ignored. Throws Error naming the file on bad input
// (unsupported camera model, track referencing a missing image or point2D, truncated file...).
SfmData ReadColmapModel(const std::filesystem::path& dir);

// Writes cameras, images and points3D into `dir` atomically (the folder is replaced as a whole).
// - Only posed views are written: COLMAP models list registered images only. Observations in
//   unposed views are dropped, and so are landmarks left without any observation.
// - With `features`, each image lists every keypoint of its view as a point2D, so point2D index
//   = id_feat exactly; observed keypoints take the observation's position. Without features, the
//   points2D are just the view's observations in landmark-id order, so on reading back id_feat
//   becomes that compact point2D index.
// - Landmark colour and error are written as RGB and ERROR. Throws Error for intrinsics COLMAP
//   cannot represent (kSpherical) or an id_feat outside the given features.
void WriteColmapModel(const SfmData& data, const std::filesystem::path& dir, ColmapModelFormat format,
                      const FeaturesPerView* features = nullptr);

}  // namespace sfm_pruning
