#include "render/display/DisplayModel.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <string>
#include <utility>

#include "radiometry/common/Error.h"
#include "radiometry/scene/EnergyBalance.h"
#include "radiometry/units/Photometry.h"
#include "render/SceneTriangles.h"

namespace radiant::render {
namespace {

double total(const Rgb& b) { return b.x + b.y + b.z; }

/// Below this a band's reflectance says too little of the light arriving there to divide by.
constexpr double kSmallestReflectanceForIlluminance = 1e-3;

/// A surface black in a band shows this instead of a colour-map colour when illuminance is mapped.
constexpr Tint kUnknownValueTint{0.55f, 0.55f, 0.55f, 0.96f};

/// The smallest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k at least `value`: an automatic range that
/// holds still while the solution creeps up, and reads well on the legend.
double roundUpForLegend(double value) {
    if (!(value > 0) || !std::isfinite(value)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (const double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
        if (m * decade >= value * (1 - 1e-9)) return m * decade;
    return 10.0 * decade;
}

} // namespace

Tint addTint(const Tint& a, const Tint& b) {
    const float amount = 1.0f - (1.0f - a.w) * (1.0f - b.w);
    if (amount <= 0.0f) return Tint(0.0f);
    return {(glm::vec3(a) * a.w * (1.0f - b.w) + glm::vec3(b) * b.w) / amount, amount};
}

void DisplayModel::setMesh(const Scene& scene, const PatchMesh& mesh) {
    const std::size_t n = mesh.patches.size();
    patchSurface_.resize(n);
    patchArea_.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        patchSurface_[p] = mesh.patches[p].surface;
        patchArea_[p] = mesh.patches[p].area;
    }
    smoothing_ = findSmoothingGroups(mesh);
    vertexPatch_.assign(smoothing_.vertexCount, 0);
    for (std::size_t p = 0; p < n; ++p)
        for (std::uint8_t k = 0; k < smoothing_.cornerCount[p]; ++k) vertexPatch_[smoothing_.cornerVertex[p][k]] = static_cast<std::uint32_t>(p);
    grids_ = findFaceGrids(scene, mesh);
    hasRadiosity_ = false;
    generation_ = 0;
    shooter_ = -1;
    radiosity_.clear();
    smoothRadiosity_.clear();
    smoothRadiosityStale_ = false;
    changed_.assign(n, 0);
    importance_.assign(n, 0.0);
    importanceShown_.reset();
    automaticKeyW_m2_ = 1.0;
    heldKeyW_m2_ = 0.0;
    dataMaxMemoW_m2_ = 1.0;
    dataMaxStale_ = false;
    setMaterials(scene, /*rekey=*/true);
}

void DisplayModel::setMaterials(const Scene& scene, bool rekey) {
    const EnergyBalance balance = enclosureEnergyBalance(scene, patchSurface_, patchArea_);
    patchEmits_.resize(patchSurface_.size());
    baseColour_.resize(patchSurface_.size());
    patchReflectance_.resize(patchSurface_.size());
    patchExitance_.resize(patchSurface_.size());
    for (std::size_t p = 0; p < patchSurface_.size(); ++p) {
        const Material& material = scene.materials.at(scene.surfaces[patchSurface_[p]].material);
        patchEmits_[p] = material.emits() ? 1 : 0;
        baseColour_[p] = displayColour(material);
        patchReflectance_[p] = material.reflectance;
        patchExitance_[p] = material.exitance.value();
    }
    if (settings_.photometric) dataMaxStale_ = true;  // illuminance depends on the materials
    // A scene that had nothing to key on derives the key anew on any edit.
    if (rekey || !(energyBalanceKeyW_m2_ > 0))
        energyBalanceKeyW_m2_ = balance.anythingEmits ? luminanceOf(balance.meanRadiosityW_m2) : 0.0;
    coloursDirty_ = true;
}

bool DisplayModel::setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter) {
    if (hasRadiosity_ == !radiosityW_m2.empty() && generation == generation_) return false;
    const std::size_t n = patchSurface_.size();
    coloursDirty_ = true;
    generation_ = generation;
    if (radiosityW_m2.empty()) {
        hasRadiosity_ = false;
        radiosity_.clear();
        smoothRadiosity_.clear();
        smoothRadiosityStale_ = false;
        return true;
    }
    if (radiosityW_m2.size() != n)
        throw RadiantError({"display", "radiosity generation " + std::to_string(generation)},
                           std::to_string(radiosityW_m2.size()) + " radiosity values for a mesh of " +
                               std::to_string(n) + " patches");

    // Changed since the last update: visibly, by more than a thousandth of the brightest reflector's
    // radiosity (emitters change by nothing but their own reflected part).
    double brightest = 0;
    for (std::size_t p = 0; p < n; ++p)
        if (!patchEmits_[p]) brightest = std::max({brightest, radiosityW_m2[p].x, radiosityW_m2[p].y, radiosityW_m2[p].z});
    const bool canDiff = radiosity_.size() == n;
    const double changeFloor = 1e-3 * brightest;
    double litArea = 0, litLuminance = 0, maxTotal = 0;
    for (std::size_t p = 0; p < n; ++p) {
        const Rgb& b = radiosityW_m2[p];
        const glm::dvec3 d = canDiff ? glm::abs(b - radiosity_[p]) : glm::dvec3(0.0);
        changed_[p] = std::max({d.x, d.y, d.z}) > changeFloor ? 1 : 0;
        maxTotal = std::max(maxTotal, total(b));
        if (!patchEmits_[p] && luminanceOf(b) > 0) {
            litArea += patchArea_[p];
            litLuminance += patchArea_[p] * luminanceOf(b);
        }
    }
    // Only a shot's reach is tinted: a gathering sweep updates every patch, and the few a late sweep
    // still moves visibly (its front, mid-surface) drew an orange staircase on a converged picture.
    // A shot that changes most of the scene says nothing by its tint either.
    if (shooter < 0 || 2 * static_cast<std::size_t>(std::count(changed_.begin(), changed_.end(), 1)) > n)
        std::fill(changed_.begin(), changed_.end(), 0);
    smoothRadiosityStale_ = true;
    // Before light has bounced, only the emitters are lit: key and range follow them then.
    automaticKeyW_m2_ = litArea > 0 ? litLuminance / litArea : std::max(maxTotal / 3.0, 1e-30);
    dataMaxStale_ = true;
    radiosity_.assign(radiosityW_m2.begin(), radiosityW_m2.end());
    hasRadiosity_ = true;
    shooter_ = shooter;
    ++updates_;
    return true;
}

void DisplayModel::setImportance(std::shared_ptr<const std::vector<double>> importance) {
    if (importance == importanceShown_) return;
    importanceShown_ = std::move(importance);
    const std::vector<double> none;
    const std::vector<double>& values = importanceShown_ ? *importanceShown_ : none;
    const double largest = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
    for (std::size_t p = 0; p < importance_.size(); ++p)
        importance_[p] = p < values.size() && largest > 0 ? values[p] / largest : 0.0;
    if (settings_.showImportance) coloursDirty_ = true;
}

void DisplayModel::setSettings(const DisplaySettings& settings) {
    if (settings.photometric != settings_.photometric && hasRadiosity_) dataMaxStale_ = true;
    settings_ = settings;
    const bool heldButUnset = settings.exposureKey == ExposureKey::Held && heldKeyW_m2_ <= 0;
    if (settings.rekeyCount != rekeysSeen_ || heldButUnset) heldKeyW_m2_ = automaticKeyW_m2_;
    rekeysSeen_ = settings.rekeyCount;
}

double DisplayModel::mappedValue(const Rgb& b, std::size_t patch) const {
    if (!settings_.photometric) return total(b);
    const Rgb& rho = patchReflectance_[patch];
    if (std::min({rho.x, rho.y, rho.z}) < kSmallestReflectanceForIlluminance) return std::nan("");
    // B = M + rho E band by band, for every method's solution (the emitters' own light excluded).
    const Rgb irradiance = (b - patchExitance_[patch]) / rho;
    return illuminanceLux(IrradianceRgb(glm::max(irradiance, Rgb(0.0))));
}

double DisplayModel::dataMaxW_m2() const {
    if (!dataMaxStale_) return dataMaxMemoW_m2_;
    std::vector<std::pair<double, double>> reflectorValues;  // (mapped value, area) of non-emitters
    reflectorValues.reserve(radiosity_.size());
    double reflectorArea = 0, largest = 0;
    for (std::size_t p = 0; p < radiosity_.size(); ++p) {
        const double value = mappedValue(radiosity_[p], p);
        if (!std::isfinite(value)) continue;
        largest = std::max(largest, value);
        if (!patchEmits_[p]) {
            reflectorValues.emplace_back(value, patchArea_[p]);
            reflectorArea += patchArea_[p];
        }
    }
    // The automatic range ends at the 99th area percentile of the reflectors: a few hot patches
    // (beside an emitter, in a corner) would otherwise squash everything else into the bottom of
    // the colour map. Brighter patches show the top colour.
    std::sort(reflectorValues.begin(), reflectorValues.end());
    double percentileValue = 0, area = 0;
    for (const auto& [value, patchAreaM2] : reflectorValues) {
        percentileValue = value;
        area += patchAreaM2;
        if (area >= 0.99 * reflectorArea) break;
    }
    dataMaxMemoW_m2_ = roundUpForLegend(percentileValue > 0 ? percentileValue : largest);
    dataMaxStale_ = false;
    return dataMaxMemoW_m2_;
}

const std::vector<Rgb>& DisplayModel::smoothRadiosity() const {
    if (smoothRadiosityStale_) {
        render::smoothRadiosity(smoothing_, patchArea_, radiosity_, smoothRadiosity_);
        smoothRadiosityStale_ = false;
    }
    return smoothRadiosity_;
}

ColourLegend DisplayModel::legend() const {
    const double top = settings_.falseColourMaxW_m2 > 0 ? static_cast<double>(settings_.falseColourMaxW_m2) : dataMaxW_m2();
    ColourLegend legend = makeLegend(top, settings_.logScale, DisplaySettings::kLogDecades);
    if (settings_.photometric) {
        legend.quantity = kIlluminanceQuantity;
        legend.unit = kIlluminanceUnit;
    }
    return legend;
}

double DisplayModel::exposureKeyW_m2() const {
    switch (settings_.exposureKey) {
    case ExposureKey::EnergyBalance:
        if (energyBalanceKeyW_m2_ > 0) return energyBalanceKeyW_m2_;
        break;  // nothing emits: no balance to key on
    case ExposureKey::Held:
        if (heldKeyW_m2_ > 0) return heldKeyW_m2_;
        break;
    case ExposureKey::Automatic: break;
    }
    return automaticKeyW_m2_;
}

double DisplayModel::exposureScale() const {
    return std::exp2(static_cast<double>(settings_.exposureStops)) * kKeyTone / exposureKeyW_m2();
}

DisplayModel::ColourInputs DisplayModel::colourInputs() const {
    const DisplaySettings& d = settings_;
    return {exposureScale(), d.colourMode, d.logScale, d.falseColourMaxW_m2, d.highlightShooter, d.showImportance, d.shading,
            d.photometric};
}

void DisplayModel::makeTints(const ColourInputs& inputs) {
    const std::size_t n = patchSurface_.size();
    colours_.tint.resize(n);
    bool anyTint = false;
    for (std::size_t p = 0; p < n; ++p) {
        Tint tint(0.0f);
        if (inputs.mode == ColourMode::FalseColour && hasRadiosity_ && !std::isfinite(mappedValue(radiosity_[p], p)))
            tint = addTint(tint, kUnknownValueTint);
        if (inputs.importance) tint = addTint(tint, {1.0f, 0.1f, 0.8f, 0.6f * static_cast<float>(importance_[p])});
        const bool isShooter = inputs.highlight && hasRadiosity_ && static_cast<std::int64_t>(p) == shooter_;
        if (inputs.highlight && hasRadiosity_ && changed_[p]) tint = addTint(tint, {1.0f, 0.55f, 0.15f, 0.22f});
        if (isShooter) tint = addTint(tint, {1.0f, 0.45f, 0.0f, 0.35f});
        colours_.tint[p] = Tint(glm::vec3(tint), tint.w + (isShooter ? 2.0f : 0.0f));
        anyTint |= colours_.tint[p].w > 0.0f;
    }
    colours_.anyTint = anyTint;
}

bool DisplayModel::refreshColours() {
    const ColourInputs inputs = colourInputs();
    if (!coloursDirty_ && inputs == coloursMadeWith_) return false;
    const std::size_t n = patchSurface_.size();
    const double scale = inputs.exposureScale;
    // The colour-map position (alpha) is read only by false colour; the tone-mapped view skips the
    // legend's percentile sort.
    const bool falseColour = inputs.mode == ColourMode::FalseColour;
    const ColourLegend range = falseColour ? legend() : ColourLegend{};
    const auto colourOf = [&](const Rgb& b, std::size_t patch) {
        double value = falseColour ? mappedValue(b, patch) : 0.0;
        if (!std::isfinite(value)) value = 0.0;  // tinted grey (makeTints)
        // False colour shows the map's colour alone (patch.frag.glsl): no tone curve for it.
        if (falseColour) return glm::vec4(0.0f, 0.0f, 0.0f, static_cast<float>(range.position(value)));
        return glm::vec4(toneCurve_(b.x * scale), toneCurve_(b.y * scale), toneCurve_(b.z * scale), 0.0f);
    };
    DisplayColours& c = colours_;
    c.patch.resize(n);
    c.vertex.resize(smoothing_.vertexCount);
    c.smooth = inputs.shading == Shading::Smooth;
    c.falseColour = falseColour && hasRadiosity_;
    if (hasRadiosity_ && inputs.mode != ColourMode::Reflectance) {
        // Only the shading shown.
        if (c.smooth) {
            const std::vector<Rgb>& smooth = smoothRadiosity();
            for (std::size_t v = 0; v < c.vertex.size(); ++v) c.vertex[v] = colourOf(smooth[v], vertexPatch_[v]);
        } else {
            for (std::size_t p = 0; p < n; ++p) c.patch[p] = colourOf(radiosity_[p], p);
        }
    } else {
        for (std::size_t p = 0; p < n; ++p) {
            const glm::vec3 encoded(static_cast<float>(linearToSrgb(baseColour_[p].x)),
                                    static_cast<float>(linearToSrgb(baseColour_[p].y)),
                                    static_cast<float>(linearToSrgb(baseColour_[p].z)));
            c.patch[p] = glm::vec4(encoded, 0.0f);
            for (std::uint8_t k = 0; k < smoothing_.cornerCount[p]; ++k) c.vertex[smoothing_.cornerVertex[p][k]] = c.patch[p];
        }
    }
    makeTints(inputs);
    coloursDirty_ = false;
    coloursMadeWith_ = inputs;
    return true;
}

} // namespace radiant::render
