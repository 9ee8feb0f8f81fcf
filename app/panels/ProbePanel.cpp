#include "app/panels/ProbePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "app/cli/ProbeCommandLine.h"
#include "app/solver/SolutionDifference.h"
#include "app/solver/SolveProgress.h"
#include "app/solver/ThreadPriority.h"
#include "app/ui/Colours.h"
#include "app/ui/ComparisonColours.h"
#include "app/ui/SidebarLayout.h"
#include "app/ui/WrappedText.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/units/Photometry.h"

namespace radiant::app {

namespace {

void rgbRow(const char* label, const char* unit, const Rgb& v) {
    ui::labelValueRow(label, 6.0f, "%.3g  %.3g  %.3g", v.x, v.y, v.z);
    // A unit that does not fit beside the numbers goes below them rather than past the edge.
    ui::sameLineIfFits(ImGui::CalcTextSize(unit).x);
    ImGui::TextDisabled("%s", unit);
}

void scalarRow(const char* label, const char* format, double value) {
    ui::labelValueRow(label, 10.0f, format, value);
}

/// "+1.2%": how far the solver's value lies from the reference, relative to the reference.
std::string percentDifference(double solver, double reference) {
    if (!(reference > 0)) return "n/a";
    char text[32];
    std::snprintf(text, sizeof text, "%+.1f%%", 100 * (solver - reference) / reference);
    return text;
}

/// Same reflectances and exitances: a new Scene object from a no-op edit needs no new path tracing.
bool sameMaterials(const Scene& a, const Scene& b) {
    if (a.materials.size() != b.materials.size() || a.surfaces.size() != b.surfaces.size()) return false;
    for (std::size_t m = 0; m < a.materials.size(); ++m)
        if (a.materials[m].reflectance != b.materials[m].reflectance ||
            a.materials[m].exitance.value() != b.materials[m].exitance.value())
            return false;
    for (std::size_t s = 0; s < a.surfaces.size(); ++s)
        if (a.surfaces[s].material != b.surfaces[s].material) return false;
    return true;
}

std::optional<std::size_t> firstEmitter(const Scene& scene) {
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s)
        if (scene.materials.at(scene.surfaces[s].material).emits()) return s;
    return std::nullopt;
}

} // namespace

ProbePanel::ProbePanel(LiveSolve& live) : live_(live) {}

ProbePanel::~ProbePanel() {
    if (job_.valid()) job_.wait();
    pathTraced_.stop();
}

bool ProbePanel::pick(const glm::dvec3& origin, const glm::dvec3& direction) {
    const std::shared_ptr<const Snapshot> snapshot = live_.current;
    if (!snapshot->scene || !snapshot->mesh || !snapshot->rays) return false;
    // The view draws faces from their fronts only (a closed room's near walls are open): a click
    // means the first face it shows, whose front faces the viewer.
    const std::optional<RayHit> hit = snapshot->rays->intersectFront(origin, direction);
    if (!hit) return false;
    pick_ = ProbePick{hit->point, hit->normal, hit->surface, hit->face, snapshot->meshGeneration};
    reading_.reset();
    error_.clear();
    dirty_ = true;
    pathTracedCurrent_ = false;
    copied_ = false;
    return true;
}

void ProbePanel::setTarget(std::size_t surface) {
    target_ = surface;
    targetMesh_ = live_.snapshot().meshGeneration;
    dirty_ = true;
}

void ProbePanel::update() {
    pathTraced_.noteFrameDrawn();
    const Snapshot& snapshot = live_.snapshot();
    if (job_.valid() && job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        Measured measured = job_.get();
        if (pick_) {
            reading_ = std::move(measured.reading);
            error_ = std::move(measured.error);
            readingGeneration_ = measured.generation;
            measureSeconds_ = measured.seconds;
            secondReading_ = std::move(measured.secondReading);
            secondReadingGeneration_ = measured.secondGeneration;
        }
    }
    if (pick_ && pick_->meshGeneration != snapshot.meshGeneration) {
        pick_.reset();  // the scene or its mesh changed under the point
        reading_.reset();
        pathTraced_.stop();
        pathTracedCurrent_ = false;
    }
    followPathTraced(live_.current);
    if (snapshot.scene && targetMesh_ != snapshot.meshGeneration) {
        target_ = firstEmitter(*snapshot.scene);
        targetMesh_ = snapshot.meshGeneration;
        dirty_ = true;
    }
    if (!pick_ || job_.valid()) return;
    const auto now = std::chrono::steady_clock::now();
    const bool stale =
        dirty_ || snapshot.generation != readingGeneration_ || secondGeneration() != secondReadingGeneration_;
    // A new pick is answered at once; a converging solve at most every refreshInterval().
    if (stale && (dirty_ || now - lastStart_ >= refreshInterval(measureSeconds_))) startMeasuring(now);
}

