#pragma once
// Undo and redo for material edits (Ctrl+Z, Ctrl+Y): what a lecturer needs after dragging the floor's
// reflectance to show colour bleeding, to put the room back as it was. One entry per gesture (a drag
// or a typed field is one entry however many values it sent), and "Reset materials" is one entry
// too. GL-free and thread-free: it only says which material commands to send; the Materials panel
// and the lab send them. An entry holds each surface's values before and after, so undo and redo
// are plain SetMaterial edits that the solver resumes from, with its form factors kept.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/solver/SolverCommand.h"
#include "radiometry/scene/Scene.h"

namespace radiant::app {

struct MaterialValues {
    Rgb reflectance;
    Rgb exitanceW_m2;
    bool operator==(const MaterialValues&) const = default;
};

class MaterialEditHistory {
public:
    /// Most entries kept: older ones are forgotten first.
    static constexpr std::size_t kMaxEntries = 200;

    /// Forgets everything when `shown` is another scene than the entries were made on (`sceneKey`:
    /// anything that changes with each scene load, e.g. the snapshot's ray caster). Remeshing keeps
    /// surfaces and materials, so the entries stay valid across it.
    void follow(const Scene& shown, const void* sceneKey);

    /// An edit about to be sent: `surface` to `after`. The value before is the last one this history
    /// sent for that surface, else the one `shown` holds. `continuesEdit`: the same gesture as the
    /// previous edit, which then only gets a new "after".
    void recordEdit(const Scene& shown, std::size_t surface, const MaterialValues& after, bool continuesEdit);
    /// "Reset materials" about to be sent: every surface this history has edited goes back to the
    /// scene's own material; undo puts their edited values back.
    void recordReset(const Scene& shown);

    /// The commands that undo the newest entry (empty: nothing to undo), and moves it to the redo list.
    std::vector<SolverCommand> undo();
    /// The commands that redo the newest undone entry (empty: nothing to redo).
    std::vector<SolverCommand> redo();

    [[nodiscard]] bool canUndo() const { return !done_.empty(); }
    [[nodiscard]] bool canRedo() const { return !undone_.empty(); }
    /// What undo / redo would change, for the buttons' tooltips and the status bar: "the edit of
    /// floor", "Reset materials (2 surfaces)"; empty when there is nothing.
    [[nodiscard]] std::string undoLabel() const;
    [[nodiscard]] std::string redoLabel() const;

private:
    struct Change {
        std::size_t surface;
        std::string name;
        MaterialValues before, after;
    };
    struct Entry {
        std::vector<Change> changes;
        bool reset = false;  ///< redone by ResetMaterials (the loaded values are the solver's to know)
    };
    [[nodiscard]] MaterialValues current(const Scene& shown, std::size_t surface) const;
    [[nodiscard]] static std::string label(const Entry& entry);

    const void* sceneKey_ = nullptr;
    std::string sceneName_;
    std::vector<Entry> done_;
    std::vector<Entry> undone_;
    /// Each surface's value as this history last sent it (the snapshot may not show it yet).
    std::map<std::size_t, MaterialValues> sent_;
    bool lastWasEdit_ = false;  ///< the newest entry is an edit a continuing gesture may extend
};

} // namespace radiant::app
