#include "render/PatchRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "radiometry/common/Error.h"
#include "render/FaceGrids.h"
#include "render/SceneTriangles.h"
#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/Texture.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {
namespace {

/// What exposure 0 makes of the key radiosity, before the tone curve: a middle tone.
constexpr double kKeyTone = 0.35;

/// The part of a drawn vertex that changes with the solution and the display settings. Vertex
/// attributes rather than buffer textures: llvmpipe's texelFetch per vertex cost more than the frame.
struct DisplayVertex {
    glm::vec4 colour;  ///< rgb: sRGB display colour; a: position on the colour map
    glm::vec4 tint;    ///< rgb: colour to mix toward; a: amount, +2 when the patch is outlined
};

/// A corner of a grid face's quad: drawn with its light map (FaceGrids.h).
struct GridVertex {
    glm::vec3 position;  ///< m
    glm::vec3 normal;    ///< the face's, unit; doubled on a two-sided face (sidedNormal)
    glm::vec2 grid;      ///< grid coordinates: (0, 0) .. (columns, rows)
    glm::vec3 layout;    ///< first atlas row, columns, rows
};

/// The attributes of GridVertex in `buffer`, as patch.vert.glsl's LIGHT_MAP variant reads them.
void describeGridVertices(gl::VertexArray& layout, const gl::Buffer& buffer) {
    constexpr std::size_t stride = sizeof(GridVertex);
    layout.addFloatAttribute(buffer, 0, 3, stride, offsetof(GridVertex, position));
    layout.addFloatAttribute(buffer, 2, 3, stride, offsetof(GridVertex, normal));
    layout.addFloatAttribute(buffer, 5, 2, stride, offsetof(GridVertex, grid));
    layout.addFloatAttribute(buffer, 6, 3, stride, offsetof(GridVertex, layout));
}

struct PatchVertex {
    glm::vec3 position;  ///< m
    glm::vec3 edge;      ///< barycentric coordinate; 1 everywhere for the edge a quad's split hides
    glm::vec3 normal;    ///< the patch's, unit; doubled on a two-sided face (sidedNormal)
};

/// A two-sided face (Surface::side) is two coincident surfaces, one per side, which the depth test
/// cannot tell apart: their normals arrive doubled, and the TWO_SIDED shader variant drops the
/// fragments of whichever of the two is seen from behind, so each side shows its own radiosity.
glm::vec3 sidedNormal(const glm::dvec3& normal, bool twoSided) { return glm::vec3(twoSided ? 2.0 * normal : normal); }


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


/// Successive tints mix(mix(c, a.rgb, a.a), b.rgb, b.a) as one mix toward a combined colour.
glm::vec4 addTint(const glm::vec4& a, const glm::vec4& b) {
    const float amount = 1.0f - (1.0f - a.w) * (1.0f - b.w);
    if (amount <= 0.0f) return glm::vec4(0.0f);
    return {(glm::vec3(a) * a.w * (1.0f - b.w) + glm::vec3(b) * b.w) / amount, amount};
}

/// Everything the colours on the GPU depend on besides the data: when it changes, they are redone.
struct ColourInputs {
    double exposureScale = 0;
    ColourMode mode = ColourMode::ToneMapped;
    bool logScale = false;
    float falseColourMaxW_m2 = 0;
    bool highlight = false;
    bool importance = false;
    Shading shading = Shading::Smooth;
    bool operator==(const ColourInputs&) const = default;
};

ColourInputs colourInputs(const DisplaySettings& d, double exposureScale) {
    return {exposureScale,        d.colourMode,       d.logScale,      d.falseColourMaxW_m2,
            d.highlightShooter, d.showImportance, d.shading};
}

/// The shader variant for a combination of features (bit 0 false colour, 1 isolines, 2 edges, 3
/// light-mapped grid faces rather than triangles, and for those 4 flat shading, 5 tints; 6 two-sided
/// faces in the scene).
std::string variantDefines(unsigned variant) {
    std::string defines;
    if (variant & 8u) defines += "#define LIGHT_MAP 1\n";
    if (variant & 16u) defines += "#define FLAT 1\n";
    if (variant & 32u) defines += "#define TINTS 1\n";
    if (variant & 1u) defines += "#define FALSE_COLOUR 1\n";
    if (variant & 2u) defines += "#define ISOLINES 1\n";
    if (variant & 4u) defines += "#define EDGES 1\n";
    if (variant & 64u) defines += "#define TWO_SIDED 1\n";
    return defines;
}

} // namespace

