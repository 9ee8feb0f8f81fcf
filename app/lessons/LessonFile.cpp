#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/lessons/Lesson.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app::lesson {

namespace {

using Json = nlohmann::json;

/// Where the reader is, so every message names the file, the step and the action.
class Place {
public:
    explicit Place(std::string file) : file_(std::move(file)) {}
    void enterStep(std::size_t index, const std::string& title) {
        step_ = "step " + std::to_string(index + 1) + (title.empty() ? "" : " ('" + title + "')");
        action_.clear();
    }
    void enterAction(std::size_t index, const std::string& key) {
        action_ = "action " + std::to_string(index + 1) + (key.empty() ? "" : " (" + key + ")");
    }
    void leaveAction() { action_.clear(); }
    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        std::string element = step_;
        for (const std::string& part : {action_, field})
            if (!part.empty()) element += (element.empty() ? "" : ", ") + part;
        throw RadiantError({file_, element}, what);
    }

private:
    std::string file_;
    std::string step_;
    std::string action_;
};

std::string typeName(const Json& value) { return value.type_name(); }

const Json& member(const Place& at, const Json& object, const char* key) {
    const auto found = object.find(key);
    if (found == object.end()) at.fail(key, "missing");
    return *found;
}

std::string text(const Place& at, const Json& value, const std::string& field) {
    if (!value.is_string()) at.fail(field, "expected a string, found " + typeName(value));
    return value.get<std::string>();
}

double number(const Place& at, const Json& value, const std::string& field, double low, double high, bool lowOpen) {
    if (!value.is_number()) at.fail(field, "expected a number, found " + typeName(value));
    const double x = value.get<double>();
    const bool below = lowOpen ? !(x > low) : !(x >= low);
    if (!std::isfinite(x) || below || x > high) {
        std::ostringstream range;
        range << (lowOpen ? "(" : "[") << low << ", " << high << "]";
        std::ostringstream message;
        message << value.dump() << " is outside " << range.str();
        at.fail(field, message.str());
    }
    return x;
}

bool flag(const Place& at, const Json& value, const std::string& field) {
    if (!value.is_boolean()) at.fail(field, "expected true or false, found " + typeName(value));
    return value.get<bool>();
}

Triple triple(const Place& at, const Json& value, const std::string& field, double low, double high) {
    if (!value.is_array() || value.size() != 3) at.fail(field, "expected [x, y, z], found " + value.dump());
    Triple t{};
    for (std::size_t i = 0; i < 3; ++i)
        t[i] = number(at, value[i], field + "[" + std::to_string(i) + "]", low, high, false);
    return t;
}

void rejectUnknownKeys(const Place& at, const Json& object, std::initializer_list<const char*> known) {
    for (const auto& [key, value] : object.items()) {
        bool ok = false;
        for (const char* k : known) ok = ok || key == k;
        if (!ok) {
            std::string list;
            for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
            at.fail(key, "unknown field (expected " + list + ")");
        }
    }
}

/// The scene a step acts on, loaded once per distinct name, with a coarse mesh for locating probe
/// points (the probe's locate() needs patches; their size does not matter for it).
struct CheckedScene {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const PatchMesh> mesh;
};

class SceneCache {
public:
    explicit SceneCache(std::filesystem::path folder) : folder_(std::move(folder)) {}
    const CheckedScene& get(const Place& at, const std::string& name) {
        const auto found = scenes_.find(name);
        if (found != scenes_.end()) return found->second;
        CheckedScene checked;
        try {
            checked.scene = std::make_shared<const Scene>(loadScene(resolve(name)).scene);
            checked.mesh = std::make_shared<const PatchMesh>(meshScene(*checked.scene, MeshingOptions{0.05}));
        } catch (const RadiantError& error) {
            at.fail("scene", error.what());
        }
        return scenes_.emplace(name, std::move(checked)).first->second;
    }
    /// A built-in name stays a name; anything else is a path relative to the lesson's folder.
    [[nodiscard]] std::string resolve(const std::string& name) const {
        for (const std::string& builtin : builtinSceneNames())
            if (builtin == name) return name;
        const std::filesystem::path path(name);
        return path.is_absolute() ? name : (folder_ / path).lexically_normal().string();
    }

private:
    std::filesystem::path folder_;
    std::map<std::string, CheckedScene> scenes_;
};

