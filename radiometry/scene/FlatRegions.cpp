#include "radiometry/scene/FlatRegions.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

namespace radiant::detail {
namespace {

glm::dvec3 areaVector(const std::vector<glm::dvec3>& p, const Triangle& t) {
    return 0.5 * glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
}

double smallestAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const auto angle = [](const glm::dvec3& at, const glm::dvec3& x, const glm::dvec3& y) {
        const glm::dvec3 u = x - at, v = y - at;
        return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
    };
    return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

class Simplifier {
public:
    Simplifier(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles, double coplanarCosine)
        : points_(points), cosine_(coplanarCosine), sine_(std::sqrt(std::max(0.0, 1 - coplanarCosine * coplanarCosine))),
          incident_(points.size()) {
        for (const Triangle& t : triangles) add(t, false);
    }

    std::vector<Triangle> run() {
        // Rounds of independent removals (no two in one ring), low degrees first, as Kirkpatrick's
        // hierarchy does: holes stay small, and the flips after each round keep degrees low, so a
        // flat grid of n triangles goes in O(n log n). A vertex whose fan is too large to order and
        // clip cheaply (k^2, k^3) is tried only once the small ones are gone, and never above kMaxFan.
        std::vector<bool> blocked(points_.size());
        std::vector<std::uint32_t> ring;
        for (const std::size_t limit : {kSmallFan, kMaxFan}) {
            bool removed = true;
            for (int round = 0; removed && round < kMaxRounds; ++round) {
                removed = false;
                std::fill(blocked.begin(), blocked.end(), false);
                for (std::uint32_t v = 0; v < points_.size(); ++v) {
                    if (blocked[v] || incident_[v].empty() || incident_[v].size() > limit || !tryRemove(v, ring)) continue;
                    removed = true;
                    for (std::uint32_t r : ring) blocked[r] = true;
                }
                flip(4);
            }
        }
        // Lawson: each flip raises the smallest angle of its pair, so the sorted angles of the whole
        // triangulation rise and the flipping ends (in a few passes in practice); the bound keeps
        // hostile input from taking long, and stopping early leaves a valid triangulation.
        flip(32);
        std::vector<Triangle> result;
        for (std::size_t t = 0; t < triangles_.size(); ++t)
            if (alive_[t]) result.push_back(triangles_[t]);
        return result;
    }

private:
    /// One coplanar run of a vertex's fan: the hole left by the vertex is the polygon `ring`.
    struct Run {
        std::vector<std::uint32_t> ring;
        glm::dvec3 normal{0.0};
        double area = 0;
    };

    void add(const Triangle& t, bool fresh) {
        const auto id = static_cast<std::uint32_t>(triangles_.size());
        triangles_.push_back(t);
        fresh_.push_back(fresh);
        const glm::dvec3 a = areaVector(points_, t);
        const double length = glm::length(a);
        normals_.push_back(length > 0 ? a / length : glm::dvec3(0.0));
        alive_.push_back(true);
        for (std::uint32_t v : t) incident_[v].push_back(id);
    }

    void kill(std::uint32_t t) {
        alive_[t] = false;
        for (std::uint32_t v : triangles_[t]) std::erase(incident_[v], t);
    }

    bool coplanar(const glm::dvec3& a, const glm::dvec3& b) const { return glm::dot(a, b) >= cosine_; }

    bool hasEdge(std::uint32_t a, std::uint32_t b) const {
        return std::any_of(incident_[a].begin(), incident_[a].end(), [&](std::uint32_t t) {
            return std::find(triangles_[t].begin(), triangles_[t].end(), b) != triangles_[t].end();
        });
    }

    /// Triangle t as (v, a, b).
    Triangle around(std::uint32_t t, std::uint32_t v) const {
        Triangle r = triangles_[t];
        while (r[0] != v) std::rotate(r.begin(), r.begin() + 1, r.end());
        return r;
    }

