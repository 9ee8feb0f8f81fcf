#include "render/PatchRenderer.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <utility>

#include "radiometry/common/Check.h"
#include "render/PatchShaderVariant.h"
#include "render/display/DisplayBuffers.h"
#include "render/display/PatchGeometry.h"
#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/Texture.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {
namespace {

/// The attributes of GridVertex in `buffer`, as patch.vert.glsl's LIGHT_MAP variant reads them.
void describeGridVertices(gl::VertexArray& layout, const gl::Buffer& buffer) {
    constexpr std::size_t stride = sizeof(GridVertex);
    layout.addFloatAttribute(buffer, 0, 3, stride, offsetof(GridVertex, position));
    layout.addFloatAttribute(buffer, 2, 3, stride, offsetof(GridVertex, normal));
    layout.addFloatAttribute(buffer, 5, 2, stride, offsetof(GridVertex, grid));
    layout.addFloatAttribute(buffer, 6, 3, stride, offsetof(GridVertex, layout));
}

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
        vertexCount = static_cast<GLsizei>(points.size() & ~std::size_t{1});
    }
};

/// Colours as shown: 8 bits per channel, what the framebuffer keeps, except in false colour, whose
/// isolines read the interpolated colour-map position (alpha) to a fraction of a legend step.
/// llvmpipe samples 8-bit texels faster: the tone-mapped view, A/B in one session, 10-13% less
/// process CPU per frame (42.8-47.3 against 45.9-54.9 ms, bench frames idle).
struct ColourAtlases {
    gl::Texture2D vertices{1, 1, GL_RGBA8};  // smooth colours, sampled bilinearly
    gl::Texture2D patches{1, 1, GL_RGBA8};   // flat colours, fetched per cell
};

/// The variants one frame draws with, from the settings and what the model holds.
struct FrameVariants {
    PatchShaderVariant triangles, grids, outlineTriangles, outlineCell;
};

FrameVariants frameVariants(const DisplayModel& model) {
    const DisplaySettings& d = model.settings();
    const DisplayColours& colours = model.colours();
    PatchShaderVariant colour;
    colour.falseColour = colours.falseColour;
    colour.isolines = colours.falseColour && d.isolines;
    FrameVariants v;
    v.triangles = colour;
    // Edges cost a derivative per pixel (a third of the frame on llvmpipe): the whole view pays for
    // them only with the wireframe; the shooter's outline redraws just its patch on top.
    v.triangles.edges = d.wireframe;
    v.grids = v.triangles;
    v.grids.lightMap = true;
    v.grids.flat = d.shading == Shading::Flat;
    v.grids.tints = colours.anyTint;
    v.outlineTriangles = colour;
    v.outlineTriangles.edges = true;
    v.outlineCell = v.grids;
    v.outlineCell.edges = true;
    v.outlineCell.tints = true;
    return v;
}

} // namespace

