#include "sfm_pruning/report/epipolar_image.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/image_codecs.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

cv::Scalar Bgr(const Rgb& c) { return cv::Scalar(c.b, c.g, c.r); }

// The panel's picture at full resolution, plus the factor from model pixels to its pixels.
cv::Mat LoadPanelImage(const EpipolarPanel& panel, const SfmData& model, const EpipolarImageOptions& options,
                       double* model_to_image) {
  *model_to_image = 1.0;
  const int width = std::max<int>(1, static_cast<int>(panel.width > 0 ? panel.width : 640));
  const int height = std::max<int>(1, static_cast<int>(panel.height > 0 ? panel.height : 480));
  if (options.images_dir) {
    cv::Mat image = ReadColorImage(*options.images_dir / panel.image);
    if (panel.width > 0) *model_to_image = static_cast<double>(image.cols) / panel.width;
    return image;
  }
  // No pixels: the features the model observed in this view, on a dark canvas.
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(70, 62, 58));
  IndexT view_id = kUndefinedIndex;
  for (const auto& [id, view] : model.views) {
    if (view.RelativeImagePath() == panel.image) view_id = id;
  }
  const int radius = std::max(2, width / 300);
  for (const auto& [id, landmark] : model.structure) {
    const auto it = landmark.observations.find(view_id);
    if (it == landmark.observations.end()) continue;
    cv::circle(canvas, cv::Point(static_cast<int>(std::lround(it->second.x.x())), static_cast<int>(std::lround(it->second.x.y()))),
               radius, cv::Scalar(200, 196, 192), cv::FILLED, cv::LINE_AA);
  }
  return canvas;
}

cv::Point ToPanel(const Eigen::Vector2d& pixel, double scale) {
  // Pixel centres at integer coordinates in both conventions: (x + 0.5) * s - 0.5.
  return cv::Point(static_cast<int>(std::lround((pixel.x() + 0.5) * scale - 0.5)),
                   static_cast<int>(std::lround((pixel.y() + 0.5) * scale - 0.5)));
}

void DrawCurves(cv::Mat* image, const std::vector<PixelPolyline>& pieces, double scale, const cv::Scalar& color,
                int thickness, bool dashed) {
  for (const PixelPolyline& piece : pieces) {
    for (size_t k = 0; k + 1 < piece.size(); ++k) {
      if (dashed && (k / 4) % 2 == 1) continue;
      cv::line(*image, ToPanel(piece[k], scale), ToPanel(piece[k + 1], scale), color, thickness, cv::LINE_AA);
    }
  }
}

void DrawRing(cv::Mat* image, const cv::Point& at, int radius, const cv::Scalar& fill, bool filled) {
  cv::circle(*image, at, radius + 2, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  if (filled) {
    cv::circle(*image, at, radius, fill, cv::FILLED, cv::LINE_AA);
    cv::circle(*image, at, radius + 1, cv::Scalar(255, 255, 255), 2, cv::LINE_AA);
  } else {
    cv::circle(*image, at, radius, cv::Scalar(255, 255, 255), 2, cv::LINE_AA);
  }
}

cv::Mat DrawPanel(const EpipolarPanel& panel, bool is_reference, const Eigen::Vector2d& point, const SfmData& model,
                  const EpipolarImageOptions& options) {
  double model_to_image = 1.0;
  cv::Mat image = LoadPanelImage(panel, model, options, &model_to_image);
  const double resize = static_cast<double>(options.panel_height) / image.rows;
  cv::Mat scaled;
  cv::resize(image, scaled, cv::Size(std::max(1, static_cast<int>(std::lround(image.cols * resize))), options.panel_height),
             0, 0, cv::INTER_AREA);
  const double scale = model_to_image * resize;
  const int thickness = 2;
  const int marker = std::max(4, options.panel_height / 60);
  if (is_reference) {
    DrawRing(&scaled, ToPanel(point, scale), marker, Bgr(report_colors::kRemoved), true);
  } else {
    // The dashed truth goes on top: where the lines coincide both colours alternate.
    DrawCurves(&scaled, panel.estimated, scale, Bgr(report_colors::kRemoved), thickness, false);
    DrawCurves(&scaled, panel.truth, scale, Bgr(report_colors::kTruth), thickness, true);
    if (panel.matched_feature) DrawRing(&scaled, ToPanel(*panel.matched_feature, scale), marker, cv::Scalar(), false);
  }
  // Caption strip under the picture.
  std::string caption = panel.image;
  if (is_reference) caption += "  (reference)";
  if (!is_reference && !panel.registered) caption += "  (not registered)";
  cv::Mat strip(26, scaled.cols, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(strip, caption, cv::Point(6, 18), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  cv::Mat out;
  cv::vconcat(scaled, strip, out);
  return out;
}

}  // namespace

std::vector<uint8_t> RenderEpipolarCheck(const EpipolarCheck& check, const SfmData& model,
                                         const EpipolarImageOptions& options, const std::string& extension) {
  options.Check();
  std::vector<cv::Mat> panels = {DrawPanel(check.reference, true, check.point, model, options)};
  for (const EpipolarPanel& panel : check.others) panels.push_back(DrawPanel(panel, false, check.point, model, options));
  const int gap = 8;
  int width = -gap;
  for (const cv::Mat& panel : panels) width += panel.cols + gap;
  const int title_height = options.title.empty() ? 0 : 28;
  cv::Mat figure(panels.front().rows + title_height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  if (title_height > 0) {
    cv::putText(figure, options.title, cv::Point(6, 20), cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(20, 20, 20), 1,
                cv::LINE_AA);
  }
  int x = 0;
  for (const cv::Mat& panel : panels) {
    panel.copyTo(figure(cv::Rect(x, title_height, panel.cols, panel.rows)));
    x += panel.cols + gap;
  }
  std::vector<uint8_t> bytes;
  const std::vector<int> parameters =
      extension == ".jpg" ? std::vector<int>{cv::IMWRITE_JPEG_QUALITY, 88} : std::vector<int>{};
  if (!EncodeImage(extension, figure, parameters, &bytes)) throw Error("could not encode the epipolar check as " + extension);
  return bytes;
}

void EpipolarImageOptions::Check() const {
  // Every panel is scaled to this many rows; images_dir and title take any value.
  RequireAtLeast(panel_height, 1, "EpipolarImageOptions::panel_height");
}

}  // namespace sfm_pruning
