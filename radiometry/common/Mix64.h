#pragma once
// One hash for the project's deterministic sample streams (visibility rays, progressive shots).
#include <cstdint>

namespace radiant {

/// SplitMix64's finaliser (Steele, Lea & Flood, OOPSLA 2014): a bijection of 64-bit words whose
/// outputs look independent for consecutive inputs.
inline std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // namespace radiant
