#pragma once
// Materials: every surface of the scene, and for the selected one its reflectance per band (a
// colour picker and numbers, each in [0, 0.999]) and its radiant exitance per band in W/m^2.
// An edit goes to the solver thread as command::SetMaterial: the solve resumes from where it was,
// with the same form factors. Values out of range are refused with a warning, never clamped.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/panels/Panel.h"
#include "app/solver/LiveSolve.h"

namespace radiant::app {

class MaterialsPanel final : public Panel {
public:
    explicit MaterialsPanel(LiveSolve& live) : live_(live) {}

    [[nodiscard]] const char* title() const override { return "Materials"; }
    void draw() override;

    /// Largest reflectance a band accepts: at 1 a closed scene never converges.
    static constexpr double kMaxReflectance = 0.999;

    /// Checks a material edit and, when every band is in range, sends it, and Run when the solve
    /// was running or had converged (it resumes from its current solution); a paused or stepped
    /// solve stays paused. Returns why it was refused, empty when it was sent.
    /// The panel's fields and the lab's tests both go through here.
    static std::string submit(LiveSolve& live, std::size_t surface, const Rgb& reflectance, const Rgb& exitanceW_m2);

private:
    void drawSurfaceList(const Scene& scene);
    void drawEditor(const Scene& scene);
    void loadFrom(const Scene& scene);
    void apply();

    LiveSolve& live_;
    std::size_t selected_ = 0;
    std::uint64_t shownMesh_ = 0;       ///< the mesh generation the selection belongs to
    bool editing_ = false;              ///< the fields hold the user's values, not the snapshot's
    std::array<float, 3> reflectance_{};
    std::array<float, 3> exitance_{};   ///< W/m^2
    std::string refusal_;               ///< why the last edit was not applied
};

} // namespace radiant::app
