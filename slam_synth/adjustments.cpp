#include "adjustments.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace lw::synth {

Moments moments(const float* x, size_t n) {
    Moments m;
    if (n == 0) return m;
    // Vectorized reductions (`omp simd`: the lane order is fixed at compile time).
    double sum = 0.0;
    float lo = x[0], hi = x[0];
#pragma omp simd reduction(+ : sum) reduction(min : lo) reduction(max : hi)
    for (size_t i = 0; i < n; ++i) {
        sum += double(x[i]);
        lo = std::min(lo, x[i]);
        hi = std::max(hi, x[i]);
    }
    m.mean = sum / double(n);
    m.min = lo;
    m.max = hi;
    double m2 = 0, m3 = 0, m4 = 0;
    const double mean = m.mean;
#pragma omp simd reduction(+ : m2, m3, m4)
    for (size_t i = 0; i < n; ++i) {
        const double d = double(x[i]) - mean, d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    m.variance = m2 / double(n);
    if (m.variance > 0.0) {
        m.skewness = m3 / double(n) / std::pow(m.variance, 1.5);
        m.kurtosis = m4 / double(n) / (m.variance * m.variance);
    }
    return m;
}

int autocorrelation_half(int rows, int cols, int limit) {
    return std::clamp((std::min(rows, cols) - 2) / 4, 0, limit);
}

Autocorrelation central_autocorrelation(const Complexes& spectrum, int rows, int cols, int half) {
    Complexes power(spectrum.size());
    for (size_t i = 0; i < spectrum.size(); ++i) power[i] = std::norm(spectrum[i]);
    Floats acf(size_t(rows) * size_t(cols));
    fft_inverse_real(rows, cols, power.data(), acf.data());
    const double n = double(rows) * double(cols);
    Autocorrelation a;
    a.half = half;
    a.values.resize(size_t(a.side() * a.side()));
    for (int dy = -half; dy <= half; ++dy)
        for (int dx = -half; dx <= half; ++dx) {
            const size_t i = size_t((dy + rows) % rows) * size_t(cols) + size_t((dx + cols) % cols);
            a.values[size_t((dy + half) * a.side() + dx + half)] = acf[i] / (n * n);
        }
    return a;
}

namespace {

// cos and sin of 2π·k·σ/n for k = 0 … n/2 and σ = −h … h, kept per thread for each (n, h):
// every iteration filters the same band sizes.
struct Twiddles {
    std::vector<double> cos, sin;  // [σ + h][k]
};
const Twiddles& twiddles(int n, int h) {
    thread_local std::map<std::pair<int, int>, Twiddles> cache;
    Twiddles& t = cache[{n, h}];
    if (t.cos.empty()) {
        const int half = n / 2 + 1;
        t.cos.resize(size_t(2 * h + 1) * size_t(half));
        t.sin.resize(t.cos.size());
        for (int s = -h; s <= h; ++s)
            for (int k = 0; k < half; ++k) {
                const double angle = 2.0 * std::numbers::pi * k * s / n;
                t.cos[size_t(s + h) * size_t(half) + size_t(k)] = std::cos(angle);
                t.sin[size_t(s + h) * size_t(half) + size_t(k)] = std::sin(angle);
            }
    }
    return t;
}

}  // namespace

void impose_autocorrelation(Complexes& spectrum, int rows, int cols, const Autocorrelation& target, float* out) {
    const int h = target.half, half_cols = cols / 2 + 1;
    const Autocorrelation cx = central_autocorrelation(spectrum, rows, cols, 2 * h);
    // Unknowns: the filter's autocorrelation Ch(σ) = Ch(−σ) on the (2h+1)² window, one per
    // ±σ pair; equations: (Ch ∗ Cx)(τ) = target(τ) for the same half window (modacor22).
    std::vector<std::pair<int, int>> lags;
    for (int dy = 0; dy <= h; ++dy)
        for (int dx = -h; dx <= h; ++dx)
            if (dy > 0 || dx >= 0) lags.emplace_back(dy, dx);
    const int m = int(lags.size());
    Matrix a(m, m);
    std::vector<double> ch(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i) {
        const auto [ty, tx] = lags[size_t(i)];
        ch[size_t(i)] = target.at(ty, tx);
        for (int j = 0; j < m; ++j) {
            const auto [sy, sx] = lags[size_t(j)];
            a(i, j) = cx.at(ty - sy, tx - sx) + ((sy != 0 || sx != 0) ? cx.at(ty + sy, tx + sx) : 0.0);
        }
    }
    const float inv_n = 1.0f / (float(rows) * float(cols));
    // textureSynth solves this system exactly (inv(Tcx)). For smooth bands it is nearly
    // singular, and the exact solution amplifies float rounding about 10⁵-fold: the same
    // texture synthesized at two lengths (A_1.0 against [A_0.5 A_0.5]) then differs by 0.1 in
    // ink. A Tikhonov term of 1e-8 × the mean diagonal of AᵀA keeps it continuous (1e-4)
    // and changes the imposed statistics by less than 0.5 dB.
    Matrix normal = multiply(transpose(a), a);
    std::vector<double> rhs(static_cast<size_t>(m), 0.0);
    double trace = 0.0;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) rhs[size_t(i)] += a(j, i) * ch[size_t(j)];
        trace += normal(i, i);
    }
    for (int i = 0; i < m; ++i) normal(i, i) += 1e-8 * trace / m;
    ch = std::move(rhs);
    const bool solved = solve_linear(normal, ch);
    if (!solved) {
        fft_inverse_real(rows, cols, spectrum.data(), out);
        for (size_t i = 0; i < size_t(rows) * size_t(cols); ++i) out[i] *= inv_n;
        return;
    }
    // Ĉh(f) = Σ_σ Ch(σ)·cos(2π(fy σy/rows + fx σx/cols)), separably: per column the sums
    // over σx (cosine and sine parts), then per row over σy.
    const int side = target.side();
    std::vector<double> full(static_cast<size_t>(side * side));
    for (int j = 0; j < m; ++j) {
        const auto [sy, sx] = lags[size_t(j)];
        full[size_t((sy + h) * side + sx + h)] = ch[size_t(j)];
        full[size_t((-sy + h) * side - sx + h)] = ch[size_t(j)];
    }
    const Twiddles& tx = twiddles(cols, h);
    std::vector<double> cc(static_cast<size_t>(side) * size_t(half_cols), 0.0), cs(cc.size(), 0.0);
    for (int sy = -h; sy <= h; ++sy)
        for (int sx = -h; sx <= h; ++sx) {
            const double v = full[size_t((sy + h) * side + sx + h)];
            double* c = &cc[size_t(sy + h) * size_t(half_cols)];
            double* s = &cs[size_t(sy + h) * size_t(half_cols)];
            const double* cos_row = &tx.cos[size_t(sx + h) * size_t(half_cols)];
            const double* sin_row = &tx.sin[size_t(sx + h) * size_t(half_cols)];
            for (int kx = 0; kx < half_cols; ++kx) {
                c[kx] += v * cos_row[kx];
                s[kx] += v * sin_row[kx];
            }
        }
    // Per row: Ĉh = C(ky) − S(ky), where C sums the cosine parts over σy and S the sine
    // parts; row rows − ky has the same C and −S, so each pair of rows is done at once (in
    // float, vectorized: the filter is applied to a float spectrum anyway).
    const std::vector<float> ccf(cc.begin(), cc.end()), csf(cs.begin(), cs.end());
    const Twiddles& ty = twiddles(rows, h);
    const int half_rows = rows / 2 + 1;
    std::vector<float> c_sum(static_cast<size_t>(half_cols)), s_sum(static_cast<size_t>(half_cols));
    auto apply = [&](int ky, float sign) {
        cfloat* row = &spectrum[size_t(ky) * size_t(half_cols)];
        for (int kx = 0; kx < half_cols; ++kx)
            row[kx] *= std::sqrt(std::abs(c_sum[size_t(kx)] - sign * s_sum[size_t(kx)])) * inv_n;
    };
    for (int k = 0; k < half_rows; ++k) {
        std::fill(c_sum.begin(), c_sum.end(), 0.0f);
        std::fill(s_sum.begin(), s_sum.end(), 0.0f);
        for (int t = 0; t < side; ++t) {
            const float c = float(ty.cos[size_t(t) * size_t(half_rows) + size_t(k)]);
            const float sn = float(ty.sin[size_t(t) * size_t(half_rows) + size_t(k)]);
            const float* cc_row = &ccf[size_t(t) * size_t(half_cols)];
            const float* cs_row = &csf[size_t(t) * size_t(half_cols)];
            for (int kx = 0; kx < half_cols; ++kx) {
                c_sum[size_t(kx)] += c * cc_row[kx];
                s_sum[size_t(kx)] += sn * cs_row[kx];
            }
        }
        apply(k, 1.0f);
        if (k != 0 && k != rows - k) apply(rows - k, -1.0f);
    }
    fft_inverse_real(rows, cols, spectrum.data(), out);
}

