// Undo and redo of material edits (MaterialEditHistory): which commands each step sends.
#include <doctest/doctest.h>

#include <variant>

#include "app/solver/MaterialEditHistory.h"
#include "radiometry/scene/Scene.h"

using namespace radiant;
using radiant::app::MaterialEditHistory;
using radiant::app::MaterialValues;
namespace command = radiant::app::command;

namespace {

Scene twoSurfaces() {
    Scene scene;
    scene.name = "two";
    scene.materials.push_back(Material{"grey", Rgb(0.5), ExitanceRgb(Rgb(0.0))});
    scene.materials.push_back(Material{"lamp", Rgb(0.0), ExitanceRgb(Rgb(10.0))});
    for (const char* name : {"floor", "lamp"}) {
        Surface surface;
        surface.name = name;
        surface.material = scene.surfaces.empty() ? 0 : 1;
        scene.surfaces.push_back(surface);
    }
    return scene;
}

const command::SetMaterial& setMaterial(const app::SolverCommand& c) {
    REQUIRE(std::holds_alternative<command::SetMaterial>(c));
    return std::get<command::SetMaterial>(c);
}

} // namespace

TEST_CASE("a drag is undone in one step, back to where it began, and redone to where it ended") {
    const Scene scene = twoSurfaces();
    MaterialEditHistory history;
    history.follow(scene, &scene);
    CHECK_FALSE(history.canUndo());
    CHECK(history.undo().empty());
    history.recordEdit(scene, 0, {Rgb(0.4), Rgb(0.0)}, false);
    history.recordEdit(scene, 0, {Rgb(0.3), Rgb(0.0)}, true);
    history.recordEdit(scene, 0, {Rgb(0.2), Rgb(0.0)}, true);
    CHECK(history.undoLabel() == "the edit of floor");

    const auto undone = history.undo();
    REQUIRE(undone.size() == 1);
    CHECK(setMaterial(undone[0]).surface == 0);
    CHECK(setMaterial(undone[0]).reflectance == Rgb(0.5));  // the scene's, before the drag
    CHECK_FALSE(history.canUndo());
    const auto redone = history.redo();
    REQUIRE(redone.size() == 1);
    CHECK(setMaterial(redone[0]).reflectance == Rgb(0.2));  // where the drag ended
    CHECK_FALSE(history.canRedo());
}

TEST_CASE("separate edits undo newest first, and a new edit forgets what was undone") {
    const Scene scene = twoSurfaces();
    MaterialEditHistory history;
    history.follow(scene, &scene);
    history.recordEdit(scene, 0, {Rgb(0.4), Rgb(0.0)}, false);
    history.recordEdit(scene, 1, {Rgb(0.0), Rgb(20.0)}, false);
    // The second edit of the floor starts from the first's value, which the snapshot may not show yet.
    history.recordEdit(scene, 0, {Rgb(0.1), Rgb(0.0)}, false);
    CHECK(setMaterial(history.undo().at(0)).reflectance == Rgb(0.4));
    const auto lamp = history.undo();
    CHECK(setMaterial(lamp.at(0)).surface == 1);
    CHECK(setMaterial(lamp.at(0)).exitance.value() == Rgb(10.0));
    CHECK(history.canRedo());
    history.recordEdit(scene, 1, {Rgb(0.0), Rgb(5.0)}, false);
    CHECK_FALSE(history.canRedo());
    // An edit to the value already there is no edit.
    history.recordEdit(scene, 1, {Rgb(0.0), Rgb(5.0)}, false);
    CHECK(setMaterial(history.undo().at(0)).exitance.value() == Rgb(10.0));
    CHECK(setMaterial(history.undo().at(0)).reflectance == Rgb(0.5));
    CHECK_FALSE(history.canUndo());
}

TEST_CASE("a reset is undone by putting back every edited surface, and redone by resetting again") {
    const Scene scene = twoSurfaces();
    MaterialEditHistory history;
    history.follow(scene, &scene);
    history.recordReset(scene);  // nothing edited: nothing to undo
    CHECK_FALSE(history.canUndo());
    history.recordEdit(scene, 0, {Rgb(0.4), Rgb(0.0)}, false);
    history.recordEdit(scene, 1, {Rgb(0.0), Rgb(20.0)}, false);
    history.recordReset(scene);
    CHECK(history.undoLabel() == "Reset materials (2 surfaces)");
    const auto undone = history.undo();
    REQUIRE(undone.size() == 2);
    CHECK(setMaterial(undone[0]).reflectance == Rgb(0.4));
    CHECK(setMaterial(undone[1]).exitance.value() == Rgb(20.0));
    const auto redone = history.redo();
    REQUIRE(redone.size() == 1);
    CHECK(std::holds_alternative<command::ResetMaterials>(redone[0]));
}

TEST_CASE("another scene forgets the history, remeshing the same scene keeps it") {
    const Scene scene = twoSurfaces();
    MaterialEditHistory history;
    history.follow(scene, &scene);
    history.recordEdit(scene, 0, {Rgb(0.4), Rgb(0.0)}, false);
    history.follow(scene, &scene);
    CHECK(history.canUndo());
    const Scene other = twoSurfaces();
    history.follow(other, &other);
    CHECK_FALSE(history.canUndo());
}
