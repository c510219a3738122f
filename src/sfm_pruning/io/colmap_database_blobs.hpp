// Blob encoding shared by the COLMAP database reader and writer: arrays of fixed-size values
// stored as raw little-endian bytes, and 3x3 matrices stored row-major.
#pragma once

#include <Eigen/Core>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::colmap_blobs {

// Decodes `count` values of T; throws naming `what` when the blob has another size.
template <typename T>
std::vector<T> DecodeArray(const std::string& blob, size_t count, const std::string& source,
                           const std::string& what) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (blob.size() != count * sizeof(T)) {
    throw FileError(source, what + " blob has " + std::to_string(blob.size()) + " bytes, expected " +
                                std::to_string(count * sizeof(T)));
  }
  std::vector<T> values(count);
  if (count > 0) std::memcpy(values.data(), blob.data(), blob.size());
  return values;
}

template <typename T>
std::string EncodeArray(const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// COLMAP writes its (column-major) Eigen matrices transposed, i.e. the blob is row-major.
inline Eigen::Matrix3d DecodeMatrix3(const std::string& blob, const std::string& source,
                                     const std::string& what) {
  if (blob.empty()) return Eigen::Matrix3d::Zero();
  const std::vector<double> values = DecodeArray<double>(blob, 9, source, what);
  const Eigen::Matrix3d matrix = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(values.data());
  if (!matrix.allFinite()) throw FileError(source, what + " is not finite");
  return matrix;
}

inline std::string EncodeMatrix3(const Eigen::Matrix3d& matrix) {
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> row_major = matrix;
  return std::string(reinterpret_cast<const char*>(row_major.data()), 9 * sizeof(double));
}

}  // namespace sfm_pruning::colmap_blobs
