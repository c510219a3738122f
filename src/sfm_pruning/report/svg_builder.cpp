#include "sfm_pruning/report/svg_builder.hpp"

#include <cmath>
#include <cstdio>

namespace sfm_pruning {

std::string EscapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string FormatNumber(double value, int decimals) {
  if (!std::isfinite(value)) return "0";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  std::string text = buffer;
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

namespace {
std::string Point(const Eigen::Vector2d& p) { return FormatNumber(p.x()) + "," + FormatNumber(p.y()); }
}  // namespace

SvgBuilder::SvgBuilder(double width, double height) : width_(width), height_(height) {}

void SvgBuilder::Close(const std::string& element, const std::string& title) {
  if (title.empty()) {
    body_ += "/>\n";
  } else {
    body_ += "><title>" + EscapeXml(title) + "</title></" + element + ">\n";
  }
}

void SvgBuilder::Line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& attributes,
                      const std::string& title) {
  body_ += "<line x1=\"" + FormatNumber(a.x()) + "\" y1=\"" + FormatNumber(a.y()) + "\" x2=\"" + FormatNumber(b.x()) +
           "\" y2=\"" + FormatNumber(b.y()) + "\" " + attributes;
  Close("line", title);
}

void SvgBuilder::Circle(const Eigen::Vector2d& center, double radius, const std::string& attributes,
                        const std::string& title) {
  body_ += "<circle cx=\"" + FormatNumber(center.x()) + "\" cy=\"" + FormatNumber(center.y()) + "\" r=\"" +
           FormatNumber(radius, 2) + "\" " + attributes;
  Close("circle", title);
}

void SvgBuilder::Rect(double x, double y, double width, double height, const std::string& attributes,
                      const std::string& title) {
  body_ += "<rect x=\"" + FormatNumber(x) + "\" y=\"" + FormatNumber(y) + "\" width=\"" + FormatNumber(width) +
           "\" height=\"" + FormatNumber(height) + "\" " + attributes;
  Close("rect", title);
}

void SvgBuilder::Polyline(const std::vector<Eigen::Vector2d>& points, const std::string& attributes) {
  if (points.size() < 2) return;
  body_ += "<polyline points=\"";
  for (size_t k = 0; k < points.size(); ++k) body_ += (k == 0 ? "" : " ") + Point(points[k]);
  body_ += "\" " + attributes + "/>\n";
}

void SvgBuilder::Polygon(const std::vector<Eigen::Vector2d>& points, const std::string& attributes,
                         const std::string& title) {
  body_ += "<polygon points=\"";
  for (size_t k = 0; k < points.size(); ++k) body_ += (k == 0 ? "" : " ") + Point(points[k]);
  body_ += "\" " + attributes;
  Close("polygon", title);
}

void SvgBuilder::Text(const Eigen::Vector2d& at, const std::string& text, const std::string& attributes) {
  body_ += "<text x=\"" + FormatNumber(at.x()) + "\" y=\"" + FormatNumber(at.y()) + "\" " + attributes + ">" +
           EscapeXml(text) + "</text>\n";
}

void SvgBuilder::BeginGroup(const std::string& attributes) { body_ += "<g " + attributes + ">\n"; }
void SvgBuilder::EndGroup() { body_ += "</g>\n"; }

std::string SvgBuilder::Finish(const std::string& css_class, const std::string& label) const {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + FormatNumber(width_) + " " +
         FormatNumber(height_) + "\" class=\"" + EscapeXml(css_class) + "\" role=\"img\" aria-label=\"" +
         EscapeXml(label) + "\">\n" + body_ + "</svg>\n";
}

}  // namespace sfm_pruning