std::chrono::duration<double> ProbePanel::refreshInterval(double lastMeasureSeconds) {
    return std::max<std::chrono::duration<double>>(kRefreshInterval,
                                                   std::chrono::duration<double>(kMeasureShare * lastMeasureSeconds));
}

bool ProbePanel::busy() const {
    // Not the path tracer: it refines for seconds, and the idle lab's half-second wake-ups show it.
    return job_.valid() || (pick_ && (dirty_ || live_.snapshot().generation != readingGeneration_ ||
                                      secondGeneration() != secondReadingGeneration_));
}

std::uint64_t ProbePanel::secondGeneration() const { return live_.secondCurrent ? live_.secondCurrent->generation : 0; }

void ProbePanel::followPathTraced(const std::shared_ptr<const Snapshot>& snapshot) {
    if (!pick_ || !snapshot->scene || !snapshot->rays || pick_->meshGeneration != snapshot->meshGeneration) return;
    const Scene* running = pathTraced_.scene();
    if (pathTracedCurrent_ && running && (running == snapshot->scene.get() || sameMaterials(*running, *snapshot->scene)))
        return;
    // The scene's one ray caster (the solver thread's), which the worker keeps alive.
    pathTraced_.start(snapshot->scene, snapshot->rays, pick_->point, pick_->normal);
    pathTracedCurrent_ = true;
}

void ProbePanel::startMeasuring(std::chrono::steady_clock::time_point now) {
    std::shared_ptr<const Snapshot> snapshot = live_.current;
    if (!snapshot->scene || !snapshot->mesh || !snapshot->rays || !pick_ || pick_->meshGeneration != snapshot->meshGeneration)
        return;
    dirty_ = false;
    lastStart_ = now;
    // The gather casts rays to every patch the point sees: tens of milliseconds on a fine mesh, so
    // it runs on a worker that holds the snapshot (scene, mesh, radiosity) alive while it reads.
    std::shared_ptr<const Snapshot> second = live_.secondCurrent;
    job_ = std::async(std::launch::async, [snapshot, second, at = *pick_, target = target_] {
        yieldToTheDisplay();  // a fresh thread each time: background work, as the solver's
        Measured measured;
        measured.generation = snapshot->generation;
        const auto start = std::chrono::steady_clock::now();
        try {
            const Probe probe(*snapshot->scene, *snapshot->mesh, snapshot->rays.get());
            measured.reading = probe.measure(at.point, at.normal, snapshot->radiosity, target);
        } catch (const std::exception& e) {
            measured.error = e.what();
        }
        // B's mesh may be another: the same point, located on it (its gather is the same rule's).
        // Before B's first step its radiosity is only the initial guess: nothing to read yet.
        if (second && hasStepped(*second)) {
            measured.secondGeneration = second->generation;
            try {
                const Probe probe(*second->scene, *second->mesh, second->rays.get());
                measured.secondReading = probe.measure(at.point, at.normal, second->radiosity);
            } catch (const std::exception& e) {
                if (measured.error.empty()) measured.error = std::string("B: ") + e.what();
            }
        } else if (second) {
            measured.secondGeneration = second->generation;
        }
        measured.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return measured;
    });
}

