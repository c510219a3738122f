// What `--help` shows. A subcommand's help lists the options most runs need; the options a user
// sets only to study or adjust the method (thresholds of the pruning's additions, solver and
// matcher internals) are marked expert and collapse to one line per group that points at
// `--help_all`, which lists every option. Without this `prunesfm run --help` is 170 lines.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace prunesfm {

// The help group of the expert options (CLI::Option::group).
inline constexpr const char* kExpertOptionsGroup = "Expert options";

// Moves `option` into the expert group; returns it for chaining.
CLI::Option* MarkExpert(CLI::Option* option);

// Moves every option of the option group `group` but `shown` (and the help flags) into the
// expert group.
void MarkExpertExcept(CLI::App* group, const std::string& shown);

// Installs the collapsing help on `app` and adds `--help_all`. Call before adding subcommands:
// they inherit both when they are created.
void UseCompactHelp(CLI::App* app);

}  // namespace prunesfm
