#include "software/commands/report_arguments.hpp"

#include <cmath>
#include <cstdlib>

#include "sfm_pruning/util/error.hpp"

namespace prunesfm {
namespace {

bool ParseDouble(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*value);
}

}  // namespace

Eigen::Vector2d ParsePixel(const std::string& text, const std::string& option) {
  const size_t comma = text.find(',');
  double x = 0.0, y = 0.0;
  if (comma == std::string::npos || !ParseDouble(text.substr(0, comma), &x) || !ParseDouble(text.substr(comma + 1), &y)) {
    throw sfm_pruning::Error(option + ": expected a pixel as x,y, got \"" + text + "\"");
  }
  return {x, y};
}

sfm_pruning::EpipolarRequest ParseCheck(const std::string& text, const std::string& option) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    throw sfm_pruning::Error(option + ": expected IMAGE:x,y, got \"" + text + "\"");
  }
  return {text.substr(0, colon), ParsePixel(text.substr(colon + 1), option)};
}

void RethrowNamingSource(const sfm_pruning::Error& error, const std::string& source,
                         const std::vector<std::string>& named) {
  const std::string message = error.what();
  for (const std::string& path : named) {
    if (!path.empty() && message.rfind(path, 0) == 0) throw error;
  }
  throw sfm_pruning::FileError(source, message);
}

}  // namespace prunesfm
