#include "sfm_pruning/pruning/model_edge_audit.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <map>
#include <utility>

namespace sfm_pruning {
namespace {

using FeatureKey = std::pair<IndexT, IndexT>;  // (view id, feature id)

std::map<FeatureKey, IndexT> LandmarkOfFeature(const SfmData& model) {
  std::map<FeatureKey, IndexT> landmark_of;
  for (const auto& [landmark_id, landmark] : model.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      landmark_of.emplace(FeatureKey{view_id, observation.id_feat}, landmark_id);
    }
  }
  return landmark_of;
}

// Whether landmark X, projected into `view`, lands within `max_px` of its feature `feature`.
bool TransfersOnto(const Eigen::Vector3d& X, const View& view, IndexT feature, const SfmData& model,
                   const FeaturesPerView& features, double max_px) {
  const auto view_features = features.find(view.id_view);
  if (view_features == features.end() || feature >= view_features->second.size()) return false;
  const Eigen::Vector3d X_camera = model.PoseOf(view).ToCamera(X);
  if (!(X_camera.z() > 0.0)) return false;
  const Eigen::Vector2d pixel = model.IntrinsicsOf(view).Project(X_camera);
  return (pixel - view_features->second.Position(feature)).norm() <= max_px;
}

}  // namespace

std::vector<EdgeAgreement> AuditEdgesAgainstModel(const ViewGraph& graph, const std::vector<ViewPair>& edges,
                                                  const SfmData& model, const FeaturesPerView& features,
                                                  const ModelEdgeAuditOptions& options) {
  const std::map<FeatureKey, IndexT> landmark_of = LandmarkOfFeature(model);
  std::vector<EdgeAgreement> out;
  for (const ViewPair& pair : edges) {
    const ViewGraphEdge* edge = graph.FindEdge(pair.first, pair.second);
    if (edge == nullptr || !model.IsPosed(pair.first) || !model.IsPosed(pair.second)) continue;
    const View& view_a = model.views.at(pair.first);
    const View& view_b = model.views.at(pair.second);
    EdgeAgreement agreement;
    agreement.pair = pair;
    for (const FeatureMatch& match : graph.OrientedMatches(pair.first, pair.second)) {
      const auto through_a = landmark_of.find({pair.first, match.i});
      const auto through_b = landmark_of.find({pair.second, match.j});
      bool agrees = false;
      if (through_a != landmark_of.end()) {
        agrees = TransfersOnto(model.structure.at(through_a->second).X, view_b, match.j, model, features,
                               options.max_transfer_error_px);
      } else if (through_b != landmark_of.end()) {
        agrees = TransfersOnto(model.structure.at(through_b->second).X, view_a, match.i, model, features,
                               options.max_transfer_error_px);
      } else {
        continue;
      }
      ++agreement.transferred;
      agreement.agreeing += agrees ? 1 : 0;
    }
    out.push_back(agreement);
  }
  return out;
}

void ModelEdgeAuditOptions::Check() const {
  RequirePositiveAtMost(max_transfer_error_px, 1e4, "ModelEdgeAuditOptions::max_transfer_error_px");
  RequireAtLeast<size_t>(min_transferred_matches, 1, "ModelEdgeAuditOptions::min_transferred_matches");
  RequireInRange(readmit_agreement, 0.0, 1.0, "ModelEdgeAuditOptions::readmit_agreement");
  RequireInRange(keep_agreement, 0.0, 1.0, "ModelEdgeAuditOptions::keep_agreement");
  // An edge can be both below keep_agreement and at readmit_agreement otherwise.
  if (!(keep_agreement <= readmit_agreement)) {
    throw std::invalid_argument("ModelEdgeAuditOptions::keep_agreement must not exceed readmit_agreement");
  }
}

}  // namespace sfm_pruning
