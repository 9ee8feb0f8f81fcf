#include "app/lessons/SessionFile.h"

#include <nlohmann/json.hpp>

#include "radiometry/solver/Solver.h"

namespace radiant::app::lesson {

namespace {

using Json = nlohmann::ordered_json;

Json triple(const Triple& t) { return Json::array({t[0], t[1], t[2]}); }

} // namespace

std::string sessionText(const SessionState& state, const std::string& savedAt) {
    Json actions = Json::array();
    actions.push_back({{"scene", state.scene}});
    actions.push_back({{"max_patch_area_m2", state.maxPatchAreaM2}});
    actions.push_back({{"method", std::string(methodName(state.method))}});
    actions.push_back({{"tolerance", state.tolerance}});
    actions.push_back({{"link_tolerance", state.linkTolerance}});
    for (const SetMaterial& material : state.materials) {
        Json edit = {{"surface", material.surface}};
        if (material.reflectance) edit["reflectance"] = triple(*material.reflectance);
        if (material.exitanceW_m2) edit["exitance_W_m2"] = triple(*material.exitanceW_m2);
        actions.push_back({{"material", edit}});
    }
    actions.push_back({{"camera",
                        {{"eye", triple(state.camera.eye)},
                         {"target", triple(state.camera.target)},
                         {"fov_deg", state.camera.fieldOfViewDegrees}}}});
    Json display = Json::object();
    if (state.display.colour) display["colour"] = *state.display.colour;
    if (state.display.links) display["links"] = *state.display.links;
    if (state.display.importance) display["importance"] = *state.display.importance;
    if (state.display.wireframe) display["wireframe"] = *state.display.wireframe;
    if (state.display.isolines) display["isolines"] = *state.display.isolines;
    if (state.display.exposureStops) display["exposure_stops"] = *state.display.exposureStops;
    actions.push_back({{"display", display}});
    actions.push_back("run");  // the solution is not saved: it is solved again, to the same tolerance
    if (state.probe) {
        Json probe = {{"point", triple(state.probe->point)}};
        if (state.probe->normal) probe["normal"] = triple(*state.probe->normal);
        if (state.probe->target) probe["target"] = *state.probe->target;
        actions.push_back({{"probe", probe}});
    }
    const Json session = {
        {"title", "Radiant session"},
        {"session", true},
        {"steps",
         Json::array({{{"title", "Saved " + savedAt},
                       {"caption", "The lab as it was saved; the solution is solved again on opening."},
                       {"actions", actions}}})}};
    return session.dump(2) + "\n";
}

} // namespace radiant::app::lesson
