#include "small_linalg.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace lw::synth {

namespace {

// Matrix is row-major; map it rather than copy it.
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
Eigen::Map<RowMajor> view(Matrix& m) { return {m.a.data(), m.rows, m.cols}; }
Eigen::Map<const RowMajor> view(const Matrix& m) { return {m.a.data(), m.rows, m.cols}; }

// SelfAdjointEigenSolver reads only the lower triangle. Our inputs (Gram matrices,
// differences of products) can be asymmetric in the last bit, so use both halves.
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen_of(const Matrix& m) {
    const auto v = view(m);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (v + v.transpose()));
}

}  // namespace

Matrix multiply(const Matrix& x, const Matrix& y) {
    Matrix out(x.rows, y.cols);
    view(out).noalias() = view(x) * view(y);
    return out;
}

Matrix transpose(const Matrix& x) {
    Matrix out(x.cols, x.rows);
    view(out) = view(x).transpose();
    return out;
}

void symmetric_eigen(const Matrix& m, std::vector<double>& values, Matrix& vectors) {
    const auto es = eigen_of(m);
    values.assign(es.eigenvalues().data(), es.eigenvalues().data() + m.rows);
    vectors = Matrix(m.rows, m.rows);
    view(vectors) = es.eigenvectors();
}

Matrix symmetric_power(const Matrix& m, double power, double floor) {
    const int n = m.rows;
    Matrix out(n, n);
    if (n == 0) return out;
    const auto es = eigen_of(m);
    const Eigen::VectorXd& l = es.eigenvalues();
    const double cut = floor * l.cwiseAbs().maxCoeff();
    Eigen::VectorXd f(n);
    for (int k = 0; k < n; ++k) f[k] = (l[k] <= cut || l[k] <= 0.0) ? 0.0 : std::pow(l[k], power);
    const Eigen::MatrixXd& v = es.eigenvectors();
    view(out).noalias() = v * f.asDiagonal() * v.transpose();
    return out;
}

bool solve_linear(Matrix a, std::vector<double>& b) {
    const int n = a.rows;
    if (n == 0) return false;
    auto av = view(a);
    const double scale = av.cwiseAbs().maxCoeff();
    if (scale == 0.0) return false;
    // In place: `a` is our copy. Eigen does not refuse singular matrices, so apply our
    // rule to the pivots (the diagonal of U): one at or below 1e-13 × max |a_ij| fails.
    const Eigen::PartialPivLU<Eigen::Ref<RowMajor>> lu(av);
    if ((lu.matrixLU().diagonal().array().abs() <= 1e-13 * scale).any()) return false;
    const Eigen::VectorXd x = lu.solve(Eigen::Map<const Eigen::VectorXd>(b.data(), n));
    b.assign(x.data(), x.data() + n);
    return true;
}

}  // namespace lw::synth
