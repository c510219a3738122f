#include "sfm_pruning/eval/synthetic_gt_cameras.hpp"

#include <iomanip>
#include <limits>
#include <ostream>
#include <string>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

void WriteGroundTruthCameras(const SfmData& data, const std::filesystem::path& path) {
  for (const auto& [id, view] : data.views) {
    if (!data.IsPosed(view)) continue;
    const CameraIntrinsics& k = data.IntrinsicsOf(view);
    if (!IsPinholeFamily(k.model()) || k.HasDistortion()) {
      throw FileError(path.string(), "view " + std::to_string(id) + " has a " + CameraModelName(k.model()) +
                                         " camera with distortion; gt_cameras.txt holds undistorted pinholes only");
    }
  }
  WriteFileAtomically(path, /*binary=*/false, [&](std::ostream& out) {
    out << "# image_name width height fx fy cx cy skew r00 r01 r02 r10 r11 r12 r20 r21 r22 tx ty tz\n";
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (const auto& [id, view] : data.views) {
      if (!data.IsPosed(view)) continue;
      const CameraIntrinsics& k = data.IntrinsicsOf(view);
      const Pose& pose = data.PoseOf(view);
      const Eigen::Vector2d pp = k.PrincipalPoint();
      const Eigen::Vector3d t = pose.translation();
      out << view.RelativeImagePath() << ' ' << view.width << ' ' << view.height << ' ' << k.FocalX() << ' '
          << k.FocalY() << ' ' << pp.x() << ' ' << pp.y() << " 0";
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out << ' ' << pose.rotation(r, c);
      }
      out << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << '\n';
    }
  });
}

}  // namespace sfm_pruning
