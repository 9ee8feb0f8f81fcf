#include "radiometry/solver/ProgressiveSolver.h"

#include <chrono>
#include <cmath>

#include <glm/common.hpp>

#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

double bandSum(const Rgb& v) { return v.x + v.y + v.z; }

} // namespace

ProgressiveSolver::ProgressiveSolver(PatchMaterials materials, ShotFormFactors formFactors)
    : materials_(std::move(materials)), formFactors_(std::move(formFactors)) {
    reset();
}

void ProgressiveSolver::reset() {
    radiosity_ = materials_.exitance;
    unshot_ = materials_.exitance;
    irradiance_.assign(materials_.size(), Rgb(0.0));
    stats_ = {};
    rescan();
}

void ProgressiveSolver::rescan() {
    Rgb unshotPower(0.0), unshotMagnitude(0.0);
    nextShooter_ = 0;
    nextShooterPower_ = 0;
    for (std::size_t i = 0; i < unshot_.size(); ++i) {
        const Rgb magnitude = materials_.area[i] * glm::abs(unshot_[i]);
        unshotPower += materials_.area[i] * unshot_[i];
        unshotMagnitude += magnitude;
        if (bandSum(magnitude) > nextShooterPower_) {
            nextShooterPower_ = bandSum(magnitude);
            nextShooter_ = i;
        }
    }
    stats_.unshotPower = PowerRgb(unshotPower);
    stats_.residual = fractionOfEmitted(unshotMagnitude, materials_.emittedPower());
}

void ProgressiveSolver::setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) {
    materials_.setSurface(surface, reflectance, exitance);
    // Keep B = E + rho H with the light already gathered (H); the change in B is light that the
    // rest of the scene has not seen yet, so it joins the unshot radiosity (negative if darker).
    for (std::size_t i = materials_.surfaceFirstPatch[surface]; i < materials_.surfaceFirstPatch[surface + 1]; ++i) {
        const Rgb updated = materials_.exitance[i] + materials_.reflectance[i] * irradiance_[i];
        unshot_[i] += updated - radiosity_[i];
        radiosity_[i] = updated;
    }
    rescan();
}

IterationStats ProgressiveSolver::step() {
    const auto start = std::chrono::steady_clock::now();
    stats_.iteration += 1;
    stats_.shooter = -1;
    if (nextShooterPower_ > 0) {
        const std::size_t shooter = nextShooter_;
        stats_.shooter = static_cast<std::int64_t>(shooter);
        toShooter_.assign(materials_.size(), 0.0);
        formFactors_(shooter, toShooter_);
        const Rgb shot = unshot_[shooter];
        unshot_[shooter] = Rgb(0.0);
        for (std::size_t j = 0; j < toShooter_.size(); ++j) {
            if (toShooter_[j] == 0) continue;
            const Rgb received = toShooter_[j] * shot;
            const Rgb reflected = materials_.reflectance[j] * received;
            irradiance_[j] += received;
            radiosity_[j] += reflected;
            unshot_[j] += reflected;
        }
        rescan();
    }
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats_;
}

Rgb ProgressiveSolver::ambient() const {
    Rgb unshotPower(0.0), reflectedArea(0.0);
    double totalArea = 0;
    for (std::size_t i = 0; i < materials_.size(); ++i) {
        unshotPower += materials_.area[i] * unshot_[i];
        reflectedArea += materials_.area[i] * materials_.reflectance[i];
        totalArea += materials_.area[i];
    }
    if (totalArea <= 0) return Rgb(0.0);
    const Rgb meanReflectance = reflectedArea / totalArea;
    return unshotPower / totalArea / (Rgb(1.0) - meanReflectance);
}

std::vector<Rgb> ProgressiveSolver::solutionWithAmbient() const {
    const Rgb ambientRadiosity = ambient();
    std::vector<Rgb> shown(radiosity_.size());
    for (std::size_t i = 0; i < shown.size(); ++i) shown[i] = radiosity_[i] + materials_.reflectance[i] * ambientRadiosity;
    return shown;
}

std::unique_ptr<ProgressiveSolver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh,
                                                         ShotFormFactors formFactors) {
    return std::make_unique<ProgressiveSolver>(PatchMaterials::from(scene, mesh), std::move(formFactors));
}

std::unique_ptr<Solver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                              Progress*) {
    return makeProgressiveSolver(scene, mesh, makeRayCastShotFormFactors(scene, mesh, options));
}

} // namespace radiant
