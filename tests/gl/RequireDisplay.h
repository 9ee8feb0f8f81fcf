#pragma once
// Every GL test opens a window: without an X display it fails with what to do, not with GLFW's error.
#include <doctest/doctest.h>

#include <cstdlib>

namespace radiant::test {

inline void requireDisplay() {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display != nullptr && *display != '\0'),
                    "no DISPLAY: the GL tests need an X server; run them under Xvfb, as scripts/test does: "
                    "xvfb-run -a -s \"-screen 0 1600x1000x24\" radiant_gl_tests");
}

} // namespace radiant::test
