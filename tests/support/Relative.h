#pragma once
// doctest's Approx(x).epsilon(e) accepts |a - x| < e * (scale + max(|a|, |x|)) with scale 1, so for
// |x| < 1 it is an absolute tolerance of about e: the Earth's 6.78e-5 sr would pass anywhere within
// +-e. Physics tests state a relative tolerance (this, or .scale(0)) or an absolute one in plain
// code (std::abs(a - x) < t), never the mixture.
#include <doctest/doctest.h>

namespace radiant::test {

/// |actual - expected| <= tolerance * max(|actual|, |expected|).
inline doctest::Approx relativeTo(double expected, double tolerance) {
    return doctest::Approx(expected).epsilon(tolerance).scale(0);
}

} // namespace radiant::test
