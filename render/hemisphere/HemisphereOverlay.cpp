#include "render/hemisphere/HemisphereOverlay.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/StateGuard.h"
#include "render/gl/VertexArray.h"
#include "render/hemicube/ImageTexture.h"

namespace radiant::render {
namespace {

constexpr int kRings = 16;      ///< from the zenith to the horizon (the picture is per pixel; these shape the outline)
constexpr int kSegments = 64;   ///< around the normal

/// A corner of the dome: its unit direction (local frame, z up) and its spherical coordinates.
/// The coordinates go with the vertex rather than being recovered per pixel: phi runs on to 2 pi at
/// the last segment, so no triangle straddles atan's branch cut, and the fragment shader needs no
/// acos or atan (two of each per pixel, twice over, were most of the dome's cost on software GL).
struct DomeVertex {
    glm::vec3 direction;
    glm::vec2 thetaPhi;  ///< radians
};

/// The dome's triangles, wound counter-clockwise seen from outside.
std::vector<DomeVertex> domeTriangles() {
    const auto at = [](int ring, int segment) {
        const double theta = std::numbers::pi / 2 * ring / kRings;
        const double phi = 2 * std::numbers::pi * segment / kSegments;
        return DomeVertex{glm::vec3(static_cast<float>(std::sin(theta) * std::cos(phi)),
                                    static_cast<float>(std::sin(theta) * std::sin(phi)),
                                    static_cast<float>(std::cos(theta))),
                          glm::vec2(static_cast<float>(theta), static_cast<float>(phi))};
    };
    std::vector<DomeVertex> triangles;
    triangles.reserve(static_cast<std::size_t>(kRings * kSegments * 6));
    for (int ring = 0; ring < kRings; ++ring)
        for (int segment = 0; segment < kSegments; ++segment) {
            const DomeVertex a = at(ring, segment), b = at(ring + 1, segment), c = at(ring + 1, segment + 1),
                             d = at(ring, segment + 1);
            triangles.insert(triangles.end(), {a, b, c, a, c, d});
        }
    return triangles;
}

} // namespace

struct HemisphereOverlay::State {
    gl::ShaderProgram program{"hemisphere.vert.glsl", "hemisphere.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
    ImageTexture sky;
    int imageSize = 0;
    glm::vec2 imageRight{-1, 0}, imageUp{0, 1};
    HemisphereOverlayPlacement placement;
    HemisphereOverlayStyle style;
};

HemisphereOverlay::HemisphereOverlay() : state_(std::make_unique<State>()) {
    const std::vector<DomeVertex> triangles = domeTriangles();
    state_->vertices.setData(std::span<const DomeVertex>(triangles));
    state_->vertexCount = static_cast<GLsizei>(triangles.size());
    state_->layout.addFloatAttribute(state_->vertices, 0, 3, sizeof(DomeVertex), offsetof(DomeVertex, direction));
    state_->layout.addFloatAttribute(state_->vertices, 1, 2, sizeof(DomeVertex), offsetof(DomeVertex, thetaPhi));
    glBindVertexArray(0);
}

HemisphereOverlay::~HemisphereOverlay() = default;
HemisphereOverlay::HemisphereOverlay(HemisphereOverlay&&) noexcept = default;
HemisphereOverlay& HemisphereOverlay::operator=(HemisphereOverlay&&) noexcept = default;

void HemisphereOverlay::setImage(int size, std::span<const std::uint8_t> rgba, double upAzimuth) {
    state_->sky.upload(size, size, rgba);
    state_->imageSize = size;
    // HemisphereViewMap's axes: up at upAzimuth in the tangent plane, right = normal x up.
    state_->imageUp = {static_cast<float>(std::cos(upAzimuth)), static_cast<float>(std::sin(upAzimuth))};
    state_->imageRight = {-state_->imageUp.y, state_->imageUp.x};
}

void HemisphereOverlay::setPlacement(const HemisphereOverlayPlacement& placement) { state_->placement = placement; }
void HemisphereOverlay::setStyle(const HemisphereOverlayStyle& style) { state_->style = style; }
bool HemisphereOverlay::hasImage() const { return state_->imageSize > 0; }

void HemisphereOverlay::draw(const Camera& camera, double aspect) const {
    if (!hasImage()) return;
    const gl::StateGuard saved;
    const State& s = *state_;
    const HemisphereOverlayPlacement& p = s.placement;
    s.program.use();
    s.program.set("viewProjection", glm::mat4(camera.viewProjection(aspect)));
    s.program.set("centre", glm::vec3(p.centre));
    s.program.set("tangent", glm::vec3(p.frame.tangent()));
    s.program.set("bitangent", glm::vec3(p.frame.bitangent()));
    s.program.set("normal", glm::vec3(p.frame.normal()));
    s.program.set("radius", static_cast<float>(p.radius));
    s.program.set("eye", glm::vec3(camera.eye));
    s.program.set("imageRight", glm::vec3(s.imageRight, 0.0f));
    s.program.set("imageUp", glm::vec3(s.imageUp, 0.0f));
    s.program.set("imageSize", static_cast<float>(s.imageSize));
    s.program.set("phiOfImageRight", static_cast<float>(std::atan2(s.imageRight.y, s.imageRight.x)));
    s.program.set("grid", s.style.grid ? 1 : 0);
    s.sky.bind(0);
    s.program.set("sky", 0);
    s.layout.bind();

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);  // the scene stays whole behind it
    glEnable(GL_CULL_FACE);
    // The far side first (its inside, seen through the near side): it shows what the point sees
    // looking away from the viewer, the same way the viewer looks, so it carries the picture; the
    // near side, showing what lies behind the viewer, is a lighter veil over it.
    s.program.set("frontOpacity", 0.0f);
    s.program.set("backOpacity", s.style.opacity);
    glCullFace(GL_FRONT);
    glDrawArrays(GL_TRIANGLES, 0, s.vertexCount);
    s.program.set("frontOpacity", 0.45f * s.style.opacity);
    s.program.set("backOpacity", 0.0f);
    glCullFace(GL_BACK);
    glDrawArrays(GL_TRIANGLES, 0, s.vertexCount);
}

} // namespace radiant::render
