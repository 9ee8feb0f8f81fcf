#include "radiometry/mesh/ContactCuts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"

namespace radiant::detail {
namespace {

struct Line {
    glm::dvec3 point{0.0};  ///< a point of the contact (its lexicographically first end)
    glm::dvec3 across{0.0};  ///< unit, in the face's plane, perpendicular to the line
    double snap = 0;  ///< m: corners this close to the line are on it (ContactCuts.h: kContactSnap)
    glm::dvec3 end{0.0};  ///< the contact's other end (the line cuts whole; the segment is the contact)
    glm::dvec3 open{0.0};  ///< unit, in the plane: the side of the contact light reaches
};

/// A face's bounding box, for the grid.
struct FaceBox {
    glm::dvec3 lo{0.0}, hi{0.0};
    std::uint32_t surface = 0, face = 0;
};

/// Faces in a uniform grid of cells by their bounding boxes, so a face only tests the faces near it;
/// a face over too many cells (a floor) is tested by every query.
class FaceGrid {
public:
    FaceGrid(std::vector<FaceBox> faces, glm::dvec3 lo, double cell) : faces_(std::move(faces)), lo_(lo), cell_(cell) {
        for (std::uint32_t e = 0; e < faces_.size(); ++e) {
            const Box box = boxOf(faces_[e].lo, faces_[e].hi);
            if (box.cells() > kMaxCells) {
                wide_.push_back(e);
                continue;
            }
            forEach(box, [&](std::uint64_t key) { cells_[key].push_back(e); });
        }
        seen_.assign(faces_.size(), 0);
    }

    template <class Visit>
    void near(const glm::dvec3& lo, const glm::dvec3& hi, Visit&& visit) {
        ++stamp_;
        const auto once = [&](std::uint32_t e) {
            if (seen_[e] == stamp_) return;
            seen_[e] = stamp_;
            visit(faces_[e]);
        };
        for (std::uint32_t e : wide_) once(e);
        const Box box = boxOf(lo, hi);
        if (box.cells() > kMaxCells) {
            for (std::uint32_t e = 0; e < faces_.size(); ++e) once(e);
            return;
        }
        forEach(box, [&](std::uint64_t key) {
            const auto found = cells_.find(key);
            if (found != cells_.end())
                for (std::uint32_t e : found->second) once(e);
        });
    }

private:
    static constexpr std::int64_t kMaxCells = 4096;
    struct Box {
        std::int64_t x0, y0, z0, x1, y1, z1;
        [[nodiscard]] std::int64_t cells() const { return (x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1); }
    };
    [[nodiscard]] std::int64_t index(double v, double lo) const {
        return static_cast<std::int64_t>(std::clamp(std::floor((v - lo) / cell_), -1.0, 1e6));
    }
    [[nodiscard]] Box boxOf(const glm::dvec3& lo, const glm::dvec3& hi) const {
        // One cell of margin: contacts are found within a tolerance, not exactly.
        return {index(lo.x, lo_.x) - 1, index(lo.y, lo_.y) - 1, index(lo.z, lo_.z) - 1,
                index(hi.x, lo_.x) + 1, index(hi.y, lo_.y) + 1, index(hi.z, lo_.z) + 1};
    }
    template <class Each>
    static void forEach(const Box& b, Each&& each) {
        for (std::int64_t x = b.x0; x <= b.x1; ++x)
            for (std::int64_t y = b.y0; y <= b.y1; ++y)
                for (std::int64_t z = b.z0; z <= b.z1; ++z)
                    each(static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^
                         static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull);
    }

