#include "app/panels/ProbePanel.h"

#include <imgui.h>

#include <cstdio>

#include <glm/geometric.hpp>

#include "app/solver/ThreadPriority.h"
#include "app/ui/Colours.h"
#include "app/ui/SidebarLayout.h"
#include "radiometry/geometry/RayCaster.h"

namespace radiant::app {

/// The ray caster of one scene's geometry, with the scene it references kept alive. Materials edits
/// publish new Scene objects with the same geometry, so one picker serves a whole mesh generation.
struct ProbePanel::Picker {
    explicit Picker(std::shared_ptr<const Scene> s, std::uint64_t generation)
        : scene(std::move(s)), rays(*scene), meshGeneration(generation) {}
    std::shared_ptr<const Scene> scene;
    RayCaster rays;
    std::uint64_t meshGeneration;
};

namespace {

void row(const char* label, const char* unit, const Rgb& v) {
    ui::labelValueRow(label, 6.0f, "%.3g  %.3g  %.3g", v.x, v.y, v.z);
    // A unit that does not fit beside the numbers goes below them rather than past the edge.
    ui::sameLineIfFits(ImGui::CalcTextSize(unit).x);
    ImGui::TextDisabled("%s", unit);
}

void scalarRow(const char* label, const char* format, double value) {
    ui::labelValueRow(label, 10.0f, format, value);
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
}

bool ProbePanel::pick(const glm::dvec3& origin, const glm::dvec3& direction) {
    const std::shared_ptr<const Snapshot> snapshot = live_.current;
    if (!snapshot->scene || !snapshot->mesh) return false;
    if (!picker_ || picker_->meshGeneration != snapshot->meshGeneration)
        picker_ = std::make_shared<const Picker>(snapshot->scene, snapshot->meshGeneration);
    const std::optional<RayHit> hit = picker_->rays.intersect(origin, direction);
    if (!hit) return false;
    // A face seen from behind is probed on its back: the detector faces the viewer.
    const glm::dvec3 normal = glm::dot(hit->normal, direction) > 0 ? -hit->normal : hit->normal;
    pick_ = ProbePick{hit->point, normal, hit->surface, hit->face, snapshot->meshGeneration};
    reading_.reset();
    error_.clear();
    dirty_ = true;
    return true;
}

void ProbePanel::setTarget(std::size_t surface) {
    target_ = surface;
    targetMesh_ = live_.snapshot().meshGeneration;
    dirty_ = true;
}

void ProbePanel::update() {
    const Snapshot& snapshot = live_.snapshot();
    if (job_.valid() && job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        Measured measured = job_.get();
        if (pick_) {
            reading_ = std::move(measured.reading);
            error_ = std::move(measured.error);
            readingGeneration_ = measured.generation;
            measureSeconds_ = measured.seconds;
        }
    }
    if (pick_ && pick_->meshGeneration != snapshot.meshGeneration) {
        pick_.reset();  // the scene or its mesh changed under the point
        reading_.reset();
    }
    if (snapshot.scene && targetMesh_ != snapshot.meshGeneration) {
        target_ = firstEmitter(*snapshot.scene);
        targetMesh_ = snapshot.meshGeneration;
        dirty_ = true;
    }
    if (!pick_ || job_.valid()) return;
    const auto now = std::chrono::steady_clock::now();
    const bool stale = dirty_ || snapshot.generation != readingGeneration_;
    // A new pick is answered at once; a converging solve at most every kRefreshInterval.
    if (stale && (dirty_ || now - lastStart_ >= kRefreshInterval)) startMeasuring(now);
}

bool ProbePanel::busy() const {
    return job_.valid() || (pick_ && (dirty_ || live_.snapshot().generation != readingGeneration_));
}

void ProbePanel::startMeasuring(std::chrono::steady_clock::time_point now) {
    std::shared_ptr<const Snapshot> snapshot = live_.current;
    if (!snapshot->scene || !snapshot->mesh || !picker_ || picker_->meshGeneration != snapshot->meshGeneration)
        return;
    dirty_ = false;
    lastStart_ = now;
    // The gather casts rays to every patch the point sees: tens of milliseconds on a fine mesh, so
    // it runs on a worker that holds the snapshot (scene, mesh, radiosity) alive while it reads.
    job_ = std::async(std::launch::async, [snapshot, picker = picker_, at = *pick_, target = target_] {
        yieldToTheDisplay();  // a fresh thread each time: background work, as the solver's
        Measured measured;
        measured.generation = snapshot->generation;
        const auto start = std::chrono::steady_clock::now();
        try {
            const Probe probe(*snapshot->scene, *snapshot->mesh, &picker->rays);
            measured.reading = probe.measure(at.point, at.normal, snapshot->radiosity, target);
        } catch (const std::exception& e) {
            measured.error = e.what();
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
        ImGui::TextWrapped("Click a surface in the 3D view to place a detector there.");
    } else if (reading_) {
        drawReadings(scene, *reading_);
    } else if (error_.empty()) {
        ImGui::TextDisabled("measuring...");
    }
    if (!error_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, theme::kErrorRed);
        ImGui::TextWrapped("%s", error_.c_str());
        ImGui::PopStyleColor();
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
        ImGui::TextWrapped("Gathers over %zu links on %zu levels of the element tree (Display: Links shows them)",
                           snapshot.focusLinkSegments->size() / 2, snapshot.focusLevels);
    }
}

void ProbePanel::drawReadings(const Scene& scene, const ProbeReading& reading) {
    const Surface& surface = scene.surfaces.at(reading.at.surface);
    const Material& material = scene.materials.at(surface.material);
    ui::labelValueRow("Surface", 6.0f, "%s", surface.name.c_str());
    char patch[32];
    std::snprintf(patch, sizeof patch, "patch %zu", reading.at.patch);
    ui::sameLineIfFits(ImGui::CalcTextSize(patch).x);
    ImGui::TextDisabled("%s", patch);
    row("Point", "m", reading.at.point);
    row("Normal", "", reading.normal);
    ImGui::Spacing();
    ImGui::TextDisabled("per band: red  green  blue");
    row("B", "W/m\xC2\xB2", reading.radiosity.value());
    row("L = B/pi", "W/(m\xC2\xB2 sr)", reading.radiance.value());
    row("E", "W/m\xC2\xB2", reading.irradiance.value());
    row("rho", "", material.reflectance);
    // The radiosity equation at this point: what leaves is what is emitted plus what is reflected.
    row("M + rho E", "W/m\xC2\xB2", material.exitance.value() + material.reflectance * reading.irradiance.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Emitted exitance plus reflected irradiance: equals B once the solve has converged\n"
                          "(up to the patch discretisation: B is interpolated, E is gathered exactly)");
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