struct PatchRenderer::Gpu {
    std::array<std::unique_ptr<gl::ShaderProgram>, PatchShaderVariant::kCount> programs;  // compiled on first need
    gl::ShaderProgram lineProgram{"wire.vert.glsl", "wire.frag.glsl"};
    PatchTriangles triangles;  // CPU copy: which patch and smoothing vertex each vertex shows
    // Indexed, one vertex per patch corner: the triangles as every variant without edges draws them.
    gl::Buffer corners;
    gl::Buffer cornerColours;  // DisplayVertex per corner
    gl::Buffer cornerIndices;
    gl::VertexArray cornerLayout;
    // Unindexed, with barycentric edges: the wireframe and the shooter's outline. Their colours are
    // uploaded only when drawn: all while the wireframe shows, else the outlined patch's.
    gl::Buffer vertices;
    gl::Buffer colours;  // DisplayVertex per drawn vertex
    gl::VertexArray layout;
    bool edgeColoursCurrent = false;  // colours holds every drawn vertex's current colour
    std::int64_t edgeColoursOf = -1;  // else the patch whose drawn vertices it holds current, or -1
    // Grid faces: one quad each, coloured from atlases of per-vertex and per-patch texels.
    gl::Buffer gridVertices;
    gl::VertexArray gridLayout;
    GLsizei gridVertexCount = 0;
    std::vector<std::int64_t> patchGrid;   // per patch: its grid, or -1
    std::vector<std::uint32_t> patchCell;  // per grid patch: its cell in the grid, row-major
    // The shooter's cell as a quad of its own: its outline redraws those pixels, not its whole face.
    gl::Buffer outlineCell;
    gl::VertexArray outlineLayout;
    std::int64_t outlineCellOf = -1;  // the patch outlineCell holds
    ColourAtlases displayAtlases;     // RGBA8
    ColourAtlases preciseAtlases;     // RGBA16F, for false colour
    bool preciseShown = false;        // which pair was filled last
    gl::Texture2D tintAtlas{1, 1, GL_RGBA8};  // tintTexel per cell
    Segments links;       // every hierarchical link
    Segments focusLinks;  // those the picked point gathers through
    bool haveMesh = false;
    std::uint64_t meshGeneration = 0;
    // Reused from one upload to the next: a snapshot a frame while solving.
    std::vector<DisplayVertex> drawnColours, cornerColourData;
    std::vector<glm::vec4> colourTexels, tintTexels;

    void compile(const PatchShaderVariant& variant) {
        std::unique_ptr<gl::ShaderProgram>& program = programs[variant.index()];
        if (!program) program = std::make_unique<gl::ShaderProgram>("patch.vert.glsl", "patch.frag.glsl", variant.defines());
    }
    [[nodiscard]] const gl::ShaderProgram& program(const PatchShaderVariant& variant) const {
        const std::unique_ptr<gl::ShaderProgram>& p = programs[variant.index()];
        RADIANT_CHECK_NE(p.get(), nullptr);  // prepare() compiles what draw uses
        return *p;
    }
    void uploadMesh(const DisplayModel& model, const PatchMesh& mesh);
    void uploadColours(const DisplayModel& model);
    void uploadEdgeColours(const DisplayModel& model, std::int64_t patch);
};

void PatchRenderer::Gpu::uploadMesh(const DisplayModel& model, const PatchMesh& mesh) {
    const FaceGrids& grids = model.grids();
    triangles = patchTriangles(mesh, grids, model.smoothing());
    corners.setData(std::span<const CornerVertex>(triangles.corners));
    cornerIndices.setData(std::span<const std::uint32_t>(triangles.cornerIndices));
    cornerColours.setData(std::span<const DisplayVertex>(std::vector<DisplayVertex>(triangles.corners.size())), GL_DYNAMIC_DRAW);
    vertices.setData(std::span<const PatchVertex>(triangles.vertices));
    colours.setData(std::span<const DisplayVertex>(std::vector<DisplayVertex>(triangles.vertices.size())), GL_DYNAMIC_DRAW);
    edgeColoursCurrent = false;
    edgeColoursOf = -1;
    const std::vector<GridVertex> quads = gridQuads(grids);
    gridVertices.setData(std::span<const GridVertex>(quads));
    gridVertexCount = static_cast<GLsizei>(quads.size());
    patchGrid.assign(mesh.size(), -1);
    patchCell.assign(mesh.size(), 0);
    for (std::size_t g = 0; g < grids.grids.size(); ++g)
        for (std::size_t cell = 0; cell < grids.grids[g].cellPatch.size(); ++cell) {
            patchGrid[grids.grids[g].cellPatch[cell]] = static_cast<std::int64_t>(g);
            patchCell[grids.grids[g].cellPatch[cell]] = static_cast<std::uint32_t>(cell);
        }
    outlineCellOf = -1;
    const auto width = static_cast<int>(grids.atlasWidth), height = static_cast<int>(grids.atlasHeight);
    displayAtlases = {gl::Texture2D(width, height, GL_RGBA8), gl::Texture2D(width, height, GL_RGBA8)};
    preciseAtlases = {gl::Texture2D(width, height, GL_RGBA16F), gl::Texture2D(width, height, GL_RGBA16F)};
    tintAtlas = gl::Texture2D(width, height, GL_RGBA8);
    links.set(nullptr);
    focusLinks.set(nullptr);
}

