#pragma once
// The one rule by which a mesh vertex averages the patches meeting at it, shared by the probe's
// vertexRadiosity() and interpolateRadiosity() (RadiosityInterpolation.h) and the display's
// smoothRadiosity() (render/display/SmoothingGroups.h), so the probe reads what the eye sees.
// Covered patches (Patch::covered: the floor under a block, a box's side sunk below the floor) see
// only backs and sit near their own exitance; where an open patch meets the vertex they would drag
// its value towards that, so they count only where no open patch meets (a vertex inside a block's
// footprint). Averaged in, they drew the floor of a closed furnace 0.5 cm from a box at 1.50
// against E / (1 - rho) = 2 (docs/ARCHITECTURE.md, "Accuracy").
#include "radiometry/units/Quantity.h"

namespace radiant {

/// A weighted mean (per band) kept in two slots, open and covered; mean() is the open slot's where it
/// holds any weight, else the covered slot's, else 0.
struct OpenFirstMean {
    Rgb openSum{0.0};
    double openWeight = 0;
    Rgb coveredSum{0.0};
    double coveredWeight = 0;

    void add(const Rgb& value, double weight, bool covered) {
        if (covered) {
            coveredSum += weight * value;
            coveredWeight += weight;
        } else {
            openSum += weight * value;
            openWeight += weight;
        }
    }

    [[nodiscard]] Rgb mean() const {
        if (openWeight > 0) return openSum / openWeight;
        if (coveredWeight > 0) return coveredSum / coveredWeight;
        return Rgb(0.0);
    }
};

} // namespace radiant
