// Writes small valid inputs for every fuzz target: `fuzz_seed_corpus OUT` fills OUT/<target>/ with
// files of a three-view scene in every format the parsers read. Small seeds keep the fuzzer fast;
// scripts/fuzz.sh adds the real files of ../shared/formats beside them.
#include <Eigen/Geometry>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "sfm_pruning/io/camera_priors.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/ground_truth_cameras.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/io/pair_list.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/util/atomic_file.hpp"

namespace sfm_pruning::fuzz {
namespace {
namespace fs = std::filesystem;

// Three views of two cameras (pinhole, radial) round a few points, each seen by every view.
SfmData ThreeViewScene() {
  SfmData data;
  data.root_path = "images";
  data.intrinsics[0] = CameraIntrinsics::Pinhole(640, 480, 500, 320, 240);
  data.intrinsics[1] = CameraIntrinsics(CameraModel::kPinholeRadialK1, 640, 480, {520, 318, 241, -0.05});
  for (IndexT id = 0; id < 3; ++id) {
    View view;
    view.id_view = view.id_pose = id;
    view.id_intrinsic = id == 2 ? 1 : 0;
    view.filename = "view_" + std::to_string(id) + ".jpg";
    view.width = 640;
    view.height = 480;
    data.views[id] = view;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.2 * id, Eigen::Vector3d::UnitY()).toRotationMatrix();
    data.poses[id] = Pose(R, Eigen::Vector3d(1.0 * id, 0.0, 0.0));
  }
  for (IndexT point = 0; point < 4; ++point) {
    Landmark& landmark = data.structure[point];
    landmark.X = Eigen::Vector3d(0.3 * point, 0.2 * point - 0.3, 6.0);
    for (IndexT view = 0; view < 3; ++view) {
      const Pose& pose = data.poses.at(view);
      const Eigen::Vector2d pixel = data.IntrinsicsOf(data.views.at(view)).Project(pose.ToCamera(landmark.X));
      landmark.observations[view] = {pixel, point};
    }
  }
  return data;
}

FeaturesPerView FeaturesOf(const SfmData& data) {
  FeaturesPerView features;
  for (const auto& [point_id, landmark] : data.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      FeatureSet& set = features[view_id];
      set.keypoints.push_back({static_cast<float>(observation.x.x()), static_cast<float>(observation.x.y()), 2.0f,
                               0.5f * static_cast<float>(point_id)});
      Descriptor descriptor{};
      for (size_t k = 0; k < descriptor.size(); ++k) descriptor[k] = static_cast<uint8_t>((k * 7 + point_id * 13) % 256);
      set.descriptors.push_back(descriptor);
    }
  }
  return features;
}

PairwiseMatches MatchesOf() {
  PairwiseMatches matches;
  for (IndexT a = 0; a < 3; ++a) {
    for (IndexT b = a + 1; b < 3; ++b) {
      for (IndexT k = 0; k < 4; ++k) matches[{a, b}].push_back({k, k});
    }
  }
  return matches;
}

std::string Read(const fs::path& path) { return ReadFileToString(path); }

// Joins the files of a multi-file format into one seed, as fuzz_input.hpp splits it.
std::string Joined(const std::vector<fs::path>& files) {
  std::string joined;
  for (size_t k = 0; k < files.size(); ++k) joined += (k == 0 ? "" : std::string(kPartSeparator)) + Read(files[k]);
  return joined;
}

void Seed(const fs::path& out, const std::string& target, const std::string& name, const std::string& bytes) {
  fs::create_directories(out / target);
  std::ofstream(out / target / name, std::ios::binary) << bytes;
}

