#pragma once
// The comparison's third view (Comparison.h): how far two solutions of one scene lie apart, per patch
// of the finer of their two meshes. Each patch of the finer mesh takes the other solution's value at
// its centre: the other mesh's patch containing that centre (the hierarchical and importance methods
// publish per-patch values as the others do, so one rule serves every pair). The difference is
// |B_A - B_B| / max(B_A, B_B, floor) of each side's total (R+G+B) radiosity, the quantity false
// colour shows: 0 where both agree, 1 where one is dark and the other lit.
//
// The floor is kDarkShare of the mesh's area-mean radiosity. Without it a patch that neither method
// should light read 100%: on the Cornell box at 0.001 m^2, progressive against Gauss-Seidel, four
// floor patches under the blocks (a side on the block's footprint) were exactly 0 in one solution and
// 1.7e-6 to 9.7e-5 W/m^2 in the other (the open floor beside them: 0.03 to 0.3 W/m^2) - a visibility
// ray starting within the ray caster's plane tolerance of the footprint line passes the block's side
// (RayCaster.cpp: a face whose plane holds the origin cannot block), about 2 in 10^5 random rays, and
// each method's rays met it at different patches (docs/ARCHITECTURE.md, comparison mode).
// GL-free; main thread.
#include <cstdint>
#include <memory>
#include <vector>

#include "app/solver/Snapshot.h"

namespace radiant::app {

struct SolutionDifference {
    std::shared_ptr<const PatchMesh> mesh;  ///< the finer mesh, which `relative` is indexed by; null: none
    std::shared_ptr<const Scene> scene;     ///< the scene of that mesh's snapshot
    bool onFirst = true;                    ///< the finer mesh is A's (B's otherwise)
    std::vector<double> relative;           ///< per patch of `mesh`
    double maxRelative = 0;
    std::size_t largestPatch = 0;  ///< the patch of `mesh` where relative is maxRelative
    double meanRelative = 0;  ///< area-weighted over the mesh
    /// W/m^2, band total: kDarkShare of the area-mean radiosity of both solutions over `mesh`; a patch
    /// darker than this on both sides has its difference taken relative to it.
    double darkFloor = 0;
    std::size_t darkPatches = 0;  ///< patches of `mesh` below darkFloor in both solutions
    std::uint64_t generation = 0;  ///< increases with every recomputation
};

/// The dark floor's share of the area-mean radiosity: a difference on a patch darker than 1% of the
/// scene's mean is reported relative to that 1%, not to the patch's own near-zero B.
inline constexpr double kDarkShare = 0.01;

/// |a - b| / max(a, b, floor) of the band totals (floor: W/m^2, band total); 0 when all are 0.
double relativeDifference(const Rgb& a, const Rgb& b, double floor = 0);

class SolutionDifferencer {
public:
    /// The difference of the two snapshots' solutions, recomputed only when either's generation
    /// changed (the patch correspondence only when either mesh did). Empty (mesh null) while either
    /// has no mesh or has not stepped yet.
    const SolutionDifference& update(const Snapshot& a, const Snapshot& b);
    [[nodiscard]] const SolutionDifference& current() const { return difference_; }

    /// For each patch of `fine`, the patch of `coarse` containing its centroid (same scene).
    static std::vector<std::size_t> correspondence(const PatchMesh& fine, const PatchMesh& coarse);

private:
    SolutionDifference difference_;
    std::uint64_t generationA_ = 0, generationB_ = 0;
    // Held, not merely pointed at: a freed mesh's address may come back as another mesh's.
    std::shared_ptr<const PatchMesh> fineMesh_, coarseMesh_;
    std::vector<std::size_t> coarseOf_;  ///< per patch of the finer mesh
};

} // namespace radiant::app
