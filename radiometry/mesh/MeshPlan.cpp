#include "radiometry/mesh/MeshPlan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/common/NumberText.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/mesh/ConvexFan.h"
#include "radiometry/mesh/VertexWelder.h"

namespace radiant::detail {
namespace {

// No edge is cut into more segments than this; the patch count then exceeds any budget long before
// an index could overflow.
constexpr std::uint64_t kMaxSegments = std::uint64_t{1} << 24;

/// Patches may exceed the requested area by this relative amount, so that a wall of 0.33 m read as
/// the float 0.33000001 is still cut into 33 rows of 1 cm, not 34.
constexpr double kAreaSlack = 4e-6;

/// Segments needed to cover `length` in steps of at most `step`, at least 1 (a length within
/// kAreaSlack / 2 of a whole number of steps takes that number).
std::uint64_t segmentsFor(double length, double step) {
    const double n = std::ceil(length / step * (1.0 - kAreaSlack / 2));
    return static_cast<std::uint64_t>(std::clamp(n, 1.0, static_cast<double>(kMaxSegments)));
}

} // namespace

double sceneDiagonal(const Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const Surface& s : scene.surfaces)
        for (const Face& f : s.faces)
            for (const glm::dvec3& v : f.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
    return lo.x <= hi.x ? glm::length(hi - lo) : 1.0;
}

double weldTolerance(const Scene& scene) { return std::max(sceneDiagonal(scene) * 1e-9, 1e-12); }

namespace {

class EdgeClasses {
public:
    std::uint32_t add(std::uint64_t segments) {
        parent_.push_back(static_cast<std::uint32_t>(parent_.size()));
        segments_.push_back(segments);
        return parent_.back();
    }
    std::uint32_t find(std::uint32_t e) {
        while (parent_[e] != e) {
            parent_[e] = parent_[parent_[e]];
            e = parent_[e];
        }
        return e;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        parent_[b] = a;
        segments_[a] = std::max(segments_[a], segments_[b]);
    }
    void require(std::uint32_t e, std::uint64_t segments) {
        const std::uint32_t root = find(e);
        segments_[root] = std::max(segments_[root], segments);
    }
    std::uint64_t segments(std::uint32_t e) { return segments_[find(e)]; }
    std::size_t size() const { return parent_.size(); }

private:
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint64_t> segments_;
};

glm::dvec3 newellNormal(const std::vector<glm::dvec3>& corners, const Piece& piece) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < piece.count; ++i)
        n += glm::cross(corners[piece.corners[i]], corners[piece.corners[(i + 1) % piece.count]]);
    return n;
}

/// Largest cell of a planar quad's nu x nv bilinear grid. On a planar quad the Jacobian
/// n . (dP/du x dP/dv) is linear in (u, v) (the uv term is d x d = 0), so a cell's area is the
/// Jacobian at its centre times du dv and the largest cell is one of the four corner cells.
double largestQuadCell(const std::array<glm::dvec3, 4>& p, const glm::dvec3& unitNormal, std::uint64_t nu,
                       std::uint64_t nv) {
    const auto jacobian = [&](double u, double v) {
        const glm::dvec3 du = (1 - v) * (p[1] - p[0]) + v * (p[2] - p[3]);
        const glm::dvec3 dv = (1 - u) * (p[3] - p[0]) + u * (p[2] - p[1]);
        return glm::dot(unitNormal, glm::cross(du, dv));
    };
    const double hu = 0.5 / static_cast<double>(nu), hv = 0.5 / static_cast<double>(nv);
    const double largest = std::max({jacobian(hu, hv), jacobian(1 - hu, hv), jacobian(hu, 1 - hv), jacobian(1 - hu, 1 - hv)});
    return largest / (static_cast<double>(nu) * static_cast<double>(nv));
}

std::size_t longestEdge(const std::vector<glm::dvec3>& corners, const Piece& piece) {
    std::size_t longest = 0;
    double longestLength = -1;
    for (std::size_t e = 0; e < piece.count; ++e) {
        const double length = glm::distance(corners[piece.corners[e]], corners[piece.corners[(e + 1) % piece.count]]);
        if (length > longestLength) {
            longestLength = length;
            longest = e;
        }
    }
    return longest;
}

