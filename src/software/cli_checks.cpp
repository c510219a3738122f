#include "software/cli_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
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
  if (!std::isfinite(value)) return "expected a finite number, got " + input;
  if (!accept(value)) return std::string("must be ") + wanted + ", got " + input;
  return {};
}

// Empty when `input` is a whole number from 0 to 2^64 - 1, else the reason.
std::string CheckUnsigned64(std::string& input) {
  const bool digits = !input.empty() && input.find_first_not_of("0123456789") == std::string::npos;
  errno = 0;
  if (digits) std::strtoull(input.c_str(), nullptr, 10);
  if (!digits || errno == ERANGE) return "expected a whole number from 0 to 18446744073709551615, got " + input;
  return {};
}

std::string Format(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
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

CLI::Validator RangeValue(double min, double max) {
  const std::string range = "in [" + Format(min) + ", " + Format(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& input) {
        return CheckNumber(input, [min, max](double v) { return v >= min && v <= max; }, range.c_str());
      },
      "NUMBER " + range);
}

CLI::Validator SeedValue() { return CLI::Validator(CheckUnsigned64, "UINT64"); }

void CheckEveryNumber(CLI::App* app) {
  // Validators without a name leave the option's help as it was.
  const CLI::Validator finite(
      [](std::string& input) { return CheckNumber(input, [](double) { return true; }, "finite"); }, "");
  const CLI::Validator unsigned_64(CheckUnsigned64, "");
  for (CLI::Option* option : app->get_options()) {
    const std::string type = option->get_type_name();
    if (type.rfind("FLOAT", 0) == 0) option->check(finite);
    if (type.rfind("UINT", 0) == 0) option->check(unsigned_64);
  }
  for (CLI::App* subcommand : app->get_subcommands([](CLI::App*) { return true; })) CheckEveryNumber(subcommand);
}

}  // namespace prunesfm
