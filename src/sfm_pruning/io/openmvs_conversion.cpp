#include "sfm_pruning/io/openmvs_conversion.hpp"

#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

Eigen::Matrix3d CalibrationMatrix(const CameraIntrinsics& intrinsics) {
  const Eigen::Vector2d pp = intrinsics.PrincipalPoint();
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  K(0, 0) = intrinsics.FocalX();
  K(1, 1) = intrinsics.FocalY();
  K(0, 2) = pp.x();
  K(1, 2) = pp.y();
  return K;
}

std::string JoinImagePath(const std::string& prefix, const std::string& relative) {
  if (prefix.empty()) return relative;
  return prefix.back() == '/' ? prefix + relative : prefix + "/" + relative;
}

CameraIntrinsics IntrinsicsFromCamera(const OpenMvsScene::Camera& camera, const std::string& source,
                                      const std::string& name) {
  if (camera.width == 0 || camera.height == 0) {
    throw Error(source + ": " + name +
                " has a normalized K without image resolution, which is not supported");
  }
  const Eigen::Matrix3d& K = camera.K;
  if (K(0, 1) != 0.0 || K(1, 0) != 0.0 || K(2, 0) != 0.0 || K(2, 1) != 0.0 || K(2, 2) != 1.0) {
    throw Error(source + ": " + name +
                " has a K that is not [fx 0 cx; 0 fy cy; 0 0 1] (skew is not supported)");
  }
  if (K(0, 0) == K(1, 1))
    return CameraIntrinsics::Pinhole(camera.width, camera.height, K(0, 0), K(0, 2), K(1, 2));
  return CameraIntrinsics(CameraModel::kPinholeFxFy, camera.width, camera.height,
                          {K(0, 0), K(1, 1), K(0, 2), K(1, 2)});
}

// Image ids become view ids when they are all defined and distinct.
bool ImageIdsAreUsable(const OpenMvsScene& scene) {
  std::set<uint32_t> seen;
  for (const OpenMvsScene::Image& image : scene.images) {
    if (image.id == kOpenMvsNoId || !seen.insert(image.id).second) return false;
  }
  return true;
}

}  // namespace

OpenMvsScene OpenMvsSceneFromSfmData(const SfmData& data, const std::string& image_prefix, uint32_t version) {
  OpenMvsScene scene;
  scene.version = version;
  std::map<IndexT, uint32_t> platform_of_intrinsic;
  std::map<IndexT, uint32_t> image_of_view;
  for (const IndexT view_id : data.PosedViewIds()) {
    const View& view = data.views.at(view_id);
    const CameraIntrinsics& intrinsics = data.IntrinsicsOf(view);
    if (!IsPinholeFamily(intrinsics.model()) || intrinsics.HasDistortion()) {
      throw Error("OpenMVS export: view " + std::to_string(view_id) + " (" + view.filename + ") has a " +
                  CameraModelName(intrinsics.model()) +
                  " camera with distortion; OpenMVS needs undistorted pinhole images");
    }
    auto [it, inserted] =
        platform_of_intrinsic.emplace(view.id_intrinsic, static_cast<uint32_t>(scene.platforms.size()));
    if (inserted) {
      OpenMvsScene::Platform platform;
      platform.name = "platform" + std::to_string(view.id_intrinsic);
      OpenMvsScene::Camera camera;
      camera.name = "camera" + std::to_string(view.id_intrinsic);
      camera.width = intrinsics.width();
      camera.height = intrinsics.height();
      camera.K = CalibrationMatrix(intrinsics);
      platform.cameras.push_back(camera);
      scene.platforms.push_back(platform);
    }
    OpenMvsScene::Platform& platform = scene.platforms[it->second];
    const Pose& pose = data.PoseOf(view);
    OpenMvsScene::Image image;
    image.name = JoinImagePath(image_prefix, view.RelativeImagePath());
    image.platform_id = it->second;
    image.camera_id = 0;
    image.pose_id = static_cast<uint32_t>(platform.poses.size());
    image.id = view_id;
    platform.poses.push_back({pose.rotation, pose.center});
    image_of_view[view_id] = static_cast<uint32_t>(scene.images.size());
    scene.images.push_back(image);
  }
  for (const auto& [landmark_id, landmark] : data.structure) {
    OpenMvsScene::Vertex vertex;
    vertex.X = landmark.X.cast<float>();
    for (const auto& [view_id, observation] : landmark.observations) {
      const auto image = image_of_view.find(view_id);
      if (image != image_of_view.end()) vertex.views.push_back({image->second, 0.0f});
    }
    if (vertex.views.empty()) continue;
    // Posed views are numbered in view-id order and observations are keyed by view id, so the
    // views are already sorted by image index.
    scene.vertices.push_back(std::move(vertex));
    scene.vertex_colors.push_back({landmark.color[2], landmark.color[1], landmark.color[0]});
  }
  return scene;
}