std::size_t surfaceIn(const Place& at, const CheckedScene* current, const std::string& name, const std::string& field) {
    if (!current) at.fail(field, "names surface '" + name + "' before any step loaded a scene");
    const std::size_t index = current->scene->findSurface(name);
    if (index == Scene::npos) {
        std::string known;
        for (const Surface& surface : current->scene->surfaces)
            known += std::string(known.empty() ? "" : ", ") + "'" + surface.name + "'";
        at.fail(field, "scene '" + current->scene->name + "' has no surface '" + name + "' (it has " + known + ")");
    }
    return index;
}

Action readAction(const Place& at, const Json& json, SceneCache& scenes, const CheckedScene*& current) {
    if (json.is_string()) {
        const std::string word = json.get<std::string>();
        if (word == "run") return Run{};
        if (word == "pause") return Pause{};
        if (word == "reset") return Reset{};
        if (word == "home-camera") return PlaceCamera{.home = true};
        at.fail("", "unknown action '" + word + "' (expected run, pause, reset, home-camera or an object)");
    }
    if (!json.is_object() || json.size() != 1)
        at.fail("", "expected one of \"run\", \"pause\", \"reset\", \"home-camera\" or an object with one key, found " +
                        json.dump());
    const std::string key = json.begin().key();
    const Json& value = json.begin().value();
    if (key == "scene") {
        LoadScene load{text(at, value, key)};
        current = &scenes.get(at, load.scene);
        load.scene = scenes.resolve(load.scene);
        return load;
    }
    if (key == "demo") {
        const std::string demo = text(at, value, key);
        for (const std::string& id : demoIds())
            if (id == demo) return OpenDemo{demo};
        std::string known;
        for (const std::string& id : demoIds()) known += std::string(known.empty() ? "" : ", ") + id;
        at.fail(key, "unknown demo '" + demo + "' (expected " + known + ")");
    }
    if (key == "method") {
        try {
            return SetMethod{parseMethod(text(at, value, key))};
        } catch (const RadiantError& error) {
            at.fail(key, error.detail());
        }
    }
    if (key == "tolerance") return SetTolerance{number(at, value, key, 0, 1, true)};
    if (key == "max_patch_area_m2") return SetMeshing{number(at, value, key, 1e-5, 100, false)};
    if (key == "link_tolerance") return SetLinkTolerance{number(at, value, key, 0, 1, true)};
    if (key == "step") {
        if (!value.is_number_integer() || value.get<long long>() < 1 || value.get<long long>() > 10000)
            at.fail(key, "expected a whole number of steps from 1 to 10000, found " + value.dump());
        return Step{static_cast<std::size_t>(value.get<long long>())};
    }
    if (key == "panel") {
        const std::string panel = text(at, value, key);
        for (const std::string& title : panelTitles())
            if (title == panel) return OpenPanel{panel};
        std::string known;
        for (const std::string& title : panelTitles()) known += std::string(known.empty() ? "" : ", ") + title;
        at.fail(key, "unknown panel '" + panel + "' (expected " + known + ")");
    }
    if (key == "compare" && value.is_boolean()) {
        if (value.get<bool>()) at.fail(key, "true says nothing of B: give {\"method\": ...}, or false to end it");
        return Compare{};
    }
    if (key != "material" && key != "camera" && key != "probe" && key != "display" && key != "compare" &&
        key != "integrals")
        at.fail("", "unknown action '" + key +
                        "' (expected scene, demo, method, tolerance, max_patch_area_m2, link_tolerance, material, "
                        "camera, step, probe, panel, display, compare, integrals, or \"run\", \"pause\", \"reset\", "
                        "\"home-camera\")");
    if (!value.is_object()) at.fail(key, "expected an object, found " + value.dump());
    if (key == "material") {
        rejectUnknownKeys(at, value, {"surface", "reflectance", "exitance_W_m2"});
        SetMaterial material{text(at, member(at, value, "surface"), "surface"), {}, {}};
        surfaceIn(at, current, material.surface, "surface");
        if (value.contains("reflectance")) material.reflectance = triple(at, value["reflectance"], "reflectance", 0, 0.999);
        if (value.contains("exitance_W_m2"))
            material.exitanceW_m2 = triple(at, value["exitance_W_m2"], "exitance_W_m2", 0, 1e9);
        if (!material.reflectance && !material.exitanceW_m2) at.fail("", "sets neither reflectance nor exitance_W_m2");
        return material;
    }
    if (key == "camera") {
        rejectUnknownKeys(at, value, {"eye", "target", "fov_deg"});
        PlaceCamera camera;
        camera.eye = triple(at, member(at, value, "eye"), "eye", -1e6, 1e6);
        camera.target = triple(at, member(at, value, "target"), "target", -1e6, 1e6);
        camera.fieldOfViewDegrees = number(at, member(at, value, "fov_deg"), "fov_deg", 1, 170, false);
        if (camera.eye == camera.target) at.fail("target", "is the eye itself: the camera looks nowhere");
        return camera;
    }
    if (key == "compare") {
        rejectUnknownKeys(at, value, {"method", "patch_area_scale", "view"});
        ComparisonSettings settings;
        try {
            settings.method = parseMethod(text(at, member(at, value, "method"), "method"));
        } catch (const RadiantError& error) {
            at.fail("method", error.detail());
        }
        if (value.contains("patch_area_scale"))
            settings.patchAreaScale = number(at, value["patch_area_scale"], "patch_area_scale", 0.01, 100, false);
        if (value.contains("view")) {
            const std::string view = text(at, value["view"], "view");
            if (view != "side-by-side" && view != "difference")
                at.fail("view", "unknown view '" + view + "' (expected side-by-side or difference)");
            settings.view = view == "difference" ? ComparisonView::Difference : ComparisonView::SideBySide;
        }
        return Compare{settings};
    }
    if (key == "integrals") {
        rejectUnknownKeys(at, value, {"integrand", "method", "theta_cells", "run"});
        SetIntegrals integrals;
        integrals.integrand = text(at, member(at, value, "integrand"), "integrand");
        if (integrals.integrand != "d-omega" && integrals.integrand != "cos-d-omega")
            at.fail("integrand", "unknown integrand '" + integrals.integrand + "' (expected d-omega or cos-d-omega)");
        integrals.method = text(at, member(at, value, "method"), "method");
        if (integrals.method != "riemann" && integrals.method != "uniform-mc" && integrals.method != "cosine-mc")
            at.fail("method", "unknown method '" + integrals.method + "' (expected riemann, uniform-mc or cosine-mc)");
        if (value.contains("theta_cells")) {
            const Json& cells = value["theta_cells"];
            if (!cells.is_number_integer() || cells.get<long long>() < 2 || cells.get<long long>() > 64)
                at.fail("theta_cells", "expected a whole number from 2 to 64, found " + cells.dump());
            if (integrals.method != "riemann") at.fail("theta_cells", "only a Riemann sum has theta cells");
            integrals.thetaCells = static_cast<int>(cells.get<long long>());
        }
        if (value.contains("run")) integrals.run = flag(at, value["run"], "run");
        return integrals;
    }
    if (key == "probe") {
        rejectUnknownKeys(at, value, {"point", "normal", "target"});
        Probe probe;
        probe.point = triple(at, member(at, value, "point"), "point", -1e6, 1e6);
        if (value.contains("normal")) {
            probe.normal = triple(at, value["normal"], "normal", -1, 1);
            const Triple& n = *probe.normal;
            if (n[0] == 0 && n[1] == 0 && n[2] == 0) at.fail("normal", "is zero");
        }
        if (value.contains("target")) {
            probe.target = text(at, value["target"], "target");
            surfaceIn(at, current, *probe.target, "target");
        }
        if (!current) at.fail("point", "a probe before any step loaded a scene");
        const radiant::Probe locator(*current->scene, *current->mesh, nullptr);
        const glm::dvec3 x{probe.point[0], probe.point[1], probe.point[2]};
        // Without a normal, any side the point lies on will do: try both of each axis.
        try {
            if (probe.normal) {
                (void)locator.locate(x, glm::normalize(glm::dvec3{(*probe.normal)[0], (*probe.normal)[1], (*probe.normal)[2]}));
            } else {
                bool found = false;
                std::string firstError;
                for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0),
                                           glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)}) {
                    try {
                        (void)locator.locate(x, n);
                        found = true;
                        break;
                    } catch (const RadiantError& error) {
                        if (firstError.empty()) firstError = error.detail();
                    }
                }
                if (!found) at.fail("point", firstError);
            }
        } catch (const RadiantError& error) {
            at.fail(probe.normal ? "normal" : "point", error.detail());
        }
        return probe;
    }
    {  // display, the last of the known keys
        rejectUnknownKeys(at, value,
                          {"colour", "links", "importance", "wireframe", "isolines", "exposure_stops", "photometric"});
        SetDisplay display;
        if (value.contains("colour")) {
            display.colour = text(at, value["colour"], "colour");
            if (*display.colour != "tone-mapped" && *display.colour != "false-colour" && *display.colour != "reflectance")
                at.fail("colour", "unknown colour '" + *display.colour + "' (expected tone-mapped, false-colour or reflectance)");
        }
        if (value.contains("links")) display.links = flag(at, value["links"], "links");
        if (value.contains("importance")) display.importance = flag(at, value["importance"], "importance");
        if (value.contains("wireframe")) display.wireframe = flag(at, value["wireframe"], "wireframe");
        if (value.contains("isolines")) display.isolines = flag(at, value["isolines"], "isolines");
        if (value.contains("exposure_stops"))
            display.exposureStops = number(at, value["exposure_stops"], "exposure_stops", -20, 20, false);
        if (value.contains("photometric")) display.photometric = flag(at, value["photometric"], "photometric");
        return display;
    }
}

