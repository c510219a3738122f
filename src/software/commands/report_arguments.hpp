// Arguments and errors shared by `prunesfm epipolar` and `prunesfm report`.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/report/html_report.hpp"
#include "sfm_pruning/util/error.hpp"

namespace prunesfm {

// "x,y" -> pixel. Throws sfm_pruning::Error naming `option` for anything else.
Eigen::Vector2d ParsePixel(const std::string& text, const std::string& option);

// "IMAGE:x,y" (the image name may itself contain ':'; the last one separates) -> request.
sfm_pruning::EpipolarRequest ParseCheck(const std::string& text, const std::string& option);

// Library errors about a model ("image X is not registered") do not say which model: rethrows
// `error` as "<source>: <message>" unless the message already starts with one of `named` (the
// paths the command was given, which the readers put first).
[[noreturn]] void RethrowNamingSource(const sfm_pruning::Error& error, const std::string& source,
                                      const std::vector<std::string>& named);

}  // namespace prunesfm
