// Value checks of numeric options. CLI11's PositiveNumber and NonNegativeNumber describe their
// range with the largest double spelled out (a 309-digit number in the error line); these say the
// same in words: "--num_threads: must be positive, got 0". None accepts NaN or infinity.
#pragma once

#include <CLI/CLI.hpp>

namespace prunesfm {

// Accepts a number > 0.
CLI::Validator PositiveValue();

// Accepts a number >= 0.
CLI::Validator NonNegativeValue();

// Accepts a number in [min, max]. Unlike CLI::Range it refuses NaN (every comparison with NaN is
// false, so a range test written as "below min or above max" lets it through).
CLI::Validator RangeValue(double min, double max);

// Accepts a seed: a whole number from 0 to 2^64 - 1 (larger ones would wrap around silently).
CLI::Validator SeedValue();

// The net under every numeric option of `app` and its subcommands, whatever checks they carry: a
// FLOAT must be finite ("--thresholds inf" would otherwise reach the code as infinity) and a UINT
// a whole number that fits in 64 bits (CLI11 reads "-1" as 2^64 - 1 and saturates 2^64). Call
// once, after every option is added.
void CheckEveryNumber(CLI::App* app);

}  // namespace prunesfm
