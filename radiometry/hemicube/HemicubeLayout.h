#pragma once
// Where the five faces of a hemicube (Cohen & Greenberg, SIGGRAPH 1985) lie in one image, and what
// each pixel of it stands for: its direction, delta form factor and solid angle.
//
// The image ("atlas") is R pixels wide and 3R high, rows counted bottom-up as OpenGL stores them:
// the top face fills rows [0, R), then the four side faces (+tangent, -tangent, +bitangent,
// -bitangent) R/2 rows each, only their upper halves (the lower halves look below the horizon).
// Every face is seen by a camera at x looking along `forward`, with `up` upward on the image and
// right = forward x up, so a renderer and this table agree pixel for pixel.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace radiant {

enum class HemicubeFace : std::uint8_t { Top, PlusTangent, MinusTangent, PlusBitangent, MinusBitangent };

/// One face's camera in x's local frame (z = the normal), and its rectangle in the atlas.
struct HemicubeFaceView {
    HemicubeFace face = HemicubeFace::Top;
    glm::dvec3 forward{0, 0, 1};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 right{-1, 0, 0};
    int firstRow = 0;  ///< in the atlas, bottom-up
    int rows = 0;      ///< R for the top face, R / 2 for the sides
    /// The image-plane range the rows cover: [-1, 1] on the top face, [0, 1] (above the horizon) on the sides.
    double bottom = -1;
};

class HemicubeLayout {
public:
    /// Throws RadiantError unless the resolution is even and in [2, 4096].
    explicit HemicubeLayout(int resolution);

    [[nodiscard]] int resolution() const { return resolution_; }
    [[nodiscard]] int width() const { return resolution_; }
    [[nodiscard]] int height() const { return 3 * resolution_; }
    [[nodiscard]] std::size_t pixelCount() const { return deltaFormFactors_.size(); }
    [[nodiscard]] const std::array<HemicubeFaceView, 5>& faces() const { return faces_; }
    /// Area of one pixel on a face of half-width 1: (2 / R)^2.
    [[nodiscard]] double pixelArea() const;

    /// The pixel's centre on its face (distance 1 from x), in x's local frame: not unit length.
    [[nodiscard]] glm::dvec3 pixelDirection(int column, int row) const;
    [[nodiscard]] HemicubeFace faceOfRow(int row) const;
    /// Index into the atlas (row-major, bottom row first) of the pixel a local direction with
    /// z >= 0 passes through.
    [[nodiscard]] std::size_t pixelIndexOf(const glm::dvec3& localDirection) const;

    /// Per atlas pixel, row-major from the bottom row: delta form factor, solid angle (sr).
    [[nodiscard]] const std::vector<double>& deltaFormFactors() const { return deltaFormFactors_; }
    [[nodiscard]] const std::vector<double>& solidAngles() const { return solidAngles_; }

private:
    int resolution_;
    std::array<HemicubeFaceView, 5> faces_{};
    std::vector<double> deltaFormFactors_;
    std::vector<double> solidAngles_;
};

} // namespace radiant
