#pragma once
// A link of hierarchical radiosity (Hanrahan, Salzman, Aupperle 1991): the receiver element gathers
// radiosity from the source element through one form factor. 16 bytes, no allocation of its own:
// millions of them live in one flat array.
#include <cmath>
#include <cstdint>

#include "radiometry/mesh/ElementTree.h"

namespace radiant {

struct Link {
    ElementIndex receiver = kNoElement;
    ElementIndex source = kNoElement;
    /// F(receiver -> source) times the link's visible share (an unbiased ray estimate):
    /// H_receiver += formFactor * B_source.
    float formFactor = 0;
    /// How uncertain formFactor is across the receiver (the kernel's spread over it, or the whole
    /// form factor when partially visible): what the refinement oracle multiplies by B and area.
    /// Stored negative for a partially visible link (see partiallyVisible()), to stay at 16 bytes.
    float errorFormFactor = 0;

    [[nodiscard]] double uncertainty() const { return std::abs(static_cast<double>(errorFormFactor)); }
    /// Some but not all of the oracle's visibility rays were blocked.
    [[nodiscard]] bool partiallyVisible() const { return std::signbit(errorFormFactor); }
};
static_assert(sizeof(Link) == 16);

} // namespace radiant
