#include "app/solver/LiveSolve.h"

namespace radiant::app {

LiveSolve::~LiveSolve() = default;

void LiveSolve::send(SolverCommand command) {
    if (const auto* load = std::get_if<command::LoadScene>(&command)) {
        sentScene_ = load->scene;
        sentMeshing_ = load->meshing;
    } else if (const auto* remesh = std::get_if<command::Remesh>(&command)) {
        sentMeshing_ = remesh->meshing;
    } else if (const auto* tolerance = std::get_if<command::SetTolerance>(&command)) {
        sentTolerance_ = tolerance->tolerance;
    } else if (const auto* links = std::get_if<command::SetLinkTolerance>(&command)) {
        sentLinkTolerance_ = links->linkTolerance;
    } else if (const auto* grouping = std::get_if<command::SetGrouping>(&command)) {
        groupingSent_ = grouping->mode;
    } else if (const auto* method = std::get_if<command::SetMethod>(&command)) {
        sentMethod_ = method->method;
    } else if (std::holds_alternative<command::Run>(command) || std::holds_alternative<command::Pause>(command)) {
        runSent_ = std::holds_alternative<command::Run>(command);
    }
    if (second)
        if (std::optional<SolverCommand> forB = commandForSecond(command, comparison_, secondCurrent->meshGeneration))
            second->send(std::move(*forB));
    thread.send(std::move(command));
}

void LiveSolve::sendAndResume(SolverCommand command) {
    const bool resume = resumesAfterChange();
    send(std::move(command));
    if (resume) send(command::Run{});
}

bool LiveSolve::refresh() {
    std::shared_ptr<const Snapshot> newest = thread.snapshot();
    const bool changed = newest->generation != current->generation;
    current = std::move(newest);
    if (second) secondCurrent = second->snapshot();
    return changed;
}

void LiveSolve::compare(bool on) {
    if (on == comparing()) return;
    if (!on) {
        second.reset();  // joins the worker; the snapshots it published live on where they are held
        secondCurrent.reset();
        return;
    }
    // The newest state, not this frame's: the lab may turn it on before its first frame took one.
    const std::shared_ptr<const Snapshot> newest = thread.snapshot();
    const Snapshot& a = *newest;
    // B the same as A would show nothing: the lecture's pair instead (Jacobi against Gauss-Seidel).
    const SolverMethod methodA = sentMethod_.value_or(a.method);
    if (comparison_.method == methodA && comparison_.patchAreaScale == 1.0)
        comparison_.method = methodA == SolverMethod::GaussSeidel ? SolverMethod::Jacobi : SolverMethod::GaussSeidel;
    second = std::make_unique<SolverThread>();
    secondCurrent = second->snapshot();
    SolverThread& b = *second;
    b.send(command::SetMethod{comparison_.method});
    b.send(command::SetTolerance{sentTolerance_.value_or(a.tolerance)});
    if (groupingSent_) b.send(command::SetGrouping{*groupingSent_});
    if (const double links = sentLinkTolerance_.value_or(a.linkTolerance); links != SolverOptions{}.linkEpsilon)
        b.send(command::SetLinkTolerance{links});
    // A scene or mesh still queued for A is what B must solve; otherwise A's scene as edited.
    const bool queued = sentScene_ && sentScene_->name != (a.scene ? a.scene->name : "");
    std::shared_ptr<const Scene> scene = queued || !a.scene ? sentScene_ : a.scene;
    MeshingOptions meshing = sentMeshing_ ? *sentMeshing_ : a.meshing;
    meshing.maxPatchArea *= comparison_.patchAreaScale;
    if (scene) b.send(command::LoadScene{scene, meshing});
    thread.send(command::Reset{});
    // A lab that was told to run (and has perhaps converged since) races the two from B = E.
    if (a.running || runSent_) {
        thread.send(command::Run{});
        b.send(command::Run{});
    }
}

void LiveSolve::setComparison(const ComparisonSettings& settings) {
    const ComparisonSettings before = comparison_;
    comparison_ = settings;
    if (!second) return;
    if (settings.method != before.method) second->send(command::SetMethod{settings.method});
    if (settings.patchAreaScale != before.patchAreaScale && (current->mesh || sentMeshing_)) {
        MeshingOptions meshing = sentMeshing_ ? *sentMeshing_ : current->meshing;
        meshing.maxPatchArea *= settings.patchAreaScale;
        second->send(command::Remesh{meshing});
    }
    // A new method or mesh stops B where A may be running: a race started goes on.
    if ((settings.method != before.method || settings.patchAreaScale != before.patchAreaScale) && runSent_)
        second->send(command::Run{});
}

} // namespace radiant::app
