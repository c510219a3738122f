// The rules an options struct's Check() applies to one field. Each throws std::invalid_argument
// with one line naming the field ("SubgraphLoopOptions::max_rotation_deg must be in (0, 180], got
// -1"), so a library caller learns which value is wrong before any work starts.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sfm_pruning {

namespace option_checks_detail {
template <typename T>
[[noreturn]] void Fail(const std::string& field, const std::string& rule, T value) {
  std::ostringstream message;
  message << field << " must be " << rule << ", got " << value;
  throw std::invalid_argument(message.str());
}
}  // namespace option_checks_detail

// min <= value <= max (NaN fails).
template <typename T>
void RequireInRange(T value, T min, T max, const std::string& field) {
  if (!(value >= min && value <= max)) {
    std::ostringstream rule;
    rule << "in [" << min << ", " << max << "]";
    option_checks_detail::Fail(field, rule.str(), value);
  }
}

// 0 < value <= max (NaN fails).
inline void RequirePositiveAtMost(double value, double max, const std::string& field) {
  if (!(value > 0.0 && value <= max)) {
    std::ostringstream rule;
    rule << "in (0, " << max << "]";
    option_checks_detail::Fail(field, rule.str(), value);
  }
}

// value >= min (NaN fails).
template <typename T>
void RequireAtLeast(T value, T min, const std::string& field) {
  if (!(value >= min)) {
    std::ostringstream rule;
    rule << "at least " << min;
    option_checks_detail::Fail(field, rule.str(), value);
  }
}

// 0 < value < infinity (NaN fails).
inline void RequirePositiveFinite(double value, const std::string& field) {
  if (!(value > 0.0 && std::isfinite(value))) option_checks_detail::Fail(field, "positive and finite", value);
}

// min <= value < max (NaN fails).
inline void RequireInHalfOpenRange(double value, double min, double max, const std::string& field) {
  if (!(value >= min && value < max)) {
    std::ostringstream rule;
    rule << "in [" << min << ", " << max << ")";
    option_checks_detail::Fail(field, rule.str(), value);
  }
}

// Any number (NaN fails): for fields where every value, negative ones included, has a meaning.
inline void RequireNumber(double value, const std::string& field) {
  if (std::isnan(value)) option_checks_detail::Fail(field, "a number", value);
}

}  // namespace sfm_pruning
