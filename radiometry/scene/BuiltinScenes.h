#pragma once
// Scenes built in code from published data. tools/make_assets writes them to assets/*.gltf, so the
// shipped files can be remade and are reviewed as code.
#include <string>
#include <vector>

#include "radiometry/scene/Scene.h"

namespace radiant {

/// The Cornell box from the Cornell Program of Computer Graphics' measured data (mm converted to
/// metres), with the light cut out of the ceiling and the common RGB stand-in reflectances.
Scene makeCornellBox();

} // namespace radiant
