// A probe point on a curved surface, within its tessellation's chord error, snaps onto the facet below
// it (issue #20 item 8). Closed form: the corners of a UV sphere's facet lie on the sphere (radius R,
// centre C), so the smooth sphere stands off the facet's plane by at most R - n . (v - C), at the foot
// of the perpendicular from C; that is the facet's chord error. Scene: tests/data/curved (a 32 x 16
// UV sphere of radius 0.5 m at (0, 0.7, 0), double-sided, in a closed lit room).
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/cli/ProbeCommandLine.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/ChordError.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"
#include "tests/support/RunRadiant.h"

using namespace radiant;

namespace {

const std::string kSphereRoom = std::string(RADIANT_TEST_DATA_DIR) + "/curved/sphere_room_double_sided.gltf";
const glm::dvec3 kCentre(0.0, 0.7, 0.0);
constexpr double kRadius = 0.5;

glm::dvec3 centroid(const Face& face) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& v : face.vertices) sum += v;
    return sum / static_cast<double>(face.vertices.size());
}

/// The smooth sphere's widest gap over a facet inscribed in it (facing out, or in for the twin).
double exactGap(const Face& face) { return kRadius - std::abs(glm::dot(face.normal, face.vertices[0] - kCentre)); }

} // namespace

TEST_SUITE("probe") {

TEST_CASE("chord error: every facet of a UV sphere within 25% above the smooth sphere's widest gap, flat faces 0") {
    const Scene scene = loadScene(kSphereRoom).scene;
    const std::vector<std::vector<double>> errors = tessellationChordErrors(scene);
    REQUIRE(errors.size() == scene.surfaces.size());
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        CAPTURE(surface.name);
        const bool sphere = surface.name.rfind("sphere", 0) == 0;
        double lowest = 1e300, highest = 0;
        for (std::size_t f = 0; f < surface.faces.size(); ++f) {
            if (!sphere) {
                CHECK(errors[s][f] == 0.0);  // walls, lamp: single flat faces, no curved neighbours
                continue;
            }
            const double ratio = errors[s][f] / exactGap(surface.faces[f]);
            lowest = std::min(lowest, ratio);
            highest = std::max(highest, ratio);
        }
        if (!sphere) continue;
        MESSAGE(surface.name << ": chord error / exact gap in [" << lowest << ", " << highest << "]");
        CHECK(lowest >= 0.999);  // covers every point of the smooth sphere above its facet
        CHECK(highest <= 1.25);
    }
}

TEST_CASE("a point on the smooth sphere is read on the facet below it, not beyond the chord error nor off a flat face") {
    const Scene scene = loadScene(kSphereRoom).scene;
    const PatchMesh mesh = meshScene(scene, MeshingOptions{0.05});
    const Probe probe(scene, mesh, nullptr);
    const std::size_t sphere = scene.findSurface("sphere");
    REQUIRE(sphere != Scene::npos);
    const std::vector<Face>& faces = scene.surfaces[sphere].faces;
    // The top's fan, a facet above the equator, one below, the underside's fan.
    for (const std::size_t f : {std::size_t{0}, faces.size() / 2 - 1, faces.size() / 2 + 5, faces.size() - 1}) {
        const Face& face = faces[f];
        CAPTURE(f);
        // On the smooth sphere, over the facet's centroid: 1 mm to 5 mm off its plane, more than the
        // probe's on-surface tolerance (0.35 mm here) and, mostly, than the command's 1 mm snap.
        const glm::dvec3 direction = glm::normalize(centroid(face) - kCentre);
        const glm::dvec3 x = kCentre + kRadius * direction;
        const double height = glm::dot(face.normal, x - face.vertices[0]);
        REQUIRE(height > 0);
        REQUIRE(height <= exactGap(face));
        CHECK_THROWS_AS((void)probe.locate(x, direction), RadiantError);  // what it did before the snap

        const std::optional<SurfaceSnap> snap = probe.snapOntoSurface(x, 0.0);
        REQUIRE(snap);
        CHECK(snap->surface / 2 == sphere / 2);  // the sphere or its twin: the same facet
        CHECK(glm::length(snap->point - (x - height * face.normal)) < 1e-9);  // along the facet's normal
        CHECK(snap->distance == doctest::Approx(height).scale(0).epsilon(1e-6));
        CHECK(snap->chordError >= snap->distance);
        CHECK(scene.surfaces[probe.locate(snap->point, direction).surface].name == "sphere");
        CHECK(scene.surfaces[probe.locate(snap->point, -direction).surface].name == "sphere (back)");

        // 1 cm off the smooth sphere is a point in mid-air (or inside the ball), not on it.
        CHECK_FALSE(probe.snapOntoSurface(kCentre + (kRadius + 0.01) * direction, 0.0).has_value());
        CHECK_FALSE(probe.snapOntoSurface(kCentre + (kRadius - 0.01) * direction, 0.0).has_value());
    }
    // The floor is flat: 2 mm above it is refused (the command's 1 mm snap aside).
    CHECK_FALSE(probe.snapOntoSurface({0.5, 0.002, 0.5}, 1e-3).has_value());
}

TEST_CASE("probe command: a point typed on the smooth sphere is read on its facet, and the warning says why") {
    const Scene scene = loadScene(kSphereRoom).scene;
    const Face& face = scene.surfaces[scene.findSurface("sphere")].faces[200];
    const glm::dvec3 direction = glm::normalize(centroid(face) - kCentre);
    const glm::dvec3 x = kCentre + kRadius * direction;
    const test::CommandRun run = test::runRadiant("probe '" + kSphereRoom + "' --point=" + app::roundTripVector(x) +
                                                  " --normal=" + app::roundTripVector(direction) +
                                                  " --method=jacobi --max-patch-area=0.25 --tolerance=1e-2 --json=-");
    REQUIRE(run.status == 0);
    const nlohmann::json out = nlohmann::json::parse(run.out);
    CHECK(out["surface"] == "sphere");
    bool warned = false;
    for (const auto& w : out["warnings"]) warned = warned || w.get<std::string>().find("chord error") != std::string::npos;
    CHECK(warned);
    CHECK(run.err.find("chord error") != std::string::npos);
}

} // TEST_SUITE