void PatchRenderer::Gpu::uploadColours(const DisplayModel& model) {
    const DisplayColours& c = model.colours();
    fillDisplayVertices(triangles.cornerPatch, triangles.cornerSmoothing, c, cornerColourData);
    cornerColours.setSubData(0, std::span<const DisplayVertex>(cornerColourData));
    edgeColoursCurrent = false;
    edgeColoursOf = -1;
    const FaceGrids& grids = model.grids();
    if (grids.grids.empty()) return;
    fillAtlasTexels(grids, model.smoothing(), c, colourTexels, tintTexels);
    ColourAtlases& atlases = c.falseColour ? preciseAtlases : displayAtlases;
    (c.smooth ? atlases.vertices : atlases.patches).upload(colourTexels);
    preciseShown = c.falseColour;
    tintAtlas.upload(tintTexels);
}

/// `patch` < 0: every drawn vertex's colour; else that patch's vertices only.
void PatchRenderer::Gpu::uploadEdgeColours(const DisplayModel& model, std::int64_t patch) {
    std::size_t first = 0, end = triangles.drawnPatch.size();
    if (patch >= 0) {
        first = triangles.patchFirstVertex[static_cast<std::size_t>(patch)];
        end = triangles.patchFirstVertex[static_cast<std::size_t>(patch) + 1];
    }
    const std::span<const std::uint32_t> drawnPatch(triangles.drawnPatch), drawnSmoothing(triangles.drawnSmoothing);
    fillDisplayVertices(drawnPatch.subspan(first, end - first), drawnSmoothing.subspan(first, end - first), model.colours(),
                        drawnColours);
    colours.setSubData(first * sizeof(DisplayVertex), std::span<const DisplayVertex>(drawnColours));
}

PatchRenderer::PatchRenderer() : gpu_(std::make_unique<Gpu>()) {
    Gpu& g = *gpu_;
    g.cornerLayout.addFloatAttribute(g.corners, 0, 3, sizeof(CornerVertex), offsetof(CornerVertex, position));
    g.cornerLayout.addFloatAttribute(g.corners, 2, 3, sizeof(CornerVertex), offsetof(CornerVertex, normal));
    g.cornerLayout.addFloatAttribute(g.cornerColours, 3, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, colour));
    g.cornerLayout.addFloatAttribute(g.cornerColours, 4, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, tint));
    g.cornerLayout.setIndexBuffer(g.cornerIndices);
    constexpr std::size_t stride = sizeof(PatchVertex);
    g.layout.addFloatAttribute(g.vertices, 0, 3, stride, offsetof(PatchVertex, position));
    g.layout.addFloatAttribute(g.vertices, 1, 3, stride, offsetof(PatchVertex, edge));
    g.layout.addFloatAttribute(g.vertices, 2, 3, stride, offsetof(PatchVertex, normal));
    g.layout.addFloatAttribute(g.colours, 3, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, colour));
    g.layout.addFloatAttribute(g.colours, 4, 4, sizeof(DisplayVertex), offsetof(DisplayVertex, tint));
    describeGridVertices(g.gridLayout, g.gridVertices);
    describeGridVertices(g.outlineLayout, g.outlineCell);
    g.compile(PatchShaderVariant{});  // the common variant, so a broken shader fails here rather than mid-frame
}

PatchRenderer::~PatchRenderer() = default;
PatchRenderer::PatchRenderer(PatchRenderer&&) noexcept = default;
PatchRenderer& PatchRenderer::operator=(PatchRenderer&&) noexcept = default;

void PatchRenderer::setMesh(const Scene& scene, const PatchMesh& mesh, std::uint64_t meshGeneration) {
    Gpu& g = *gpu_;
    if (g.haveMesh && meshGeneration == g.meshGeneration) return;
    model_.setMesh(scene, mesh);
    g.uploadMesh(model_, mesh);
    g.haveMesh = true;
    g.meshGeneration = meshGeneration;
    prepared_ = false;
}

