#include "fft.h"

#include <cstdint>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <fftw3.h>

namespace lw::synth {

namespace {

struct BlockPool {
    static constexpr size_t kSmallest = 4096, kPerSize = 64;
    std::unordered_map<size_t, std::vector<void*>> free;
    ~BlockPool() {
        for (auto& [bytes, blocks] : free)
            for (void* p : blocks) fftwf_free(p);
    }
};
thread_local BlockPool pool;

}  // namespace

void* fft_malloc(size_t bytes) {
    if (bytes >= BlockPool::kSmallest) {
        auto it = pool.free.find(bytes);
        if (it != pool.free.end() && !it->second.empty()) {
            void* p = it->second.back();
            it->second.pop_back();
            return p;
        }
    }
    return fftwf_malloc(bytes);
}

void fft_free(void* p, size_t bytes) {
    if (!p) return;
    if (bytes >= BlockPool::kSmallest) {
        std::vector<void*>& blocks = pool.free[bytes];
        if (blocks.size() < BlockPool::kPerSize) {
            blocks.push_back(p);
            return;
        }
    }
    fftwf_free(p);
}

namespace {

enum class Kind { Forward, InverseReal, InverseComplex };

// Plans live until the process ends; there are a few dozen sizes in a SLAM run.
fftwf_plan plan_for(Kind kind, int rows, int cols) {
    static std::mutex mutex;
    static std::map<std::tuple<Kind, int, int>, fftwf_plan> plans;
    std::lock_guard<std::mutex> lock(mutex);
    const auto key = std::make_tuple(kind, rows, cols);
    if (auto it = plans.find(key); it != plans.end()) return it->second;
    const size_t n = size_t(rows) * size_t(cols);
    // Planning arrays from fftwf_malloc: the same alignment as every buffer executed later.
    auto* a = static_cast<fftwf_complex*>(fftwf_malloc(sizeof(fftwf_complex) * n));
    auto* b = static_cast<fftwf_complex*>(fftwf_malloc(sizeof(fftwf_complex) * n));
    fftwf_plan plan = nullptr;
    const unsigned flags = FFTW_ESTIMATE;
    switch (kind) {
        case Kind::Forward: plan = fftwf_plan_dft_r2c_2d(rows, cols, reinterpret_cast<float*>(a), b, flags); break;
        case Kind::InverseReal: plan = fftwf_plan_dft_c2r_2d(rows, cols, a, reinterpret_cast<float*>(b), flags); break;
        case Kind::InverseComplex: plan = fftwf_plan_dft_2d(rows, cols, a, b, FFTW_BACKWARD, flags); break;
    }
    fftwf_free(a);
    fftwf_free(b);
    if (!plan) throw std::runtime_error("FFTW could not plan a " + std::to_string(rows) + "x" + std::to_string(cols) + " transform");
    plans.emplace(key, plan);
    return plan;
}

fftwf_complex* as_fftw(cfloat* p) { return reinterpret_cast<fftwf_complex*>(p); }

}  // namespace

void fft_forward_real(int rows, int cols, const float* in, cfloat* out) {
    fftwf_execute_dft_r2c(plan_for(Kind::Forward, rows, cols), const_cast<float*>(in), as_fftw(out));
}

void fft_inverse_real(int rows, int cols, cfloat* in, float* out) {
    fftwf_execute_dft_c2r(plan_for(Kind::InverseReal, rows, cols), as_fftw(in), out);
}

void fft_inverse_complex(int rows, int cols, const cfloat* in, cfloat* out) {
    fftwf_execute_dft(plan_for(Kind::InverseComplex, rows, cols), as_fftw(const_cast<cfloat*>(in)), as_fftw(out));
}

}  // namespace lw::synth