namespace {

using Poly = std::vector<double>;  // coefficients of z^0, z^1, …

Poly multiply(const Poly& a, const Poly& b) {
    Poly out(a.size() + b.size() - 1, 0.0);
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
    return out;
}

// E[y^k] for y = z + λ·q(z), as a polynomial in λ, from the moments mu[j] = E[z^j].
Poly power_expectation(const Poly& q, int k, const std::vector<double>& mu) {
    Poly out(size_t(k) + 1, 0.0);
    double binomial = 1.0;
    Poly qj = {1.0};
    for (int j = 0; j <= k; ++j) {
        Poly term = qj;
        for (int i = 0; i < k - j; ++i) term = multiply(term, {0.0, 1.0});
        double e = 0.0;
        for (size_t i = 0; i < term.size(); ++i) e += term[i] * mu[i];
        out[size_t(j)] = binomial * e;
        binomial = binomial * (k - j) / (j + 1);
        qj = multiply(qj, q);
    }
    return out;
}

double evaluate(const Poly& p, double x) {
    double v = 0.0;
    for (size_t i = p.size(); i-- > 0;) v = v * x + p[i];
    return v;
}

// The λ of smallest |λ| with stat(λ) = target, searched on both sides of 0 by geometric
// steps and bisection; when neither side reaches the target, the λ that comes closest
// (saturation, as textureSynth's modskew/modkurt do).
double solve_lambda(const std::function<double(double)>& stat, double target) {
    const double f0 = stat(0.0) - target;
    double best = 0.0, best_error = std::abs(f0), root = std::numeric_limits<double>::infinity();
    for (double direction : {1.0, -1.0}) {
        double previous = 0.0, previous_f = f0;
        for (double step = 1e-4; step < 1e4; step *= 1.25) {
            const double lambda = direction * step, f = stat(lambda) - target;
            if (!std::isfinite(f)) break;
            if ((f > 0.0) != (f0 > 0.0)) {
                double lo = previous, hi = lambda;
                for (int i = 0; i < 60; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    ((stat(mid) - target > 0.0) == (f0 > 0.0) ? lo : hi) = mid;
                }
                if (std::abs(lo) < std::abs(root)) root = 0.5 * (lo + hi);
                break;
            }
            if (std::abs(f) < best_error) {
                best_error = std::abs(f);
                best = lambda;
            }
            if (std::abs(f) > std::abs(previous_f) && std::abs(f) > best_error) break;  // past the extremum
            previous = lambda;
            previous_f = f;
        }
    }
    return std::isfinite(root) ? root : best;
}

// Shared by skewness (order 3) and kurtosis (order 4): standardize, find λ, apply x + λ·q(x),
// restore mean and variance.
void impose_standardized_moment(float* x, size_t n, double target, int order) {
    const Moments m = moments(x, n);
    if (m.variance <= 0.0 || !std::isfinite(target)) return;
    const double sd = std::sqrt(m.variance);
    const int top = order == 3 ? 6 : 12;
    // Moments of z up to 12 (kurtosis) or 6 (skewness), accumulated in registers.
    double a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0, a8 = 0, a9 = 0, a10 = 0, a11 = 0, a12 = 0;
    const double mean = m.mean, inv_sd = 1.0 / sd;
    if (top == 6) {
#pragma omp simd reduction(+ : a1, a2, a3, a4, a5, a6)
        for (size_t i = 0; i < n; ++i) {
            const double z = (double(x[i]) - mean) * inv_sd, z2 = z * z, z3 = z2 * z, z4 = z2 * z2;
            a1 += z, a2 += z2, a3 += z3, a4 += z4, a5 += z4 * z, a6 += z4 * z2;
        }
    } else {
#pragma omp simd reduction(+ : a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12)
        for (size_t i = 0; i < n; ++i) {
            const double z = (double(x[i]) - mean) * inv_sd, z2 = z * z, z3 = z2 * z, z4 = z2 * z2, z8 = z4 * z4;
            a1 += z, a2 += z2, a3 += z3, a4 += z4, a5 += z4 * z, a6 += z4 * z2;
            a7 += z4 * z3, a8 += z8, a9 += z8 * z, a10 += z8 * z2, a11 += z8 * z3, a12 += z8 * z4;
        }
    }
    double acc[13] = {0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12};
    acc[0] = double(n);
    std::vector<double> mu(acc, acc + top + 1);
    for (double& v : mu) v /= double(n);
    const double current = order == 3 ? mu[3] : mu[4];
    // Already there: textureSynth skips kurtosis above 60 dB SNR.
    if (std::abs(current - target) <= (order == 3 ? 1e-4 : 1e-3 * std::abs(target))) return;
    // q is orthogonal to 1 and z, so E[y] = 0 and E[y²] = 1 + λ²E[q²].
    const Poly q = order == 3 ? Poly{-1.0, -mu[3], 1.0} : Poly{-mu[3], -mu[4], 0.0, 1.0};
    const Poly e2 = power_expectation(q, 2, mu), ek = power_expectation(q, order, mu);
    const auto stat = [&](double lambda) {
        return evaluate(ek, lambda) / std::pow(evaluate(e2, lambda), 0.5 * order);
    };
    const double lambda = solve_lambda(stat, target);
    if (lambda == 0.0) return;
    const double rescale = sd / std::sqrt(evaluate(e2, lambda));
    // y = mean + rescale·(z + λ·q(z)) with q of degree ≤ 3, z = (x − mean)/sd.
    const double q0 = q[0], q1 = q[1], q2 = q[2], q3 = q.size() > 3 ? q[3] : 0.0;
#pragma omp simd
    for (size_t i = 0; i < n; ++i) {
        const double z = (double(x[i]) - mean) * inv_sd;
        x[i] = float(mean + rescale * (z + lambda * (q0 + z * (q1 + z * (q2 + z * q3)))));
    }
}

}  // namespace

