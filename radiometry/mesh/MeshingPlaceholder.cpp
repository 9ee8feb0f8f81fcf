// PLACEHOLDER: deleted when meshing lands.
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant {
PatchPolygon PatchPolygon::from(std::span<const glm::dvec3>) { throw RadiantError({}, "meshing not available yet"); }
PatchPolygon PatchMesh::polygon(std::size_t) const { throw RadiantError({}, "meshing not available yet"); }
double PatchMesh::totalArea() const { throw RadiantError({}, "meshing not available yet"); }
PatchMesh meshScene(const Scene&, const MeshingOptions&, Progress*) { throw RadiantError({}, "meshing not available yet"); }
std::size_t estimatePatchCount(const Scene&, const MeshingOptions&) { throw RadiantError({}, "meshing not available yet"); }
} // namespace radiant