/// True when the piece lies along a contact of its face on the side light reaches: one of its edges
/// runs on the contact's segment for more than the snap (the floor before a block's side, not the
/// footprint under it).
bool besideContact(const std::vector<glm::dvec3>& corners, const Piece& piece, const std::vector<ContactSegment>& contacts) {
    glm::dvec3 centre(0.0);
    for (std::size_t j = 0; j < piece.count; ++j) centre += corners[piece.corners[j]] / static_cast<double>(piece.count);
    for (const ContactSegment& contact : contacts) {
        const double length = glm::distance(contact.from, contact.to);
        if (!(length > 0) || glm::dot(centre - contact.from, contact.open) <= 0) continue;
        const glm::dvec3 along = (contact.to - contact.from) / length;
        for (std::size_t e = 0; e < piece.count; ++e) {
            const glm::dvec3& p = corners[piece.corners[e]];
            const glm::dvec3& q = corners[piece.corners[(e + 1) % piece.count]];
            if (std::abs(glm::dot(p - contact.from, contact.open)) > contact.snap ||
                std::abs(glm::dot(q - contact.from, contact.open)) > contact.snap)
                continue;
            const double tp = glm::dot(p - contact.from, along), tq = glm::dot(q - contact.from, along);
            if (std::min(std::max(tp, tq), length) - std::max(std::min(tp, tq), 0.0) > contact.snap) return true;
        }
    }
    return false;
}

