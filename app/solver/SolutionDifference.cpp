#include "app/solver/SolutionDifference.h"

#include <algorithm>
#include <cmath>

#include "app/solver/SolveProgress.h"
#include "radiometry/mesh/PatchLocator.h"

namespace radiant::app {
namespace {

double sumOfBands(const Rgb& b) { return b.x + b.y + b.z; }

bool samePatches(const PatchMesh& a, const PatchMesh& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t p = 0; p < a.size(); ++p)
        if (a.patches[p].surface != b.patches[p].surface || a.patches[p].centroid != b.patches[p].centroid) return false;
    return true;
}

} // namespace

double relativeDifference(const Rgb& a, const Rgb& b, double floor) {
    const double ta = sumOfBands(a), tb = sumOfBands(b);
    const double larger = std::max({std::abs(ta), std::abs(tb), floor});
    return larger > 0 ? std::abs(ta - tb) / larger : 0.0;
}

std::vector<std::size_t> SolutionDifferencer::correspondence(const PatchMesh& fine, const PatchMesh& coarse) {
    std::vector<std::size_t> coarseOf(fine.size());
    // Two threads meshing the same scene alike make the same patches: the identity, without a search.
    if (samePatches(fine, coarse)) {
        for (std::size_t p = 0; p < fine.size(); ++p) coarseOf[p] = p;
        return coarseOf;
    }
    const PatchLocator locator(coarse);
    for (std::size_t p = 0; p < fine.size(); ++p) {
        const Patch& patch = fine.patches[p];
        const std::size_t q = locator.find(patch.surface, patch.face, patch.centroid);
        coarseOf[p] = q == PatchLocator::npos ? 0 : q;  // a face both meshes cut has patches in both
    }
    return coarseOf;
}

const SolutionDifference& SolutionDifferencer::update(const Snapshot& a, const Snapshot& b) {
    if (a.generation == generationA_ && b.generation == generationB_) return difference_;
    generationA_ = a.generation;
    generationB_ = b.generation;
    // Before its first step a side shows its emission alone (while its form factors compute, say):
    // no solution to set against the other's yet.
    if (!hasStepped(a) || !hasStepped(b)) {
        difference_.mesh.reset();
        difference_.relative.clear();
        ++difference_.generation;
        return difference_;
    }
    const bool firstIsFiner = a.mesh->size() >= b.mesh->size();
    const Snapshot& fine = firstIsFiner ? a : b;
    const Snapshot& coarse = firstIsFiner ? b : a;
    if (fine.mesh != fineMesh_ || coarse.mesh != coarseMesh_) {
        coarseOf_ = correspondence(*fine.mesh, *coarse.mesh);
        fineMesh_ = fine.mesh;
        coarseMesh_ = coarse.mesh;
    }
    SolutionDifference& d = difference_;
    d.mesh = fine.mesh;
    d.scene = fine.scene;
    d.onFirst = firstIsFiner;
    d.relative.resize(fine.mesh->size());
    const std::vector<Patch>& patches = fine.mesh->patches;
    // The scale: both solutions' area-mean radiosity over the finer mesh (emitters included).
    double power = 0, area = 0;
    for (std::size_t p = 0; p < d.relative.size(); ++p) {
        power += 0.5 * (sumOfBands(fine.radiosity[p]) + sumOfBands(coarse.radiosity[coarseOf_[p]])) * patches[p].area;
        area += patches[p].area;
    }
    d.darkFloor = area > 0 ? kDarkShare * std::abs(power) / area : 0;
    d.maxRelative = 0;
    d.largestPatch = 0;
    d.darkPatches = 0;
    double weighted = 0;
    for (std::size_t p = 0; p < d.relative.size(); ++p) {
        const Rgb& bFine = fine.radiosity[p];
        const Rgb& bCoarse = coarse.radiosity[coarseOf_[p]];
        const double r = relativeDifference(bFine, bCoarse, d.darkFloor);
        d.relative[p] = r;
        if (r > d.maxRelative) {
            d.maxRelative = r;
            d.largestPatch = p;
        }
        if (std::abs(sumOfBands(bFine)) < d.darkFloor && std::abs(sumOfBands(bCoarse)) < d.darkFloor) ++d.darkPatches;
        weighted += r * patches[p].area;
    }
    d.meanRelative = area > 0 ? weighted / area : 0;
    ++d.generation;
    return d;
}

} // namespace radiant::app