void impose_skewness(float* x, size_t n, double target) { impose_standardized_moment(x, n, target, 3); }
void impose_kurtosis(float* x, size_t n, double target) { impose_standardized_moment(x, n, target, 4); }

namespace {

// Σ x·y_j for up to four columns y_j in one pass over x: float sums over blocks of 1024
// samples, vectorized (`omp simd`: the lane order is fixed at compile time, so results repeat
// run to run), the blocks summed in double.
void dots(const float* x, const float* const* y, int count, size_t n, double* out) {
    const float* y0 = y[0];
    const float* y1 = y[count > 1 ? 1 : 0];
    const float* y2 = y[count > 2 ? 2 : 0];
    const float* y3 = y[count > 3 ? 3 : 0];
    double total[4] = {0, 0, 0, 0};
    for (size_t start = 0; start < n; start += 1024) {
        const size_t end = std::min(n, start + 1024);
        float s0 = 0, s1 = 0, s2 = 0, s3 = 0;
#pragma omp simd reduction(+ : s0, s1, s2, s3)
        for (size_t t = start; t < end; ++t) {
            s0 += x[t] * y0[t];
            s1 += x[t] * y1[t];
            s2 += x[t] * y2[t];
            s3 += x[t] * y3[t];
        }
        total[0] += s0, total[1] += s1, total[2] += s2, total[3] += s3;
    }
    for (int j = 0; j < count; ++j) out[j] = total[j];
}

}  // namespace

