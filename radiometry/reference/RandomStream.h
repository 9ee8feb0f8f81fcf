#pragma once
// The path tracer's own random numbers, so that the reference shares no code with the radiosity
// solvers' jitter: xoshiro256+ (Blackman & Vigna, "Scrambled linear pseudorandom number generators",
// ACM TOMS 2021), seeded through SplitMix64 as its authors recommend. A stream is fully determined by
// (seed, stream index): batch k of a run always draws the same numbers, whichever thread runs it.
#include <cstdint>

namespace radiant::reference {

class RandomStream {
public:
    RandomStream(std::uint64_t seed, std::uint64_t stream) {
        std::uint64_t z = seed ^ (0x9E3779B97F4A7C15ull * (stream + 1));
        for (std::uint64_t& word : state_) word = splitMix(z);
    }

    /// Uniform in [0, 1), 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    static std::uint64_t splitMix(std::uint64_t& z) {
        std::uint64_t x = (z += 0x9E3779B97F4A7C15ull);
        x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
        x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
        return x ^ (x >> 31);
    }
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

    std::uint64_t next() {
        const std::uint64_t result = state_[0] + state_[3];
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }

    std::uint64_t state_[4];
};

} // namespace radiant::reference