/// "line 3, column 14" of a byte offset, for JSON syntax errors.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

} // namespace

const std::vector<std::string>& panelTitles() {
    static const std::vector<std::string> titles = {"Scene", "Solver",   "Materials", "Display",      "Probe",
                                                    "Hemisphere", "Integrals", "Info", "Lecture demos"};
    return titles;
}

const std::vector<std::string>& demoIds() {
    static const std::vector<std::string> ids = {"point-source",       "diffuse-emitter", "sun",
                                                 "square-solid-angle", "dodecahedron",    "radiance-irradiance"};
    return ids;
}

Lesson parseLesson(const std::string& source, const std::filesystem::path& file) {
    Place at(file.string());
    Json json;
    try {
        json = Json::parse(source);
    } catch (const Json::parse_error& error) {
        // nlohmann's own text quotes the offending input, which may be long: name the place instead.
        throw RadiantError({file.string(), lineAndColumn(source, error.byte > 0 ? error.byte - 1 : 0)},
                           "not valid JSON");
    }
    if (!json.is_object()) at.fail("", "expected an object with \"title\" and \"steps\", found " + typeName(json));
    rejectUnknownKeys(at, json, {"title", "session", "steps"});
    Lesson lesson;
    lesson.file = file;
    if (json.contains("session")) lesson.session = flag(at, json["session"], "session");
    lesson.title = text(at, member(at, json, "title"), "title");
    const Json& steps = member(at, json, "steps");
    if (!steps.is_array() || steps.empty()) at.fail("steps", "expected a list of one or more steps");

    SceneCache scenes(file.parent_path());
    const CheckedScene* current = nullptr;
    for (std::size_t s = 0; s < steps.size(); ++s) {
        const Json& stepJson = steps[s];
        at.enterStep(s, stepJson.is_object() && stepJson.contains("title") && stepJson["title"].is_string()
                            ? stepJson["title"].get<std::string>()
                            : "");
        if (!stepJson.is_object()) at.fail("", "expected an object, found " + typeName(stepJson));
        rejectUnknownKeys(at, stepJson, {"title", "caption", "actions"});
        LessonStep step;
        step.title = text(at, member(at, stepJson, "title"), "title");
        step.caption = text(at, member(at, stepJson, "caption"), "caption");
        if (stepJson.contains("actions")) {
            const Json& actions = stepJson["actions"];
            if (!actions.is_array()) at.fail("actions", "expected a list, found " + typeName(actions));
            for (std::size_t a = 0; a < actions.size(); ++a) {
                const Json& action = actions[a];
                at.enterAction(a, action.is_object() && action.size() == 1 ? action.begin().key()
                                  : action.is_string()                     ? action.get<std::string>()
                                                                           : "");
                step.actions.push_back(readAction(at, action, scenes, current));
                at.leaveAction();
            }
        }
        if (s == 0 && !current) {
            bool opensDemo = false;
            for (const Action& action : step.actions) opensDemo = opensDemo || std::holds_alternative<OpenDemo>(action);
            if (!opensDemo) at.fail("actions", "the first step must load a scene or open a demo");
        }
        lesson.steps.push_back(std::move(step));
    }
    return lesson;
}

std::vector<std::filesystem::path> shippedLessonFiles() {
    std::vector<std::filesystem::path> files;
    const std::string assets = assetDirectory();
    if (assets.empty()) return files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(assets) / "lessons", error))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

Lesson readLesson(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw RadiantError({file.string(), ""}, "cannot open the lesson file");
    std::ostringstream text;
    text << in.rdbuf();
    return parseLesson(text.str(), file);
}

} // namespace radiant::app::lesson
