#pragma once
// Checks of Radiant's own invariants (as pbrt's CHECK_EQ): a failure is a bug in Radiant, not bad
// input, so it is not a RadiantError. It throws InvariantError naming the source line, the
// expression and both operands' values; the command line reports it as an internal error (exit 1)
// and the lab shows it without exiting. Input is checked with RadiantError instead.
#include <sstream>
#include <stdexcept>
#include <string>

namespace radiant {

class InvariantError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

namespace detail {
template <class A, class B>
[[noreturn]] void failCheck(const char* file, int line, const char* expression, const A& a, const B& b) {
    std::ostringstream message;
    message << file << ":" << line << ": check failed: " << expression << " (" << a << " vs " << b << ")";
    throw InvariantError(message.str());
}
} // namespace detail

} // namespace radiant

#define RADIANT_CHECK_OP(a, op, b)                                                                    \
    do {                                                                                              \
        const auto& radiantCheckA_ = (a);                                                             \
        const auto& radiantCheckB_ = (b);                                                             \
        if (!(radiantCheckA_ op radiantCheckB_))                                                      \
            ::radiant::detail::failCheck(__FILE__, __LINE__, #a " " #op " " #b, radiantCheckA_, radiantCheckB_); \
    } while (false)

#define RADIANT_CHECK_EQ(a, b) RADIANT_CHECK_OP(a, ==, b)
#define RADIANT_CHECK_NE(a, b) RADIANT_CHECK_OP(a, !=, b)
#define RADIANT_CHECK_LT(a, b) RADIANT_CHECK_OP(a, <, b)
#define RADIANT_CHECK_LE(a, b) RADIANT_CHECK_OP(a, <=, b)
#define RADIANT_CHECK_GT(a, b) RADIANT_CHECK_OP(a, >, b)
#define RADIANT_CHECK_GE(a, b) RADIANT_CHECK_OP(a, >=, b)