    std::vector<FaceBox> faces_;
    glm::dvec3 lo_;
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> wide_;
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
};

double planeDistance(const Face& face, const glm::dvec3& p) { return glm::dot(face.normal, p - face.vertices[0]); }

/// Length of segment ab inside the convex polygon v (normal n), farther than `margin` from its edges.
double lengthInside(const std::vector<glm::dvec3>& v, const glm::dvec3& n, const glm::dvec3& a, const glm::dvec3& b,
                    double margin) {
    double t0 = 0, t1 = 1;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const glm::dvec3 inward = glm::normalize(glm::cross(n, v[(i + 1) % v.size()] - v[i]));
        const double da = glm::dot(inward, a - v[i]) - margin, db = glm::dot(inward, b - v[i]) - margin;
        if (da < 0 && db < 0) return 0;
        if (da < 0) t0 = std::max(t0, da / (da - db));
        if (db < 0) t1 = std::min(t1, da / (da - db));
    }
    return t1 > t0 ? (t1 - t0) * glm::distance(a, b) : 0;
}

bool lexicographicallyLess(const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

/// Splits a convex polygon by the line; corners within `snap` of it count as on it. Returns false
/// (and leaves the output empty) when the line does not cross the polygon's inside.
bool split(const std::vector<glm::dvec3>& polygon, const Line& line, std::vector<glm::dvec3>& front,
           std::vector<glm::dvec3>& back, std::vector<glm::dvec3>& made) {
    const double snap = line.snap;
    std::vector<double> side(polygon.size());
    bool anyFront = false, anyBack = false;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const double s = glm::dot(line.across, polygon[i] - line.point);
        side[i] = std::abs(s) < snap ? 0.0 : s;
        anyFront |= side[i] > 0;
        anyBack |= side[i] < 0;
    }
    if (!anyFront || !anyBack) return false;
    front.clear();
    back.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::size_t j = (i + 1) % polygon.size();
        if (side[i] >= 0) front.push_back(polygon[i]);
        if (side[i] <= 0) back.push_back(polygon[i]);
        if ((side[i] > 0 && side[j] < 0) || (side[i] < 0 && side[j] > 0)) {
            // The same point from both faces sharing the edge: computed from its endpoints in one order.
            const bool ordered = lexicographicallyLess(polygon[i], polygon[j]);
            const glm::dvec3& p = ordered ? polygon[i] : polygon[j];
            const glm::dvec3& q = ordered ? polygon[j] : polygon[i];
            const double sp = ordered ? side[i] : side[j], sq = ordered ? side[j] : side[i];
            const glm::dvec3 cut = p + (sp / (sp - sq)) * (q - p);
            front.push_back(cut);
            back.push_back(cut);
            made.push_back(cut);
        }
    }
    return front.size() >= 3 && back.size() >= 3;
}

/// Every finite face's box, with the scene's bounds.
struct SceneFaces {
    std::vector<FaceBox> faces;
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};
};

SceneFaces collectFaces(const Scene& scene) {
    SceneFaces result;
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        for (std::uint32_t f = 0; f < scene.surfaces[s].faces.size(); ++f) {
            const auto& v = scene.surfaces[s].faces[f].vertices;
            bool finite = !v.empty();
            for (const glm::dvec3& p : v) finite &= std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            if (!finite) continue;  // refused by the mesher, with its name
            FaceBox box{v[0], v[0], s, f};
            for (const glm::dvec3& p : v) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
            result.lo = glm::min(result.lo, box.lo);
            result.hi = glm::max(result.hi, box.hi);
            result.faces.push_back(box);
        }
    }
    return result;
}

bool usable(const Face& face) { return face.vertices.size() >= 3 && face.area > 0 && std::isfinite(face.area); }

/// Where the convex face `crossing` passes through the plane of `face`: the segment a-b between its
/// two edges that cross it. False when it only touches the plane.
bool crossingOfPlane(const Face& crossing, const Face& face, glm::dvec3& a, glm::dvec3& b) {
    const auto& v = crossing.vertices;
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < v.size() && points.size() < 2; ++i) {
        const glm::dvec3 &p = v[i], &q = v[(i + 1) % v.size()];
        const double dp = planeDistance(face, p), dq = planeDistance(face, q);
        if ((dp < 0) == (dq < 0) || dp == dq) continue;
        // From the endpoints in one order, so both faces sharing the edge compute the same point.
        const bool ordered = lexicographicallyLess(p, q);
        const glm::dvec3& from = ordered ? p : q;
        const glm::dvec3& to = ordered ? q : p;
        const double dFrom = ordered ? dp : dq, dTo = ordered ? dq : dp;
        points.push_back(from + (dFrom / (dFrom - dTo)) * (to - from));
    }
    if (points.size() < 2) return false;
    a = points[0];
    b = points[1];
    return glm::distance(a, b) > 0;
}

/// Tolerances of one scene, from its diagonal (ContactCuts.h).
struct ContactTolerances {
    double plane = 0;  ///< m: how far from a face's plane a contact edge may lie
    double snap = 0;  ///< m: the largest snap of a line
    double onEdge = 0;  ///< m: a cut's end this close to an edge lies on it
};

