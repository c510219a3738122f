#include "sfm_pruning/util/blas_product.hpp"

#include <mutex>

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
  // One product at a time: Debian's serial OpenBLAS (libopenblas0-serial, built without
  // USE_LOCKING) shares its work buffers between calls, so two threads multiplying at once corrupt
  // each other's results (seen as matches that changed from run to run with 2 threads). The
  // callers' other work still runs in parallel.
  static std::mutex one_product_at_a_time;
  const std::lock_guard<std::mutex> lock(one_product_at_a_time);
  sgemm_(&transpose, &keep, &rows_b, &rows_a, &cols, &one, b, &cols, a, &cols, &zero, out, &rows_b);
}

}  // namespace sfm_pruning
