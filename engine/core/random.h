// engine/core/random.h — seeded random numbers that are the same on every standard library.
//
// std::mt19937's output sequence is fixed by the standard, but std::uniform_*_distribution and
// std::normal_distribution are implementation-defined; so the distributions are written here
// from the engine's 32-bit words: uniform doubles from 53 bits (two words), normals by
// Box–Muller, indices by a multiply-shift of one word (bias below 2^-32 · n).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

namespace lw {

// splitmix64's finalizer: a 64-bit word to another, every input bit reaching every output bit
// (seeds for hashed noise and tie-breaks, and keys of values), the same everywhere.
inline uint64_t mix64(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

class Rng {
public:
    explicit Rng(uint64_t seed) : engine_(static_cast<uint32_t>(seed ^ (seed >> 32))) {}

    // Uniform in [0, 1).
    double uniform() {
        const uint64_t a = engine_() >> 5, b = engine_() >> 6;  // 27 + 26 bits
        return double(a * 67108864ull + b) * (1.0 / 9007199254740992.0);
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform in {0, …, n − 1}; n > 0.
    size_t index(size_t n) { return size_t((uint64_t(engine_()) * uint64_t(n)) >> 32); }
    // Standard normal (Box–Muller; the second value is dropped to keep the state simple).
    double normal() {
        const double u1 = 1.0 - uniform();  // (0, 1]
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

private:
    std::mt19937 engine_;
};

}  // namespace lw
