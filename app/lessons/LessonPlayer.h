#pragma once
// Plays a lesson on whatever implements LessonStage (the lab; a recording stage in the tests): going
// to a step sets the lab up as the lesson says, whichever way the lecturer came to it. GL-free.
#include <cstddef>
#include <optional>
#include <string>

#include "app/lessons/Lesson.h"
#include "app/solver/SolverCommand.h"
#include "render/DisplaySettings.h"

namespace radiant::app {

/// What a lesson's actions act on. Calls come from the frame loop's thread.
class LessonStage {
public:
    virtual ~LessonStage() = default;
    /// Loads and sends the scene (meshed at the stage's current patch area); throws RadiantError.
    virtual void loadScene(const std::string& nameOrPath) = 0;
    /// Remeshes the shown scene with patches of at most `maxPatchAreaM2`.
    virtual void remesh(double maxPatchAreaM2) = 0;
    /// The scene last loaded (or remeshed) is the one shown, meshed and pickable.
    [[nodiscard]] virtual bool sceneReady() const = 0;
    virtual void openDemo(const std::string& id) = 0;
    virtual void send(SolverCommand command) = 0;
    /// Throws RadiantError when the material is refused (the Materials panel's checks).
    virtual void setMaterial(const lesson::SetMaterial& material) = 0;
    virtual void placeCamera(const lesson::PlaceCamera& camera) = 0;
    /// Picks the probe point; false while the shown scene cannot take it yet (try again next frame).
    virtual bool probe(const lesson::Probe& probe) = 0;
    virtual void openPanel(const std::string& title) = 0;
    virtual render::DisplaySettings& display() = 0;
    /// Starts (or changes) two methods side by side; nullopt ends the comparison.
    virtual void compare(const std::optional<ComparisonSettings>& settings) = 0;
    /// Sets up (and maybe starts) the Integrals panel's hemisphere integral.
    virtual void setIntegrals(const lesson::SetIntegrals& integrals) = 0;
};

class LessonPlayer {
public:
    void open(lesson::Lesson lesson);
    void close();
    [[nodiscard]] bool isOpen() const { return lesson_.has_value(); }
    [[nodiscard]] const lesson::Lesson& lesson() const { return *lesson_; }
    [[nodiscard]] std::size_t step() const { return step_; }
    [[nodiscard]] std::size_t stepCount() const { return lesson_ ? lesson_->steps.size() : 0; }

    /// Goes to a step. From the settled step before it, only the step's own actions run (the solve
    /// goes on from where it is); from anywhere else every step up to it is replayed from the
    /// first, so a jump back shows what the lesson showed there (a comparison a later step began
    /// ends). Out-of-range steps are ignored.
    void goTo(std::size_t step);
    void next() { goTo(step_ + 1); }
    void previous() {
        if (step_ > 0) goTo(step_ - 1);
    }

    /// Runs the pending actions it can this frame: those that need the new scene on screen (camera,
    /// probe, material) wait for it. A refused action stops the step; its message is returned once.
    std::optional<std::string> update(LessonStage& stage);
    /// Every action of the current step has run.
    [[nodiscard]] bool settled() const;

private:
    struct Cursor {
        std::size_t step;
        std::size_t action;
    };
    void advance();
    /// Runs one action; false when it must wait for a later frame.
    bool perform(const lesson::Action& action, LessonStage& stage);

    std::optional<lesson::Lesson> lesson_;
    std::size_t step_ = 0;
    std::optional<Cursor> cursor_;  ///< the next action to run; empty once the step has settled
    bool waitingForScene_ = false;
    int probeAttempts_ = 0;
    bool replayFromStart_ = false;  ///< the next update plays from the first step: undo later steps' comparison
};

} // namespace radiant::app