void PatchRenderer::setMaterials(const Scene& scene, bool rekey) {
    model_.setMaterials(scene, rekey);
    prepared_ = false;
}

void PatchRenderer::setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter) {
    if (model_.setRadiosity(radiosityW_m2, generation, shooter)) prepared_ = false;
}

void PatchRenderer::setImportance(std::shared_ptr<const std::vector<double>> importance) {
    model_.setImportance(std::move(importance));
    prepared_ = false;
}

void PatchRenderer::setLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds) {
    gpu_->links.set(std::move(segmentEnds));
}

void PatchRenderer::setFocusLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds) {
    gpu_->focusLinks.set(std::move(segmentEnds));
}

void PatchRenderer::setSettings(const DisplaySettings& settings) {
    model_.setSettings(settings);
    prepared_ = false;
}

void PatchRenderer::prepare() {
    Gpu& g = *gpu_;
    if (model_.refreshColours() && g.haveMesh) g.uploadColours(model_);
    const FrameVariants v = frameVariants(model_);
    g.compile(v.triangles);
    if (model_.settings().wireframe && !g.edgeColoursCurrent && g.haveMesh) {
        g.uploadEdgeColours(model_, -1);
        g.edgeColoursCurrent = true;
    }
    if (g.gridVertexCount > 0) g.compile(v.grids);
    const std::int64_t shooter = model_.shooter();
    if (model_.settings().highlightShooter && shooter >= 0 && static_cast<std::size_t>(shooter) < model_.patchCount()) {
        const auto p = static_cast<std::size_t>(shooter);
        if (const std::int64_t grid = g.patchGrid[p]; grid >= 0) {
            g.compile(v.outlineCell);
            if (g.outlineCellOf != shooter) {
                const std::array<GridVertex, 6> quad =
                    gridCellQuad(model_.grids().grids[static_cast<std::size_t>(grid)], g.patchCell[p]);
                g.outlineCell.setData(std::span<const GridVertex>(quad), GL_DYNAMIC_DRAW);
                g.outlineCellOf = shooter;
            }
        } else {
            g.compile(v.outlineTriangles);
            if (!g.edgeColoursCurrent && g.edgeColoursOf != shooter) {
                g.uploadEdgeColours(model_, shooter);
                g.edgeColoursOf = shooter;
            }
        }
    }
    prepared_ = true;
}

