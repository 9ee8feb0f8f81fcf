#pragma once
// A link of hierarchical radiosity (Hanrahan, Salzman, Aupperle 1991): the receiver element gathers
// radiosity from the source element through one form factor. 16 bytes, no allocation of its own:
// millions of them live in one flat array.
#include <cstdint>

#include "radiometry/mesh/ElementTree.h"

namespace radiant {

struct Link {
    ElementIndex receiver = kNoElement;
    ElementIndex source = kNoElement;
    /// F(receiver -> source) with visibility: H_receiver += formFactor * B_source.
    float formFactor = 0;
    /// The unoccluded form factor weighted by how uncertain the visibility is: what the refinement
    /// oracle multiplies by radiosity and area (partially visible links count in full).
    float errorFormFactor = 0;
};
static_assert(sizeof(Link) == 16);

} // namespace radiant
