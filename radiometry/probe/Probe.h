#pragma once
// The point probe: what a small detector lying on a surface at x, facing n, would read.
//
//   B(x)  = M(x) + rho(x) E(x): the radiosity leaving x, from the irradiance gathered at x below (a
//         final gather of the solution: one more bounce, evaluated at the point instead of averaged
//         over a patch, so a shadow edge or a contact corner inside a patch reads right)
//   B_interp(x) radiosity interpolated from the per-patch solution (RadiosityInterpolation.h): what
//         the 3D view shows; it differs from B(x) by the discretisation error of the mesh
//   L(x)  = B(x) / pi, the radiance leaving a diffuse surface
//   E(x)  = sum_j B_j F(dx -> j) V(x, j): irradiance gathered at the exact point. F(dx -> j) is
//         Lambert's exact point-to-polygon form factor; V the visible fraction of patch j seen from
//         x, from stratified rays weighted by the form-factor kernel cos_x cos_j / r^2, so that V F
//         estimates the occluded integral. This is the gather of Wallace, Elmquist & Haines, "A Ray
//         Tracing Algorithm for Progressive Radiosity" (SIGGRAPH 1989), at one point. B_j is read
//         with a slope across the patch (least squares on its neighbours, limited after Barth &
//         Jespersen, AIAA 89-0366), weighted by the kernel's first moment over the same rays: a
//         point near a patch weighs its near side more, where a shadow or a contact makes the
//         radiosity fall steeply.
//   For a target surface: its solid angle (the part above x's horizon, Van Oosterom & Strackee),
//   projected solid angle (integral of cos theta_x d omega) and form factor, each times its visible
//   fraction (rays weighted by the kernel whose integral it corrects).
//   E(x) also holds the scene's punctual lights' direct irradiance at x, each light with one shadow
//   ray (DirectLighting.h): a patch's solution holds their light only averaged over the patch.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchLocator.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/PolygonSamples.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/sources/DirectLighting.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

class RayCaster;

struct ProbeOptions {
    int gatherRaysPerSide = 4;  ///< irradiance: k x k stratified rays to each patch that x sees
    /// irradiance: k x k rays again to a patch the first ones see only in part (Probe.cpp); 0: none
    int partialRaysPerSide = 16;
    /// irradiance: weigh each patch's radiosity with a slope fitted to its neighbours (Probe.cpp)
    /// instead of as a constant; needs the rays above (their points give the kernel's moment)
    bool gatherSlopes = true;
    /// irradiance: within each patch near the point, the light the emitters (in a scene of at most 16
    /// emitting faces) and the lights send to each of the gather's points (shadow rays) in place of the
    /// patch's mean direct part, so a shadow's edge across a patch is read where it lies (Probe.cpp);
    /// needs the rays above
    bool gatherDirect = true;
    int directRaysPerSide = 4;  ///< gatherDirect: k x k rays to each emitting face from each point
    int targetRaysPerSide = 8;  ///< target readings: k x k rays to each patch of the target
    std::uint64_t seed = 1;     ///< the jitter is deterministic for a seed
    /// How far from a face's plane a point may lie and still be on it, relative to the scene's size.
    double onSurfaceTolerance = 1e-4;
};

/// Where on the scene a probe sits.
struct SurfacePoint {
    std::uint32_t surface = 0;
    std::uint32_t face = 0;
    std::size_t patch = 0;
    glm::dvec3 point{0.0};  ///< projected onto the face's plane
};

/// A point moved onto the nearest surface (Probe::snapOntoSurface).
struct SurfaceSnap {
    glm::dvec3 point{0.0};   ///< on the face
    double distance = 0;     ///< m, how far it moved
    std::uint32_t surface = 0;
    /// m: when the point lay farther than the caller's maxDistance from the face but within this,
    /// the face's chord error (ChordError.h), so on the smooth surface a curved tessellation stands
    /// for; 0 when maxDistance took it.
    double chordError = 0;
};

struct TargetReading {
    std::size_t surface = 0;
    std::string name;
    SolidAngle solidAngle{};           ///< visible, above x's horizon, faces seen from either side (sr)
    /// Visible integral of cos theta_x d omega over the target, faces seen from either side (sr):
    /// pi x formFactor when x sees only front faces.
    SolidAngle projectedSolidAngle{};
    double formFactor = 0;             ///< visible F(dx -> target): front faces only (light leaves fronts)
    /// Without occluders, front faces only: a closed target's silhouette counted once.
    SolidAngle unoccludedSolidAngle{};
    double unoccludedFormFactor = 0;
};

