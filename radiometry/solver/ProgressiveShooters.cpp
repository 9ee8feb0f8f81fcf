// Grouping a mesh's patches into shooters (Cohen, Greenberg, Immel, Brock 1986; see the header).
// The mesher emits each quad piece as an nu x nv grid, row by row, neighbours sharing corner
// vertices; the grids are recovered here from those shared vertices alone, so nothing but the
// PatchMesh is needed. On a planar quad the grid lines are straight, so a block of the grid is
// exactly the convex quad of its four outer corners.
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

/// Tiles a triangle lattice with parallelograms of whole cells (an up and a down triangle each),
/// as large as fit below the long edge, from `block` x `block` down to single cells; the up
/// triangles along the long edge, which have no down partner, shoot alone.
void addTriangleBlocks(ProgressiveShooters& shooters, const PatchMesh& mesh, const TriangleLattice& lattice,
                       std::size_t block) {
    const std::size_t n = lattice.n();
    // Cell (i, j) is whole where i + j + 1 < n.
    std::vector<char> taken(n * n, 0);
    std::vector<std::uint32_t> cell;
    const auto free = [&](std::size_t i0, std::size_t j0, std::size_t size) {
        if (i0 + j0 + 2 * (size - 1) + 1 >= n) return false;
        for (std::size_t j = j0; j < j0 + size; ++j)
            for (std::size_t i = i0; i < i0 + size; ++i)
                if (taken[j * n + i]) return false;
        return true;
    };
    for (std::size_t size = std::min(block, n); size >= 1; --size) {
        for (std::size_t j0 = 0; j0 < n; ++j0) {
            for (std::size_t i0 = 0; i0 + j0 + 1 < n; ++i0) {
                if (!free(i0, j0, size)) continue;
                cell.clear();
                for (std::size_t j = j0; j < j0 + size; ++j)
                    for (std::size_t i = i0; i < i0 + size; ++i) {
                        taken[j * n + i] = 1;
                        cell.push_back(static_cast<std::uint32_t>(lattice.upIndex(i, j)));
                        cell.push_back(static_cast<std::uint32_t>(lattice.upIndex(i, j) + 1));
                    }
                const std::size_t i1 = i0 + size - 1, j1 = j0 + size - 1;
                const std::array<glm::dvec3, 4> corners{mesh.vertices[lattice.up(i0, j0).corners[0]],
                                                        mesh.vertices[lattice.up(i1, j0).corners[1]],
                                                        mesh.vertices[lattice.down(i1, j1).corners[1]],
                                                        mesh.vertices[lattice.up(i0, j1).corners[2]]};
                PatchPolygon outline = PatchPolygon::from(corners);
                outline.normal = lattice.up(i0, j0).normal;
                addGroup(shooters, mesh, cell, outline);
            }
        }
    }
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = n - 1 - j;
        const auto index = static_cast<std::uint32_t>(lattice.upIndex(i, j));
        addGroup(shooters, mesh, std::span<const std::uint32_t>(&index, 1), mesh.polygon(index));
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
        const auto [nu, nv] = block == 1 ? std::array<std::size_t, 2>{1, 1} : gridAt(mesh, start);
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
