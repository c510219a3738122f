// MultiplyByTranspose (util/blas_product.hpp): the row-major/column-major bookkeeping around sgemm.
#include <gtest/gtest.h>

#include <vector>

#include "sfm_pruning/util/blas_product.hpp"

namespace sfm_pruning {
namespace {

TEST(BlasProduct, MultipliesRowMajorMatricesByTheTransposeOfTheSecond) {
  // a: 3 x 2, b: 4 x 2 (row-major); out = a * b^T is 3 x 4, entry (i, j) = a_i . b_j.
  const std::vector<float> a = {1, 2, 3, 4, 5, 6};
  const std::vector<float> b = {1, 0, 0, 1, 1, 1, 2, -1};
  std::vector<float> out(12, -7.f);
  MultiplyByTranspose(a.data(), 3, b.data(), 4, 2, out.data());
  const std::vector<float> expected = {1, 2, 3, 0, 3, 4, 7, 2, 5, 6, 11, 4};
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_FLOAT_EQ(out[k], expected[k]) << "entry " << k;
}

TEST(BlasProduct, LongRowsMatchAPlainLoop) {
  // The descriptor case: 128 columns, more rows than one register block.
  const int rows_a = 37;
  const int rows_b = 53;
  const int cols = 128;
  std::vector<float> a(static_cast<size_t>(rows_a * cols));
  std::vector<float> b(static_cast<size_t>(rows_b * cols));
  for (size_t k = 0; k < a.size(); ++k) a[k] = static_cast<float>((k * 7919) % 255);
  for (size_t k = 0; k < b.size(); ++k) b[k] = static_cast<float>((k * 104729) % 255);
  std::vector<float> out(static_cast<size_t>(rows_a * rows_b));
  MultiplyByTranspose(a.data(), rows_a, b.data(), rows_b, cols, out.data());
  for (int i = 0; i < rows_a; ++i) {
    for (int j = 0; j < rows_b; ++j) {
      double dot = 0.0;
      for (int c = 0; c < cols; ++c) dot += double{a[static_cast<size_t>(i * cols + c)]} * b[static_cast<size_t>(j * cols + c)];
      // Integer-valued products below 2^24 per term: float sums are exact up to a few ulps.
      EXPECT_NEAR(out[static_cast<size_t>(i * rows_b + j)], dot, 1e-6 * dot) << i << "," << j;
    }
  }
}

TEST(BlasProduct, EmptyInputsLeaveTheOutputAlone) {
  std::vector<float> out(1, 3.f);
  MultiplyByTranspose(nullptr, 0, nullptr, 0, 128, out.data());
  EXPECT_EQ(out[0], 3.f);
}

}  // namespace
}  // namespace sfm_pruning
