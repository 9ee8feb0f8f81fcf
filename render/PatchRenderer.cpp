#include "render/PatchRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <tuple>
#include <vector>

#include "radiometry/common/Error.h"
#include "render/SceneTriangles.h"
#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/TextureBuffer.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {
namespace {

/// What exposure 0 makes of the key radiosity, before the tone curve: a middle tone.
constexpr double kKeyTone = 0.5;

struct PatchVertex {
    glm::vec3 position;  ///< m
    glm::vec3 edge;      ///< barycentric coordinate; 1 everywhere for the edge a quad's split hides
    std::int32_t patch;
    std::int32_t smoothingVertex;  ///< into the per-vertex radiosity
};

enum TextureUnit : GLuint { kVertexRadiosityUnit = 0, kPatchRadiosityUnit = 1, kPatchStyleUnit = 2 };

double luminance(const Rgb& b) { return glm::dot(b, glm::dvec3(0.2126, 0.7152, 0.0722)); }
double total(const Rgb& b) { return b.x + b.y + b.z; }

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

struct PatchRenderer::State {
    gl::ShaderProgram program{"patch.vert.glsl", "patch.frag.glsl"};
    gl::ShaderProgram lineProgram{"wire.vert.glsl", "wire.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
    gl::TextureBuffer vertexRadiosity;  // per smoothing vertex: rgb W/m^2
    gl::TextureBuffer patchRadiosity;   // per patch: rgb W/m^2, a = changed in the last update
    gl::TextureBuffer patchStyle;       // per patch: rgb base colour, a = importance
    gl::Buffer links;
    gl::VertexArray linkLayout;
    GLsizei linkVertexCount = 0;

    DisplaySettings settings;
    bool haveMesh = false;
    std::uint64_t meshGeneration = 0;
    std::uint64_t radiosityGeneration = 0;
    std::uint64_t uploads = 0;
    bool hasRadiosity = false;
    std::int64_t shooter = -1;

    // CPU copies of what the GPU holds, to smooth, diff and re-style without the mesh.
    std::vector<std::uint32_t> patchSurface;
    std::vector<double> patchArea;
    std::vector<std::array<std::uint32_t, 4>> patchSmoothing;  // smoothing vertex per corner
    std::vector<std::uint8_t> patchCorners;
    std::vector<char> patchEmits;
    std::size_t smoothingVertexCount = 0;
    std::vector<Rgb> previousRadiosity;
    std::vector<glm::vec4> style;
    std::vector<glm::vec4> patchTexels;
    std::vector<glm::vec4> vertexTexels;
    double keyW_m2 = 1.0;
    double dataMaxW_m2 = 1.0;  // largest total radiosity of a non-emitter, rounded for the legend

    void uploadStyle() { patchStyle.update(style); }
};

PatchRenderer::PatchRenderer() : state_(std::make_unique<State>()) {
    constexpr std::size_t stride = sizeof(PatchVertex);
    state_->layout.addFloatAttribute(state_->vertices, 0, 3, stride, offsetof(PatchVertex, position));
    state_->layout.addFloatAttribute(state_->vertices, 1, 3, stride, offsetof(PatchVertex, edge));
    state_->layout.addIntAttribute(state_->vertices, 2, stride, offsetof(PatchVertex, patch));
    state_->layout.addIntAttribute(state_->vertices, 3, stride, offsetof(PatchVertex, smoothingVertex));
    state_->linkLayout.addFloatAttribute(state_->links, 0, 3, sizeof(glm::vec3), 0);
    glBindVertexArray(0);
    // Buffer textures must have a store before they are sampled.
    state_->vertexRadiosity.update({});
    state_->patchRadiosity.update({});
    state_->patchStyle.update({});
}

PatchRenderer::~PatchRenderer() = default;
PatchRenderer::PatchRenderer(PatchRenderer&&) noexcept = default;
PatchRenderer& PatchRenderer::operator=(PatchRenderer&&) noexcept = default;

void PatchRenderer::setMesh(const Scene& scene, const PatchMesh& mesh, std::uint64_t meshGeneration) {
    State& s = *state_;
    if (s.haveMesh && meshGeneration == s.meshGeneration) return;
    const std::size_t n = mesh.patches.size();
    s.patchSurface.resize(n);
    s.patchArea.resize(n);
    s.patchSmoothing.assign(n, {});
    s.patchCorners.resize(n);

    // Radiosity is smoothed over the patches that share a vertex AND a plane: surfaces do not share
    // vertices, but one surface's faces may meet at a crease (a block's sides), where light jumps.
    std::map<std::tuple<std::uint32_t, long, long, long>, std::uint32_t> smoothingIds;
    std::vector<PatchVertex> triangles;
    triangles.reserve(n * 6);
    for (std::size_t p = 0; p < n; ++p) {
        const Patch& patch = mesh.patches[p];
        s.patchSurface[p] = patch.surface;
        s.patchArea[p] = patch.area;
        s.patchCorners[p] = patch.cornerCount;
        const glm::dvec3 key = glm::round(patch.normal * 1e4);
        for (std::uint8_t c = 0; c < patch.cornerCount; ++c) {
            const auto [it, added] = smoothingIds.try_emplace(
                {patch.corners[c], std::lround(key.x), std::lround(key.y), std::lround(key.z)},
                static_cast<std::uint32_t>(smoothingIds.size()));
            s.patchSmoothing[p][c] = it->second;
        }
        const auto corner = [&](std::uint8_t c, const glm::vec3& edge) {
            triangles.push_back({glm::vec3(mesh.vertices[patch.corners[c]]), edge, static_cast<std::int32_t>(p),
                                 static_cast<std::int32_t>(s.patchSmoothing[p][c])});
        };
        // Fan about corner 0. Barycentric coordinate k is 1 at the triangle's vertex k and 0 on the
        // edge opposite; for a fan's inner diagonal (not a patch edge) that coordinate is held at 1,
        // so the wireframe and the shooter outline show patch edges only.
        for (std::uint8_t i = 1; i + 1 < patch.cornerCount; ++i) {
            const float diagonalZ = i == 1 ? 0.0f : 1.0f;                      // edge corner 0 - corner i
            const float diagonalY = i + 2 == patch.cornerCount ? 0.0f : 1.0f;  // edge corner 0 - corner i+1
            corner(0, {1, diagonalY, diagonalZ});
            corner(i, {0, 1, diagonalZ});
            corner(static_cast<std::uint8_t>(i + 1), {0, diagonalY, 1});
        }
    }
    s.smoothingVertexCount = smoothingIds.size();
    s.vertices.setData(std::span<const PatchVertex>(triangles));
    s.vertexCount = static_cast<GLsizei>(triangles.size());
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    s.haveMesh = true;
    s.meshGeneration = meshGeneration;
    s.hasRadiosity = false;
    s.radiosityGeneration = 0;
    s.shooter = -1;
    s.previousRadiosity.clear();
    s.keyW_m2 = 1.0;
    s.dataMaxW_m2 = 1.0;
    s.style.assign(n, glm::vec4(0.0f));
    s.linkVertexCount = 0;
    setMaterials(scene);
}

void PatchRenderer::setMaterials(const Scene& scene) {
    State& s = *state_;
    s.patchEmits.resize(s.patchSurface.size());
    for (std::size_t p = 0; p < s.patchSurface.size(); ++p) {
        const std::size_t surface = s.patchSurface[p];
        if (surface >= scene.surfaces.size())
            throw RadiantError({"patch renderer", "patch " + std::to_string(p)},
                               "surface " + std::to_string(surface) + " is not in the scene (" +
                                   std::to_string(scene.surfaces.size()) + " surfaces)");
        const Material& material = scene.materials.at(scene.surfaces[surface].material);
        s.patchEmits[p] = material.emits() ? 1 : 0;
        s.style[p] = glm::vec4(displayColour(material), s.style[p].w);
    }
    s.uploadStyle();
}

void PatchRenderer::setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter) {
    State& s = *state_;
    if (s.hasRadiosity == !radiosityW_m2.empty() && generation == s.radiosityGeneration) return;
    const std::size_t n = s.patchSurface.size();
    if (radiosityW_m2.empty()) {
        s.hasRadiosity = false;
        s.radiosityGeneration = generation;
        s.previousRadiosity.clear();
        return;
    }
    if (radiosityW_m2.size() != n)
        throw RadiantError({"patch renderer", "radiosity generation " + std::to_string(generation)},
                           std::to_string(radiosityW_m2.size()) + " radiosity values for a mesh of " +
                               std::to_string(n) + " patches");

    // Changed since the last upload: more than a millionth of the brightest patch.
    double brightest = 0;
    for (const Rgb& b : radiosityW_m2) brightest = std::max({brightest, b.x, b.y, b.z});
    const bool canDiff = s.previousRadiosity.size() == n;
    const double changeFloor = 1e-6 * brightest;

    s.patchTexels.resize(n);
    std::vector<glm::dvec4> smoothSums(s.smoothingVertexCount, glm::dvec4(0.0));
    double litArea = 0, litLuminance = 0, maxTotal = 0, maxTotalAll = 0;
    for (std::size_t p = 0; p < n; ++p) {
        const Rgb& b = radiosityW_m2[p];
        bool changed = false;
        if (canDiff) {
            const glm::dvec3 d = glm::abs(b - s.previousRadiosity[p]);
            changed = std::max({d.x, d.y, d.z}) > changeFloor;
        }
        s.patchTexels[p] = glm::vec4(glm::vec3(b), changed ? 1.0f : 0.0f);
        for (std::uint8_t c = 0; c < s.patchCorners[p]; ++c)
            smoothSums[s.patchSmoothing[p][c]] += glm::dvec4(b * s.patchArea[p], s.patchArea[p]);
        maxTotalAll = std::max(maxTotalAll, total(b));
        if (!s.patchEmits[p]) {
            maxTotal = std::max(maxTotal, total(b));
            if (luminance(b) > 0) {
                litArea += s.patchArea[p];
                litLuminance += s.patchArea[p] * luminance(b);
            }
        }
    }
    s.vertexTexels.resize(smoothSums.size());
    for (std::size_t v = 0; v < smoothSums.size(); ++v)
        s.vertexTexels[v] = smoothSums[v].w > 0 ? glm::vec4(glm::vec3(glm::dvec3(smoothSums[v]) / smoothSums[v].w), 0.0f)
                                                : glm::vec4(0.0f);
    s.patchRadiosity.update(s.patchTexels);
    s.vertexRadiosity.update(s.vertexTexels);

    // Before light has bounced, only the emitters are lit: key and range follow them then.
    s.keyW_m2 = litArea > 0 ? litLuminance / litArea : std::max(maxTotalAll / 3.0, 1e-30);
    s.dataMaxW_m2 = roundUpForLegend(maxTotal > 0 ? maxTotal : maxTotalAll);
    s.previousRadiosity.assign(radiosityW_m2.begin(), radiosityW_m2.end());
    s.hasRadiosity = true;
    s.radiosityGeneration = generation;
    s.shooter = shooter;
    ++s.uploads;
}

void PatchRenderer::setImportance(std::span<const double> importance) {
    State& s = *state_;
    const double largest = importance.empty() ? 0.0 : *std::max_element(importance.begin(), importance.end());
    for (std::size_t p = 0; p < s.style.size(); ++p)
        s.style[p].w = p < importance.size() && largest > 0 ? static_cast<float>(importance[p] / largest) : 0.0f;
    s.uploadStyle();
}

void PatchRenderer::setLinks(std::span<const glm::vec3> segmentEnds) {
    State& s = *state_;
    s.links.setData(segmentEnds, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    s.linkVertexCount = static_cast<GLsizei>(segmentEnds.size() & ~std::size_t{1});
}

void PatchRenderer::setSettings(const DisplaySettings& settings) { state_->settings = settings; }
const DisplaySettings& PatchRenderer::settings() const { return state_->settings; }

ColourLegend PatchRenderer::legend() const {
    const DisplaySettings& d = state_->settings;
    const double top = d.falseColourMaxW_m2 > 0 ? static_cast<double>(d.falseColourMaxW_m2) : state_->dataMaxW_m2;
    return makeLegend(top, d.logScale, DisplaySettings::kLogDecades);
}

double PatchRenderer::exposureKeyW_m2() const { return state_->keyW_m2; }

double PatchRenderer::exposureScale() const {
    return std::exp2(static_cast<double>(state_->settings.exposureStops)) * kKeyTone / state_->keyW_m2;
}

std::size_t PatchRenderer::patchCount() const { return state_->patchSurface.size(); }
bool PatchRenderer::hasRadiosity() const { return state_->hasRadiosity; }
std::uint64_t PatchRenderer::radiosityUploads() const { return state_->uploads; }

void PatchRenderer::draw(const Camera& camera, double aspect) const {
    const State& s = *state_;
    if (!s.haveMesh || s.vertexCount == 0) return;
    const DisplaySettings& d = s.settings;
    const glm::mat4 viewProjection(camera.viewProjection(aspect));

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // walls are seen from inside, blocks from outside: both sides are real
    glDisable(GL_BLEND);
    const gl::ShaderProgram& p = s.program;
    p.use();
    p.set("viewProjection", viewProjection);
    p.set("eye", glm::vec3(camera.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const glm::dvec3 up = glm::cross(right, camera.forward);
    p.set("keyDirection", glm::vec3(glm::normalize(-camera.forward + 0.8 * up + 0.6 * right)));
    s.vertexRadiosity.bind(kVertexRadiosityUnit);
    s.patchRadiosity.bind(kPatchRadiosityUnit);
    s.patchStyle.bind(kPatchStyleUnit);
    p.set("vertexRadiosity", static_cast<int>(kVertexRadiosityUnit));
    p.set("patchRadiosity", static_cast<int>(kPatchRadiosityUnit));
    p.set("patchStyle", static_cast<int>(kPatchStyleUnit));
    p.set("hasRadiosity", s.hasRadiosity ? 1 : 0);
    p.set("smoothShading", d.shading == Shading::Smooth ? 1 : 0);
    p.set("exposureScale", static_cast<float>(exposureScale()));
    const ColourLegend range = legend();
    p.set("falseColour", d.colourMode == ColourMode::FalseColour ? 1 : 0);
    p.set("logScale", range.logScale ? 1 : 0);
    p.set("legendMin", static_cast<float>(range.minW_m2));
    p.set("legendMax", static_cast<float>(range.maxW_m2));
    p.set("isolines", d.isolines ? 1 : 0);
    const double step = range.ticksW_m2.size() >= 2 ? range.ticksW_m2[1] - range.ticksW_m2[0] : range.maxW_m2;
    p.set("isolineStep", static_cast<float>(step));
    p.set("wireframe", d.wireframe ? 1 : 0);
    p.set("highlight", d.highlightShooter ? 1 : 0);
    p.set("shooter", static_cast<int>(s.shooter));
    p.set("showImportance", d.showImportance ? 1 : 0);
    // Pushed back by their depth slope so overlays drawn at the same depth stay on top.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    s.layout.bind();
    glDrawArrays(GL_TRIANGLES, 0, s.vertexCount);
    glDisable(GL_POLYGON_OFFSET_FILL);

    if (d.showLinks && s.linkVertexCount > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        s.lineProgram.use();
        s.lineProgram.set("viewProjection", viewProjection);
        s.lineProgram.set("colour", glm::vec4(1.0f, 0.85f, 0.3f, 0.35f));
        s.linkLayout.bind();
        glDrawArrays(GL_LINES, 0, s.linkVertexCount);
        glDisable(GL_BLEND);
    }
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace radiant::render
