// slam_synth/small_linalg.h — the few dense operations the texture model needs on matrices
// of at most a few dozen rows (correlation matrices, the autocorrelation solve): symmetric
// eigen-decomposition, matrix functions of symmetric matrices, and a linear solve with
// partial pivoting. All in double precision, computed by Eigen 3.4 on views of Matrix.
#pragma once

#include <cstddef>
#include <vector>

namespace lw::synth {

struct Matrix {
    int rows = 0, cols = 0;
    std::vector<double> a;  // row-major
    Matrix() = default;
    Matrix(int r, int c, double value = 0.0) : rows(r), cols(c), a(size_t(r) * size_t(c), value) {}
    double& operator()(int r, int c) { return a[size_t(r) * size_t(cols) + size_t(c)]; }
    double operator()(int r, int c) const { return a[size_t(r) * size_t(cols) + size_t(c)]; }
};

[[nodiscard]] Matrix multiply(const Matrix& x, const Matrix& y);
[[nodiscard]] Matrix transpose(const Matrix& x);

// Eigenvalues (any order; Eigen gives them ascending) and orthonormal eigenvectors (columns,
// signs arbitrary) of a symmetric matrix; m is symmetrized first, (m + mᵀ)/2.
void symmetric_eigen(const Matrix& m, std::vector<double>& values, Matrix& vectors);

// V·diag(λ^power)·Vᵀ of a symmetric matrix. Eigenvalues at or below `floor` × the largest
// |λ| count as zero (0^power := 0 for negative powers too: a pseudo-inverse), so
// indefinite or rank-deficient targets degrade gracefully instead of producing NaNs.
[[nodiscard]] Matrix symmetric_power(const Matrix& m, double power, double floor = 1e-10);

// Solves a·x = b in place (b becomes x). False when a is singular to working precision.
[[nodiscard]] bool solve_linear(Matrix a, std::vector<double>& b);

}  // namespace lw::synth