void PatchRenderer::draw(const Camera& camera, double aspect) const {
    const Gpu& g = *gpu_;
    if (!g.haveMesh || (g.triangles.vertices.empty() && g.gridVertexCount == 0)) return;
    RADIANT_CHECK_EQ(prepared_, true);  // a setter ran since prepare(): the GPU holds older colours
    const DisplaySettings& d = model_.settings();
    const FrameVariants variants = frameVariants(model_);
    const glm::mat4 viewProjection(camera.viewProjection(aspect));
    const std::int64_t shooter = model_.shooter();
    const bool outline = d.highlightShooter && shooter >= 0 && static_cast<std::size_t>(shooter) < model_.patchCount();

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // A face is seen from its front only: its back reflects nothing (a two-sided face is two
    // surfaces back to back), and a closed room's near walls, seen from behind, open like a cut-away.
    // PatchGeometry winds every triangle counter-clockwise about its normal.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_BLEND);
    const glm::dvec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const glm::dvec3 up = glm::cross(right, camera.forward);
    const ColourLegend range = model_.colours().falseColour ? model_.legend() : ColourLegend{};
    const auto useProgram = [&](const PatchShaderVariant& variant) {
        const gl::ShaderProgram& p = g.program(variant);
        p.use();
        p.set("viewProjection", viewProjection);
        p.set("eye", glm::vec3(camera.eye));
        p.set("keyDirection", glm::vec3(glm::normalize(-camera.forward + 0.8 * up + 0.6 * right)));
        p.set("hasRadiosity", model_.hasRadiosity() ? 1 : 0);
        p.set("wireframe", d.wireframe ? 1 : 0);
        if (variant.lightMap) {
            const ColourAtlases& atlases = g.preciseShown ? g.preciseAtlases : g.displayAtlases;
            atlases.vertices.bind(0);
            atlases.patches.bind(1);
            g.tintAtlas.bind(2);
            p.set("vertexColours", 0);
            p.set("patchColours", 1);
            p.set("patchTints", 2);
            p.set("atlasSize", glm::vec2(static_cast<float>(model_.grids().atlasWidth),
                                         static_cast<float>(model_.grids().atlasHeight)));
        }
        // Isolines where the value crosses a tick (ColourLegend::isolineCoordinate, mirrored by the shader).
        if (range.logScale) {
            const double lo = std::log10(range.minW_m2), hi = std::log10(range.maxW_m2);
            p.set("isolineScale", static_cast<float>(hi - lo));
            p.set("isolineOffset", static_cast<float>(lo));
            p.set("isolineLog", 1);
        } else {
            const double step = range.linearStepW_m2();
            p.set("isolineScale", static_cast<float>((range.maxW_m2 - range.minW_m2) / step));
            p.set("isolineOffset", static_cast<float>(range.minW_m2 / step));
            p.set("isolineLog", 0);
        }
    };
    // Pushed back by their depth slope so overlays drawn at the same depth stay on top.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    const auto triangleCount = static_cast<GLsizei>(g.triangles.vertices.size());
    if (triangleCount > 0) {
        useProgram(variants.triangles);
        if (variants.triangles.edges) {
            g.layout.bind();
            glDrawArrays(GL_TRIANGLES, 0, triangleCount);
        } else {
            g.cornerLayout.bind();
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(g.triangles.cornerIndices.size()), GL_UNSIGNED_INT, nullptr);
        }
    }
    if (g.gridVertexCount > 0) {
        useProgram(variants.grids);
        g.gridLayout.bind();
        glDrawArrays(GL_TRIANGLES, 0, g.gridVertexCount);
    }
    if (outline && !d.wireframe) {
        glDepthFunc(GL_LEQUAL);  // the same triangles at the same depth
        const auto p = static_cast<std::size_t>(shooter);
        if (g.patchGrid[p] >= 0) {
            RADIANT_CHECK_EQ(g.outlineCellOf, shooter);
            // Not pushed back as the faces were: the cell's own triangles need not match the face's
            // depth to the last bit, and the outline must win.
            glDisable(GL_POLYGON_OFFSET_FILL);
            useProgram(variants.outlineCell);
            g.outlineLayout.bind();
            glDrawArrays(GL_TRIANGLES, 0, 6);
        } else {
            useProgram(variants.outlineTriangles);
            g.layout.bind();
            const auto first = static_cast<GLint>(g.triangles.patchFirstVertex[p]);
            glDrawArrays(GL_TRIANGLES, first, static_cast<GLint>(g.triangles.patchFirstVertex[p + 1]) - first);
        }
        glDepthFunc(GL_LESS);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);

    if (d.showLinks && g.links.vertexCount > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        g.lineProgram.use();
        g.lineProgram.set("viewProjection", viewProjection);
        // Faint: thousands of links overlap, and the shading under them must stay readable; fainter
        // still beside a picked point's own links, drawn bright on top (the lines to what it gathers
        // from, at every level above it).
        const bool focused = g.focusLinks.vertexCount > 0;
        g.lineProgram.set("colour", glm::vec4(1.0f, 0.9f, 0.45f, focused ? 0.05f : 0.12f));
        g.links.layout.bind();
        glDrawArrays(GL_LINES, 0, g.links.vertexCount);
        if (focused) {
            glDisable(GL_DEPTH_TEST);  // all of them, also where they pass behind a block
            g.lineProgram.set("colour", glm::vec4(0.3f, 0.95f, 1.0f, 0.85f));
            g.focusLinks.layout.bind();
            glDrawArrays(GL_LINES, 0, g.focusLinks.vertexCount);
            glEnable(GL_DEPTH_TEST);
        }
        glDisable(GL_BLEND);
    }
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace radiant::render
