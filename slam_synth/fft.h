// slam_synth/fft.h — FFTW3 (float) behind a small interface: aligned buffers, one plan per
// transform kind and size, reused for the whole run.
//
// Conventions: forward transforms are unnormalized, inverse transforms are unnormalized too
// (the caller scales, see steerable_pyramid.h for the amplitude convention). Real images are
// rows × cols, row-major; their spectra are FFTW's half layout rows × (cols/2 + 1).
// Plans are created with FFTW_ESTIMATE (no timing measurements), so results are identical
// from run to run; creation is serialized by a mutex, execution is thread-safe (FFTW's
// new-array execute), so synthesis threads share the plans.
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <new>
#include <vector>

namespace lw::synth {

using cfloat = std::complex<float>;

// fftwf_malloc/fftwf_free behind a per-thread pool of freed blocks by size: synthesis
// iterations allocate the same sizes again and again, and fresh large blocks cost page
// faults (a sixth of the run time without the pool).
void* fft_malloc(size_t bytes);
void fft_free(void* p, size_t bytes);

// Every buffer handed to FFTW comes from fftwf_malloc, so all of them share the SIMD
// alignment the plans were made with (a condition of the new-array execute functions).
template <typename T>
struct FftAllocator {
    using value_type = T;
    FftAllocator() = default;
    template <typename U>
    FftAllocator(const FftAllocator<U>&) {}
    T* allocate(size_t n) {
        void* p = fft_malloc(n * sizeof(T));
        if (!p) throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) { fft_free(p, n * sizeof(T)); }
    bool operator==(const FftAllocator&) const { return true; }
    bool operator!=(const FftAllocator&) const { return false; }
};

using Floats = std::vector<float, FftAllocator<float>>;
using Complexes = std::vector<cfloat, FftAllocator<cfloat>>;

// A real image: rows × cols, row-major.
struct Plane {
    int rows = 0, cols = 0;
    Floats v;
    Plane() = default;
    Plane(int r, int c, float value = 0.0f) : rows(r), cols(c), v(size_t(r) * size_t(c), value) {}
    float& at(int r, int c) { return v[size_t(r) * size_t(cols) + size_t(c)]; }
    float at(int r, int c) const { return v[size_t(r) * size_t(cols) + size_t(c)]; }
    size_t size() const { return v.size(); }
};

// A complex image (a pyramid band), rows × cols.
struct ComplexPlane {
    int rows = 0, cols = 0;
    Complexes v;
    ComplexPlane() = default;
    ComplexPlane(int r, int c) : rows(r), cols(c), v(size_t(r) * size_t(c)) {}
    size_t size() const { return v.size(); }
};

// |z| without hypot's overflow care (std::abs calls hypotf): values here are O(1).
inline float magnitude_of(cfloat z) { return std::sqrt(z.real() * z.real() + z.imag() * z.imag()); }

inline size_t half_size(int rows, int cols) { return size_t(rows) * size_t(cols / 2 + 1); }

// in: rows × cols reals (kept); out: rows × (cols/2+1).
void fft_forward_real(int rows, int cols, const float* in, cfloat* out);
// in: rows × (cols/2+1), destroyed; out: rows × cols reals. Unnormalized.
void fft_inverse_real(int rows, int cols, cfloat* in, float* out);
// Complex to complex, e^{+i}, unnormalized; in kept.
void fft_inverse_complex(int rows, int cols, const cfloat* in, cfloat* out);

}  // namespace lw::synth