void ProbePanel::draw() {
    const Snapshot& snapshot = live_.snapshot();
    if (!snapshot.scene) {
        ImGui::TextDisabled("no scene loaded");
        return;
    }
    const Scene& scene = *snapshot.scene;
    if (!pick_) {
        ui::wrappedText("Click a surface in the 3D view to place a detector there.");
    } else if (reading_) {
        drawReadings(scene, *reading_);
    } else if (error_.empty()) {
        ImGui::TextDisabled("measuring...");
    }
    if (!error_.empty()) {
        ui::wrappedTextColoured(theme::kErrorRed, error_);
    }
    drawTarget(scene);
    if (reading_ && reading_->target) {
        const TargetReading& t = *reading_->target;
        scalarRow("Solid angle", "%.5f sr", t.solidAngle.value());
        scalarRow("Projected s. angle", "%.5f sr", t.projectedSolidAngle.value());
        scalarRow("Form factor", "%.5f", t.formFactor);
        if (t.unoccludedFormFactor > t.formFactor * (1 + 1e-6))
            scalarRow("  without occlusion", "%.5f", t.unoccludedFormFactor);
    }
    if (reading_)
        ImGui::TextDisabled("at solver iteration %zu, gathered in %.0f ms", snapshot.stats.iteration,
                            measureSeconds_ * 1e3);
    if (pick_ && snapshot.focusLinkSegments) {
        // Hierarchical radiosity: the point's irradiance is what its element and each ancestor
        // gathered over their own links, pushed down.
        ImGui::Spacing();
        ui::wrappedText("Gathers over %zu links on %zu levels of the element tree (Display: Links shows them)",
                           snapshot.focusLinkSegments->size() / 2, snapshot.focusLevels);
    }
    // The independent check last: above it, the target's solid angle and form factor fell below
    // the window's bottom at UI scale 1.5 (lesson 02's "What a point sees" is about them).
    if (pick_ && reading_) drawPathTraced(*reading_);
}

