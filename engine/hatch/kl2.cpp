#include "hatch/kl2.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

double silverman_h(int dim, size_t n) {
    const double d = double(dim);
    return std::pow(4.0 / (d + 2.0), 1.0 / (d + 4.0)) * std::pow(double(std::max<size_t>(n, 1)), -1.0 / (d + 4.0));
}

double parzen_log_density(const Samples& sample, double h, const double* x) {
    const size_t n = sample.size();
    const int d = sample.dim;
    // ln [(1/n) Σ (2πh²)^(−d/2) exp(−‖x − x_i‖² / 2h²)] by log-sum-exp.
    thread_local std::vector<double> exponents;
    exponents.resize(n);
    double top = -INFINITY;
    const double inv = 1.0 / (2.0 * h * h);
    for (size_t i = 0; i < n; ++i) {
        const double* y = sample.row(i);
        double r2 = 0.0;
        for (int k = 0; k < d; ++k) r2 += (x[k] - y[k]) * (x[k] - y[k]);
        exponents[i] = -r2 * inv;
        top = std::max(top, exponents[i]);
    }
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) sum += std::exp(exponents[i] - top);
    return top + std::log(sum) - std::log(double(n)) - 0.5 * double(d) * std::log(2.0 * 3.141592653589793 * h * h);
}

double kl2_divergence(const Samples& t, const Samples& g) {
    if (t.size() == 0 || g.size() == 0 || t.dim != g.dim) throw Error("KL2: needs two non-empty samples of one dimension");
    const double ht = silverman_h(t.dim, t.size()), hg = silverman_h(g.dim, g.size());
    double sum = 0.0;
    for (size_t i = 0; i < t.size(); ++i) sum += parzen_log_density(t, ht, t.row(i)) - parzen_log_density(g, hg, t.row(i));
    return sum / double(t.size());
}

}  // namespace lw
