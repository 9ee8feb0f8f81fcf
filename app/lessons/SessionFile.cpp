#include "app/lessons/SessionFile.h"

#include <ctime>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app::lesson {

namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson triple(const Triple& t) { return OrderedJson::array({t[0], t[1], t[2]}); }

} // namespace

std::string sessionText(const SessionState& state, const std::string& savedAt) {
    OrderedJson actions = OrderedJson::array();
    actions.push_back({{"scene", state.scene}});
    actions.push_back({{"max_patch_area_m2", state.maxPatchAreaM2}});
    actions.push_back({{"method", std::string(methodName(state.method))}});
    actions.push_back({{"tolerance", state.tolerance}});
    actions.push_back({{"link_tolerance", state.linkTolerance}});
    for (const SetMaterial& material : state.materials) {
        OrderedJson edit = {{"surface", material.surface}};
        if (material.reflectance) edit["reflectance"] = triple(*material.reflectance);
        if (material.exitanceW_m2) edit["exitance_W_m2"] = triple(*material.exitanceW_m2);
        actions.push_back({{"material", edit}});
    }
    actions.push_back({{"camera",
                        {{"eye", triple(state.camera.eye)},
                         {"target", triple(state.camera.target)},
                         {"fov_deg", state.camera.fieldOfViewDegrees}}}});
    OrderedJson display = OrderedJson::object();
    if (state.display.colour) display["colour"] = *state.display.colour;
    if (state.display.links) display["links"] = *state.display.links;
    if (state.display.importance) display["importance"] = *state.display.importance;
    if (state.display.wireframe) display["wireframe"] = *state.display.wireframe;
    if (state.display.isolines) display["isolines"] = *state.display.isolines;
    if (state.display.exposureStops) display["exposure_stops"] = *state.display.exposureStops;
    if (state.display.photometric) display["photometric"] = *state.display.photometric;
    actions.push_back({{"display", display}});
    // Before "run", which then starts both solvers (LiveSolve forwards A's commands to B); false ends
    // a comparison the lab may be showing when the session opens.
    if (const std::optional<ComparisonSettings>& c = state.comparison.settings)
        actions.push_back({{"compare",
                            {{"method", std::string(methodName(c->method))},
                             {"patch_area_scale", c->patchAreaScale},
                             {"view", c->view == ComparisonView::Difference ? "difference" : "side-by-side"}}}});
    else
        actions.push_back({{"compare", false}});
    actions.push_back("run");  // the solution is not saved: it is solved again, to the same tolerance
    if (state.probe) {
        OrderedJson probe = {{"point", triple(state.probe->point)}};
        if (state.probe->normal) probe["normal"] = triple(*state.probe->normal);
        if (state.probe->target) probe["target"] = *state.probe->target;
        actions.push_back({{"probe", probe}});
    }
    const OrderedJson session = {
        {"title", "Radiant session"},
        {"session", true},
        {"steps",
         OrderedJson::array({{{"title", "Saved " + savedAt},
                       {"caption", "The lab as it was saved; the solution is solved again on opening."},
                       {"actions", actions}}})}};
    return session.dump(2) + "\n";
}

SessionState captureSession(const Snapshot& shown, const render::Camera& camera, const glm::dvec3& pivot,
                            const std::optional<ProbePick>& pick, const std::optional<std::string>& target,
                            const render::DisplaySettings& display,
                            const std::optional<ComparisonSettings>& comparison) {
    if (!shown.scene) throw RadiantError({"session", ""}, "no scene is shown yet");
    SessionState state;
    bool builtin = false;
    for (const std::string& name : builtinSceneNames()) builtin = builtin || name == shown.scene->name;
    // A file by its absolute path, so the session opens from any folder.
    state.scene = builtin ? shown.scene->name : std::filesystem::absolute(shown.scene->name).lexically_normal().string();
    state.maxPatchAreaM2 = shown.meshing.maxPatchArea;
    state.method = shown.method;
    state.tolerance = shown.tolerance;
    state.linkTolerance = shown.linkTolerance;
    for (const Surface& surface : shown.scene->surfaces) {
        const Material& m = shown.scene->materials[surface.material];
        const Rgb e = m.exitance.value();
        state.materials.push_back(
            {surface.name, Triple{m.reflectance.x, m.reflectance.y, m.reflectance.z}, Triple{e.x, e.y, e.z}});
    }
    state.camera = {false, {camera.eye.x, camera.eye.y, camera.eye.z}, {pivot.x, pivot.y, pivot.z},
                    camera.fieldOfView.value() * 180.0 / std::numbers::pi};
    if (pick)
        state.probe = Probe{{pick->point.x, pick->point.y, pick->point.z},
                            Triple{pick->normal.x, pick->normal.y, pick->normal.z}, target};
    state.display.colour = display.colourMode == render::ColourMode::FalseColour   ? "false-colour"
                           : display.colourMode == render::ColourMode::Reflectance ? "reflectance"
                                                                                   : "tone-mapped";
    state.display.links = display.showLinks;
    state.display.importance = display.showImportance;
    state.display.wireframe = display.wireframe;
    state.display.isolines = display.isolines;
    state.display.exposureStops = display.exposureStops;
    state.display.photometric = display.photometric;
    state.comparison.settings = comparison;
    return state;
}

std::filesystem::path writeSession(const SessionState& state, const std::string& path) {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32], readable[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::strftime(readable, sizeof readable, "%Y-%m-%d %H:%M:%S", &local);
    const std::filesystem::path file =
        path.empty() ? std::filesystem::path("radiant-session-" + std::string(stamp) + ".json") : std::filesystem::path(path);
    std::ofstream out(file);
    if (!out) throw RadiantError({file.string(), ""}, "cannot open for writing");
    out << sessionText(state, readable);
    if (!out) throw RadiantError({file.string(), ""}, "write failed");
    return std::filesystem::absolute(file);
}

} // namespace radiant::app::lesson
