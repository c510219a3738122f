// Value checks of numeric options. CLI11's PositiveNumber and NonNegativeNumber describe their
// range with the largest double spelled out (a 309-digit number in the error line); these say the
// same in words: "--num_threads: must be positive, got 0".
#pragma once

#include <CLI/CLI.hpp>

namespace prunesfm {

// Accepts a number > 0.
CLI::Validator PositiveValue();

// Accepts a number >= 0.
CLI::Validator NonNegativeValue();

}  // namespace prunesfm
