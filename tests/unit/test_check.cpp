// RADIANT_CHECK_*: an invariant that fails names the expression and both operands' values.
#include <doctest/doctest.h>

#include <cstddef>
#include <string>

#include "radiometry/common/Check.h"

TEST_SUITE("core") {

TEST_CASE("a failed invariant check throws with its expression and both values") {
    const std::size_t values = 3, patches = 4;
    std::string message;
    try {
        RADIANT_CHECK_EQ(values, patches);
    } catch (const radiant::InvariantError& e) {
        message = e.what();
    }
    INFO(message);
    CHECK(message.find("check failed: values == patches") != std::string::npos);
    CHECK(message.find("(3 vs 4)") != std::string::npos);
    CHECK(message.find("test_check.cpp:") != std::string::npos);
    CHECK_NOTHROW(RADIANT_CHECK_LT(values, patches));
    CHECK_THROWS_AS(RADIANT_CHECK_GT(values, patches), radiant::InvariantError);
}

} // TEST_SUITE