struct ProbeReading {
    SurfacePoint at;
    glm::dvec3 normal{0, 0, 1};   ///< unit
    RadiosityRgb radiosity{};     ///< M + rho E at the point, W/m^2
    RadiosityRgb interpolatedRadiosity{};  ///< from the patches' solution, as the 3D view shows it, W/m^2
    RadiosityRgb patchRadiosity{};  ///< the solver's value for the patch under the point, W/m^2
    RadianceRgb radiance{};       ///< B / pi, W/(m^2 sr)
    IrradianceRgb irradiance{};   ///< gathered at the point, W/m^2, the lights' direct part included
    IrradianceRgb directIrradiance{};  ///< the punctual lights' part of it, W/m^2
    std::optional<TargetReading> target;
};

class Probe {
public:
    /// Keeps references: scene, mesh and rays must outlive the probe. rays may be null (no occlusion).
    Probe(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays, const ProbeOptions& options = {});

    /// The face (and patch) whose polygon contains x within the tolerance, preferring the face whose
    /// normal agrees best with n. Throws RadiantError naming the point (and the nearest surface) when
    /// x lies on no surface, or when n points into the surface it lies on.
    [[nodiscard]] SurfacePoint locate(const glm::dvec3& x, const glm::dvec3& n) const;

    /// For a point off every surface (beyond locate's tolerance) but within `maxDistance` (m) of a
    /// face, or within a curved surface's chord error of one of its facets: the nearest point of the
    /// nearest such face (x moved along the face's normal where it lies over the face), which locate
    /// accepts. nullopt when x already lies on a surface, or lies farther than both from every face.
    /// A point typed with a few digits too few (a copied reading) is meant, and so is a point on the
    /// smooth sphere a tessellated one stands for, but not one a millimetre away in mid-air.
    [[nodiscard]] std::optional<SurfaceSnap> snapOntoSurface(const glm::dvec3& x, double maxDistance) const;

    /// Every reading at x with normal n; `radiosity` is the solver's per-patch solution (W/m^2).
    [[nodiscard]] ProbeReading measure(const glm::dvec3& x, const glm::dvec3& n, std::span<const Rgb> radiosity,
                                       std::optional<std::size_t> targetSurface = std::nullopt) const;
    /// The same for a point already located (a ray hit from picking).
    [[nodiscard]] ProbeReading measure(const SurfacePoint& at, const glm::dvec3& n, std::span<const Rgb> radiosity,
                                       std::optional<std::size_t> targetSurface = std::nullopt) const;

    /// E(x) = sum_j F(dx -> j) V(x, j) <B_j>, skipping the patches of x's own face, plus the lights'
    /// direct irradiance at x. <B_j> is patch j's radiosity as x's kernel weighs it: B_j plus a
    /// linear slope across the patch fitted to its neighbours' values (see Probe.cpp).
    [[nodiscard]] IrradianceRgb irradiance(const SurfacePoint& at, const glm::dvec3& n,
                                           std::span<const Rgb> radiosity) const;
    /// Solid angle, projected solid angle and form factor of a surface from x, with visibility.
    [[nodiscard]] TargetReading target(const SurfacePoint& at, const glm::dvec3& n, std::size_t surface) const;

private:
    const Scene& scene_;
    const PatchMesh& mesh_;
    const RayCaster* rays_;
    ProbeOptions options_;
    PatchLocator locator_;
    DirectLighting lighting_;
    double sceneSize_ = 1;
    /// The emitting faces (triangles and quads; larger faces fanned) with their exitance, for
    /// gatherDirect; none in a scene with more than a few (Probe.cpp).
    struct Emitter {
        PatchPolygon polygon;
        Rgb exitance{0.0};
    };
    std::vector<Emitter> emitters_;
    /// Direct irradiance at y (normal n) from the emitters and the punctual lights, with shadow rays.
    [[nodiscard]] Rgb directAt(const glm::dvec3& y, const glm::dvec3& n, std::uint64_t seed,
                               std::vector<PolygonSample>& scratch) const;
    /// directAt at the gather's points of patch j (`atSamples`), and its area-weighted mean.
    [[nodiscard]] Rgb directOverSamples(std::size_t j, std::vector<Rgb>& atSamples, std::vector<PolygonSample>& points,
                                        std::vector<PolygonSample>& scratch) const;
    /// The seed of patch j's gather points (the same for every reading).
    [[nodiscard]] std::uint64_t gatherSeed(std::size_t j) const { return mixBits(options_.seed ^ mixBits(j)); }
    /// Each patch's neighbours for the gather's linear reconstruction (patches of the same surface and
    /// face sharing a corner with it), compressed: patch j's are neighbours_[neighbourFirst_[j] ..
    /// neighbourFirst_[j + 1]).
    std::vector<std::uint32_t> neighbourFirst_;
    std::vector<std::uint32_t> neighbours_;
};

} // namespace radiant