void WriteSeeds(const fs::path& out, const fs::path& work) {
  const SfmData scene = ThreeViewScene();
  const FeaturesPerView features = FeaturesOf(scene);
  WriteSfmData(scene, work / "sfm_data.json");
  WriteSfmData(scene, work / "sfm_data.bin");
  Seed(out, "fuzz_sfm_data_json", "three_views.json", Read(work / "sfm_data.json"));
  Seed(out, "fuzz_sfm_data_binary", "three_views.bin", Read(work / "sfm_data.bin"));

  for (const auto& [target, format, ext] : {std::make_tuple("fuzz_colmap_model_binary", ColmapModelFormat::kBinary, ".bin"),
                                            std::make_tuple("fuzz_colmap_model_text", ColmapModelFormat::kText, ".txt")}) {
    const fs::path model = work / (std::string("model") + ext);
    WriteColmapModel(scene, model, format, &features);
    Seed(out, target, std::string("three_views") + ext,
         Joined({model / (std::string("cameras") + ext), model / (std::string("images") + ext),
                 model / (std::string("points3D") + ext)}));
  }

  ColmapDatabase database;
  database.sfm_data.intrinsics = scene.intrinsics;
  database.sfm_data.views = scene.views;
  database.features = features;
  database.putative = MatchesOf();
  for (const auto& [pair, matches] : database.putative) {
    ColmapTwoViewGeometry geometry;
    geometry.inliers = matches;
    geometry.config = 2;
    geometry.E = Eigen::Matrix3d::Identity();
    database.verified[pair] = geometry;
  }
  WriteColmapDatabase(database, work / "database.db");
  Seed(out, "fuzz_colmap_database", "three_views.db", Read(work / "database.db"));

  WriteFeatFile(work / "view.feat", features.at(0).keypoints);
  WriteDescFile(work / "view.desc", features.at(0).descriptors);
  Seed(out, "fuzz_openmvg_features", "view", Joined({work / "view.feat", work / "view.desc"}));
  WriteOpenMvgMatches(work / "matches.bin", MatchesOf());
  WriteOpenMvgMatches(work / "matches.txt", MatchesOf());
  Seed(out, "fuzz_openmvg_matches", "three_views", Joined({work / "matches.bin", work / "matches.txt"}));
  WriteSiftImageDescriber(work / "image_describer.json");
  Seed(out, "fuzz_image_describer", "sift.json", Read(work / "image_describer.json"));

  Seed(out, "fuzz_k_file", "K.txt", "2759.48 0 1520.69\n0 2764.16 1006.81\n0 0 1\n");
  for (const bool binary : {true, false}) {
    PlyWriteOptions options;
    options.binary = binary;
    WritePly(scene, work / "cloud.ply", options);
    Seed(out, "fuzz_ply", binary ? "binary.ply" : "ascii.ply", Read(work / "cloud.ply"));
  }
  SfmData pinhole_scene = scene;  // OpenMVS and gt_cameras.txt take undistorted pinhole cameras only
  pinhole_scene.intrinsics[1] = CameraIntrinsics::Pinhole(640, 480, 520, 318, 241);
  WriteOpenMvsScene(OpenMvsSceneFromSfmData(pinhole_scene, "images/"), work / "scene.mvs");
  Seed(out, "fuzz_openmvs_scene", "three_views.mvs", Read(work / "scene.mvs"));
  WriteGroundTruthCameras(pinhole_scene, work / "gt_cameras.txt");
  Seed(out, "fuzz_ground_truth_cameras", "gt_cameras.txt", Read(work / "gt_cameras.txt"));
  WritePairList(work / "pairs.txt", {{0, 1}, {0, 2}, {1, 2}});
  Seed(out, "fuzz_pair_list", "pairs.txt", Read(work / "pairs.txt"));
  CameraPriors priors;
  priors.cameras.push_back({0, "Canon EOS 5D", 500.0, "exif_35mm", true, 2});
  priors.cameras.push_back({1, "", 768.0, "default_guess", false, 1});
  priors.skipped_images.push_back({"broken.jpg", "does not decode as an image"});
  WriteCameraPriors(work / "camera_priors.json", priors);
  Seed(out, "fuzz_camera_priors", "priors.json", Read(work / "camera_priors.json"));
}

}  // namespace
}  // namespace sfm_pruning::fuzz

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seed_corpus OUT\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  try {
    sfm_pruning::fuzz::WriteSeeds(out, out / ".work");
    std::filesystem::remove_all(out / ".work");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_seed_corpus: %s\n", e.what());
    return 1;
  }
  return 0;
}
