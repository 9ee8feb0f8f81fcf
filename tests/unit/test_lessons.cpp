// Lesson files (docs/lessons.md): every shipped lesson reads and checks, and bad files are refused
// with one line naming the file, the step, the action and the field.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "app/cli/CommandLine.h"
#include "app/lessons/Lesson.h"
#include "app/lessons/SessionFile.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;
using namespace radiant::app::lesson;

namespace {

std::vector<std::filesystem::path> shippedLessons() { return shippedLessonFiles(); }

/// The one-line message parseLesson gives for `text`, or "" when it accepts it.
std::string refusal(const std::string& text) {
    try {
        (void)parseLesson(text, "bad.json");
    } catch (const RadiantError& error) {
        return error.what();
    }
    return "";
}

std::string withAction(const std::string& action) {
    return R"({"title": "t", "steps": [{"title": "first", "caption": "c", "actions": [{"scene": "cornell-box"}, )" +
           action + "]}]}";
}

} // namespace

TEST_SUITE("lessons") {

TEST_CASE("six or more lessons ship, each checks, and each step has a title and a caption") {
    const std::vector<std::filesystem::path> files = shippedLessons();
    CHECK(files.size() >= 6);
    for (const std::filesystem::path& file : files) {
        CAPTURE(file.string());
        const Lesson lesson = readLesson(file);
        CHECK_FALSE(lesson.title.empty());
        CHECK(lesson.steps.size() >= 3);
        for (const LessonStep& step : lesson.steps) {
            CHECK_FALSE(step.title.empty());
            CHECK_FALSE(step.caption.empty());
        }
    }
}

TEST_CASE("a lesson's actions come out as the values the lab plays") {
    const Lesson lesson = parseLesson(
        withAction(R"({"method": "jacobi"}, {"step": 3}, "run", {"material": {"surface": "light", "exitance_W_m2": [1, 2, 3]}},
                      {"probe": {"point": [0.42, 0, 0.12], "target": "light"}}, {"panel": "Probe"},
                      {"display": {"colour": "false-colour", "links": true}}, {"max_patch_area_m2": 0.01})"),
        "lesson.json");
    REQUIRE(lesson.steps.size() == 1);
    const std::vector<Action>& actions = lesson.steps[0].actions;
    REQUIRE(actions.size() == 9);
    CHECK(std::get<LoadScene>(actions[0]).scene == "cornell-box");
    CHECK(std::get<SetMethod>(actions[1]).method == SolverMethod::Jacobi);
    CHECK(std::get<Step>(actions[2]).count == 3);
    CHECK(std::holds_alternative<Run>(actions[3]));
    const SetMaterial& material = std::get<SetMaterial>(actions[4]);
    CHECK(material.surface == "light");
    CHECK_FALSE(material.reflectance);
    CHECK(*material.exitanceW_m2 == Triple{1, 2, 3});
    const app::lesson::Probe& probe = std::get<app::lesson::Probe>(actions[5]);
    CHECK(probe.point == Triple{0.42, 0, 0.12});
    CHECK_FALSE(probe.normal);
    CHECK(*probe.target == "light");
    CHECK(std::get<OpenPanel>(actions[6]).panel == "Probe");
    CHECK(*std::get<SetDisplay>(actions[7]).colour == "false-colour");
    CHECK(*std::get<SetDisplay>(actions[7]).links);
    CHECK(std::get<SetMeshing>(actions[8]).maxPatchAreaM2 == 0.01);
}

TEST_CASE("an integrals action comes out as the Integrals panel's settings, and a bad one is refused naming its field") {
    const Lesson lesson = parseLesson(
        withAction(R"({"integrals": {"integrand": "cos-d-omega", "method": "riemann", "theta_cells": 8, "run": true}},
                      {"integrals": {"integrand": "d-omega", "method": "cosine-mc"}})"),
        "lesson.json");
    const std::vector<Action>& actions = lesson.steps.at(0).actions;
    REQUIRE(actions.size() == 3);
    const SetIntegrals& riemann = std::get<SetIntegrals>(actions[1]);
    CHECK(riemann.integrand == "cos-d-omega");
    CHECK(riemann.method == "riemann");
    CHECK(*riemann.thetaCells == 8);
    CHECK(riemann.run);
    const SetIntegrals& cosine = std::get<SetIntegrals>(actions[2]);
    CHECK(cosine.integrand == "d-omega");
    CHECK_FALSE(cosine.thetaCells);
    CHECK_FALSE(cosine.run);  // set up, not started, unless the lesson says so

    CHECK(refusal(withAction(R"({"integrals": {"integrand": "L", "method": "riemann"}})")) ==
          "bad.json: step 1 ('first'), action 2 (integrals), integrand: unknown integrand 'L' (expected d-omega or "
          "cos-d-omega)");
    CHECK(refusal(withAction(R"({"integrals": {"integrand": "d-omega", "method": "uniform-mc", "theta_cells": 8}})")) ==
          "bad.json: step 1 ('first'), action 2 (integrals), theta_cells: only a Riemann sum has theta cells");
    CHECK(refusal(withAction(R"({"integrals": {"integrand": "d-omega", "method": "riemann", "theta_cells": 65}})")) ==
          "bad.json: step 1 ('first'), action 2 (integrals), theta_cells: expected a whole number from 2 to 64, found 65");
}

TEST_CASE("bad lessons are refused in one line naming the step, the action and the field") {
    // Syntax: the place, not the text (which may be long).
    const std::string syntax = refusal("{\"title\": \"t\",\n \"steps\": [ {\"title\": } ]}");
    CHECK(syntax.find("bad.json: line 2, column 23: not valid JSON") == 0);

    CHECK(refusal(withAction(R"({"method": "jacobbi"})")) ==
          "bad.json: step 1 ('first'), action 2 (method), method: unknown method 'jacobbi' (expected jacobi, "
          "gauss-seidel, progressive, hierarchical or importance)");
    CHECK(refusal(withAction(R"({"material": {"surface": "lamp", "reflectance": [0.5, 0.5, 0.5]}})"))
              .find("bad.json: step 1 ('first'), action 2 (material), surface: scene 'cornell-box' has no surface "
                    "'lamp' (it has 'floor'") == 0);
    CHECK(refusal(withAction(R"({"material": {"surface": "floor", "reflectance": [0.5, 1.5, 0.5]}})")) ==
          "bad.json: step 1 ('first'), action 2 (material), reflectance[1]: 1.5 is outside [0, 0.999]");
    CHECK(refusal(withAction(R"({"step": 0})")) ==
          "bad.json: step 1 ('first'), action 2 (step), step: expected a whole number of steps from 1 to 10000, found 0");
    CHECK(refusal(withAction(R"({"probe": {"point": [0.3, 0.2, 0.3]}})"))
              .find("bad.json: step 1 ('first'), action 2 (probe), point: the point (0.3,0.2,0.3) lies on no surface") == 0);
    CHECK(refusal(withAction(R"({"panel": "Probes"})")).find("action 2 (panel), panel: unknown panel 'Probes'") !=
          std::string::npos);
    CHECK(refusal(withAction(R"({"explode": 1})")).find("action 2 (explode): unknown action 'explode'") != std::string::npos);
    CHECK(refusal(withAction(R"("jump")")).find("action 2 (jump): unknown action 'jump'") != std::string::npos);
    CHECK(refusal(withAction(R"({"camera": {"eye": [0, 0, 0], "target": [0, 0, 0], "fov_deg": 40}})"))
              .find("target: is the eye itself") != std::string::npos);
    CHECK(refusal(withAction(R"({"scene": "no-such-scene.gltf"})")).find("action 2 (scene), scene: ") != std::string::npos);
    CHECK(refusal(R"({"title": "t", "steps": [{"title": "a", "caption": "c", "actions": ["run"]}]})") ==
          "bad.json: step 1 ('a'), actions: the first step must load a scene or open a demo");
    CHECK(refusal(R"({"title": "t", "steps": [{"title": "a", "captoin": "c"}]})") ==
          "bad.json: step 1 ('a'), captoin: unknown field (expected title, caption, actions)");
    CHECK(refusal(R"({"title": "t", "steps": []})") == "bad.json: steps: expected a list of one or more steps");
    CHECK(refusal(R"([1, 2])") == "bad.json: expected an object with \"title\" and \"steps\", found array");
    CHECK(refusal(withAction(R"({"compare": {"method": "progressive", "view": "split"}})")) ==
          "bad.json: step 1 ('first'), action 2 (compare), view: unknown view 'split' (expected side-by-side or difference)");
    CHECK(refusal(withAction(R"({"compare": {"patch_area_scale": 4}})")) ==
          "bad.json: step 1 ('first'), action 2 (compare), method: missing");
    CHECK(refusal(withAction(R"({"compare": {"method": "jacobi", "patch_area_scale": 0}})")) ==
          "bad.json: step 1 ('first'), action 2 (compare), patch_area_scale: 0 is outside [0.01, 100]");
    CHECK(refusal(withAction(R"({"compare": true})")).find("action 2 (compare), compare: true says nothing of B") !=
          std::string::npos);
}

TEST_CASE("a session saved while comparing two methods, in photometric units, reads back as it was") {
    SessionState state;
    state.scene = "cornell-box";
    state.maxPatchAreaM2 = 0.01;
    state.method = SolverMethod::GaussSeidel;
    state.tolerance = 1e-4;
    state.linkTolerance = 1e-4;
    state.camera = {false, {0.28, 0.27, -0.8}, {0.28, 0.27, 0.28}, 39.3};
    state.display.photometric = true;
    state.comparison.settings = app::ComparisonSettings{SolverMethod::Progressive, 4.0, app::ComparisonView::Difference};
    const Lesson read = parseLesson(sessionText(state, "now"), "session.json");
    REQUIRE(read.steps.size() == 1);
    std::optional<app::ComparisonSettings> compared;
    bool photometric = false, comparedBeforeRun = false, ran = false;
    for (const Action& action : read.steps[0].actions) {
        if (const auto* c = std::get_if<Compare>(&action)) {
            compared = c->settings;
            comparedBeforeRun = !ran;
        }
        if (const auto* d = std::get_if<SetDisplay>(&action); d && d->photometric) photometric = *d->photometric;
        ran = ran || std::holds_alternative<Run>(action);
    }
    REQUIRE(compared);
    CHECK(*compared == *state.comparison.settings);
    CHECK(comparedBeforeRun);  // "run" then starts both solvers
    CHECK(photometric);
    // Not comparing: "compare": false, so a lab that is comparing when the session opens stops.
    state.comparison.settings.reset();
    std::size_t ends = 0;
    const Lesson off = parseLesson(sessionText(state, "now"), "session.json");  // held: a range over a temporary's member dangles
    for (const Action& action : off.steps[0].actions)
        if (const auto* c = std::get_if<Compare>(&action)) ends += c->settings ? 0 : 1;
    CHECK(ends == 1);
}

TEST_CASE("`radiant lesson check` exits 0 on the shipped lessons and 2 on a bad one") {
    std::vector<std::string> arguments = {"radiant", "lesson", "check"};
    for (const std::filesystem::path& file : shippedLessons()) arguments.push_back(file.string());
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    CHECK(app::runCommandLine(static_cast<int>(argv.size()), argv.data()) == 0);

    const std::filesystem::path bad = std::filesystem::temp_directory_path() / "radiant-test-bad-lesson.json";
    std::ofstream(bad) << withAction(R"({"step": -2})");
    std::string badPath = bad.string();
    std::string lesson = "lesson", check = "check", radiant = "radiant";
    char* badArgv[] = {radiant.data(), lesson.data(), check.data(), badPath.data()};
    CHECK(app::runCommandLine(4, badArgv) == 2);
    std::filesystem::remove(bad);
}

TEST_CASE("a bad session file is refused in one line") {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "radiant-test-bad-session.json";
    std::ofstream(file) << R"({"title": "Radiant session", "session": "yes", "steps": []})";
    try {
        (void)readLesson(file);
        FAIL("accepted");
    } catch (const RadiantError& error) {
        CHECK(std::string(error.what()) == file.string() + ": session: expected true or false, found string");
    }
    std::filesystem::remove(file);
}

} // TEST_SUITE
