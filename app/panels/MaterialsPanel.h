#pragma once
// Materials: every surface of the scene, and for the selected one its reflectance per band (a
// colour picker and numbers, each in [0, 0.999]) and its radiant exitance per band in W/m^2.
// An edit goes to the solver thread as command::SetMaterial: the solve resumes from where it was,
// with the same form factors. Values out of range are refused with a warning, never clamped.
// A point picked with the probe selects its surface; "Reset materials" brings back the scene's
// materials as loaded and restarts the solve. Every edit and reset can be undone (Ctrl+Z, Ctrl+Y:
// MaterialEditHistory).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "app/panels/Panel.h"
#include "app/panels/ProbePanel.h"
#include "app/solver/LiveSolve.h"

namespace radiant::app {

class MaterialsPanel final : public Panel {
public:
    /// `probed` gives the probe's current pick (none: the panel follows no pick).
    using ProbedPoint = std::function<std::optional<ProbePick>()>;
    explicit MaterialsPanel(LiveSolve& live, ProbedPoint probed = {}) : live_(live), probed_(std::move(probed)) {}

    [[nodiscard]] const char* title() const override { return "Materials"; }
    void draw() override;

    /// Largest reflectance a band accepts: at 1 a closed scene never converges.
    static constexpr double kMaxReflectance = 0.999;

    /// Checks a material edit and, when every band is in range, sends it, and Run when the solve
    /// was running or had converged (it resumes from its current solution); a paused or stepped
    /// solve stays paused. Returns why it was refused, empty when it was sent.
    /// The panel's fields and the lab's tests both go through here.
    /// `continuesEdit`: the same gesture as the previous edit (SetMaterial::continuesEdit).
    static std::string submit(LiveSolve& live, std::size_t surface, const Rgb& reflectance, const Rgb& exitanceW_m2,
                              bool continuesEdit = false);
    /// Every material back to the scene's as loaded; the solve restarts from B = E, and runs again
    /// when it was running or had converged. Undoable.
    static void resetMaterials(LiveSolve& live);
    /// Ctrl+Z / Ctrl+Y: undoes or redoes the newest material edit (a whole drag, or a reset) and
    /// resumes the solve as an edit does. Returns what it changed for the status bar ("undid the
    /// edit of Floor"), or empty when there was nothing to undo or redo.
    static std::string undo(LiveSolve& live);
    static std::string redo(LiveSolve& live);
    /// The surface selected for editing.
    [[nodiscard]] std::size_t selected() const { return selected_; }

private:
    void drawSurfaceList(const Scene& scene);
    void drawEditor(const Scene& scene);
    void loadFrom(const Scene& scene);
    void apply(bool continuesEdit);
    void followProbe(const Snapshot& snapshot);
    void drawUndoButtons();

    LiveSolve& live_;
    ProbedPoint probed_;
    std::optional<ProbePick> followed_;  ///< the pick whose surface was last selected
    std::size_t selected_ = 0;
    std::uint64_t shownMesh_ = 0;       ///< the mesh generation the selection belongs to
    bool editing_ = false;              ///< the fields hold the user's values, not the snapshot's
    bool scrollToSelected_ = false;     ///< a pick selected a surface the list may not show
    std::array<float, 3> reflectance_{};
    std::array<float, 3> exitance_{};   ///< W/m^2
    std::string refusal_;               ///< why the last edit was not applied
};

} // namespace radiant::app
