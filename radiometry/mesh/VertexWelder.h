#pragma once
// Merges points closer than a tolerance into one id: a hash grid with cells as large as the
// tolerance, so a point's match lies in its own cell or one of the 26 around it.
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace radiant::detail {

class VertexWelder {
public:
    explicit VertexWelder(double tolerance) : tolerance_(tolerance) {}

    /// The id of an earlier point within the tolerance, else a new id for p.
    std::uint32_t weld(const glm::dvec3& p) {
        const Cell home = cellOf(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto found = cells_.find(hash({home.x + dx, home.y + dy, home.z + dz}));
                    if (found == cells_.end()) continue;
                    for (std::uint32_t id : found->second)
                        if (glm::distance(points_[id], p) <= tolerance_) return id;
                }
        const auto id = static_cast<std::uint32_t>(points_.size());
        points_.push_back(p);
        cells_[hash(home)].push_back(id);
        return id;
    }

    [[nodiscard]] const std::vector<glm::dvec3>& points() const { return points_; }
    std::vector<glm::dvec3> takePoints() { return std::move(points_); }

private:
    struct Cell {
        std::int64_t x, y, z;
    };
    [[nodiscard]] Cell cellOf(const glm::dvec3& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x / tolerance_)),
                static_cast<std::int64_t>(std::floor(p.y / tolerance_)),
                static_cast<std::int64_t>(std::floor(p.z / tolerance_))};
    }
    // Collisions only cost a distance test: the bucket's points are compared exactly.
    static std::uint64_t hash(const Cell& c) {
        return static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull ^
               static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full ^
               static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull;
    }

    double tolerance_;
    std::vector<glm::dvec3> points_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace radiant::detail
