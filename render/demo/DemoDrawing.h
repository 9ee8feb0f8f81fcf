#pragma once
// What a lecture demo shows in the 3D view, as plain data: coloured triangles (with an optional
// contour coordinate for isolines), coloured line segments of a width in pixels, and text labels
// anchored at world points. The demos (app/panels/demos/) build one from their settings every frame;
// render/demo/DemoRenderer draws it and the lab writes the labels. GL-free, so the demos' pictures
// can be checked without a context.
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace radiant::render {

struct DemoVertex {
    glm::vec3 position{0.0f};  ///< m
    glm::vec4 colour{1.0f};    ///< sRGB-encoded, with opacity
    /// Isolines are drawn where this crosses an integer; negative: none on this triangle.
    float contour = -1.0f;
};

struct DemoSegment {
    glm::vec3 from{0.0f}, to{0.0f};  ///< m
    glm::vec4 colour{1.0f};          ///< sRGB-encoded, with opacity
    float widthPixels = 2.0f;        ///< at UI scale 1 (the renderer scales it with the UI)
};

struct DemoLabel {
    glm::vec3 anchor{0.0f};  ///< m: the label's left end (right end if `endsAtAnchor`), centred vertically
    std::string text;        ///< may hold several lines
    glm::vec4 colour{1.0f};
    /// Drawn at its anchor whatever it covers (a tick label, whose place is its meaning); other
    /// labels move clear of each other and of it (app/ui/LabelLayout.h).
    bool pinned = false;
    /// The text reads to the left of the anchor: a label beside the left of a figure stays against it
    /// whatever the text's width at the UI's scale.
    bool endsAtAnchor = false;
};

class DemoDrawing {
public:
    std::vector<DemoVertex> triangles;  ///< three per triangle, either winding (drawn two-sided)
    std::vector<DemoSegment> segments;
    std::vector<DemoLabel> labels;

    void triangle(const DemoVertex& a, const DemoVertex& b, const DemoVertex& c) { triangles.insert(triangles.end(), {a, b, c}); }
    /// Two triangles a-b-c, a-c-d in one colour.
    void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d, const glm::vec4& colour);
    void line(const glm::vec3& from, const glm::vec3& to, const glm::vec4& colour, float widthPixels = 2.0f) {
        segments.push_back({from, to, colour, widthPixels});
    }
    /// A dashed line: dashes of `dash` metres with gaps as long.
    void dashedLine(const glm::vec3& from, const glm::vec3& to, float dash, const glm::vec4& colour, float widthPixels = 2.0f);
    /// A closed polygon through the points.
    void loop(const std::vector<glm::vec3>& points, const glm::vec4& colour, float widthPixels = 2.0f);
    /// A circle of `radius` about `centre` in the plane spanned by the unit vectors u and v.
    void circle(const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float radius, const glm::vec4& colour,
                float widthPixels = 2.0f, int segments = 64);
    /// A filled sphere (latitude-longitude triangles).
    void sphere(const glm::vec3& centre, float radius, const glm::vec4& colour, int rings = 12);
    /// A shaft from `from` to `to` with a head of length `head` metres (lines).
    void arrow(const glm::vec3& from, const glm::vec3& to, float head, const glm::vec4& colour, float widthPixels = 3.0f);
    void label(const glm::vec3& anchor, std::string text, const glm::vec4& colour = glm::vec4(1.0f)) {
        labels.push_back({anchor, std::move(text), colour});
    }
    /// A label whose right end is at `anchor`.
    void labelLeftOf(const glm::vec3& anchor, std::string text, const glm::vec4& colour = glm::vec4(1.0f)) {
        labels.push_back({anchor, std::move(text), colour, false, true});
    }
    void pinnedLabel(const glm::vec3& anchor, std::string text, const glm::vec4& colour = glm::vec4(1.0f)) {
        labels.push_back({anchor, std::move(text), colour, true});
    }
};

/// The demos' shared palette (sRGB): bright on the lab's dark backdrop, distinct on a projector.
namespace demo_colour {
inline constexpr glm::vec4 kText{0.95f, 0.95f, 0.95f, 1.0f};
inline constexpr glm::vec4 kAxis{0.70f, 0.72f, 0.75f, 1.0f};
inline constexpr glm::vec4 kGrid{0.40f, 0.42f, 0.45f, 1.0f};
inline constexpr glm::vec4 kLight{1.00f, 0.85f, 0.30f, 1.0f};    ///< sources, the Sun
inline constexpr glm::vec4 kHighlight{1.00f, 0.45f, 0.10f, 1.0f};///< the thing the numbers are about
inline constexpr glm::vec4 kProbe{0.35f, 0.85f, 1.00f, 1.0f};    ///< probes, rays, cursor readouts
inline constexpr glm::vec4 kSurface{0.55f, 0.58f, 0.62f, 1.0f};
} // namespace demo_colour

} // namespace radiant::render