SurfacePlan planSurface(const Scene& scene, std::size_t surfaceIndex, const MeshingOptions& options, double tolerance,
                        const std::vector<std::vector<std::vector<glm::dvec3>>>& contactPolygons,
                        const std::vector<std::vector<ContactSegment>>& contactSegments) {
    const Surface& surface = scene.surfaces[surfaceIndex];
    SurfacePlan plan;
    VertexWelder welder(tolerance);
    std::unordered_map<std::uint64_t, std::uint32_t> edgeIds;
    EdgeClasses classes;

    const auto edgeBetween = [&](std::uint32_t a, std::uint32_t b) {
        const PlanEdge edge{std::min(a, b), std::max(a, b)};
        const std::uint64_t key = (std::uint64_t{edge.low} << 32) | edge.high;
        const auto [it, inserted] = edgeIds.try_emplace(key, static_cast<std::uint32_t>(plan.edges.size()));
        if (inserted) {
            plan.edges.push_back(edge);
            classes.add(1);
        }
        return it->second;
    };

    const auto addPolygon = [&](std::size_t f, const std::vector<glm::dvec3>& polygon, bool contactCut) {
        std::vector<std::uint32_t> ids;
        for (const glm::dvec3& v : polygon) {
            const std::uint32_t id = welder.weld(v);
            if (ids.empty() || ids.back() != id) ids.push_back(id);
        }
        while (ids.size() > 1 && ids.front() == ids.back()) ids.pop_back();
        if (ids.size() < 3) return;

        forEachFanPiece(ids.size(), [&](std::size_t first, std::size_t count) {
            Piece piece;
            piece.face = static_cast<std::uint32_t>(f);
            piece.count = static_cast<std::uint8_t>(count);
            piece.contactCut = contactCut;
            for (std::size_t j = 0; j < count; ++j) piece.corners[j] = j == 0 ? ids[0] : ids[first + j - 1];
            plan.pieces.push_back(piece);
        });
    };
    for (std::size_t f = 0; f < surface.faces.size(); ++f) {
        const Face& face = surface.faces[f];
        for (const glm::dvec3& v : face.vertices) {
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                throw RadiantError({scene.name, "surface '" + surface.name + "', face " + std::to_string(f)},
                                   "vertex (" + numberText(v.x) + ", " + numberText(v.y) + ", " + numberText(v.z) +
                                       ") is not finite");
            }
        }
        if (!(face.area > 0)) continue;  // degenerate: nothing to light
        // A face cut along contacts (ContactCuts.h) is meshed as its convex cut polygons.
        if (contactPolygons[f].empty()) {
            addPolygon(f, face.vertices, false);
        } else {
            for (const auto& polygon : contactPolygons[f]) addPolygon(f, polygon, true);
        }
    }
    plan.corners = welder.takePoints();
    // Collinear corners can leave a piece without area; it would only carry a NaN normal.
    std::erase_if(plan.pieces, [&](const Piece& piece) { return !(glm::length(newellNormal(plan.corners, piece)) > 0); });

    // Each piece asks for the fewest segments that keep its patches under its bound and near square.
    for (Piece& piece : plan.pieces) {
        for (std::size_t e = 0; e < piece.count; ++e)
            piece.edges[e] = edgeBetween(piece.corners[e], piece.corners[(e + 1) % piece.count]);
        const bool finer = options.besideContactAreaShare < 1 && piece.contactCut &&
                           besideContact(plan.corners, piece, contactSegments[piece.face]);
        const double maxArea = options.maxPatchArea * (finer ? options.besideContactAreaShare : 1.0);
        const double area = 0.5 * glm::length(newellNormal(plan.corners, piece));
        if (piece.count == 3) {
            if (area <= 2 * maxArea * (1 + kAreaSlack)) {
                // Halving suffices: two segments on the longest edge. Cut by a zipper (Meshing.cpp),
                // no triangle exceeds area / 2 once any edge carries two.
                if (area > maxArea * (1 + kAreaSlack)) classes.require(piece.edges[longestEdge(plan.corners, piece)], 2);
                continue;
            }
            // Uniform n-subdivision: n^2 triangles, each area / n^2 and similar to the piece.
            // Every edge carries at least n, so the stitched ring (Meshing.cpp) stays under maxArea.
            const std::uint64_t n = segmentsFor(std::sqrt(area), std::sqrt(maxArea));
            piece.fitsTwoPatches = false;
            for (std::size_t e = 0; e < 3; ++e) classes.require(piece.edges[e], n);
        } else if (area <= maxArea * (1 + kAreaSlack)) {
            // Already a patch: cutting it near-square would make patches far under the requested
            // size and pass the count along its rows of quads.
            classes.unite(piece.edges[0], piece.edges[2]);
            classes.unite(piece.edges[1], piece.edges[3]);
        } else {
            // Cells of side s along both directions; for a parallelogram with angle theta the cell
            // area is s^2 sin(theta), hence the scaling of s by lu lv / area = 1 / sin(theta).
            const auto& c = plan.corners;
            const auto& k = piece.corners;
            const double lu = 0.5 * (glm::distance(c[k[0]], c[k[1]]) + glm::distance(c[k[2]], c[k[3]]));
            const double lv = 0.5 * (glm::distance(c[k[1]], c[k[2]]) + glm::distance(c[k[3]], c[k[0]]));
            const double side = std::sqrt(maxArea * lu * lv / area);
            classes.require(piece.edges[0], segmentsFor(lu, side));
            classes.require(piece.edges[1], segmentsFor(lv, side));
            classes.unite(piece.edges[0], piece.edges[2]);
            classes.unite(piece.edges[1], piece.edges[3]);
        }
    }

    // A quad that is not a parallelogram has cells of unequal size: refine until its largest cell
    // fits the bound every patch keeps (a piece beside a contact asked for finer cells above, and
    // keeps them where it is a parallelogram). Counts only grow, and growing one class never breaks
    // another piece's bound.
    for (bool changed = true; changed;) {
        changed = false;
        for (const Piece& piece : plan.pieces) {
            if (piece.count != 4) continue;
            std::array<glm::dvec3, 4> p{};
            for (std::size_t j = 0; j < 4; ++j) p[j] = plan.corners[piece.corners[j]];
            const glm::dvec3 normal = glm::normalize(newellNormal(plan.corners, piece));
            const std::uint64_t nu = classes.segments(piece.edges[0]), nv = classes.segments(piece.edges[1]);
            const double largest = largestQuadCell(p, normal, nu, nv);
            if (largest <= options.maxPatchArea * (1 + kAreaSlack)) continue;
            if (nu >= kMaxSegments && nv >= kMaxSegments) continue;  // beyond any budget anyway
            // Both directions grow by at least one segment, so the loop always progresses.
            const double grow = std::sqrt(largest / options.maxPatchArea);
            const auto grown = [&](std::uint64_t segments) {
                return std::max(segments + 1, segmentsFor(static_cast<double>(segments) * grow, 1.0));
            };
            classes.require(piece.edges[0], std::min(grown(nu), kMaxSegments));
            classes.require(piece.edges[1], std::min(grown(nv), kMaxSegments));
            changed = true;
        }
    }

    plan.edgeClass.resize(plan.edges.size());
    std::vector<std::uint32_t> classOfRoot(classes.size(), std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t e = 0; e < plan.edges.size(); ++e) {
        const std::uint32_t root = classes.find(e);
        if (classOfRoot[root] == std::numeric_limits<std::uint32_t>::max()) {
            classOfRoot[root] = static_cast<std::uint32_t>(plan.classSegments.size());
            plan.classSegments.push_back(classes.segments(root));
        }
        plan.edgeClass[e] = classOfRoot[root];
    }
    return plan;
}

} // namespace

