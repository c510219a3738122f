// A minimal SVG text builder: numbers with fixed precision (so output is byte-stable across
// runs), escaped text, and the few elements the report draws.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace sfm_pruning {

// "&", "<", ">", '"' escaped for HTML/SVG text and attribute values.
std::string EscapeXml(const std::string& text);
// Fixed-point with `decimals` digits, trailing zeros and "-0" removed ("12.5", "3", "0").
std::string FormatNumber(double value, int decimals = 1);

class SvgBuilder {
 public:
  SvgBuilder(double width, double height);

  // Attributes are passed pre-formatted ("stroke=\"#333\" stroke-width=\"1\""); `title`, when
  // not empty, becomes a <title> child (the browser's tooltip).
  void Line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& attributes,
            const std::string& title = "");
  void Circle(const Eigen::Vector2d& center, double radius, const std::string& attributes,
              const std::string& title = "");
  void Rect(double x, double y, double width, double height, const std::string& attributes,
            const std::string& title = "");
  void Polyline(const std::vector<Eigen::Vector2d>& points, const std::string& attributes);
  void Polygon(const std::vector<Eigen::Vector2d>& points, const std::string& attributes,
               const std::string& title = "");
  void Text(const Eigen::Vector2d& at, const std::string& text, const std::string& attributes);
  // Groups: everything added until EndGroup goes inside <g attributes>.
  void BeginGroup(const std::string& attributes);
  void EndGroup();
  void Raw(const std::string& markup) { body_ += markup; }

  // <svg viewBox=... class="css_class" role="img" aria-label="label">body</svg>
  std::string Finish(const std::string& css_class, const std::string& label) const;

 private:
  void Close(const std::string& element, const std::string& title);
  double width_;
  double height_;
  std::string body_;
};

}  // namespace sfm_pruning