    /// The fan of v in order around it (each triangle's b is the next one's a), and whether it is
    /// closed; nothing when the fan is not one manifold run.
    std::optional<std::pair<std::vector<std::uint32_t>, bool>> orderedFan(std::uint32_t v) const {
        const std::vector<std::uint32_t>& fan = incident_[v];
        const std::size_t k = fan.size();
        std::vector<Triangle> local;
        for (std::uint32_t t : fan) local.push_back(around(t, v));
        const auto startingAt = [&](std::uint32_t a) {
            std::size_t found = k, count = 0;
            for (std::size_t j = 0; j < k; ++j)
                if (local[j][1] == a) found = j, ++count;
            return count == 1 ? found : (count == 0 ? k : k + 1);
        };
        std::size_t start = 0, starts = 0;
        for (std::size_t i = 0; i < k; ++i) {
            std::size_t ending = 0;
            for (std::size_t j = 0; j < k; ++j) ending += local[j][2] == local[i][1];
            if (ending > 1) return std::nullopt;
            if (ending == 0) start = i, ++starts;
        }
        if (starts > 1) return std::nullopt;
        std::vector<std::uint32_t> order{static_cast<std::uint32_t>(start)};
        bool closed = false;
        while (order.size() <= k) {
            const std::size_t next = startingAt(local[order.back()][2]);
            if (next > k) return std::nullopt;
            if (next == k) break;
            if (next == start) {
                closed = true;
                break;
            }
            order.push_back(static_cast<std::uint32_t>(next));
        }
        if (order.size() != k || closed != (starts == 0)) return std::nullopt;
        for (std::uint32_t& i : order) i = fan[i];
        return std::make_pair(std::move(order), closed);
    }

    bool collinearThrough(std::uint32_t x, std::uint32_t v, std::uint32_t y) const {
        const glm::dvec3 a = points_[x] - points_[v], b = points_[y] - points_[v];
        return glm::dot(a, b) < 0 && glm::length(glm::cross(a, b)) <= sine_ * glm::length(a) * glm::length(b);
    }

    /// The coplanar runs of v's fan whose removal keeps the geometry; nothing when v must stay.
    std::optional<std::vector<Run>> runsOf(std::uint32_t v, std::vector<std::uint32_t> order, bool closed) const {
        const std::size_t k = order.size();
        std::vector<std::size_t> breaks;
        for (std::size_t i = closed ? 0 : 1; i < k; ++i)
            if (!coplanar(normals_[order[(i + k - 1) % k]], normals_[order[i]])) breaks.push_back(i);
        if (closed && breaks.size() == 2) {
            std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(breaks[0]), order.end());
            breaks = {0, breaks[1] - breaks[0]};
        } else if (!breaks.empty() || (!closed && k < 2)) {
            return std::nullopt;
        } else {
            breaks = {0};
        }
        std::vector<Run> runs;
        for (std::size_t r = 0; r < breaks.size(); ++r) {
            const std::size_t end = r + 1 < breaks.size() ? breaks[r + 1] : k;
            Run run;
            for (std::size_t i = breaks[r]; i < end; ++i) {
                const Triangle t = around(order[i], v);
                run.ring.push_back(t[1]);
                const glm::dvec3 a = areaVector(points_, t);
                run.normal += a;
                run.area += glm::length(a);
            }
            if (!(closed && breaks.size() == 1)) run.ring.push_back(around(order[end - 1], v)[2]);
            run.normal = glm::normalize(run.normal);
            for (std::size_t i = breaks[r]; i < end; ++i)
                if (!coplanar(normals_[order[i]], run.normal)) return std::nullopt;
            runs.push_back(std::move(run));
        }
        // A crease or a border: v must lie on the straight line its two border edges make.
        if (!(closed && runs.size() == 1) && !collinearThrough(runs[0].ring.front(), v, runs[0].ring.back())) return std::nullopt;
        return runs;
    }