TriangleCut triangleCut(const Piece& piece, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    if (a == b && b == c) return TriangleCut::Lattice;
    return piece.fitsTwoPatches ? TriangleCut::Zipper : TriangleCut::Core;
}

std::uint64_t triangleCoreSegments(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    const std::uint64_t n = std::max({a, b, c});
    return a == b && b == c ? n : std::max<std::uint64_t>(n, 3);
}

double SurfacePlan::patchCount(const Piece& piece) const {
    const auto a = static_cast<double>(segments(piece.edges[0])), b = static_cast<double>(segments(piece.edges[1]));
    if (piece.count == 4) return a * b;
    const auto c = static_cast<double>(segments(piece.edges[2]));
    const TriangleCut cut = triangleCut(piece, segments(piece.edges[0]), segments(piece.edges[1]), segments(piece.edges[2]));
    if (cut == TriangleCut::Lattice) return a * a;
    if (cut == TriangleCut::Zipper) return a + b + c - 2;  // a convex polygon of a + b + c corners
    // A core of n segments has (n - 3)^2 triangles inside its ring of interior vertices; the ring
    // to the edges holds one triangle per edge segment and one per core-side segment.
    const auto n = static_cast<double>(triangleCoreSegments(segments(piece.edges[0]), segments(piece.edges[1]),
                                                            segments(piece.edges[2])));
    return (n - 3) * (n - 3) + a + b + c + 3 * (n - 3);
}

MeshPlan planMeshing(const Scene& scene, const MeshingOptions& options) {
    if (!(options.maxPatchArea > 0) || !std::isfinite(options.maxPatchArea)) {
        throw RadiantError({scene.name, "max patch area"},
                           "must be a positive number of m^2, not " + numberText(options.maxPatchArea));
    }
    if (!(options.besideContactAreaShare > 0 && options.besideContactAreaShare <= 1)) {
        throw RadiantError({scene.name, "patch area beside contacts"},
                           "must be a share of the max patch area in (0, 1], not " + numberText(options.besideContactAreaShare));
    }
    MeshPlan plan;
    const double tolerance = weldTolerance(scene);
    ContactSegments segments;
    auto contacts = std::make_shared<const ContactPolygons>(cutAlongContacts(scene, nullptr, &segments));
    plan.contacts = contacts;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        plan.surfaces.push_back(planSurface(scene, s, options, tolerance, (*contacts)[s], segments[s]));
        for (const Piece& piece : plan.surfaces.back().pieces) plan.patchCount += plan.surfaces.back().patchCount(piece);
    }
    return plan;
}

} // namespace radiant::detail
