#include "software/cli_checks.hpp"

#include <cstdlib>
#include <functional>
#include <string>

namespace prunesfm {
namespace {

// Empty when the whole of `input` parses as a number and `accept` holds for it, else the reason.
std::string CheckNumber(const std::string& input, const std::function<bool(double)>& accept, const char* wanted) {
  char* end = nullptr;
  const double value = std::strtod(input.c_str(), &end);
  if (input.empty() || end != input.c_str() + input.size()) return "expected a number, got '" + input + "'";
  if (!accept(value)) return std::string("must be ") + wanted + ", got " + input;
  return {};
}

}  // namespace

CLI::Validator PositiveValue() {
  return CLI::Validator(
      [](std::string& input) { return CheckNumber(input, [](double v) { return v > 0.0; }, "positive"); },
      "POSITIVE");
}

CLI::Validator NonNegativeValue() {
  return CLI::Validator(
      [](std::string& input) { return CheckNumber(input, [](double v) { return v >= 0.0; }, "zero or more"); },
      "NONNEGATIVE");
}

}  // namespace prunesfm
