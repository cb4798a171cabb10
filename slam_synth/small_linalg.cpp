#include "small_linalg.h"

#include <algorithm>
#include <cmath>

namespace lw::synth {

Matrix multiply(const Matrix& x, const Matrix& y) {
    Matrix out(x.rows, y.cols);
    for (int i = 0; i < x.rows; ++i)
        for (int k = 0; k < x.cols; ++k)
            for (int j = 0; j < y.cols; ++j) out(i, j) += x(i, k) * y(k, j);
    return out;
}

Matrix transpose(const Matrix& x) {
    Matrix out(x.cols, x.rows);
    for (int i = 0; i < x.rows; ++i)
        for (int j = 0; j < x.cols; ++j) out(j, i) = x(i, j);
    return out;
}

void symmetric_eigen(const Matrix& m, std::vector<double>& values, Matrix& vectors) {
    const int n = m.rows;
    Matrix a = m;
    vectors = Matrix(n, n);
    for (int i = 0; i < n; ++i) vectors(i, i) = 1.0;
    for (int sweep = 0; sweep < 60; ++sweep) {
        double off = 0.0, total = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) (i == j ? total : off) += a(i, j) * a(i, j);
        if (off <= 1e-30 * (total + off) || off == 0.0) break;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) {
                if (a(p, q) == 0.0) continue;
                // The rotation that zeroes a(p, q) (Golub & Van Loan, symmetric Schur).
                const double theta = (a(q, q) - a(p, p)) / (2.0 * a(p, q));
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < n; ++k) {
                    const double akp = a(k, p), akq = a(k, q);
                    a(k, p) = c * akp - s * akq;
                    a(k, q) = s * akp + c * akq;
                }
                for (int k = 0; k < n; ++k) {
                    const double apk = a(p, k), aqk = a(q, k);
                    a(p, k) = c * apk - s * aqk;
                    a(q, k) = s * apk + c * aqk;
                }
                for (int k = 0; k < n; ++k) {
                    const double vkp = vectors(k, p), vkq = vectors(k, q);
                    vectors(k, p) = c * vkp - s * vkq;
                    vectors(k, q) = s * vkp + c * vkq;
                }
            }
    }
    values.resize(size_t(n));
    for (int i = 0; i < n; ++i) values[size_t(i)] = a(i, i);
}

Matrix symmetric_power(const Matrix& m, double power, double floor) {
    std::vector<double> values;
    Matrix v;
    symmetric_eigen(m, values, v);
    double largest = 0.0;
    for (double l : values) largest = std::max(largest, std::abs(l));
    const int n = m.rows;
    Matrix out(n, n);
    for (int k = 0; k < n; ++k) {
        const double l = values[size_t(k)];
        if (l <= floor * largest || l <= 0.0) continue;
        const double f = std::pow(l, power);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) out(i, j) += v(i, k) * f * v(j, k);
    }
    return out;
}

bool solve_linear(Matrix a, std::vector<double>& b) {
    const int n = a.rows;
    double scale = 0.0;
    for (double x : a.a) scale = std::max(scale, std::abs(x));
    if (scale == 0.0) return false;
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        for (int r = col + 1; r < n; ++r)
            if (std::abs(a(r, col)) > std::abs(a(pivot, col))) pivot = r;
        if (std::abs(a(pivot, col)) <= 1e-13 * scale) return false;
        if (pivot != col) {
            for (int k = 0; k < n; ++k) std::swap(a(col, k), a(pivot, k));
            std::swap(b[size_t(col)], b[size_t(pivot)]);
        }
        for (int r = col + 1; r < n; ++r) {
            const double f = a(r, col) / a(col, col);
            if (f == 0.0) continue;
            for (int k = col; k < n; ++k) a(r, k) -= f * a(col, k);
            b[size_t(r)] -= f * b[size_t(col)];
        }
    }
    for (int r = n - 1; r >= 0; --r) {
        double sum = b[size_t(r)];
        for (int k = r + 1; k < n; ++k) sum -= a(r, k) * b[size_t(k)];
        b[size_t(r)] = sum / a(r, r);
    }
    return true;
}

}  // namespace lw::synth
