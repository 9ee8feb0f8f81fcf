#pragma once
// The radiometry lecture's demos (K. Bala, "Radiometry and Rendering Equation", Cornell 2004), one
// panel each, one file each: sliders, the live numbers with their units, and the formula behind them.
// Each demo's numbers come from a plain function of its settings (radiometry/ does the physics), so
// the tests check them against docs/reference.md's closed forms. Each also draws in the 3D view
// (LectureDemo.h): its picture, one more member defined in the demo's file, uses the same numbers.
#include <vector>

#include "app/panels/demos/LectureDemo.h"
#include "radiometry/units/Quantity.h"

namespace radiant::app {

// --- Point source over a plane: inverse-square and cosine laws. ---
struct PointSourceSettings { double powerW = 100, heightM = 1, offsetM = 0; };
struct PointSourceNumbers {
    Intensity intensity;       ///< W/sr
    Length distance;           ///< m, source to the point on the plane
    double cosIncidence = 1;
    Irradiance irradiance;     ///< W/m^2 at the offset
    Irradiance directlyBelow;  ///< W/m^2 at offset 0
};
PointSourceNumbers pointSourceNumbers(const PointSourceSettings& s);

class PointSourceDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: point source over a plane"; }
    [[nodiscard]] const char* id() const override { return "point-source"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    PointSourceSettings settings;
};

// --- Diffuse emitter: P = L A pi. ---
struct DiffuseEmitterSettings { double radianceW_m2sr = 100, areaM2 = 1; };
struct DiffuseEmitterNumbers { Power power; Radiosity exitance; SolidAngle projectedSolidAngle; };
DiffuseEmitterNumbers diffuseEmitterNumbers(const DiffuseEmitterSettings& s);

class DiffuseEmitterDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: diffuse emitter"; }
    [[nodiscard]] const char* id() const override { return "diffuse-emitter"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    DiffuseEmitterSettings settings;
};

// --- The Sun, Earth and Mars. ---
struct SunPlanetNumbers {
    Length distance;
    SolidAngle lectureSolidAngle;     ///< the lecture's rounded value
    SolidAngle projectedAreaSolidAngle;  ///< pi R^2 / d^2
    SolidAngle exactSolidAngle;       ///< 2 pi (1 - cos alpha)
    Irradiance lectureIrradiance;     ///< L x lecture omega
    Irradiance irradiance;            ///< L x exact omega
};
struct SunNumbers { Radiance radiance; Length sunRadius; SunPlanetNumbers earth, mars; };
SunNumbers sunNumbers();

class SunDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: the Sun, Earth and Mars"; }
    [[nodiscard]] const char* id() const override { return "sun"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    double distanceAu = 5.2;  ///< a third planet the slider moves, from Jupiter's distance
};

// --- Solid angle of a square against A / R^2. ---
struct SquareSolidAngleSettings { double sideM = 1, distanceM = 2; };
struct SquareSolidAngleNumbers { SolidAngle exact; SolidAngle smallArea; double relativeError = 0; };
SquareSolidAngleNumbers squareSolidAngleNumbers(const SquareSolidAngleSettings& s);

class SquareSolidAngleDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: solid angle of a square"; }
    [[nodiscard]] const char* id() const override { return "square-solid-angle"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    SquareSolidAngleSettings settings;
};

// --- The dodecahedron's face of ~1 sr. ---
struct RegularSolidNumbers { int faces = 12; SolidAngle perFace; SolidAngle polygonRoute; };
/// 4 pi / n, and the same face's solid angle from its vertices (Van Oosterom & Strackee).
RegularSolidNumbers regularSolidNumbers(int faces);

class DodecahedronDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: one steradian (dodecahedron)"; }
    [[nodiscard]] const char* id() const override { return "dodecahedron"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    int faceChoice = 3;  ///< index into 4, 6, 8, 12, 20
};

// --- Radiance vs irradiance: projected area and cos theta. ---
struct RadianceIrradianceSettings { double radianceW_m2sr = 1000, sourceSolidAngleSr = 1e-3, tiltDeg = 30; };
struct RadianceIrradianceNumbers {
    Radiance radiance;            ///< unchanged by the tilt
    Irradiance irradiance;        ///< L omega cos(theta)
    double projectedAreaPerM2 = 1;///< cos(theta): the receiver's area seen from the source, per m^2
};
RadianceIrradianceNumbers radianceIrradianceNumbers(const RadianceIrradianceSettings& s);

class RadianceIrradianceDemo final : public LectureDemo {
public:
    [[nodiscard]] const char* title() const override { return "Demo: radiance vs irradiance"; }
    [[nodiscard]] const char* id() const override { return "radiance-irradiance"; }
    [[nodiscard]] render::DemoDrawing picture(const std::optional<PickRay>& cursor) const override;
    [[nodiscard]] DemoFraming framing() const override;
    void draw() override;
    RadianceIrradianceSettings settings;
};

} // namespace radiant::app
