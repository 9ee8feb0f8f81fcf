#pragma once
// The scene as the solvers see it: named surfaces made of planar convex polygons, each surface with
// one diffuse material in SI units (metres, W/m^2). Built by the glTF loader or in code.
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "radiometry/sources/PunctualLight.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

/// A diffuse material: reflectance per band in [0, 1) and radiant exitance per band in W/m^2.
struct Material {
    std::string name;
    Rgb reflectance{0.0};   ///< dimensionless, each band in [0, 1)
    ExitanceRgb exitance{}; ///< W/m^2 emitted, each band >= 0

    [[nodiscard]] bool emits() const {
        const Rgb& e = exitance.value();
        return e.x > 0 || e.y > 0 || e.z > 0;
    }
};

/// A planar convex polygon, vertices counter-clockwise seen from the side its normal points to.
struct Face {
    std::vector<glm::dvec3> vertices;  ///< metres
    glm::dvec3 normal{0, 0, 1};        ///< unit, the emitting/reflecting side
    double area = 0;                   ///< m^2

    /// Recomputes normal and area from the vertices (Newell's method).
    void updateGeometry();
};

/// Which side of a two-sided face a surface is. A double-sided glTF material makes each face two
/// surfaces back to back (the front as written, the back reversed, named "<name> (back)"), each
/// meshed and solved on its own: one radiosity per side, as a sheet lit from both sides has.
enum class FaceSide { Single, Front, Back };

/// A named group of faces sharing one material: what the Materials panel edits ("left wall").
struct Surface {
    std::string name;
    std::size_t material = 0;  ///< index into Scene::materials
    std::vector<Face> faces;
    std::string origin;        ///< where it came from, for messages: "mesh 3, primitive 0"
    /// Front: the next surface is its reversed twin (Back), face for face; Back: the previous one.
    FaceSide side = FaceSide::Single;

    [[nodiscard]] double area() const;
};

/// A perspective view stored with the scene (a glTF camera): where a renderer may look from.
struct SceneCamera {
    std::string name;                ///< the camera's, else its node's, else "camera N"
    glm::dvec3 position{0.0};        ///< m
    glm::dvec3 forward{0, 0, -1};    ///< unit: glTF cameras look down their local -z
    glm::dvec3 up{0, 1, 0};          ///< unit, perpendicular to forward
    double verticalFieldOfView = 0;  ///< radians (glTF yfov)
    double aspectRatio = 0;          ///< width / height as stored; 0 when the file leaves it open
};

struct Scene {
    std::string name;  ///< built-in name or file path
    std::vector<Material> materials;
    std::vector<Surface> surfaces;
    std::vector<SceneCamera> cameras;   ///< in file order; may be empty
    std::vector<PunctualLight> lights;  ///< glTF's KHR_lights_punctual, each a source in every method
    std::vector<std::string> warnings;  ///< the loader's, one line each, naming file and element

    [[nodiscard]] double totalArea() const;
    [[nodiscard]] std::size_t faceCount() const;
    /// Faces made two surfaces back to back (counted once per pair).
    [[nodiscard]] std::size_t doubleSidedSurfaceCount() const;
    [[nodiscard]] bool emits() const;
    /// Something to solve: a surface emits or a light shines.
    [[nodiscard]] bool lit() const { return emits() || !lights.empty(); }
    /// Index of the surface with this name, or npos.
    [[nodiscard]] std::size_t findSurface(const std::string& surfaceName) const;
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

} // namespace radiant