Matrix gram(const std::vector<const float*>& x, const std::vector<const float*>& y, size_t n) {
    const int k = int(x.size()), m = int(y.size());
    Matrix out(k, m);
    double sums[4];
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < m; j += 4) {
            const int count = std::min(4, m - j);
            dots(x[size_t(i)], &y[size_t(j)], count, n, sums);
            for (int c = 0; c < count; ++c) out(i, j + c) = sums[c] / double(n);
        }
    return out;
}

namespace {

std::vector<const float*> as_const(const std::vector<float*>& x) { return {x.begin(), x.end()}; }

// x ← x·mx + y·my, in blocks that stay in the first-level cache: each output column is
// accumulated from every source column before it is stored.
void recombine(const std::vector<float*>& x, const Matrix& mx, const std::vector<const float*>& y, const Matrix& my,
               size_t n) {
    const int k = int(x.size()), m = int(y.size());
    constexpr size_t block = 512;
    std::vector<float> in(size_t(k) * block), acc(block);
    for (size_t start = 0; start < n; start += block) {
        const size_t len = std::min(block, n - start);
        for (int i = 0; i < k; ++i) std::copy(x[size_t(i)] + start, x[size_t(i)] + start + len, &in[size_t(i) * block]);
        for (int j = 0; j < k; ++j) {
            std::fill(acc.begin(), acc.begin() + std::ptrdiff_t(len), 0.0f);
            auto add = [&](const float* src, double w) {
                const float f = float(w);
                for (size_t t = 0; t < len; ++t) acc[t] += f * src[t];
            };
            for (int i = 0; i < k; ++i) add(&in[size_t(i) * block], mx(i, j));
            for (int i = 0; i < m; ++i) add(y[size_t(i)] + start, my(i, j));
            std::copy(acc.begin(), acc.begin() + std::ptrdiff_t(len), x[size_t(j)] + start);
        }
    }
}

}  // namespace

