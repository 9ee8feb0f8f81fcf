#pragma once
// The comparison's third view (Comparison.h): how far two solutions of one scene lie apart, per patch
// of the finer of their two meshes. Each patch of the finer mesh takes the other solution's value at
// its centre: the other mesh's patch containing that centre (the hierarchical and importance methods
// publish per-patch values as the others do, so one rule serves every pair). The difference is
// |B_A - B_B| / max(B_A, B_B) of each side's total (R+G+B) radiosity, the quantity false colour shows:
// 0 where both agree, 1 where one is dark and the other lit. GL-free; main thread.
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
    double meanRelative = 0;  ///< area-weighted over the mesh
    std::uint64_t generation = 0;  ///< increases with every recomputation
};

/// |a - b| / max(a, b) of the band totals; 0 when both are 0.
double relativeDifference(const Rgb& a, const Rgb& b);

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
