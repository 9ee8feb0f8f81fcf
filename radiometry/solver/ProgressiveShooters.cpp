// Grouping a mesh's patches into shooters (Cohen, Greenberg, Immel, Brock 1986; see the header).
// The mesher emits each quad piece as an nu x nv grid, row by row, neighbours sharing corner
// vertices; the grids are recovered here from those shared vertices alone, so nothing but the
// PatchMesh is needed. On a planar quad the grid lines are straight, so a block of the grid is
// exactly the convex quad of its four outer corners. Triangle pieces with equal edge counts are
// barycentric lattices, and so is the core of one with unequal counts (its band to the edges and a
// zipped small triangle are lone patches here); in a lattice, coarse parallelograms and triangles
// bounded by lattice lines are again exact unions.
#include "radiometry/solver/ProgressiveShooters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "radiometry/common/Error.h"

namespace radiant {

namespace {

bool isQuad(const Patch& p) { return p.cornerCount == 4; }

/// Patches a and b are neighbours in one grid row: b continues a along its corner 1 -> 2 edge.
bool continuesRow(const Patch& a, const Patch& b) {
    return isQuad(a) && isQuad(b) && a.surface == b.surface && a.face == b.face && b.corners[0] == a.corners[1] &&
           b.corners[3] == a.corners[2];
}

/// Patch b lies on top of patch a in the grid: b starts from a's corner 3 -> 2 edge.
bool continuesColumn(const Patch& a, const Patch& b) {
    return isQuad(a) && isQuad(b) && a.surface == b.surface && a.face == b.face && b.corners[0] == a.corners[3] &&
           b.corners[1] == a.corners[2];
}

/// The grid starting at patch `start`: its row length and row count (1 x 1 for a lone patch).
std::array<std::size_t, 2> gridAt(const PatchMesh& mesh, std::size_t start) {
    const auto& p = mesh.patches;
    std::size_t nu = 1;
    while (start + nu < p.size() && continuesRow(p[start + nu - 1], p[start + nu])) ++nu;
    std::size_t nv = 1;
    const auto rowFollows = [&](std::size_t row) {
        const std::size_t base = start + row * nu;
        if (base + nu > p.size()) return false;
        for (std::size_t i = 0; i < nu; ++i)
            if (!continuesColumn(p[base - nu + i], p[base + i])) return false;
        return true;
    };
    if (isQuad(p[start]))
        while (rowFollows(nv)) ++nv;
    return {nu, nv};
}

bool isTriangle(const Patch& p) { return p.cornerCount == 3; }

/// The barycentric lattice of a triangle piece as Meshing.cpp emits it: row j holds up(i, j) =
/// (i, j), (i+1, j), (i, j+1) and, where i + j + 1 < n, down(i, j) = (i+1, j), (i+1, j+1), (i, j+1).
class TriangleLattice {
public:
    /// The lattice starting at patch `start`, or n = 0 when the patches there do not form one.
    TriangleLattice(const PatchMesh& mesh, std::size_t start) : mesh_(mesh), start_(start) {
        const auto& p = mesh.patches;
        const auto sameFace = [&](std::size_t k) {
            return k < p.size() && isTriangle(p[k]) && p[k].surface == p[start].surface && p[k].face == p[start].face;
        };
        if (!sameFace(start)) return;
        std::size_t n = 1;
        while (sameFace(start + 2 * n) && sameFace(start + 2 * n - 1) &&
               p[start + 2 * n].corners[0] == p[start + 2 * n - 2].corners[1] &&
               p[start + 2 * n - 1].corners[0] == p[start + 2 * n - 2].corners[1])
            ++n;
        n_ = n;
        rowStart_.assign(n + 1, 0);
        for (std::size_t j = 0; j < n; ++j) rowStart_[j + 1] = rowStart_[j] + 2 * (n - j) - 1;
        // Every up triangle must sit on the one below it; else this is not a lattice.
        bool valid = sameFace(start + n * n - 1);
        for (std::size_t j = 1; valid && j < n; ++j)
            for (std::size_t i = 0; valid && i + j < n; ++i)
                valid = up(i, j).corners[0] == up(i, j - 1).corners[2] && (i + j + 1 >= n || isTriangle(down(i, j)));
        if (!valid) n_ = 0;
    }
    [[nodiscard]] std::size_t n() const { return n_; }
    [[nodiscard]] std::size_t upIndex(std::size_t i, std::size_t j) const { return start_ + rowStart_[j] + 2 * i; }
    [[nodiscard]] const Patch& up(std::size_t i, std::size_t j) const { return mesh_.patches[upIndex(i, j)]; }
    [[nodiscard]] const Patch& down(std::size_t i, std::size_t j) const { return mesh_.patches[upIndex(i, j) + 1]; }

private:
    const PatchMesh& mesh_;
    std::size_t start_;
    std::size_t n_ = 0;
    std::vector<std::size_t> rowStart_;
};

void addGroup(ProgressiveShooters& shooters, const PatchMesh& mesh, std::span<const std::uint32_t> patches,
              const PatchPolygon& outline) {
    shooters.members.insert(shooters.members.end(), patches.begin(), patches.end());
    shooters.first.push_back(static_cast<std::uint32_t>(shooters.members.size()));
    shooters.polygons.push_back(outline);
    shooters.surface.push_back(mesh.patches[patches.front()].surface);
    shooters.face.push_back(mesh.patches[patches.front()].face);
}

/// Tiles a triangle lattice of n segments a side with coarse pieces whose edges are lattice lines,
/// so each is exactly the union of its triangles. In lattice coordinates (x, y), x + y <= n: the
/// part x + y <= n' (n' the largest multiple of `block` up to n) is a coarse lattice of side
/// block - block x block parallelograms and, along its long edge, triangles of side block; the band
/// n' <= x + y <= n left over is cut at x = multiples of block into parallelograms, with a small
/// triangle where it meets y = 0.
void addTriangleBlocks(ProgressiveShooters& shooters, const PatchMesh& mesh, const TriangleLattice& lattice,
                       std::size_t block) {
    const std::size_t n = lattice.n();
    block = std::min(block, n);
    const std::size_t coarse = n / block, inner = coarse * block;
    const std::size_t bandPieces = (inner + block - 1) / block;
    const glm::dvec3 origin = mesh.vertices[lattice.up(0, 0).corners[0]];
    const glm::dvec3 alongX = (mesh.vertices[lattice.up(n - 1, 0).corners[1]] - origin) / static_cast<double>(n);
    const glm::dvec3 alongY = (mesh.vertices[lattice.up(0, n - 1).corners[2]] - origin) / static_cast<double>(n);
    const auto at = [&](std::size_t x, std::size_t y) {
        return origin + static_cast<double>(x) * alongX + static_cast<double>(y) * alongY;
    };
    // Region of a triangle by its centroid (never on a lattice line): coarse cells first, then the
    // band pieces, then the corner triangle.
    const std::size_t regions = coarse * coarse + bandPieces + 1;
    std::vector<std::vector<std::uint32_t>> members(regions);
    const auto regionOf = [&](double x, double y) -> std::size_t {
        if (x + y < static_cast<double>(inner))
            return static_cast<std::size_t>(y) / block * coarse + static_cast<std::size_t>(x) / block;
        if (x < static_cast<double>(inner)) return coarse * coarse + static_cast<std::size_t>(x) / block;
        return regions - 1;
    };
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i + j < n; ++i) {
            const auto up = static_cast<std::uint32_t>(lattice.upIndex(i, j));
            const double x = static_cast<double>(i), y = static_cast<double>(j);
            members[regionOf(x + 1.0 / 3, y + 1.0 / 3)].push_back(up);
            if (i + j + 1 < n) members[regionOf(x + 2.0 / 3, y + 2.0 / 3)].push_back(up + 1);
        }
    const glm::dvec3 normal = lattice.up(0, 0).normal;
    const auto add = [&](std::size_t region, std::initializer_list<glm::dvec3> corners) {
        if (members[region].empty()) return;
        PatchPolygon outline = PatchPolygon::from(std::span<const glm::dvec3>(corners.begin(), corners.size()));
        outline.normal = normal;
        addGroup(shooters, mesh, members[region], outline);
    };
    for (std::size_t J = 0; J < coarse; ++J)
        for (std::size_t I = 0; I + J < coarse; ++I) {
            const std::size_t x = I * block, y = J * block;
            if (I + J + 1 < coarse)
                add(J * coarse + I, {at(x, y), at(x + block, y), at(x + block, y + block), at(x, y + block)});
            else
                add(J * coarse + I, {at(x, y), at(x + block, y), at(x, y + block)});
        }
    if (inner < n) {
        for (std::size_t piece = 0; piece < bandPieces; ++piece) {
            const std::size_t x0 = piece * block, x1 = std::min(inner, x0 + block);
            add(coarse * coarse + piece, {at(x0, inner - x0), at(x1, inner - x1), at(x1, n - x1), at(x0, n - x0)});
        }
        add(regions - 1, {at(inner, 0), at(n, 0), at(inner, n - inner)});
    }
}

} // namespace