SfmData SfmDataFromOpenMvsScene(const OpenMvsScene& scene, const std::string& source) {
  ValidateOpenMvsScene(scene, source);
  SfmData data;
  std::map<std::pair<uint32_t, uint32_t>, IndexT> intrinsic_of_camera;
  for (uint32_t p = 0; p < scene.platforms.size(); ++p) {
    for (uint32_t c = 0; c < scene.platforms[p].cameras.size(); ++c) {
      const IndexT id = static_cast<IndexT>(intrinsic_of_camera.size());
      const std::string name = "platform " + std::to_string(p) + " camera " + std::to_string(c);
      data.intrinsics[id] = IntrinsicsFromCamera(scene.platforms[p].cameras[c], source, name);
      intrinsic_of_camera[{p, c}] = id;
    }
  }
  const bool use_image_ids = ImageIdsAreUsable(scene);
  std::vector<IndexT> view_of_image(scene.images.size(), kUndefinedIndex);
  for (uint32_t i = 0; i < scene.images.size(); ++i) {
    const OpenMvsScene::Image& image = scene.images[i];
    const IndexT view_id = use_image_ids ? image.id : i;
    view_of_image[i] = view_id;
    const IndexT intrinsic_id = intrinsic_of_camera.at({image.platform_id, image.camera_id});
    const CameraIntrinsics& intrinsics = data.intrinsics.at(intrinsic_id);
    View view;
    view.id_view = view_id;
    view.id_intrinsic = intrinsic_id;
    const size_t slash = image.name.find_last_of('/');
    view.local_path = slash == std::string::npos ? "" : image.name.substr(0, slash);
    view.filename = slash == std::string::npos ? image.name : image.name.substr(slash + 1);
    view.width = intrinsics.width();
    view.height = intrinsics.height();
    if (image.pose_id != kOpenMvsNoId) {
      // Camera pose = the camera's mounting composed with the platform pose.
      const OpenMvsScene::Platform& platform = scene.platforms[image.platform_id];
      const OpenMvsScene::Camera& camera = platform.cameras[image.camera_id];
      const OpenMvsScene::PlatformPose& pose = platform.poses[image.pose_id];
      view.id_pose = view_id;
      data.poses[view_id] = Pose(camera.R * pose.R, pose.R.transpose() * camera.C + pose.C);
    }
    data.views[view_id] = view;
  }
  // Unused intrinsics would be orphans (OpenMVG refuses them).
  std::set<IndexT> used_intrinsics;
  for (const auto& [id, view] : data.views) used_intrinsics.insert(view.id_intrinsic);
  for (auto it = data.intrinsics.begin(); it != data.intrinsics.end();) {
    it = used_intrinsics.count(it->first) ? std::next(it) : data.intrinsics.erase(it);
  }
  for (size_t v = 0; v < scene.vertices.size(); ++v) {
    const OpenMvsScene::Vertex& vertex = scene.vertices[v];
    Landmark landmark;
    landmark.X = vertex.X.cast<double>();
    if (!scene.vertex_colors.empty()) {
      const OpenMvsScene::ColorBgr& bgr = scene.vertex_colors[v];
      landmark.color = {bgr[2], bgr[1], bgr[0]};
    }
    for (const OpenMvsScene::View& seen : vertex.views) {
      const View& view = data.views.at(view_of_image[seen.image_id]);
      if (!data.IsPosed(view)) continue;
      const Eigen::Vector3d X_cam = data.PoseOf(view).ToCamera(landmark.X);
      if (X_cam.z() <= 0) continue;
      landmark.observations[view.id_view] = {data.IntrinsicsOf(view).Project(X_cam), kUndefinedIndex};
    }
    data.structure[static_cast<IndexT>(v)] = std::move(landmark);
  }
  return data;
}

}  // namespace sfm_pruning