/// The lines that contacts cut face f of surface s along (several per contact when found from
/// several sides; they are merged once spread over the plane).
std::vector<Line> contactLinesOfFace(const Scene& scene, std::uint32_t s, std::uint32_t f, FaceGrid& grid,
                                     const ContactTolerances& tolerance) {
    std::vector<Line> lines;
    const Face& face = scene.surfaces[s].faces[f];
    if (!usable(face)) return lines;
    const auto addContact = [&](const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& standing) {
        // A small thing's contact snaps at a share of its own size, not the scene's: a chair
        // leg in a hall still cuts, and lines a leg's width apart stay apart.
        const double lineSnap = std::min(tolerance.snap, kContactSnapOfEdge * glm::distance(from, to));
        if (lengthInside(face.vertices, face.normal, from, to, lineSnap) <= lineSnap) return;
        // Ordered ends, so the same contact read from a file (floats, another winding) makes the
        // same line.
        const bool ordered = lexicographicallyLess(from, to);
        const glm::dvec3& a = ordered ? from : to;
        const glm::dvec3& b = ordered ? to : from;
        // The standing face's front looks out over the open side (a block's side over the floor
        // before it); a face through the plane does the same with its part in front.
        const glm::dvec3 across = glm::normalize(glm::cross(face.normal, glm::normalize(b - a)));
        const glm::dvec3 open = glm::dot(across, standing) >= 0 ? across : -across;
        lines.push_back({a, across, lineSnap, b, open});
    };
    glm::dvec3 flo(std::numeric_limits<double>::max()), fhi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& v : face.vertices) flo = glm::min(flo, v), fhi = glm::max(fhi, v);
    grid.near(flo, fhi, [&](const FaceBox& near) {
        if (near.surface == s && near.face == f) return;
        const Face& other = scene.surfaces[near.surface].faces[near.face];
        if (!usable(other) || std::abs(glm::dot(other.normal, face.normal)) > 1 - 1e-6) return;
        double lowest = 0, highest = 0;
        for (const glm::dvec3& v : other.vertices) {
            lowest = std::min(lowest, planeDistance(face, v));
            highest = std::max(highest, planeDistance(face, v));
        }
        if (lowest < -tolerance.plane && highest > tolerance.plane) {
            // A face through the plane (a box sunk into the floor, as Blender users place them; the
            // floor through the box's sides): its part in front stands on this face along the line
            // where it crosses the plane.
            glm::dvec3 a, b;
            if (crossingOfPlane(other, face, a, b)) addContact(a, b, other.normal);
            return;
        }
        // Otherwise it must stand on this face's front, on an edge of its own lying in the plane (a
        // wall below a floor lights nothing here).
        if (lowest < -tolerance.plane || highest <= tolerance.plane) return;
        const auto& v = other.vertices;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const glm::dvec3 &a = v[i], &b = v[(i + 1) % v.size()];
            if (std::abs(planeDistance(face, a)) <= tolerance.plane && std::abs(planeDistance(face, b)) <= tolerance.plane)
                addContact(a, b, other.normal);
        }
    });
    return lines;
}

/// Every face of the surface in the plane of a cut face takes the cut face's lines, in a fixed order,
/// each line once.
std::vector<std::vector<Line>> spreadOverPlanes(const Surface& surface, const std::vector<std::vector<Line>>& lines,
                                                double planeTolerance) {
    std::vector<std::vector<Line>> applied(surface.faces.size());
    for (std::uint32_t f = 0; f < surface.faces.size(); ++f) {
        if (lines[f].empty()) continue;
        const Face& face = surface.faces[f];
        for (std::uint32_t g = 0; g < surface.faces.size(); ++g) {
            const Face& other = surface.faces[g];
            if (!usable(other) || glm::dot(other.normal, face.normal) < 1 - 1e-6) continue;
            bool coplanar = true;
            for (const glm::dvec3& v : other.vertices) coplanar &= std::abs(planeDistance(face, v)) <= planeTolerance;
            if (coplanar) applied[g].insert(applied[g].end(), lines[f].begin(), lines[f].end());
        }
    }
    // Snapping makes the pieces depend on the order of the cuts: a fixed one, not the grid's (the
    // two edges leaving a footprint's corner share its point, so the direction breaks the tie).
    // A contact found from two faces of the plane (a floor stored as two triangles) cuts once.
    for (auto& faceLines : applied) {
        std::sort(faceLines.begin(), faceLines.end(), [](const Line& l, const Line& r) {
            return l.point != r.point ? lexicographicallyLess(l.point, r.point) : lexicographicallyLess(l.across, r.across);
        });
        faceLines.erase(std::unique(faceLines.begin(), faceLines.end(),
                                    [](const Line& l, const Line& r) {
                                        return glm::distance(l.point, r.point) <= std::min(l.snap, r.snap) &&
                                               glm::dot(l.across, r.across) > kSameDirection;
                                    }),
                        faceLines.end());
    }
    return applied;
}

