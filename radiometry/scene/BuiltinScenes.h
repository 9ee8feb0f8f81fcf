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

/// A closed 1 m cube, [0, 1]^3, every face facing inward; the ceiling (y = 1) emits 1 W/m^2 per
/// band; every reflectance is 0.5. Surfaces: floor, ceiling, wall -x, wall +x, wall -z, wall +z.
Scene makeUnitCube();

/// The furnace test: a closed 2 m x 1 m x 1.5 m box, faces inward, one material of reflectance 0.5
/// and exitance 1 W/m^2 on every face, so B = E / (1 - rho) = 2 W/m^2 everywhere.
Scene makeFurnace();

/// Two directly opposed unit squares 1 m apart facing each other: "emitter" (y = 0, facing +y,
/// exitance 1 W/m^2, reflectance 0) and "receiver" (y = 1, facing -y, reflectance 0.5). F = 0.199825.
Scene makeParallelPlates();

/// Two unit squares sharing the edge x = y = 0: "emitter" on the floor (y = 0, facing +y,
/// exitance 1 W/m^2, reflectance 0) and "receiver" on the wall x = 0 (facing +x, reflectance 0.5).
/// F = 0.200044.
Scene makePerpendicularPlates();

/// Every built-in scene's name, in the order a menu shows them ("cornell-box" first).
std::vector<std::string> builtinSceneNames();
/// Builds the named built-in scene in code; throws RadiantError naming the known names otherwise.
Scene makeBuiltinScene(const std::string& name);

} // namespace radiant
