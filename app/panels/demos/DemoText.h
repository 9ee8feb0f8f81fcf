#pragma once
// Small helpers the demos' pictures share: printf into a std::string for their labels, and a float
// point from the double-precision numbers the physics returns.
#include <string>

#include <glm/vec3.hpp>

namespace radiant::app {

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
std::string printed(const char* format, ...);

inline glm::vec3 point3(double x, double y, double z) {
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

} // namespace radiant::app
