#pragma once
// glTF 2.0 (.gltf with embedded, data-URI or external buffers, and .glb) into a Scene.
//
//  - Geometry: every node of the default scene (else scene 0, else every root node) with its
//    transform (matrix or TRS) composed down the hierarchy; triangle primitives, indexed (u8, u16,
//    u32) or not. Units are metres, as glTF defines them.
//  - Faces: vertices inside a flat region of a primitive (and on a straight line between two flat
//    regions, or on a straight border) are removed and their holes retriangulated in the plane, so
//    a subdivided flat wall or a cylinder's cap keeps only its outline (TriangleMerging.h); then
//    coplanar edge-adjacent triangles that form a convex quad become one quad face, so a wall
//    exported as two triangles is one face.
//  - Surfaces: one per primitive instance, named after its node, else its mesh, else "mesh N";
//    where a mesh has several primitives, "<node>/<material name>"; " (2)", " (3)" ... where a
//    name still repeats; Surface::origin is "mesh M, primitive P".
//  - doubleSided materials: each face is also a reversed twin surface "<name> (back)" right after
//    it (Surface::side), meshed and solved on its own; an emissive one emits from both sides.
//  - Cameras: perspective cameras placed by nodes become Scene::cameras (orthographic: a warning).
//  - KHR_lights_punctual point, spot and directional lights placed by nodes become Scene::lights,
//    converted from candela (lux for directional) at 179 lm/W (GltfLights.h); a light no node places,
//    or one that gives no light, is named in a warning.
//  - External files (buffers, images) resolve against the glTF's own folder only; each must be a
//    regular file within its byteLength and SceneLoadOptions::fileByteBudget (GltfExternalFiles.h).
//    A missing image is a warning, and its material uses reflectance baseColorFactor x 0.5.
//  - Materials: reflectance = baseColorFactor x the mean of baseColorTexture (decoded, sRGB to
//    linear) where there is one; exitance (W/m^2) = emissiveFactor x KHR_materials_emissive_strength.
//    extras.radiant {"reflectance": [r, g, b], "exitance_W_m2": [r, g, b]} overrides either with
//    exact SI values. A primitive without a material gets reflectance 0.5 (with a warning).
//
// Bad input throws RadiantError with one line naming the file and the element; recoverable
// oddities (zero-area triangles, points and lines, reflectance >= 1 clamped to 0.999) are warnings.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct SceneLoadOptions {
    std::size_t triangleBudget = 2'000'000;  ///< refuse (BudgetError, with the numbers) above this
    std::uint64_t fileByteBudget = std::uint64_t{1} << 30;  ///< per file read (glTF, buffer, image)
    /// Remove the vertices of flat regions (exact: the geometry is unchanged); off, every triangle
    /// stays (paired into quads), as exported. Tests compare the two.
    bool groupCoplanarTriangles = true;
};

struct LoadedScene {
    Scene scene;
    std::vector<std::string> warnings;  ///< one line each, already naming file and element (= scene.warnings)
    std::size_t ignoredLights = 0;      ///< KHR_lights_punctual lights not read (unplaced, dark, unknown type), each named in a warning
};

/// Loads a .gltf or .glb file. Scene::name is the path as given.
LoadedScene loadGltf(const std::string& path, const SceneLoadOptions& options = {});

/// Loads a .gltf (JSON text) or .glb (recognised by its "glTF" magic) held in memory, with every
/// check loadGltf makes; `name` stands for the file in errors and becomes Scene::name. Only
/// self-contained files load: external buffer or image URIs are refused (data: URIs and the .glb
/// binary chunk work), so untrusted bytes never open other files.
LoadedScene loadGltfFromMemory(std::span<const unsigned char> bytes, const std::string& name,
                               const SceneLoadOptions& options = {});

} // namespace radiant
