#include "app/lessons/LessonPlayer.h"

#include <type_traits>
#include <utility>

#include "radiometry/common/Error.h"

namespace radiant::app {

namespace {

// A probe point waits this many frames for the new scene's picker before the step gives up on it.
constexpr int kProbeAttempts = 600;

render::ColourMode colourMode(const std::string& name) {
    if (name == "false-colour") return render::ColourMode::FalseColour;
    if (name == "reflectance") return render::ColourMode::Reflectance;
    return render::ColourMode::ToneMapped;  // the lesson reader accepts only these three names
}

} // namespace

void LessonPlayer::open(lesson::Lesson lesson) {
    lesson_ = std::move(lesson);
    step_ = 0;
    cursor_ = Cursor{0, 0};
    waitingForScene_ = false;
    probeAttempts_ = 0;
    replayFromStart_ = true;
}

void LessonPlayer::close() {
    lesson_.reset();
    cursor_.reset();
}

void LessonPlayer::goTo(std::size_t step) {
    if (!lesson_ || step >= lesson_->steps.size()) return;
    const bool onward = step == step_ + 1 && settled();
    step_ = step;
    cursor_ = onward ? Cursor{step, 0} : Cursor{0, 0};
    waitingForScene_ = false;
    probeAttempts_ = 0;
    replayFromStart_ = !onward;
}

bool LessonPlayer::settled() const { return !cursor_; }

void LessonPlayer::advance() {
    ++cursor_->action;
    while (cursor_ && cursor_->action >= lesson_->steps[cursor_->step].actions.size()) {
        if (cursor_->step >= step_) {
            cursor_.reset();
        } else {
            cursor_ = Cursor{cursor_->step + 1, 0};
        }
    }
}

bool LessonPlayer::perform(const lesson::Action& action, LessonStage& stage) {
    return std::visit(
        [&](const auto& a) -> bool {
            using A = std::decay_t<decltype(a)>;
            if constexpr (std::is_same_v<A, lesson::LoadScene>) {
                stage.loadScene(a.scene);
                waitingForScene_ = true;
            } else if constexpr (std::is_same_v<A, lesson::SetMeshing>) {
                stage.remesh(a.maxPatchAreaM2);
                waitingForScene_ = true;
            } else if constexpr (std::is_same_v<A, lesson::OpenDemo>) {
                stage.openDemo(a.demo);
            } else if constexpr (std::is_same_v<A, lesson::SetMethod>) {
                stage.send(command::SetMethod{a.method});
            } else if constexpr (std::is_same_v<A, lesson::SetTolerance>) {
                stage.send(command::SetTolerance{a.tolerance});
            } else if constexpr (std::is_same_v<A, lesson::SetLinkTolerance>) {
                stage.send(command::SetLinkTolerance{a.linkTolerance});
            } else if constexpr (std::is_same_v<A, lesson::SetMaterial>) {
                stage.setMaterial(a);
            } else if constexpr (std::is_same_v<A, lesson::PlaceCamera>) {
                stage.placeCamera(a);
            } else if constexpr (std::is_same_v<A, lesson::Run>) {
                stage.send(command::Run{});
            } else if constexpr (std::is_same_v<A, lesson::Pause>) {
                stage.send(command::Pause{});
            } else if constexpr (std::is_same_v<A, lesson::Reset>) {
                stage.send(command::Reset{});
            } else if constexpr (std::is_same_v<A, lesson::Step>) {
                stage.send(command::Step{a.count});
            } else if constexpr (std::is_same_v<A, lesson::Probe>) {
                if (!stage.probe(a)) {
                    if (++probeAttempts_ < kProbeAttempts) return false;
                    throw RadiantError({lesson_->file.string(), "step " + std::to_string(cursor_->step + 1)},
                                       "the probe point could not be picked in the scene shown");
                }
                probeAttempts_ = 0;
            } else if constexpr (std::is_same_v<A, lesson::OpenPanel>) {
                stage.openPanel(a.panel);
            } else if constexpr (std::is_same_v<A, lesson::SetDisplay>) {
                render::DisplaySettings& display = stage.display();
                if (a.colour) display.colourMode = colourMode(*a.colour);
                if (a.links) display.showLinks = *a.links;
                if (a.importance) display.showImportance = *a.importance;
                if (a.wireframe) display.wireframe = *a.wireframe;
                if (a.isolines) display.isolines = *a.isolines;
                if (a.exposureStops) display.exposureStops = static_cast<float>(*a.exposureStops);
                if (a.photometric) display.photometric = *a.photometric;
            } else if constexpr (std::is_same_v<A, lesson::Compare>) {
                stage.compare(a.settings);
            } else if constexpr (std::is_same_v<A, lesson::SetIntegrals>) {
                stage.setIntegrals(a);
            }
            return true;
        },
        action);
}

std::optional<std::string> LessonPlayer::update(LessonStage& stage) {
    if (cursor_ && replayFromStart_) {
        // Steps set the lab up as from a fresh start: a comparison only a later step began (or one
        // left on before the lesson opened) would otherwise stay on screen.
        stage.compare(std::nullopt);
        replayFromStart_ = false;
    }
    while (cursor_) {
        if (waitingForScene_) {
            if (!stage.sceneReady()) return std::nullopt;
            waitingForScene_ = false;
        }
        const std::vector<lesson::Action>& actions = lesson_->steps[cursor_->step].actions;
        if (cursor_->action >= actions.size()) {  // a step without actions
            advance();
            continue;
        }
        try {
            if (!perform(actions[cursor_->action], stage)) return std::nullopt;
        } catch (const RadiantError& error) {
            cursor_.reset();  // the rest of the step would act on a state the lesson did not expect
            return std::string(error.what());
        }
        advance();
    }
    if (lesson_ && lesson_->session) close();  // a session restores the lab and is done
    return std::nullopt;
}

} // namespace radiant::app