void ProbePanel::drawReadings(const Scene& scene, const ProbeReading& reading) {
    const Surface& surface = scene.surfaces.at(reading.at.surface);
    const Material& material = scene.materials.at(surface.material);
    ui::labelValueRow("Surface", 6.0f, "%s", surface.name.c_str());
    char patch[32];
    std::snprintf(patch, sizeof patch, "patch %zu", reading.at.patch);
    ui::sameLineIfFits(ImGui::CalcTextSize(patch).x);
    ImGui::TextDisabled("%s", patch);
    // Six significant digits: typed back into `radiant probe`, the point lies on the surface within
    // its tolerance (and the exact value is one "Copy as command" away).
    const glm::dvec3& p = reading.at.point;
    char point[96];
    std::snprintf(point, sizeof point, "%.6g, %.6g, %.6g", p.x, p.y, p.z);
    ImGui::TextDisabled("Point, m");
    ui::sameLineIfFits(ImGui::CalcTextSize(point).x);
    if (ImGui::GetCursorPosX() < ImGui::GetFontSize() * 6.0f) ImGui::SetCursorPosX(ImGui::GetFontSize() * 6.0f);
    ImGui::TextUnformatted(point);
    rgbRow("Normal", "", reading.normal);
    drawCopyCommand();
    ImGui::Spacing();
    ImGui::TextDisabled("per band: red  green  blue");
    rgbRow("E", "W/m\xC2\xB2", reading.irradiance.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Irradiance gathered at this point: the solver's patch radiosities, each read with the slope\n"
                          "its neighbours on the same face show (limited, its mean kept), seen through\n"
                          "Lambert's exact point-to-polygon form factors, with ray-cast visibility (16 x 16 rays\n"
                          "where a patch is seen in part); on the patches near the point the light the lamps send\n"
                          "is traced to each gather point, so a shadow's edge across a patch is read where it lies");
    rgbRow("rho", "", material.reflectance);
    // The radiosity equation at this point: what leaves is what is emitted plus what is reflected.
    rgbRow("B = M+rho E", "W/m\xC2\xB2", reading.radiosity.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Radiosity leaving this point: its exitance M plus rho times the E gathered here\n"
                          "(a final gather of the solution, so shadows inside a patch read right)");
    rgbRow("L = B/pi", "W/(m\xC2\xB2 sr)", reading.radiance.value());
    rgbRow("B drawn", "W/m\xC2\xB2", reading.interpolatedRadiosity.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Interpolated from the patches' radiosities at their corners, as the 3D view shows it.\n"
                          "It differs from B = M + rho E by the mesh's discretisation error: a finer mesh\n"
                          "(Scene panel) brings them together.");
    rgbRow("B of patch", "W/m\xC2\xB2", reading.patchRadiosity.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The solver's own value for patch %zu, constant over the patch", reading.at.patch);
    if (display_ && display_->photometric) {
        ImGui::Spacing();
        scalarRow("E_v", "%.4g lx", illuminanceLux(reading.irradiance));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Illuminance: 179 lm/W x (0.265 E_r + 0.670 E_g + 0.065 E_b), Radiance's convention");
        scalarRow("L_v", "%.4g cd/m\xC2\xB2", luminanceCdPerM2(reading.radiance));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Luminance: 179 lm/W x (0.265 L_r + 0.670 L_g + 0.065 L_b), Radiance's convention");
    }
    if (live_.secondCurrent) drawComparison(reading, *live_.secondCurrent);
}

void ProbePanel::drawComparison(const ProbeReading& a, const Snapshot& secondSnapshot) {
    ImGui::Spacing();
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme::kSideA), "A");
    ImGui::SameLine(0, 0);
    ImGui::TextDisabled(" and ");
    ImGui::SameLine(0, 0);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme::kSideB), "B");
    ImGui::SameLine(0, 0);
    ImGui::TextDisabled(" at this point (comparison)");
    const Snapshot& firstSnapshot = live_.snapshot();
    if (!hasStepped(firstSnapshot) || !hasStepped(secondSnapshot) || !secondReading_) {
        // Either side's radiosity before its first step is its initial guess, not a solution.
        if (hasStepped(firstSnapshot) && hasStepped(secondSnapshot))
            ImGui::TextDisabled("reading B here...");
        else
            ui::wrappedTextDisabled(
                "waiting for both to step (A: %s; B: %s)", progressLine(firstSnapshot, longWorkDone(live_.thread)).c_str(),
                progressLine(secondSnapshot, live_.second ? longWorkDone(*live_.second) : std::nullopt).c_str());
        return;
    }
    const ProbeReading& b = *secondReading_;
    rgbRow("A: B of patch", "W/m\xC2\xB2", a.patchRadiosity.value());
    rgbRow("B: B of patch", "W/m\xC2\xB2", b.patchRadiosity.value());
    scalarRow("|A - B| / B", "%.3g%%", 100 * relativeDifference(a.patchRadiosity.value(), b.patchRadiosity.value()));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Relative difference of the two solvers' own values for the patch under the point (R+G+B\n"
                          "totals, relative to the larger; the difference view shows this for every patch of the finer\n"
                          "mesh, relative to 1%% of the scene's mean radiosity where both are darker than that)");
    rgbRow("A: M+rho E", "W/m\xC2\xB2", a.radiosity.value());
    rgbRow("B: M+rho E", "W/m\xC2\xB2", b.radiosity.value());
    scalarRow("|A - B| / B", "%.3g%%", 100 * relativeDifference(a.radiosity.value(), b.radiosity.value()));
}

std::string ProbePanel::commandLine() const {
    const Snapshot& snapshot = live_.snapshot();
    if (!pick_ || !snapshot.scene) return {};
    ProbeCommandInputs inputs;
    inputs.scene = snapshot.scene->name;
    inputs.point = pick_->point;
    inputs.normal = pick_->normal;
    if (target_ && *target_ < snapshot.scene->surfaces.size()) inputs.target = snapshot.scene->surfaces[*target_].name;
    inputs.method = snapshot.method;
    inputs.maxPatchArea = snapshot.meshing.maxPatchArea;
    inputs.tolerance = snapshot.tolerance;
    if (methodInfo(snapshot.method).traits.links) inputs.linkTolerance = snapshot.linkTolerance;
    return probeCommandLine(inputs);
}

