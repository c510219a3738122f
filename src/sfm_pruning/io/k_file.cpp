#include "sfm_pruning/io/k_file.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

Eigen::Matrix3d ReadKFile(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path.string(), "cannot open the K file");
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    try {
      size_t used = 0;
      values.push_back(std::stod(token, &used));
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      throw FileError(path.string(), "not a number: '" + token + "' (a K file holds the 9 numbers of a 3x3 matrix)");
    }
  }
  if (values.size() != 9) {
    throw FileError(path.string(), "a K file holds the 9 numbers of a 3x3 matrix, found " +
                                       std::to_string(values.size()));
  }
  Eigen::Matrix3d K;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) K(r, c) = values[static_cast<size_t>(3 * r + c)];
  }
  if (!(K(0, 0) > 0.0 && K(1, 1) > 0.0) || K(1, 0) != 0.0 || K(2, 0) != 0.0 || K(2, 1) != 0.0 || K(2, 2) != 1.0 ||
      !std::isfinite(K.sum())) {
    throw FileError(path.string(), "not a camera matrix [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0");
  }
  return K;
}

}  // namespace sfm_pruning
