// Shared expectations of the options structs' Check() tests: the defaults pass, and each spoiled
// field fails with one line that starts with "Struct::field" (util/option_checks.hpp).
#pragma once

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace sfm_pruning::testing {

// The usual spoilers of a range (a few fields take infinity as "no limit").
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The message of the std::invalid_argument that `options.Check()` throws ("" when none).
template <typename Options>
std::string CheckMessage(const Options& options) {
  try {
    options.Check();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// How to spoil (or set) fields of default options.
template <typename Options>
using Spoil = std::function<void(Options*)>;

// The message of default options after `spoil` ("" when Check() passes): CheckMessage<O>([](O* o) {...}).
template <typename Options>
std::string CheckMessage(const Spoil<Options>& spoil) {
  Options options;
  spoil(&options);
  return CheckMessage(options);
}

// (how to spoil one field of default options, the field the message must start with).
template <typename Options>
using SpoiledCases = std::vector<std::pair<Spoil<Options>, std::string>>;

template <typename Options>
void ExpectEachCaseNamesItsField(const SpoiledCases<Options>& cases) {
  for (const auto& [spoil, field] : cases) {
    const std::string message = CheckMessage<Options>(spoil);
    EXPECT_EQ(message.rfind(field, 0), 0u) << "expected a message starting with " << field << ", got '" << message
                                           << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace sfm_pruning::testing
