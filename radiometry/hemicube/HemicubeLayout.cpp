#include "radiometry/hemicube/HemicubeLayout.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/hemicube/DeltaFormFactor.h"

namespace radiant {
namespace {

HemicubeFaceView faceView(HemicubeFace face, const glm::dvec3& forward, const glm::dvec3& up, int firstRow,
                          int rows, double bottom) {
    return {face, forward, up, glm::cross(forward, up), firstRow, rows, bottom};
}

} // namespace

HemicubeLayout::HemicubeLayout(int resolution) : resolution_(resolution) {
    if (resolution < 2 || resolution > 4096 || resolution % 2 != 0)
        throw RadiantError({"", "hemicube resolution"},
                           "must be even and within [2, 4096], got " + std::to_string(resolution));
    const int half = resolution / 2;
    const glm::dvec3 z{0, 0, 1};
    faces_ = {faceView(HemicubeFace::Top, z, {0, 1, 0}, 0, resolution, -1.0),
              faceView(HemicubeFace::PlusTangent, {1, 0, 0}, z, resolution, half, 0.0),
              faceView(HemicubeFace::MinusTangent, {-1, 0, 0}, z, resolution + half, half, 0.0),
              faceView(HemicubeFace::PlusBitangent, {0, 1, 0}, z, resolution + 2 * half, half, 0.0),
              faceView(HemicubeFace::MinusBitangent, {0, -1, 0}, z, resolution + 3 * half, half, 0.0)};

    const std::size_t count = static_cast<std::size_t>(width()) * static_cast<std::size_t>(height());
    deltaFormFactors_.resize(count);
    solidAngles_.resize(count);
    const double area = pixelArea();
    for (int row = 0; row < height(); ++row)
        for (int column = 0; column < width(); ++column) {
            const glm::dvec3 d = pixelDirection(column, row);
            const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(width()) +
                                  static_cast<std::size_t>(column);
            deltaFormFactors_[i] = deltaFormFactor(d, area);
            solidAngles_[i] = deltaSolidAngle(d, area);
        }
}

double HemicubeLayout::pixelArea() const {
    const double side = 2.0 / resolution_;
    return side * side;
}

HemicubeFace HemicubeLayout::faceOfRow(int row) const {
    for (auto it = faces_.rbegin(); it != faces_.rend(); ++it)
        if (row >= it->firstRow) return it->face;
    return HemicubeFace::Top;
}

glm::dvec3 HemicubeLayout::pixelDirection(int column, int row) const {
    const HemicubeFaceView& view = faces_[static_cast<std::size_t>(faceOfRow(row))];
    const double step = 2.0 / resolution_;
    const double sx = -1.0 + (column + 0.5) * step;
    const double sy = view.bottom + (row - view.firstRow + 0.5) * step;
    return view.forward + sx * view.right + sy * view.up;
}

std::size_t HemicubeLayout::pixelIndexOf(const glm::dvec3& d) const {
    const double ax = std::abs(d.x), ay = std::abs(d.y);
    HemicubeFace face = HemicubeFace::Top;
    if (d.z < std::max(ax, ay)) {
        if (ax >= ay)
            face = d.x >= 0 ? HemicubeFace::PlusTangent : HemicubeFace::MinusTangent;
        else
            face = d.y >= 0 ? HemicubeFace::PlusBitangent : HemicubeFace::MinusBitangent;
    }
    const HemicubeFaceView& view = faces_[static_cast<std::size_t>(face)];
    const double t = glm::dot(d, view.forward);
    const double sx = glm::dot(d, view.right) / t, sy = glm::dot(d, view.up) / t;
    const double step = 2.0 / resolution_;
    const int column = std::clamp(static_cast<int>(std::floor((sx + 1.0) / step)), 0, resolution_ - 1);
    const int rowInFace = std::clamp(static_cast<int>(std::floor((sy - view.bottom) / step)), 0, view.rows - 1);
    return static_cast<std::size_t>(view.firstRow + rowInFace) * static_cast<std::size_t>(resolution_) +
           static_cast<std::size_t>(column);
}

} // namespace radiant
