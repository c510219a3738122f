#include "sfm_pruning/util/blas_product.hpp"

// The Fortran interface: every BLAS Debian ships exports it, while the C interface (cblas) lives
// in different libraries and headers depending on the implementation.
extern "C" void sgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const float* alpha, const float* a, const int* lda, const float* b, const int* ldb,
                       const float* beta, float* c, const int* ldc);

namespace sfm_pruning {

void MultiplyByTranspose(const float* a, int rows_a, const float* b, int rows_b, int cols, float* out) {
  if (rows_a <= 0 || rows_b <= 0) return;
  // BLAS is column-major: a row-major (rows_a x rows_b) result is the column-major product
  // b * a^T of size (rows_b x rows_a), and the row-major inputs are the column-major b^T and a^T.
  const char transpose = 'T';
  const char keep = 'N';
  const float one = 1.0f;
  const float zero = 0.0f;
  sgemm_(&transpose, &keep, &rows_b, &rows_a, &cols, &one, b, &cols, a, &cols, &zero, out, &rows_b);
}

}  // namespace sfm_pruning
