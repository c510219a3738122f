#include "report_test_run.hpp"

#include <cmath>
#include <fstream>
#include <random>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"

namespace sfm_pruning::testing {

SfmData RingScene(int num_views, double radial_k1) {
  SfmData scene;
  scene.intrinsics[0] = radial_k1 == 0.0
                            ? CameraIntrinsics::Pinhole(640, 480, 500.0, 319.5, 239.5)
                            : CameraIntrinsics(CameraModel::kPinholeRadialK3, 640, 480,
                                               {500.0, 319.5, 239.5, radial_k1, 0.0, 0.0});
  for (int k = 0; k < num_views; ++k) {
    const double angle = 2.0 * M_PI * k / num_views;
    const Eigen::Vector3d center(4.0 * std::cos(angle), 4.0 * std::sin(angle), 0.3);
    // Camera z towards the origin, camera y pointing down (world -z).
    const Eigen::Vector3d z = (-center).normalized();
    const Eigen::Vector3d y = (z.cross(Eigen::Vector3d::UnitZ()).cross(z)).normalized() * -1.0;
    const Eigen::Vector3d x = y.cross(z);
    Eigen::Matrix3d R;
    R.row(0) = x.transpose();
    R.row(1) = y.transpose();
    R.row(2) = z.transpose();
    View view;
    view.id_view = view.id_pose = static_cast<IndexT>(k);
    view.id_intrinsic = 0;
    char name[32];
    std::snprintf(name, sizeof(name), "img_%03d.jpg", k);
    view.filename = name;
    view.width = 640;
    view.height = 480;
    scene.views[view.id_view] = view;
    scene.poses[view.id_pose] = Pose(R, center);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (IndexT id = 0; id < 200; ++id) {
    Landmark landmark;
    landmark.X = Eigen::Vector3d(uniform(rng), uniform(rng), 0.5 * uniform(rng));
    for (const auto& [view_id, view] : scene.views) {
      const Eigen::Vector3d X_cam = scene.poses.at(view.id_pose).ToCamera(landmark.X);
      if (X_cam.z() <= 0.1) continue;
      const Eigen::Vector2d pixel = scene.intrinsics.at(0).Project(X_cam);
      if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > 639 || pixel.y() > 479) continue;
      landmark.observations[view_id] = {pixel, id};
    }
    if (landmark.observations.size() >= 2) scene.structure[id] = landmark;
  }
  return scene;
}

RunViewGraph TwoSubgraphGraph(const SfmData& scene) {
  RunViewGraph graph;
  graph.engine = "GLOBAL_PRUNED";
  graph.num_subgraphs = 2;
  const int n = static_cast<int>(scene.views.size());
  for (const auto& [id, view] : scene.views) {
    graph.views.push_back({id, view.RelativeImagePath(), static_cast<int>(id) < n / 2 ? 0 : 1});
  }
  for (int i = 0; i < n; ++i) {
    for (int step = 1; step <= 2; ++step) {
      const int j = (i + step) % n;
      RunGraphEdge edge;
      edge.i = static_cast<IndexT>(std::min(i, j));
      edge.j = static_cast<IndexT>(std::max(i, j));
      edge.inliers = 50 + static_cast<size_t>(10 * step);
      edge.removed = (i < n / 2) != (j < n / 2);
      if (edge.removed) {
        edge.reason = "inter_subgraph_inconsistent";
        edge.value = 12.5;
        edge.threshold = 5.0;
        edge.measure = "degrees";
      }
      graph.edges.push_back(edge);
    }
  }
  std::sort(graph.edges.begin(), graph.edges.end(),
            [](const RunGraphEdge& a, const RunGraphEdge& b) { return std::tie(a.i, a.j) < std::tie(b.i, b.j); });
  return graph;
}

void WriteTestRun(const SfmData& scene, const std::string& engine, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  WriteSfmData(scene, dir / "sfm_data.json");
  RunViewGraph graph = TwoSubgraphGraph(scene);
  graph.engine = engine;
  if (engine != "GLOBAL_PRUNED") {
    graph.num_subgraphs = 0;
    for (RunGraphView& view : graph.views) view.subgraph = -1;
    for (RunGraphEdge& edge : graph.edges) edge = {edge.i, edge.j, edge.inliers, false, "", 0.0, 0.0, "", edge.relative_pose, edge.rotation_std_deg};
  }
  WriteRunViewGraph(graph, dir / "view_graph.json");
  std::ofstream(dir / "timings.json") << R"({"engine": ")" << engine
                                      << R"(", "stages": [{"stage": "verification", "seconds": 1.5},)"
                                         R"( {"stage": "bundle adjustment", "seconds": 0.75}],)"
                                         R"( "counts": {"final_rms_px": 0.5}})";
}

}  // namespace sfm_pruning::testing