/// The pieces of one surface's faces cut by their lines ([face]; empty where uncut), with the points
/// the cuts made on the pieces' edges; nothing when the pieces would pass kMostContactPieces.
struct SurfacePieces {
    std::vector<std::vector<std::vector<glm::dvec3>>> pieces;
    std::vector<glm::dvec3> made;
    std::size_t linesApplied = 0;
    bool overBudget = false;
};

SurfacePieces cutByLines(const Surface& surface, const std::vector<std::vector<Line>>& applied) {
    // Each line cuts every piece of the plane it crosses (ContactCuts.h: why not only the pieces its
    // contact segment crosses).
    SurfacePieces result;
    result.pieces.resize(surface.faces.size());
    std::size_t piecesSoFar = 0;
    for (std::uint32_t g = 0; g < surface.faces.size(); ++g) {
        if (applied[g].empty()) continue;
        result.linesApplied += applied[g].size();
        std::vector<std::vector<glm::dvec3>> polygons{surface.faces[g].vertices}, next;
        std::vector<glm::dvec3> front, back;
        for (const Line& line : applied[g]) {
            next.clear();
            for (auto& polygon : polygons) {
                if (split(polygon, line, front, back, result.made)) {
                    next.push_back(front);
                    next.push_back(back);
                } else {
                    next.push_back(std::move(polygon));
                }
            }
            std::swap(polygons, next);
            // Whole lines across a crowded plane multiply (n lines in general position: about n^2 / 2
            // pieces; 30 turned desks on a floor hung the load for minutes).
            if (piecesSoFar + polygons.size() > kMostContactPieces) {
                result.overBudget = true;
                return result;
            }
        }
        piecesSoFar += polygons.size();
        if (polygons.size() > 1) result.pieces[g] = std::move(polygons);
    }
    return result;
}

/// A cut ends on an edge that a face beside it keeps whole (a face of the surface out of the plane):
/// that edge takes the cut's end as a corner, so the surface stays conforming. Such a polygon has
/// corners on a straight side, which a fan from a corner would turn into flat triangles; it is fanned
/// from its centre instead. Returns the face's convex pieces, or nothing when neither a cut nor a
/// cut's end changed it.
std::vector<std::vector<glm::dvec3>> conformingPieces(const Face& face, const std::vector<std::vector<glm::dvec3>>& cut,
                                                      const std::vector<glm::dvec3>& made, double onEdge) {
    const std::vector<std::vector<glm::dvec3>> polygons = cut.empty() ? std::vector<std::vector<glm::dvec3>>{face.vertices} : cut;
    std::vector<std::vector<glm::dvec3>> convex;
    bool changed = !cut.empty();
    for (const auto& polygon : polygons) {
        std::vector<glm::dvec3> corners;
        bool inserted = false;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec3 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
            corners.push_back(p);
            const double length2 = glm::dot(q - p, q - p);
            if (!(length2 > 0)) continue;
            std::vector<std::pair<double, glm::dvec3>> onThis;
            for (const glm::dvec3& x : made) {
                const double t = glm::dot(x - p, q - p) / length2;
                if (t * std::sqrt(length2) <= onEdge || (1 - t) * std::sqrt(length2) <= onEdge) continue;
                if (glm::distance(p + t * (q - p), x) <= onEdge) onThis.emplace_back(t, x);
            }
            std::sort(onThis.begin(), onThis.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
            for (const auto& [t, x] : onThis) {
                if (glm::distance(corners.back(), x) <= onEdge) continue;
                corners.push_back(x);
                inserted = true;
            }
        }
        if (!inserted) {
            convex.push_back(polygon);
            continue;
        }
        changed = true;
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& c : polygon) centre += c;
        centre /= static_cast<double>(polygon.size());
        for (std::size_t i = 0; i < corners.size(); ++i) convex.push_back({centre, corners[i], corners[(i + 1) % corners.size()]});
    }
    if (!changed) return {};
    // Each piece from its lowest corner, so the mesher's fan does not depend on where the face's
    // corner list started.
    for (auto& polygon : convex)
        std::rotate(polygon.begin(), std::min_element(polygon.begin(), polygon.end(), lexicographicallyLess), polygon.end());
    return convex;
}

} // namespace