    /// Ear clipping in the run's plane, the ear with the largest smallest angle first; an ear may
    /// not hold another corner of the hole, nor close an edge that exists outside it.
    std::optional<std::vector<Triangle>> triangulate(const Run& run) const {
        std::vector<std::uint32_t> left = run.ring;
        for (std::size_t i = 0; i < left.size(); ++i)
            if (std::count(left.begin(), left.end(), left[i]) != 1) return std::nullopt;
        if (left.size() < 3) return std::nullopt;
        const glm::dvec3 n = run.normal;
        const glm::dvec3 u = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0)));
        const glm::dvec3 w = glm::cross(n, u);
        const auto cross2 = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            const glm::dvec3 ab = points_[b] - points_[a], ac = points_[c] - points_[a];
            return glm::dot(ab, u) * glm::dot(ac, w) - glm::dot(ab, w) * glm::dot(ac, u);
        };
        const auto convex = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            return cross2(a, b, c) > sine_ * glm::distance(points_[a], points_[b]) * glm::distance(points_[b], points_[c]);
        };
        std::vector<Triangle> result;
        while (left.size() > 3) {
            std::size_t best = left.size();
            double bestAngle = 0;
            for (std::size_t i = 0; i < left.size(); ++i) {
                const std::uint32_t p = left[(i + left.size() - 1) % left.size()], c = left[i], q = left[(i + 1) % left.size()];
                if (!convex(p, c, q) || hasEdge(p, q)) continue;
                const bool holds = std::any_of(left.begin(), left.end(), [&](std::uint32_t r) {
                    return r != p && r != c && r != q && cross2(p, c, r) >= 0 && cross2(c, q, r) >= 0 && cross2(q, p, r) >= 0;
                });
                const double angle = holds ? 0 : smallestAngle(points_[p], points_[c], points_[q]);
                if (angle > bestAngle) {
                    bestAngle = angle;
                    best = i;
                }
            }
            if (best == left.size()) return std::nullopt;
            result.push_back({left[(best + left.size() - 1) % left.size()], left[best], left[(best + 1) % left.size()]});
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
        }
        if (!convex(left[0], left[1], left[2])) return std::nullopt;
        result.push_back({left[0], left[1], left[2]});
        double area = 0;
        for (const Triangle& t : result) {
            const glm::dvec3 a = areaVector(points_, t);
            if (!coplanar(glm::normalize(a), n)) return std::nullopt;
            area += glm::length(a);
        }
        // Interior vertices keep the area to rounding; a border vertex may sit off its line by the
        // collinearity angle. A wrong (overlapping) triangulation would be off by far more.
        if (std::abs(area - run.area) > 1e-6 * run.area) return std::nullopt;
        return result;
    }

    /// Up to `passes` passes of flips, then the dead triangles dropped from the arrays.
    void flip(int passes) {
        for (int pass = 0; pass < passes && flipPass(); ++pass) {
        }
        std::vector<std::pair<Triangle, bool>> alive;
        for (std::size_t t = 0; t < triangles_.size(); ++t)
            if (alive_[t]) alive.emplace_back(triangles_[t], fresh_[t]);
        triangles_.clear();
        fresh_.clear();
        normals_.clear();
        alive_.clear();
        for (auto& fan : incident_) fan.clear();
        for (const auto& [t, fresh] : alive) add(t, fresh);
    }

    /// Removes v where that keeps the geometry; `ring` gets the vertices whose fans changed.
    bool tryRemove(std::uint32_t v, std::vector<std::uint32_t>& ring) {
        const auto fan = orderedFan(v);
        if (!fan) return false;
        const auto runs = runsOf(v, fan->first, fan->second);
        if (!runs) return false;
        // A crease or border closes the edge between its two neighbours: it must be new.
        if (runs->size() == 2 || !fan->second) {
            const std::uint32_t x = runs->front().ring.front(), y = runs->front().ring.back();
            if (hasEdge(x, y)) return false;
        }
        std::vector<Triangle> replacement;
        for (const Run& run : *runs) {
            const auto triangles = triangulate(run);
            if (!triangles) return false;
            replacement.insert(replacement.end(), triangles->begin(), triangles->end());
        }
        const std::vector<std::uint32_t> old = incident_[v];
        ring.clear();
        for (const Run& run : *runs) ring.insert(ring.end(), run.ring.begin(), run.ring.end());
        for (std::uint32_t t : old) kill(t);
        for (const Triangle& t : replacement) add(t, true);
        return true;
    }

    /// Flips every coplanar pair (a, b, c) + (b, a, w), one of them made here, into (a, w, c) +
    /// (w, b, c) where that raises the pair's smallest angle; true when any flipped.
    bool flipPass() {
        bool flipped = false;
        for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
            for (std::size_t i = 0; i < 3 && alive_[t]; ++i) {
                const std::uint32_t a = triangles_[t][i], b = triangles_[t][(i + 1) % 3], c = triangles_[t][(i + 2) % 3];
                std::uint32_t u = 0, w = 0;
                bool found = false;
                for (std::uint32_t s : incident_[b]) {
                    if (s == t) continue;
                    const Triangle r = around(s, b);
                    if (r[1] == a) {
                        u = s, w = r[2], found = true;
                        break;
                    }
                }
                // The exporter's own triangles keep their diagonals where nothing was removed.
                if (!found || !(fresh_[t] || fresh_[u]) || !coplanar(normals_[t], normals_[u]) || w == c || hasEdge(c, w)) continue;
                // A third face on the edge (a fin, a CAD file's inner wall) would be left hanging by the flip.
                const auto onEdge = std::count_if(incident_[a].begin(), incident_[a].end(), [&](std::uint32_t s) {
                    const Triangle& r = triangles_[s];
                    return alive_[s] && (r[0] == b || r[1] == b || r[2] == b);
                });
                if (onEdge != 2) continue;
                const Triangle first{a, w, c}, second{w, b, c};
                const glm::dvec3 n1 = areaVector(points_, first), n2 = areaVector(points_, second);
                const double l1 = glm::length(n1), l2 = glm::length(n2);
                if (!(l1 > 0 && l2 > 0) || !coplanar(n1 / l1, normals_[t]) || !coplanar(n2 / l2, normals_[t])) continue;
                const double before = std::min(smallestAngle(points_[a], points_[b], points_[c]), smallestAngle(points_[b], points_[a], points_[w]));
                const double after = std::min(smallestAngle(points_[a], points_[w], points_[c]), smallestAngle(points_[w], points_[b], points_[c]));
                if (!(after > before + 1e-9)) continue;
                kill(t);
                kill(u);
                add(first, true);
                add(second, true);
                flipped = true;
            }
        }
        return flipped;
    }

    static constexpr std::size_t kSmallFan = 12, kMaxFan = 128;
    static constexpr int kMaxRounds = 64;

    const std::vector<glm::dvec3>& points_;
    double cosine_, sine_;
    std::vector<Triangle> triangles_;
    std::vector<bool> fresh_;  ///< made by a removal or a flip, not given
    std::vector<glm::dvec3> normals_;
    std::vector<bool> alive_;
    std::vector<std::vector<std::uint32_t>> incident_;
};

} // namespace

std::vector<Triangle> removeFlatVertices(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
                                         double coplanarCosine) {
    // Triangles whose corners were welded together have no fan to take part in; they pass through.
    std::vector<Triangle> proper, result;
    for (const Triangle& t : triangles)
        (t[0] != t[1] && t[1] != t[2] && t[2] != t[0] && glm::length(areaVector(points, t)) > 0 ? proper : result).push_back(t);
    const std::vector<Triangle> simplified = Simplifier(points, proper, coplanarCosine).run();
    result.insert(result.end(), simplified.begin(), simplified.end());
    return result;
}

} // namespace radiant::detail
