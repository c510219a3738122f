// Error reporting for everything that touches user input.
//
// Library code throws sfm_pruning::Error for bad input (a file that is missing, truncated,
// of the wrong type, or that references ids that do not exist). The message is one line that
// names the file and the problem, so the CLI can print it verbatim and exit non-zero.
// Programming errors (broken invariants inside the library) are not reported this way.
#pragma once

#include <stdexcept>
#include <string>

namespace sfm_pruning {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Builds "<path>: <problem>", the one-line form every user-facing error takes.
inline Error FileError(const std::string& path, const std::string& problem) {
  return Error(path + ": " + problem);
}

}  // namespace sfm_pruning
