// Single-precision matrix products through the system BLAS (libblas.so.3, which Debian's
// alternatives point at OpenBLAS, ATLAS or the reference implementation). The products here are
// large and dense (descriptor distances), where a tuned BLAS is several times faster than Eigen
// compiled for the baseline x86-64 instruction set.
#pragma once

namespace sfm_pruning {

// out (rows_a x rows_b, row-major) = a (rows_a x cols, row-major) * b^T, with b (rows_b x cols,
// row-major). All three arrays are contiguous. Safe to call from several threads: the products
// run one at a time (the serial OpenBLAS is not reentrant).
void MultiplyByTranspose(const float* a, int rows_a, const float* b, int rows_b, int cols, float* out);

}  // namespace sfm_pruning
