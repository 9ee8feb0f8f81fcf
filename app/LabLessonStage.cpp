#include "app/LabLessonStage.h"

#include <algorithm>
#include <numbers>
#include <optional>
#include <vector>

#include "app/LabScene.h"
#include "app/lessons/Lesson.h"
#include "app/panels/IntegralsPanel.h"
#include "app/panels/MaterialsPanel.h"
#include "app/panels/ProbePanel.h"
#include "app/panels/demos/LectureDemosPanel.h"
#include "app/ui/Sidebar.h"
#include "radiometry/common/Error.h"

namespace radiant::app {

namespace {

/// The shown scene is `scene` as loaded, meshed at `patchArea`: the same name and surfaces (a lesson
/// names a built-in scene or a file; materials may have been edited since, ResetMaterials undoes that).
bool showsAlready(const Snapshot& shown, const Scene& scene, double patchArea) {
    return shown.scene && shown.mesh && shown.scene->name == scene.name &&
           shown.scene->surfaces.size() == scene.surfaces.size() && shown.meshing.maxPatchArea == patchArea;
}

} // namespace

void LabLessonStage::loadScene(const std::string& nameOrPath) {
    std::shared_ptr<const Scene> scene = openScene(nameOrPath);
    demos_.closeDemo();  // the step is about the scene: the 3D view shows it again
    const Snapshot& shown = live_.snapshot();
    // Page Up replays the lesson from its first step, which loads the scene the lab already shows:
    // loading it again recomputed every form factor (a minute of black box on a busy 2-core
    // laptop, the Probe panel reading the old E against a zero B meanwhile). Its materials as
    // loaded are all the load would change; the mesh, form factors and probe point stay.
    if (showsAlready(shown, *scene, patchArea_)) {
        live_.send(command::ResetMaterials{});
        awaitedScene_.reset();
        awaitedAfter_ = shown.meshGeneration - 1;  // ready now
        return;
    }
    awaitedScene_ = std::move(scene);
    awaitedAfter_ = shown.meshGeneration;
    live_.send(command::LoadScene{awaitedScene_, MeshingOptions{patchArea_}});
}

void LabLessonStage::remesh(double maxPatchAreaM2) {
    patchArea_ = maxPatchAreaM2;
    if (const Snapshot& shown = live_.snapshot(); shown.mesh && shown.meshing.maxPatchArea == maxPatchAreaM2) {
        awaitedScene_.reset();
        awaitedAfter_ = shown.meshGeneration - 1;  // meshed so already (a replayed step): nothing to redo
        return;
    }
    awaitedScene_.reset();  // the shown scene, whatever its materials
    awaitedAfter_ = live_.snapshot().meshGeneration;
    live_.send(command::Remesh{MeshingOptions{maxPatchAreaM2}});
}

bool LabLessonStage::sceneReady() const {
    const Snapshot& s = live_.snapshot();
    // The very scene object sent (the solver thread publishes the pointer it was given): a name would
    // also match the lab's own load of the same scene still on its way, whose mesh then replaces
    // the one a probe was picked on.
    return s.scene && s.mesh && s.meshGeneration > awaitedAfter_ && (!awaitedScene_ || s.scene == awaitedScene_);
}

void LabLessonStage::openDemo(const std::string& id) {
    const std::vector<std::string>& ids = lesson::demoIds();
    const auto found = std::find(ids.begin(), ids.end(), id);
    demos_.focus(static_cast<std::size_t>(found - ids.begin()));  // and shows it in the 3D view
    sidebar_.focus("Lecture demos");
}

void LabLessonStage::send(SolverCommand command) { live_.send(std::move(command)); }

void LabLessonStage::setMaterial(const lesson::SetMaterial& edit) {
    const Scene& shown = *live_.snapshot().scene;
    const std::size_t surface = shown.findSurface(edit.surface);
    if (surface == Scene::npos)
        throw RadiantError({shown.name, "material"}, "no surface '" + edit.surface + "' in the scene shown");
    const Material& material = shown.materials[shown.surfaces[surface].material];
    const auto rgb = [](const lesson::Triple& t) { return Rgb(t[0], t[1], t[2]); };
    const std::string refused =
        MaterialsPanel::submit(live_, surface, edit.reflectance ? rgb(*edit.reflectance) : material.reflectance,
                               edit.exitanceW_m2 ? rgb(*edit.exitanceW_m2) : material.exitance.value());
    if (!refused.empty()) throw RadiantError({shown.name, "material '" + edit.surface + "'"}, refused);
}

void LabLessonStage::placeCamera(const lesson::PlaceCamera& place) {
    demos_.closeDemo();  // the camera placed is the scene's
    if (place.home) {
        orbit_ = orbitFromHome(*live_.snapshot().scene, live_.snapshot().rays.get());
        return;
    }
    render::Camera camera;
    camera.eye = {place.eye[0], place.eye[1], place.eye[2]};
    const glm::dvec3 target{place.target[0], place.target[1], place.target[2]};
    camera.forward = glm::normalize(target - camera.eye);
    camera.fieldOfView = Radians(place.fieldOfViewDegrees * std::numbers::pi / 180.0);
    orbit_ = render::OrbitCamera(camera, target);
}

bool LabLessonStage::probe(const lesson::Probe& at) {
    demos_.closeDemo();  // a probed point is shown on the scene
    const glm::dvec3 point{at.point[0], at.point[1], at.point[2]};
    std::vector<glm::dvec3> normals;
    if (at.normal) normals.push_back(glm::normalize(glm::dvec3{(*at.normal)[0], (*at.normal)[1], (*at.normal)[2]}));
    else normals = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
    // A short ray onto the point from its front: the same pick a click there makes.
    for (const glm::dvec3& n : normals) {
        if (!probe_.pick(point + 0.01 * n, -n)) continue;
        const std::optional<ProbePick>& pick = probe_.picked();
        if (!pick || glm::length(pick->point - point) > 1e-3) continue;
        if (at.target) {
            const std::size_t target = live_.snapshot().scene->findSurface(*at.target);
            if (target != Scene::npos) probe_.setTarget(target);
        }
        return true;
    }
    return false;
}

void LabLessonStage::openPanel(const std::string& title) {
    if (title != "Lecture demos") demos_.closeDemo();  // another panel is about the scene
    sidebar_.focus(title);
}

void LabLessonStage::compare(const std::optional<ComparisonSettings>& settings) {
    if (!settings) {
        live_.compare(false);
        return;
    }
    demos_.closeDemo();  // the comparison is of the scene's solutions
    live_.setComparison(*settings);  // changes B while comparing; otherwise what compare(true) starts
    live_.compare(true);
}

void LabLessonStage::setIntegrals(const lesson::SetIntegrals& set) {
    IntegralSettings settings;  // a full run of the panel's default size and seed: the same samples each time
    settings.method = set.method == "riemann"      ? IntegralMethod::Riemann
                      : set.method == "cosine-mc" ? IntegralMethod::CosineMonteCarlo
                                                  : IntegralMethod::UniformMonteCarlo;  // the reader takes only these
    if (set.thetaCells) settings.thetaCells = *set.thetaCells;
    integrals_.select(set.integrand == "d-omega" ? HemisphereIntegrand::SolidAngle
                                                 : HemisphereIntegrand::ProjectedSolidAngle,
                      settings);
    integrals_.run(set.run);
}

} // namespace radiant::app
