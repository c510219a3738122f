#include "sfm_pruning/report/top_view.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "sfm_pruning/report/svg_builder.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

Eigen::Vector3d AnyPerpendicular(const Eigen::Vector3d& v) {
  const Eigen::Vector3d other = std::abs(v.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return v.cross(other).normalized();
}

// Value at `fraction` of the sorted values (nearest rank).
double Quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(fraction * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

TopViewFrame TopViewFrameOf(const TopViewScene& scene) {
  TopViewFrame frame;
  if (scene.cameras.empty()) return frame;
  const bool use_truth = std::all_of(scene.cameras.begin(), scene.cameras.end(),
                                     [](const TopViewCamera& c) { return c.true_center.has_value(); });
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  for (const TopViewCamera& camera : scene.cameras) up -= camera.pose.rotation.row(1).transpose();
  std::vector<Eigen::Vector3d> centers;
  for (const TopViewCamera& camera : scene.cameras) centers.push_back(use_truth ? *camera.true_center : camera.pose.center);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& c : centers) mean += c;
  mean /= static_cast<double>(centers.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& c : centers) scatter += (c - mean) * (c - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  // Centres spread over a plane (a ring, an orbit, a grid of aerial shots): that plane is the
  // ground, whichever way the images were held (the Middlebury rings are shot sideways). Its
  // normal takes the sign of the cameras' up vector, or else points away from where the cameras
  // look (they look down at an object more often than up). Otherwise (a street, a single line
  // of views) the mean up vector of the cameras, when they agree on one.
  const Eigen::Vector3d spread = eigen.eigenvalues().cwiseMax(0.0);
  const bool planar = centers.size() >= 4 && spread(1) > 0.05 * spread(2) && spread(0) < 0.2 * spread(1);
  if (planar || up.norm() < 0.3 * static_cast<double>(scene.cameras.size())) {
    Eigen::Vector3d normal = eigen.eigenvectors().col(0);
    Eigen::Vector3d looking = Eigen::Vector3d::Zero();
    for (const TopViewCamera& camera : scene.cameras) looking += camera.pose.ViewingDirection();
    const double sign = std::abs(normal.dot(up.normalized())) > 0.5 ? normal.dot(up) : -normal.dot(looking);
    up = sign < 0.0 ? -normal : normal;
  }
  up.normalize();
  // Largest spread of the centres within the plane orthogonal to up.
  Eigen::Vector3d axis_x = eigen.eigenvectors().col(2);
  axis_x -= up * up.dot(axis_x);
  if (axis_x.norm() < 1e-6) axis_x = eigen.eigenvectors().col(1) - up * up.dot(eigen.eigenvectors().col(1));
  axis_x = axis_x.norm() < 1e-6 ? AnyPerpendicular(up) : axis_x.normalized();
  // Eigenvectors have no sign: fix it so the first camera is on the left.
  if ((centers.front() - mean).dot(axis_x) > 0.0) axis_x = -axis_x;
  frame.axis_x = axis_x;
  frame.axis_y = up.cross(axis_x);
  return frame;
}

std::string DrawTopViewSvg(const TopViewScene& scene, const TopViewFrame& frame, const TopViewOptions& options) {
  options.Check();
  const auto plane = [&](const Eigen::Vector3d& X) { return Eigen::Vector2d(frame.axis_x.dot(X), frame.axis_y.dot(X)); };
  const size_t stride = std::max<size_t>(1, (scene.points.size() + options.max_points - 1) / std::max<size_t>(1, options.max_points));

  // Extent: all cameras (and true centres) plus the central quantile of the points.
  std::vector<Eigen::Vector2d> anchors;
  for (const TopViewCamera& camera : scene.cameras) {
    anchors.push_back(plane(camera.pose.center));
    if (camera.true_center) anchors.push_back(plane(*camera.true_center));
  }
  std::vector<double> xs, ys;
  for (size_t k = 0; k < scene.points.size(); k += stride) {
    const Eigen::Vector2d p = plane(scene.points[k].X);
    xs.push_back(p.x());
    ys.push_back(p.y());
  }
  const double tail = (1.0 - options.point_quantile) / 2.0;
  if (!xs.empty()) {
    anchors.emplace_back(Quantile(xs, tail), Quantile(ys, tail));
    anchors.emplace_back(Quantile(xs, 1.0 - tail), Quantile(ys, 1.0 - tail));
  }
  Eigen::Vector2d low(0, 0), high(1, 1);
  if (!anchors.empty()) {
    low = high = anchors.front();
    for (const Eigen::Vector2d& a : anchors) {
      low = low.cwiseMin(a);
      high = high.cwiseMax(a);
    }
  }
  const double margin = 18.0;
  const Eigen::Vector2d span = (high - low).cwiseMax(1e-9);
  const double scale = std::min((options.width - 2 * margin) / span.x(), (options.height - 2 * margin) / span.y());
  const Eigen::Vector2d mid = (low + high) / 2.0;
  const auto screen = [&](const Eigen::Vector3d& X) {
    const Eigen::Vector2d p = (plane(X) - mid) * scale;
    return Eigen::Vector2d(options.width / 2.0 + p.x(), options.height / 2.0 - p.y());
  };
  const auto inside = [&](const Eigen::Vector2d& s) {
    return s.x() >= 0 && s.y() >= 0 && s.x() <= options.width && s.y() <= options.height;
  };

  SvgBuilder svg(options.width, options.height);
  svg.Rect(0, 0, options.width, options.height, "fill=\"#fbfbfc\" stroke=\"#d9dde3\"");
  svg.BeginGroup("class=\"points\" fill-opacity=\"0.55\"");
  for (size_t k = 0; k < scene.points.size(); k += stride) {
    const Eigen::Vector2d s = screen(scene.points[k].X);
    if (inside(s)) svg.Rect(s.x() - 0.7, s.y() - 0.7, 1.4, 1.4, "fill=\"" + scene.points[k].color.Hex() + "\"");
  }
  svg.EndGroup();

  const double size = std::clamp(160.0 / std::sqrt(static_cast<double>(scene.cameras.size()) + 1.0), 4.0, 9.0);
  const std::string truth = report_colors::kTruth.Hex();
  std::vector<Eigen::Vector2d> true_path, path;
  for (const TopViewCamera& camera : scene.cameras) {
    path.push_back(screen(camera.pose.center));
    if (camera.true_center) true_path.push_back(screen(*camera.true_center));
  }
  svg.Polyline(true_path, "fill=\"none\" stroke=\"" + truth + "\" stroke-width=\"1\" stroke-opacity=\"0.5\"");
  svg.Polyline(path, "fill=\"none\" stroke=\"#333a45\" stroke-width=\"0.8\" stroke-opacity=\"0.45\"");
  svg.BeginGroup("class=\"cameras\"");
  for (const TopViewCamera& camera : scene.cameras) {
    const Eigen::Vector2d c = screen(camera.pose.center);
    if (camera.true_center) {
      const Eigen::Vector2d t = screen(*camera.true_center);
      svg.Line(c, t, "stroke=\"" + truth + "\" stroke-width=\"0.8\" stroke-opacity=\"0.8\"");
      svg.Circle(t, size * 0.55, "fill=\"none\" stroke=\"" + truth + "\" stroke-width=\"1.2\"",
                 camera.label + " (ground truth)");
    }
    // A wedge pointing along the viewing direction projected into the plane.
    Eigen::Vector2d direction = screen(camera.pose.center + camera.pose.ViewingDirection()) - c;
    direction = direction.norm() > 1e-9 ? direction.normalized() : Eigen::Vector2d(0, -1);
    const Eigen::Vector2d side(-direction.y(), direction.x());
    const Eigen::Vector2d tip = c + direction * size * 1.3;
    const Eigen::Vector2d base = c - direction * size * 0.4;
    svg.Polygon({tip, base + side * size * 0.6, base - side * size * 0.6},
                "fill=\"" + camera.color.Hex() + "\" stroke=\"#1d2230\" stroke-width=\"0.5\"", camera.label);
  }
  svg.EndGroup();
  return svg.Finish("topview", "top view of the cameras and points");
}

void TopViewOptions::Check() const {
  // The drawing's size in SVG pixels: every position is computed from it.
  RequirePositiveFinite(width, "TopViewOptions::width");
  RequirePositiveFinite(height, "TopViewOptions::height");
  // The subsample keeps at least one point whatever the cap, so 0 would not mean "none".
  RequireAtLeast<size_t>(max_points, 1, "TopViewOptions::max_points");
  RequireInRange(point_quantile, 0.0, 1.0, "TopViewOptions::point_quantile");
}

}  // namespace sfm_pruning
