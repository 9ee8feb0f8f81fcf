#include "radiometry/solver/ProgressiveSolver.h"

#include <chrono>
#include <cmath>

#include <glm/common.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

double bandSum(const Rgb& v) { return v.x + v.y + v.z; }

} // namespace

ProgressiveSolver::ProgressiveSolver(PatchMaterials materials, ShotFormFactors formFactors)
    : materials_(std::move(materials)),
      formFactors_([f = std::move(formFactors), column = std::make_shared<std::vector<double>>()](
                       std::size_t shooter, std::uint32_t shot, std::span<const Rgb>, double, std::span<Rgb> out) {
          column->resize(out.size());
          f(shooter, shot, *column);
          for (std::size_t j = 0; j < out.size(); ++j) out[j] = Rgb((*column)[j]);
      }) {
    shooters_ = ProgressiveShooters::eachPatch(materials_.size());
    prepareShooters();
}

ProgressiveSolver::ProgressiveSolver(PatchMaterials materials, ProgressiveShooters shooters,
                                     GroupShotFormFactors formFactors)
    : materials_(std::move(materials)), shooters_(std::move(shooters)), formFactors_(std::move(formFactors)) {
    prepareShooters();
}

void ProgressiveSolver::prepareShooters() {
    if (shooters_.members.size() != materials_.size())
        throw RadiantError({"progressive solver", "shooters"},
                           "the shooter groups hold " + std::to_string(shooters_.members.size()) +
                               " patches, the mesh has " + std::to_string(materials_.size()));
    shooterArea_.assign(shooters_.size(), 0.0);
    for (std::size_t g = 0; g < shooters_.size(); ++g)
        for (const std::uint32_t i : shooters_.group(g)) shooterArea_[g] += materials_.area[i];
    reset();
}

void ProgressiveSolver::reset() {
    radiosity_ = materials_.source;
    unshot_ = materials_.source;
    irradiance_.assign(materials_.size(), Rgb(0.0));
    timesShot_.assign(shooters_.size(), 0);
    stats_ = {};
    lastGroup_ = -1;
    rescan();
}

void ProgressiveSolver::rescan() {
    Rgb unshotPower(0.0), unshotMagnitude(0.0);
    nextShooter_ = 0;
    nextShooterPower_ = 0;
    // A group is chosen by the magnitudes of its patches, not of their sum: positive and negative
    // light (after a material edit) in one group must not hide each other from the residual.
    for (std::size_t g = 0; g < shooters_.size(); ++g) {
        double groupMagnitude = 0;
        for (const std::uint32_t i : shooters_.group(g)) {
            const Rgb magnitude = materials_.area[i] * glm::abs(unshot_[i]);
            unshotPower += materials_.area[i] * unshot_[i];
            unshotMagnitude += magnitude;
            groupMagnitude += bandSum(magnitude);
        }
        if (groupMagnitude > nextShooterPower_) {
            nextShooterPower_ = groupMagnitude;
            nextShooter_ = g;
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
        const Rgb updated = materials_.source[i] + materials_.reflectance[i] * irradiance_[i];
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
        const std::size_t group = nextShooter_;
        lastGroup_ = static_cast<std::int64_t>(group);
        // The group's mean unshot radiosity times F_{j -> group} per band, which weighs each member
        // by its share of that band's power (ProgressiveShot.cpp): the light leaves from where it
        // is, in the colour it has there.
        Rgb power(0.0);
        double brightest = -1;
        memberPower_.clear();
        for (const std::uint32_t i : shooters_.group(group)) {
            power += materials_.area[i] * unshot_[i];
            const double magnitude = materials_.area[i] * bandSum(glm::abs(unshot_[i]));
            memberPower_.push_back(materials_.area[i] * glm::abs(unshot_[i]) / nextShooterPower_);
            if (magnitude > brightest) {
                brightest = magnitude;
                stats_.shooter = static_cast<std::int64_t>(i);
            }
            unshot_[i] = Rgb(0.0);
        }
        toShooter_.assign(materials_.size(), Rgb(0.0));
        const double emitted = bandSum(materials_.emittedPower());
        formFactors_(group, timesShot_[group]++, memberPower_, emitted > 0 ? nextShooterPower_ / emitted : 1.0, toShooter_);
        const Rgb shot = shooterArea_[group] > 0 ? power / shooterArea_[group] : Rgb(0.0);
        for (std::size_t j = 0; j < toShooter_.size(); ++j) {
            if (toShooter_[j] == Rgb(0.0)) continue;
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

std::unique_ptr<ProgressiveSolver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh,
                                                         const SolverOptions& options,
                                                         const ProgressiveOptions& progressive) {
    const std::size_t block = progressive.shooterBlock > 0
                                  ? progressive.shooterBlock
                                  : blockForShooterCount(mesh.size(), progressive.shooterCount);
    ProgressiveShooters shooters = blockShooters(mesh, block);
    GroupShotFormFactors formFactors = makeRayCastGroupShotFormFactors(scene, mesh, shooters, options);
    return std::make_unique<ProgressiveSolver>(PatchMaterials::from(scene, mesh, options.rays.get()), std::move(shooters),
                                               std::move(formFactors));
}

std::unique_ptr<Solver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                              Progress*) {
    return makeProgressiveSolver(scene, mesh, options, ProgressiveOptions{});
}

} // namespace radiant