void ProbePanel::drawCopyCommand() {
    if (ImGui::SmallButton("Copy as command")) {
        const std::string line = commandLine();
        ImGui::SetClipboardText(line.c_str());
        copied_ = true;
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetNextWindowSize({ImGui::GetFontSize() * 30.0f, 0});
        ImGui::BeginTooltip();
        ui::wrappedText("Puts this reading's `radiant probe` line on the clipboard (exact point, method, mesh, "
                           "tolerance):\n%s", commandLine().c_str());
        if (methodInfo(live_.snapshot().method).traits.viewDependent)
            ui::wrappedText("Importance: the command line refines for the scene's home view, not this camera.");
        ImGui::EndTooltip();
    }
    if (copied_) {
        ui::sameLineIfFits(ImGui::CalcTextSize("copied").x);
        ImGui::TextColored(theme::kDoneGreen, "copied");
    }
}

void ProbePanel::drawPathTraced(const ProbeReading& reading) {
    const PathTracedReading::State state = pathTraced_.state();
    ImGui::Spacing();
    ImGui::TextDisabled("Path-traced reference (independent check)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The rendering equation solved at this point by Monte Carlo path tracing: no patches,\n"
                          "no form factors, nothing shared with the radiosity solver but the scene and its rays.\n"
                          "It converges to the exact answer, so 'solver vs path-traced' is the error of the method,\n"
                          "mesh and convergence you chose. +- is one standard error of the path tracer's estimate.");
    if (!state.error.empty()) {
        ui::wrappedTextColoured(theme::kErrorRed, state.error);
        return;
    }
    if (!state.estimate) {
        ImGui::TextDisabled("tracing...");
        return;
    }
    const ReferenceEstimate& e = *state.estimate;
    const auto differenceRow = [](const char* label, const Rgb& solver, const Rgb& reference) {
        ImGui::TextDisabled("%s", label);
        ImGui::SameLine(ImGui::GetFontSize() * 6.0f);
        ImGui::Text("%s  %s  %s", percentDifference(solver.x, reference.x).c_str(),
                    percentDifference(solver.y, reference.y).c_str(), percentDifference(solver.z, reference.z).c_str());
    };
    rgbRow("B traced", "W/m\xC2\xB2", e.radiosity.value());
    rgbRow("E traced", "W/m\xC2\xB2", e.irradiance.value());
    ImGui::TextDisabled("solver vs path-traced:");
    differenceRow("B", reading.radiosity.value(), e.radiosity.value());
    differenceRow("E", reading.irradiance.value(), e.irradiance.value());
    // The stopping rule in the line itself: refining shows what it refines to, a stopped run that
    // it met it (a run that stops short of it, stopped by a new pick, shows neither).
    const double target = 100 * PathTracedReading::kTargetRelativeError;
    char status[64] = "";
    if (state.waitingForStillView)
        std::snprintf(status, sizeof status, ", paused while the view redraws");
    else if (state.refining)
        std::snprintf(status, sizeof status, ", refining to \xC2\xB1%.2f%%", target);
    else if (PathTracedReading::converged(e))
        std::snprintf(status, sizeof status, ", converged (target \xC2\xB1%.2f%%)", target);
    ui::wrappedTextDisabled("\xC2\xB1%.2f%% (one standard error), %.2g paths%s", 100 * e.relativeStandardError(),
                       static_cast<double>(e.samples), status);  // wrapped: the status may not fit beside it
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The path tracer stops once the standard error of E is under %.2f%% in every band: the\n"
                          "differences above show tenths of a percent. It traces on one background thread at the\n"
                          "solver's low priority, and after its first estimate only while the view is still: a\n"
                          "running solve or a moving camera redraws the view, and the view's frames come first.",
                          target);
}

void ProbePanel::drawTarget(const Scene& scene) {
    ImGui::Spacing();
    ImGui::TextDisabled("Target surface");
    ImGui::SetNextItemWidth(-1);
    const char* preview = target_ && *target_ < scene.surfaces.size() ? scene.surfaces[*target_].name.c_str() : "none";
    if (ImGui::BeginCombo("##target", preview)) {
        for (std::size_t s = 0; s < scene.surfaces.size(); ++s)
            if (ImGui::Selectable(scene.surfaces[s].name.c_str(), target_ == s)) setTarget(s);
        ImGui::EndCombo();
    }
}

} // namespace radiant::app