struct PatchRenderer::State {
    std::array<std::unique_ptr<gl::ShaderProgram>, 128> programs;  // compiled on first use
    gl::ShaderProgram lineProgram{"wire.vert.glsl", "wire.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
    gl::Buffer colours;  // DisplayVertex per drawn vertex, rewritten when the colours change
    std::vector<std::uint32_t> drawnPatch;      // per drawn vertex
    std::vector<std::uint32_t> drawnSmoothing;  // per drawn vertex
    std::vector<GLint> patchFirstVertex;        // per patch and one past the last: its drawn vertices
    // Grid faces: one quad each, coloured from atlases of per-vertex and per-patch texels.
    FaceGrids grids;
    gl::Buffer gridVertices;
    gl::VertexArray gridLayout;
    GLsizei gridVertexCount = 0;
    std::vector<std::int64_t> patchGrid;  // per patch: its grid, or -1
    std::vector<std::uint32_t> patchCell; // per grid patch: its cell in the grid, row-major
    // The shooter's cell as a quad of its own: its outline redraws those pixels, not its whole face.
    gl::Buffer outlineCell;
    gl::VertexArray outlineLayout;
    std::int64_t outlineCellOf = -1;  // the patch outlineCell holds
    // Colours as shown: 8 bits per channel, what the framebuffer keeps, except in false colour, whose
    // isolines read the interpolated colour-map position (alpha) to a fraction of a legend step.
    // llvmpipe samples 8-bit texels faster: the tone-mapped view, A/B in one session, 10-13% less
    // process CPU per frame (42.8-47.3 against 45.9-54.9 ms, bench frames idle).
    struct ColourAtlases {
        gl::Texture2D vertices{1, 1, GL_RGBA8};  // smooth colours, sampled bilinearly
        gl::Texture2D patches{1, 1, GL_RGBA8};   // flat colours, fetched per cell
    };
    ColourAtlases displayAtlases;  // RGBA8
    ColourAtlases preciseAtlases;  // RGBA16F, for false colour
    bool preciseShown = false;     // which pair fillAtlases filled last
    // Tints, fetched per cell: 8 bits, alpha = amount / 2, + 1/2 when outlined (the amount is at most
    // 0.8: importance, changed and shooter tints combined).
    gl::Texture2D tintAtlas{1, 1, GL_RGBA8};
    /// Line segments (pairs of ends) uploaded when their shared data changes.
    struct Segments {
        gl::Buffer buffer;
        gl::VertexArray layout;
        GLsizei vertexCount = 0;
        std::shared_ptr<const std::vector<glm::vec3>> shown;

        Segments() { layout.addFloatAttribute(buffer, 0, 3, sizeof(glm::vec3), 0); }
        void set(std::shared_ptr<const std::vector<glm::vec3>> ends) {
            if (ends == shown) return;
            shown = std::move(ends);
            const std::span<const glm::vec3> points = shown ? std::span<const glm::vec3>(*shown) : std::span<const glm::vec3>();
            buffer.setData(points, GL_DYNAMIC_DRAW);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            vertexCount = static_cast<GLsizei>(points.size() & ~std::size_t{1});
        }
    };
    Segments links;       // every hierarchical link
    Segments focusLinks;  // those the picked point gathers through

    DisplaySettings settings;
    bool haveMesh = false;
    std::uint64_t meshGeneration = 0;
    std::uint64_t radiosityGeneration = 0;
    std::uint64_t uploads = 0;
    bool hasRadiosity = false;
    std::int64_t shooter = -1;
    bool coloursDirty = true;
    bool anyTint = false;  // some patch is tinted or outlined in the colours last made
    std::vector<char> patchTwoSided;  // per patch: its surface is one side of a two-sided face
    bool anyTwoSided = false;
    ColourInputs coloursMadeWith;

    // CPU copies of the data, to smooth, diff and recolour without the mesh.
    std::vector<std::uint32_t> patchSurface;
    std::vector<double> patchArea;
    std::vector<std::array<std::uint32_t, 4>> patchSmoothing;  // smoothing vertex per corner
    std::vector<std::uint8_t> patchCorners;
    std::vector<char> patchEmits;
    std::vector<glm::vec3> baseColour;  // linear: reflectance, or an emitter's chromaticity
    std::vector<double> importance;     // relative to its maximum
    std::shared_ptr<const std::vector<double>> importanceShown;
    std::size_t smoothingVertexCount = 0;
    std::vector<Rgb> radiosity;         // per patch, W/m^2
    std::vector<Rgb> smoothRadiosity;   // per smoothing vertex, W/m^2
    std::vector<char> changed;          // per patch: changed in the last update
    double automaticKeyW_m2 = 1.0;      // mean luminance of the lit reflectors now
    double energyBalanceKeyW_m2 = 0.0;  // from the materials; 0 when nothing emits
    double heldKeyW_m2 = 0.0;           // 0 until re-keyed
    unsigned rekeysSeen = 0;
    // 99th area percentile of the non-emitters' total radiosity, rounded up: the automatic false-colour
    // range. Its sort is worked out only when false colour asks (dataMax), not on every snapshot.
    double dataMaxW_m2 = 1.0;
    bool dataMaxStale = false;
    double maxTotalAllW_m2 = 0.0;
    ToneCurveTable toneCurve;
    // Reused from one recolouring to the next: a snapshot a frame while solving.
    std::vector<glm::vec4> patchColours, vertexColours, tints, colourTexels, tintTexels;
    std::vector<DisplayVertex> drawnColours;

    [[nodiscard]] double dataMax();

    /// The grid faces' quads and atlases, after `grids` was found.
    void uploadGrids();
    /// Cell `cell` of grid `g` as a quad: corners on the face's bilinear map, grid coordinates as
    /// the face's quad gives them there.
    void uploadOutlineCell(std::size_t g, std::uint32_t cell);
    /// Writes the grid faces' texels from vertexColours or patchColours (as shown) and tints, into the
    /// 8-bit colour atlases, or the 16-bit ones when `precise` (false colour).
    void fillAtlases(bool smooth, bool precise);

    const gl::ShaderProgram& program(unsigned variant) {
        if (!programs[variant])
            programs[variant] =
                std::make_unique<gl::ShaderProgram>("patch.vert.glsl", "patch.frag.glsl", variantDefines(variant));
        return *programs[variant];
    }
};

void PatchRenderer::State::uploadGrids() {
    patchGrid.assign(patchSurface.size(), -1);
    patchCell.assign(patchSurface.size(), 0);
    outlineCellOf = -1;
    std::vector<GridVertex> quads;
    quads.reserve(grids.grids.size() * 6);
    for (std::size_t g = 0; g < grids.grids.size(); ++g) {
        const FaceGrid& grid = grids.grids[g];
        for (std::size_t cell = 0; cell < grid.cellPatch.size(); ++cell) {
            patchGrid[grid.cellPatch[cell]] = static_cast<std::int64_t>(g);
            patchCell[grid.cellPatch[cell]] = static_cast<std::uint32_t>(cell);
        }
        const auto columns = static_cast<float>(grid.columns), rows = static_cast<float>(grid.rows);
        const glm::vec3 atlasLayout(static_cast<float>(grid.atlasRow), columns, rows);
        const std::array<glm::vec2, 4> at{glm::vec2(0, 0), glm::vec2(columns, 0), glm::vec2(columns, rows),
                                          glm::vec2(0, rows)};
        for (const int k : {0, 1, 2, 0, 2, 3})
            quads.push_back({glm::vec3(grid.corners[static_cast<std::size_t>(k)]), sidedNormal(grid.normal, patchTwoSided[grid.cellPatch[0]] != 0),
                             at[static_cast<std::size_t>(k)], atlasLayout});
    }
    gridVertices.setData(std::span<const GridVertex>(quads));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    gridVertexCount = static_cast<GLsizei>(quads.size());
    const auto width = static_cast<int>(grids.atlasWidth), height = static_cast<int>(grids.atlasHeight);
    displayAtlases = {gl::Texture2D(width, height, GL_RGBA8), gl::Texture2D(width, height, GL_RGBA8)};
    preciseAtlases = {gl::Texture2D(width, height, GL_RGBA16F), gl::Texture2D(width, height, GL_RGBA16F)};
    tintAtlas = gl::Texture2D(width, height, GL_RGBA8);
}

double PatchRenderer::State::dataMax() {
    if (!dataMaxStale) return dataMaxW_m2;
    std::vector<std::pair<double, double>> reflectorTotals;  // (total radiosity, area) of non-emitters
    reflectorTotals.reserve(radiosity.size());
    double reflectorArea = 0;
    for (std::size_t p = 0; p < radiosity.size(); ++p)
        if (!patchEmits[p]) {
            reflectorTotals.emplace_back(total(radiosity[p]), patchArea[p]);
            reflectorArea += patchArea[p];
        }
    // The automatic false-colour range ends at the 99th area percentile of the reflectors: a few
    // hot patches (beside an emitter, in a corner) would otherwise squash everything else into
    // the bottom of the colour map. Brighter patches show the top colour.
    std::sort(reflectorTotals.begin(), reflectorTotals.end());
    double percentileTotal = 0, area = 0;
    for (const auto& [value, patchAreaM2] : reflectorTotals) {
        percentileTotal = value;
        area += patchAreaM2;
        if (area >= 0.99 * reflectorArea) break;
    }
    dataMaxW_m2 = roundUpForLegend(percentileTotal > 0 ? percentileTotal : maxTotalAllW_m2);
    dataMaxStale = false;
    return dataMaxW_m2;
}

void PatchRenderer::State::uploadOutlineCell(std::size_t g, std::uint32_t cell) {
    const FaceGrid& grid = grids.grids[g];
    const std::uint32_t i = cell % grid.columns, j = cell / grid.columns;
    const auto at = [&](std::uint32_t column, std::uint32_t row) {
        const double u = static_cast<double>(column) / grid.columns, v = static_cast<double>(row) / grid.rows;
        const std::array<glm::dvec3, 4>& c = grid.corners;
        const glm::dvec3 position = c[0] + (c[1] - c[0]) * u + (c[3] - c[0]) * v + (c[0] - c[1] + c[2] - c[3]) * (u * v);
        return GridVertex{glm::vec3(position), sidedNormal(grid.normal, patchTwoSided[grid.cellPatch[0]] != 0),
                          glm::vec2(static_cast<float>(column), static_cast<float>(row)),
                          glm::vec3(static_cast<float>(grid.atlasRow), static_cast<float>(grid.columns),
                                    static_cast<float>(grid.rows))};
    };
    const std::array<GridVertex, 4> corners{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
    std::array<GridVertex, 6> quad{};
    std::size_t k = 0;
    for (const int corner : {0, 1, 2, 0, 2, 3}) quad[k++] = corners[static_cast<std::size_t>(corner)];
    outlineCell.setData(std::span<const GridVertex>(quad), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void PatchRenderer::State::fillAtlases(bool smooth, bool precise) {
    if (grids.grids.empty()) return;
    const std::size_t width = grids.atlasWidth;
    // Texels outside the grids are never sampled: left as they are.
    colourTexels.resize(width * grids.atlasHeight);
    tintTexels.resize(width * grids.atlasHeight);
    for (const FaceGrid& grid : grids.grids) {
        const std::size_t n = grid.columns, m = grid.rows, row = grid.atlasRow;
        for (std::size_t j = 0; j < m; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint32_t patch = grid.cellPatch[j * n + i];
                const glm::vec4& tint = tints[patch];
                const bool outlined = tint.w >= 2.0f;
                tintTexels[(row + j) * width + i] = {glm::vec3(tint), outlined ? 0.5f + (tint.w - 2.0f) / 2.0f : tint.w / 2.0f};
                if (!smooth) colourTexels[(row + j) * width + i] = patchColours[patch];
            }
        if (smooth)
            for (std::size_t j = 0; j <= m; ++j)
                for (std::size_t i = 0; i <= n; ++i) {
                    const std::uint32_t corner = grid.vertexCorner[j * (n + 1) + i];
                    colourTexels[(row + j) * width + i] = vertexColours[patchSmoothing[corner / 4][corner % 4]];
                }
    }
    const auto upload = [&](const gl::Texture2D& texture, const std::vector<glm::vec4>& texels) {
        glBindTexture(GL_TEXTURE_2D, texture.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, texture.width(), texture.height(), GL_RGBA, GL_FLOAT, texels.data());
    };
    const ColourAtlases& atlases = precise ? preciseAtlases : displayAtlases;
    upload(smooth ? atlases.vertices : atlases.patches, colourTexels);
    preciseShown = precise;
    upload(tintAtlas, tintTexels);
    glBindTexture(GL_TEXTURE_2D, 0);
}

PatchRenderer::PatchRenderer() : state_(std::make_unique<State>()) {
    constexpr std::size_t stride = sizeof(PatchVertex);
    state_->layout.addFloatAttribute(state_->vertices, 0, 3, stride, offsetof(PatchVertex, position));
    state_->layout.addFloatAttribute(state_->vertices, 1, 3, stride, offsetof(PatchVertex, edge));
    state_->layout.addFloatAttribute(state_->vertices, 2, 3, stride, offsetof(PatchVertex, normal));
    state_->layout.addFloatAttribute(state_->colours, 3, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, colour));
    state_->layout.addFloatAttribute(state_->colours, 4, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, tint));
    describeGridVertices(state_->gridLayout, state_->gridVertices);
    describeGridVertices(state_->outlineLayout, state_->outlineCell);
    glBindVertexArray(0);
    state_->program(0);  // the common variant, so a broken shader fails here rather than mid-frame
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
    s.drawnPatch.clear();
    s.drawnSmoothing.clear();
    s.patchFirstVertex.assign(n + 1, 0);
    s.grids = findFaceGrids(scene, mesh);
    s.patchTwoSided.resize(n);
    for (std::size_t p = 0; p < n; ++p) s.patchTwoSided[p] = scene.surfaces[mesh.patches[p].surface].side != FaceSide::Single;
    s.anyTwoSided = std::find(s.patchTwoSided.begin(), s.patchTwoSided.end(), 1) != s.patchTwoSided.end();
    for (std::size_t p = 0; p < n; ++p) {
        const Patch& patch = mesh.patches[p];
        s.patchFirstVertex[p] = static_cast<GLint>(triangles.size());
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
        if (s.grids.patchInGrid[p]) continue;  // drawn by its face's light map
        const auto corner = [&](std::uint8_t c, const glm::vec3& edge) {
            triangles.push_back({glm::vec3(mesh.vertices[patch.corners[c]]), edge, sidedNormal(patch.normal, s.patchTwoSided[p] != 0)});
            s.drawnPatch.push_back(static_cast<std::uint32_t>(p));
            s.drawnSmoothing.push_back(s.patchSmoothing[p][c]);
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
    s.patchFirstVertex[n] = static_cast<GLint>(triangles.size());
    s.uploadGrids();
    s.smoothingVertexCount = smoothingIds.size();
    s.vertices.setData(std::span<const PatchVertex>(triangles));
    s.vertexCount = static_cast<GLsizei>(triangles.size());
    s.colours.setData(std::span<const DisplayVertex>(std::vector<DisplayVertex>(triangles.size())), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    s.haveMesh = true;
    s.meshGeneration = meshGeneration;
    s.hasRadiosity = false;
    s.radiosityGeneration = 0;
    s.shooter = -1;
    s.radiosity.clear();
    s.smoothRadiosity.clear();
    s.changed.assign(n, 0);
    s.importance.assign(n, 0.0);
    s.importanceShown.reset();
    s.links.set(nullptr);
    s.focusLinks.set(nullptr);
    s.automaticKeyW_m2 = 1.0;
    s.heldKeyW_m2 = 0.0;
    s.dataMaxW_m2 = 1.0;
    s.dataMaxStale = false;
    setMaterials(scene, /*rekey=*/true);
}

void PatchRenderer::setMaterials(const Scene& scene, bool rekey) {
    State& s = *state_;
    s.patchEmits.resize(s.patchSurface.size());
    s.baseColour.resize(s.patchSurface.size());
    // Energy balance of a closed enclosure: at convergence all emitted power P is absorbed,
    // P = sum A (1 - rho) H, so the mean irradiance is H = P / sum A (1 - rho) per band, and a
    // patch's radiosity E + rho H. The key is the area mean over the reflectors (over every patch
    // when all emit, as in the furnace, where it is exactly E / (1 - rho)).
    Rgb emitted(0.0), absorbing(0.0), reflectorSum(0.0), emitterSum(0.0);
    double reflectorArea = 0, emitterArea = 0;
    for (std::size_t p = 0; p < s.patchSurface.size(); ++p) {
        const std::size_t surface = s.patchSurface[p];
        if (surface >= scene.surfaces.size())
            throw RadiantError({"patch renderer", "patch " + std::to_string(p)},
                               "surface " + std::to_string(surface) + " is not in the scene (" +
                                   std::to_string(scene.surfaces.size()) + " surfaces)");
        const Material& material = scene.materials.at(scene.surfaces[surface].material);
        s.patchEmits[p] = material.emits() ? 1 : 0;
        s.baseColour[p] = displayColour(material);
        const double area = s.patchArea[p];
        emitted += area * material.exitance.value();
        absorbing += area * (Rgb(1.0) - material.reflectance);
    }
    const Rgb meanIrradiance = glm::max(absorbing, Rgb(1e-12));
    for (std::size_t p = 0; p < s.patchSurface.size(); ++p) {
        const Material& material = scene.materials.at(scene.surfaces[s.patchSurface[p]].material);
        const Rgb radiosity = material.exitance.value() + material.reflectance * (emitted / meanIrradiance);
        (s.patchEmits[p] ? emitterSum : reflectorSum) += s.patchArea[p] * radiosity;
        (s.patchEmits[p] ? emitterArea : reflectorArea) += s.patchArea[p];
    }
    const Rgb meanRadiosity = reflectorArea > 0 ? reflectorSum / reflectorArea
                              : emitterArea > 0 ? emitterSum / emitterArea
                                                : Rgb(0.0);
    // Kept across material edits: with the key fixed, doubling a lamp doubles what the picture shows
    // (a lecture's moment). A new mesh, or a scene that had nothing to key on, derives it anew.
    if (rekey || !(s.energyBalanceKeyW_m2 > 0))
        s.energyBalanceKeyW_m2 = luminance(emitted) > 0 ? luminance(meanRadiosity) : 0.0;
    s.coloursDirty = true;
}

void PatchRenderer::setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter) {
    State& s = *state_;
    if (s.hasRadiosity == !radiosityW_m2.empty() && generation == s.radiosityGeneration) return;
    const std::size_t n = s.patchSurface.size();
    s.coloursDirty = true;
    if (radiosityW_m2.empty()) {
        s.hasRadiosity = false;
        s.radiosityGeneration = generation;
        s.radiosity.clear();
        return;
    }
    if (radiosityW_m2.size() != n)
        throw RadiantError({"patch renderer", "radiosity generation " + std::to_string(generation)},
                           std::to_string(radiosityW_m2.size()) + " radiosity values for a mesh of " +
                               std::to_string(n) + " patches");

    // Changed since the last upload: visibly, by more than a thousandth of the brightest reflector's
    // radiosity (emitters change by nothing but their own reflected part).
    double brightest = 0;
    for (std::size_t p = 0; p < n; ++p)
        if (!s.patchEmits[p]) brightest = std::max({brightest, radiosityW_m2[p].x, radiosityW_m2[p].y, radiosityW_m2[p].z});
    const bool canDiff = s.radiosity.size() == n;
    const double changeFloor = 1e-3 * brightest;

    std::vector<glm::dvec4> smoothSums(s.smoothingVertexCount, glm::dvec4(0.0));
    double litArea = 0, litLuminance = 0, maxTotalAll = 0;
    for (std::size_t p = 0; p < n; ++p) {
        const Rgb& b = radiosityW_m2[p];
        if (canDiff) {
            const glm::dvec3 d = glm::abs(b - s.radiosity[p]);
            s.changed[p] = std::max({d.x, d.y, d.z}) > changeFloor ? 1 : 0;
        } else {
            s.changed[p] = 0;
        }
        for (std::uint8_t c = 0; c < s.patchCorners[p]; ++c)
            smoothSums[s.patchSmoothing[p][c]] += glm::dvec4(b * s.patchArea[p], s.patchArea[p]);
        maxTotalAll = std::max(maxTotalAll, total(b));
        if (!s.patchEmits[p] && luminance(b) > 0) {
            litArea += s.patchArea[p];
            litLuminance += s.patchArea[p] * luminance(b);
        }
    }
    // A tint on every patch (a gathering sweep) says nothing and hides the picture: tint only when the
    // step touched part of the scene, as a shot does.
    if (2 * static_cast<std::size_t>(std::count(s.changed.begin(), s.changed.end(), 1)) > n)
        std::fill(s.changed.begin(), s.changed.end(), 0);
    s.smoothRadiosity.resize(smoothSums.size());
    for (std::size_t v = 0; v < smoothSums.size(); ++v)
        s.smoothRadiosity[v] = smoothSums[v].w > 0 ? glm::dvec3(smoothSums[v]) / smoothSums[v].w : Rgb(0.0);

    // Before light has bounced, only the emitters are lit: key and range follow them then.
    s.automaticKeyW_m2 = litArea > 0 ? litLuminance / litArea : std::max(maxTotalAll / 3.0, 1e-30);
    s.maxTotalAllW_m2 = maxTotalAll;
    s.dataMaxStale = true;
    s.radiosity.assign(radiosityW_m2.begin(), radiosityW_m2.end());
    s.hasRadiosity = true;
    s.radiosityGeneration = generation;
    s.shooter = shooter;
    ++s.uploads;
}

void PatchRenderer::setImportance(std::shared_ptr<const std::vector<double>> importance) {
    State& s = *state_;
    if (importance == s.importanceShown) return;
    s.importanceShown = importance;
    const std::vector<double> none;
    const std::vector<double>& values = importance ? *importance : none;
    const double largest = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
    for (std::size_t p = 0; p < s.importance.size(); ++p)
        s.importance[p] = p < values.size() && largest > 0 ? values[p] / largest : 0.0;
    if (s.settings.showImportance) s.coloursDirty = true;
}

void PatchRenderer::setLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds) {
    state_->links.set(std::move(segmentEnds));
}

void PatchRenderer::setFocusLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds) {
    state_->focusLinks.set(std::move(segmentEnds));
}

void PatchRenderer::setSettings(const DisplaySettings& settings) {
    State& s = *state_;
    s.settings = settings;
    const bool heldButUnset = settings.exposureKey == ExposureKey::Held && s.heldKeyW_m2 <= 0;
    if (settings.rekeyCount != s.rekeysSeen || heldButUnset) s.heldKeyW_m2 = s.automaticKeyW_m2;
    s.rekeysSeen = settings.rekeyCount;
}
const DisplaySettings& PatchRenderer::settings() const { return state_->settings; }

ColourLegend PatchRenderer::legend() const {
    const DisplaySettings& d = state_->settings;
    const double top = d.falseColourMaxW_m2 > 0 ? static_cast<double>(d.falseColourMaxW_m2) : state_->dataMax();
    return makeLegend(top, d.logScale, DisplaySettings::kLogDecades);
}

double PatchRenderer::exposureKeyW_m2() const {
    const State& s = *state_;
    switch (s.settings.exposureKey) {
    case ExposureKey::EnergyBalance:
        if (s.energyBalanceKeyW_m2 > 0) return s.energyBalanceKeyW_m2;
        break;  // nothing emits: no balance to key on
    case ExposureKey::Held:
        if (s.heldKeyW_m2 > 0) return s.heldKeyW_m2;
        break;
    case ExposureKey::Automatic: break;
    }
    return s.automaticKeyW_m2;
}

double PatchRenderer::automaticExposureKeyW_m2() const { return state_->automaticKeyW_m2; }

double PatchRenderer::exposureScale() const {
    return std::exp2(static_cast<double>(state_->settings.exposureStops)) * kKeyTone / exposureKeyW_m2();
}

std::size_t PatchRenderer::patchCount() const { return state_->patchSurface.size(); }
bool PatchRenderer::hasRadiosity() const { return state_->hasRadiosity; }
std::uint64_t PatchRenderer::radiosityUploads() const { return state_->uploads; }

void PatchRenderer::refreshColours() const {
    State& s = *state_;
    const double scale = exposureScale();
    const ColourInputs inputs = colourInputs(s.settings, scale);
    if (!s.coloursDirty && inputs == s.coloursMadeWith) return;
    const std::size_t n = s.patchSurface.size();
    // The colour-map position (alpha) is read only by false colour; the tone-mapped view skips the
    // legend's percentile sort.
    const bool falseColour = inputs.mode == ColourMode::FalseColour;
    const ColourLegend range = falseColour ? legend() : ColourLegend{};
    const auto colourOf = [&](const Rgb& b) {
        const float position = falseColour ? static_cast<float>(range.position(total(b))) : 0.0f;
        return glm::vec4(s.toneCurve(b.x * scale), s.toneCurve(b.y * scale), s.toneCurve(b.z * scale), position);
    };
    std::vector<glm::vec4>& patchColours = s.patchColours;
    std::vector<glm::vec4>& vertexColours = s.vertexColours;
    std::vector<glm::vec4>& tints = s.tints;
    patchColours.resize(n);
    vertexColours.resize(s.smoothingVertexCount);
    tints.resize(n);
    const bool smooth = inputs.shading == Shading::Smooth;
    if (s.hasRadiosity && inputs.mode != ColourMode::Reflectance) {
        // Only the shading shown.
        if (smooth)
            for (std::size_t v = 0; v < vertexColours.size(); ++v) vertexColours[v] = colourOf(s.smoothRadiosity[v]);
        else
            for (std::size_t p = 0; p < n; ++p) patchColours[p] = colourOf(s.radiosity[p]);
    } else {
        for (std::size_t p = 0; p < n; ++p) {
            const glm::vec3 encoded(static_cast<float>(linearToSrgb(s.baseColour[p].x)),
                                    static_cast<float>(linearToSrgb(s.baseColour[p].y)),
                                    static_cast<float>(linearToSrgb(s.baseColour[p].z)));
            patchColours[p] = glm::vec4(encoded, 0.0f);
            for (std::uint8_t c = 0; c < s.patchCorners[p]; ++c) vertexColours[s.patchSmoothing[p][c]] = patchColours[p];
        }
    }
    bool anyTint = false;
    for (std::size_t p = 0; p < n; ++p) {
        glm::vec4 tint(0.0f);
        if (inputs.importance) tint = addTint(tint, {1.0f, 0.1f, 0.8f, 0.6f * static_cast<float>(s.importance[p])});
        const bool isShooter = inputs.highlight && s.hasRadiosity && static_cast<std::int64_t>(p) == s.shooter;
        if (inputs.highlight && s.hasRadiosity && s.changed[p]) tint = addTint(tint, {1.0f, 0.55f, 0.15f, 0.22f});
        if (isShooter) tint = addTint(tint, {1.0f, 0.45f, 0.0f, 0.35f});
        tints[p] = glm::vec4(glm::vec3(tint), tint.w + (isShooter ? 2.0f : 0.0f));
        anyTint |= tints[p].w > 0.0f;
    }
    s.anyTint = anyTint;
    s.fillAtlases(smooth, falseColour);
    // Gouraud: each drawn vertex takes its smoothing vertex's colour; flat: its patch's.
    std::vector<DisplayVertex>& drawn = s.drawnColours;
    drawn.resize(s.drawnPatch.size());
    for (std::size_t v = 0; v < drawn.size(); ++v)
        drawn[v] = {smooth ? vertexColours[s.drawnSmoothing[v]] : patchColours[s.drawnPatch[v]], tints[s.drawnPatch[v]]};
    glBindBuffer(GL_ARRAY_BUFFER, s.colours.id());
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(drawn.size() * sizeof(DisplayVertex)), drawn.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    s.coloursDirty = false;
    s.coloursMadeWith = inputs;
}

void PatchRenderer::draw(const Camera& camera, double aspect) const {
    State& s = *state_;
    if (!s.haveMesh || (s.vertexCount == 0 && s.gridVertexCount == 0)) return;
    refreshColours();
    const DisplaySettings& d = s.settings;
    const glm::mat4 viewProjection(camera.viewProjection(aspect));
    const bool falseColour = d.colourMode == ColourMode::FalseColour && s.hasRadiosity;
    const bool outline = d.highlightShooter && s.hasRadiosity && s.shooter >= 0 &&
                         static_cast<std::size_t>(s.shooter) < s.patchSurface.size();
    const unsigned colourVariant = (falseColour ? 1u : 0u) | (falseColour && d.isolines ? 2u : 0u) | (s.anyTwoSided ? 64u : 0u);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // walls are seen from inside, blocks from outside: both sides are real
    glDisable(GL_BLEND);
    const glm::dvec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const glm::dvec3 up = glm::cross(right, camera.forward);
    const ColourLegend range = falseColour ? legend() : ColourLegend{};
    const auto useProgram = [&](unsigned variant) {
        const gl::ShaderProgram& p = s.program(variant);
        p.use();
        p.set("viewProjection", viewProjection);
        p.set("eye", glm::vec3(camera.eye));
        p.set("keyDirection", glm::vec3(glm::normalize(-camera.forward + 0.8 * up + 0.6 * right)));
        p.set("hasRadiosity", s.hasRadiosity ? 1 : 0);
        p.set("wireframe", d.wireframe ? 1 : 0);
        if (variant & 8u) {
            const State::ColourAtlases& atlases = s.preciseShown ? s.preciseAtlases : s.displayAtlases;
            atlases.vertices.bind(0);
            atlases.patches.bind(1);
            s.tintAtlas.bind(2);
            p.set("vertexColours", 0);
            p.set("patchColours", 1);
            p.set("patchTints", 2);
            glUniform2f(glGetUniformLocation(p.id(), "atlasSize"), static_cast<float>(s.grids.atlasWidth),
                        static_cast<float>(s.grids.atlasHeight));
        }
        // Isolines where the value crosses a tick: linear legends tick every `step` W/m^2 from the
        // minimum, log legends at each power of ten.
        if (range.logScale) {
            const double lo = std::log10(range.minW_m2), hi = std::log10(range.maxW_m2);
            p.set("isolineScale", static_cast<float>(hi - lo));
            p.set("isolineOffset", static_cast<float>(lo));
        } else {
            const double step = range.ticksW_m2.size() >= 2 ? range.ticksW_m2[1] - range.ticksW_m2[0] : range.maxW_m2;
            p.set("isolineScale", static_cast<float>((range.maxW_m2 - range.minW_m2) / step));
            p.set("isolineOffset", static_cast<float>(range.minW_m2 / step));
        }
    };
    // Edges cost a derivative per pixel (a third of the frame on llvmpipe): the whole view pays for
    // them only with the wireframe; the shooter's outline redraws just its patch on top.
    const unsigned mainVariant = colourVariant | (d.wireframe ? 4u : 0u);
    // Pushed back by their depth slope so overlays drawn at the same depth stay on top.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    if (s.vertexCount > 0) {
        useProgram(mainVariant);
        s.layout.bind();
        glDrawArrays(GL_TRIANGLES, 0, s.vertexCount);
    }
    const unsigned gridVariant = 8u | (d.shading == Shading::Flat ? 16u : 0u);
    if (s.gridVertexCount > 0) {
        useProgram(mainVariant | gridVariant | (s.anyTint ? 32u : 0u));
        s.gridLayout.bind();
        glDrawArrays(GL_TRIANGLES, 0, s.gridVertexCount);
    }
    if (outline && !d.wireframe) {
        glDepthFunc(GL_LEQUAL);  // the same triangles at the same depth
        const auto shooter = static_cast<std::size_t>(s.shooter);
        if (const std::int64_t grid = s.patchGrid[shooter]; grid >= 0) {
            if (s.outlineCellOf != s.shooter) {
                s.uploadOutlineCell(static_cast<std::size_t>(grid), s.patchCell[shooter]);
                s.outlineCellOf = s.shooter;
            }
            // Not pushed back as the faces were: the cell's own triangles need not match the face's
            // depth to the last bit, and the outline must win.
            glDisable(GL_POLYGON_OFFSET_FILL);
            useProgram(colourVariant | 4u | gridVariant | 32u);
            s.outlineLayout.bind();
            glDrawArrays(GL_TRIANGLES, 0, 6);
        } else {
            useProgram(colourVariant | 4u);
            s.layout.bind();
            glDrawArrays(GL_TRIANGLES, s.patchFirstVertex[shooter],
                         s.patchFirstVertex[shooter + 1] - s.patchFirstVertex[shooter]);
        }
        glDepthFunc(GL_LESS);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);

    if (d.showLinks && s.links.vertexCount > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        s.lineProgram.use();
        s.lineProgram.set("viewProjection", viewProjection);
        // Faint: thousands of links overlap, and the shading under them must stay readable; fainter
        // still beside a picked point's own links, drawn bright on top (the lines to what it gathers
        // from, at every level above it).
        const bool focused = s.focusLinks.vertexCount > 0;
        s.lineProgram.set("colour", glm::vec4(1.0f, 0.9f, 0.45f, focused ? 0.05f : 0.12f));
        s.links.layout.bind();
        glDrawArrays(GL_LINES, 0, s.links.vertexCount);
        if (focused) {
            glDisable(GL_DEPTH_TEST);  // all of them, also where they pass behind a block
            s.lineProgram.set("colour", glm::vec4(0.3f, 0.95f, 1.0f, 0.85f));
            s.focusLinks.layout.bind();
            glDrawArrays(GL_LINES, 0, s.focusLinks.vertexCount);
            glEnable(GL_DEPTH_TEST);
        }
        glDisable(GL_BLEND);
    }
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace radiant::render