ProgressiveShooters ProgressiveShooters::eachPatch(std::size_t patchCount) {
    ProgressiveShooters shooters;
    shooters.first.resize(patchCount + 1);
    shooters.members.resize(patchCount);
    for (std::size_t i = 0; i <= patchCount; ++i) shooters.first[i] = static_cast<std::uint32_t>(i);
    for (std::size_t i = 0; i < patchCount; ++i) shooters.members[i] = static_cast<std::uint32_t>(i);
    return shooters;
}

ProgressiveShooters patchShooters(const PatchMesh& mesh) { return blockShooters(mesh, 1); }

ProgressiveShooters blockShooters(const PatchMesh& mesh, std::size_t block) {
    if (block == 0) throw RadiantError({"progressive shooters", "block"}, "the block size must be at least 1, got 0");
    ProgressiveShooters shooters;
    shooters.first.push_back(0);
    shooters.members.reserve(mesh.size());
    std::vector<std::uint32_t> cell;
    for (std::size_t start = 0; start < mesh.size();) {
        if (block > 1 && isTriangle(mesh.patches[start])) {
            const TriangleLattice lattice(mesh, start);
            if (lattice.n() > 1) {
                addTriangleBlocks(shooters, mesh, lattice, block);
                start += lattice.n() * lattice.n();
                continue;
            }
        }
        // Not a structured binding: clang 14 cannot capture those in the lambda below.
        const std::array<std::size_t, 2> grid = block == 1 ? std::array<std::size_t, 2>{1, 1} : gridAt(mesh, start);
        const std::size_t nu = grid[0], nv = grid[1];
        for (std::size_t j0 = 0; j0 < nv; j0 += block) {
            for (std::size_t i0 = 0; i0 < nu; i0 += block) {
                const std::size_t i1 = std::min(nu, i0 + block) - 1, j1 = std::min(nv, j0 + block) - 1;
                cell.clear();
                for (std::size_t j = j0; j <= j1; ++j)
                    for (std::size_t i = i0; i <= i1; ++i) cell.push_back(static_cast<std::uint32_t>(start + j * nu + i));
                const auto patchAt = [&](std::size_t i, std::size_t j) -> const Patch& {
                    return mesh.patches[start + j * nu + i];
                };
                PatchPolygon outline;
                if (cell.size() == 1) {
                    outline = mesh.polygon(cell.front());
                } else {
                    const std::array<glm::dvec3, 4> corners{mesh.vertices[patchAt(i0, j0).corners[0]],
                                                            mesh.vertices[patchAt(i1, j0).corners[1]],
                                                            mesh.vertices[patchAt(i1, j1).corners[2]],
                                                            mesh.vertices[patchAt(i0, j1).corners[3]]};
                    outline = PatchPolygon::from(corners);
                    outline.normal = patchAt(i0, j0).normal;  // the face's plane, not its round-off
                }
                addGroup(shooters, mesh, cell, outline);
            }
        }
        start += nu * nv;
    }
    return shooters;
}

std::size_t blockForShooterCount(std::size_t patchCount, std::size_t shooters) {
    if (shooters == 0 || patchCount <= shooters) return 1;
    const double side = std::sqrt(static_cast<double>(patchCount) / static_cast<double>(shooters));
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(side)));
}

} // namespace radiant