ContactPolygons cutAlongContacts(const Scene& scene, std::vector<std::string>* warnings, ContactSegments* segments) {
    ContactPolygons result(scene.surfaces.size());
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) result[s].resize(scene.surfaces[s].faces.size());
    if (segments) {
        segments->assign(scene.surfaces.size(), {});
        for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) (*segments)[s].resize(scene.surfaces[s].faces.size());
    }
    SceneFaces faces = collectFaces(scene);
    if (!(faces.lo.x <= faces.hi.x)) return result;
    const double extent = glm::length(faces.hi - faces.lo);
    if (!(extent > 0) || !std::isfinite(extent)) return result;
    const ContactTolerances tolerance{kContactPlaneTolerance * extent, kContactSnap * extent, 1e-7 * extent};

    FaceGrid grid(std::move(faces.faces), faces.lo, extent / 64);
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        std::vector<std::vector<Line>> lines(surface.faces.size());
        bool any = false;
        for (std::uint32_t f = 0; f < surface.faces.size(); ++f) {
            lines[f] = contactLinesOfFace(scene, s, f, grid, tolerance);
            any |= !lines[f].empty();
        }
        if (!any) continue;

        const std::vector<std::vector<Line>> applied = spreadOverPlanes(surface, lines, tolerance.plane);
        const SurfacePieces cut = cutByLines(surface, applied);
        if (cut.overBudget) {
            // The surface is meshed as if nothing stood on it, and the user is told.
            if (warnings)
                warnings->push_back(scene.name + ": surface '" + surface.name + "': the " + std::to_string(cut.linesApplied) +
                                    " edges standing on it would cut it into more than " +
                                    std::to_string(kMostContactPieces) +
                                    " pieces; it is meshed uncut, so its patches along what stands on it may lie "
                                    "partly under it and read darker there");
            continue;
        }
        for (std::uint32_t g = 0; g < surface.faces.size(); ++g)
            if (usable(surface.faces[g])) result[s][g] = conformingPieces(surface.faces[g], cut.pieces[g], cut.made, tolerance.onEdge);
        if (segments)
            for (std::uint32_t g = 0; g < surface.faces.size(); ++g)
                for (const Line& line : applied[g]) (*segments)[s][g].push_back({line.point, line.end, line.open, line.snap});
    }
    return result;
}

bool coveredPiece(const RayCaster& rays, std::span<const glm::dvec3> polygon, const glm::dvec3& normal, double offset) {
    if (polygon.size() < 3) return false;
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : polygon) centre += v;
    centre /= static_cast<double>(polygon.size());
    const glm::dvec3 from = centre + offset * normal;
    // An orthonormal frame about the normal for the rings.
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(normal, helper)), w = glm::cross(normal, u);
    std::vector<glm::dvec3> directions{normal};
    for (const double elevation : {5.0, 20.0, 45.0, 70.0}) {
        const double e = elevation * std::numbers::pi / 180;
        for (int k = 0; k < 8; ++k) {
            const double a = (k + 0.5 * (elevation == 20.0 || elevation == 70.0)) * std::numbers::pi / 4;
            directions.push_back(std::cos(e) * (std::cos(a) * u + std::sin(a) * w) + std::sin(e) * normal);
        }
    }
    bool sawBack = false;
    for (const glm::dvec3& d : directions) {
        // A double-sided face's twin lies at the same distance: the caster hands a ray arriving at
        // its back to the twin facing it, so the front wins the tie.
        const std::optional<RayHit> hit = rays.intersect(from, d);
        if (!hit) continue;
        if (glm::dot(hit->normal, d) < 0) return false;
        sawBack = true;
    }
    return sawBack;
}

} // namespace radiant::detail