FixedColumns fixed_columns(std::vector<const float*> columns, size_t n) {
    FixedColumns f;
    f.columns = std::move(columns);
    f.inverse_gram = symmetric_power(gram(f.columns, f.columns, n), -1.0);
    return f;
}

void impose_correlation(const std::vector<float*>& x, size_t n, const Matrix& target) {
    const Matrix c = gram(as_const(x), as_const(x), n);
    const Matrix mx = multiply(symmetric_power(c, -0.5), symmetric_power(target, 0.5));
    recombine(x, mx, {}, Matrix(0, int(x.size())), n);
}

void impose_correlation_with(const std::vector<float*>& x, const FixedColumns& y, size_t n, const Matrix& target_xx,
                             const Matrix& target_xy) {
    const Matrix bx = gram(as_const(x), as_const(x), n), bxy = gram(as_const(x), y.columns, n);
    const Matrix& iby = y.inverse_gram;
    // Covariance of x once its linear prediction from y is removed: current and desired.
    auto residual = [&](const Matrix& xx, const Matrix& xy) {
        Matrix r = multiply(multiply(xy, iby), transpose(xy));
        for (size_t i = 0; i < r.a.size(); ++i) r.a[i] = xx.a[i] - r.a[i];
        return r;
    };
    const Matrix mx =
        multiply(symmetric_power(residual(bx, bxy), -0.5), symmetric_power(residual(target_xx, target_xy), 0.5));
    Matrix rhs = transpose(target_xy);
    const Matrix correction = multiply(transpose(bxy), mx);
    for (size_t i = 0; i < rhs.a.size(); ++i) rhs.a[i] -= correction.a[i];
    recombine(x, mx, y.columns, multiply(iby, rhs), n);
}

}  // namespace lw::synth
