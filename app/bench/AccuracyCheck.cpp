#include "app/bench/AccuracyCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "app/bench/BenchTable.h"
#include "radiometry/common/Error.h"
#include "radiometry/reference/PathTracer.h"

namespace radiant::app {

PatchDistance patchDistance(const PatchMesh& mesh, const std::vector<Rgb>& solution, const std::vector<Rgb>& reference) {
    PatchDistance d;
    double area = 0;
    for (std::size_t p = 0; p < mesh.size() && p < solution.size() && p < reference.size(); ++p) {
        double worst = 0;
        bool lit = false;
        for (int b = 0; b < 3; ++b) {
            if (!(reference[p][b] > 1e-9)) continue;
            lit = true;
            worst = std::max(worst, std::abs(solution[p][b] - reference[p][b]) / reference[p][b]);
        }
        if (!lit) continue;
        d.mean += mesh.patches[p].area * worst;
        area += mesh.patches[p].area;
        d.over5Percent += worst > 0.05 ? 1 : 0;
    }
    if (area > 0) d.mean /= area;
    return d;
}

ReferencePoint pointOnSurface(const Scene& scene, const std::string& surface, const glm::dvec3& approximate) {
    const std::size_t s = scene.findSurface(surface);
    if (s == Scene::npos) throw RadiantError({scene.name, "bench accuracy"}, "no surface '" + surface + "'");
    for (const Face& face : scene.surfaces[s].faces) {
        const glm::dvec3 onPlane = approximate - glm::dot(face.normal, approximate - face.vertices[0]) * face.normal;
        try {
            const ReferencePoint at = locateReferencePoint(scene, onPlane, face.normal);
            if (at.surface == s) return at;
        } catch (const RadiantError&) {
        }
    }
    throw RadiantError({scene.name, "bench accuracy"}, "no point of '" + surface + "' near the one asked for");
}

// The centre is at least 8 cm from the side's edges on either block of the Cornell box.
ReferencePoint blockSide(const Scene& scene, const std::string& block, std::size_t side, double height) {
    const std::size_t s = scene.findSurface(block);
    if (s == Scene::npos) throw RadiantError({scene.name, "bench accuracy"}, "no surface '" + block + "'");
    const Face& face = scene.surfaces.at(s).faces.at(side);
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : face.vertices) centre += v / static_cast<double>(face.vertices.size());
    if (height >= 0) centre.y = height;
    return locateReferencePoint(scene, centre, face.normal);
}

std::vector<AccuracyPoint> accuracyPoints(const Scene& scene) {
    std::vector<AccuracyPoint> points;
    const auto add = [&](std::string label, const ReferencePoint& at) { points.push_back({std::move(label), at, {}}); };
    add("floor, front right", pointOnSurface(scene, "floor", {0.45, 0, 0.08}));
    add("floor, behind the short block", pointOnSurface(scene, "floor", {0.12, 0, 0.45}));
    add("ceiling, front right corner", pointOnSurface(scene, "ceiling", {0.50, 0.5488, 0.06}));
    add("ceiling, back left", pointOnSurface(scene, "ceiling", {0.10, 0.5488, 0.45}));
    add("back wall, centre", pointOnSurface(scene, "back wall", {0.28, 0.30, 0.5592}));
    add("back wall, high left", pointOnSurface(scene, "back wall", {0.08, 0.48, 0.5592}));
    add("green wall, centre", pointOnSurface(scene, "right wall", {0, 0.27, 0.28}));
    add("green wall, low back", pointOnSurface(scene, "right wall", {0, 0.07, 0.48}));
    // Away from the diagonal that splits the measured red wall into two triangles.
    add("red wall, low back", pointOnSurface(scene, "left wall", {0.553, 0.15, 0.40}));
    add("red wall, high front", pointOnSurface(scene, "left wall", {0.555, 0.47, 0.07}));
    for (std::size_t side = 1; side <= 4; ++side) {
        add("short block, side " + std::to_string(side), blockSide(scene, "short block", side));
        add("tall block, side " + std::to_string(side), blockSide(scene, "tall block", side));
    }
    return points;
}

MethodErrors errorsAgainstReference(const std::vector<AccuracyPoint>& points, const std::vector<ProbeReading>& readings) {
    MethodErrors errors;
    std::size_t terms = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const AccuracyPoint& point = points[k];
        const ProbeReading& reading = readings[k];
        for (int band = 0; band < 3; ++band) {
            const double bRef = point.reference.radiosity.value()[band];
            const double eRef = point.reference.irradiance.value()[band];
            const double bError = std::abs(reading.radiosity.value()[band] - bRef) / bRef;
            const double eError = std::abs(reading.irradiance.value()[band] - eRef) / eRef;
            errors.meanB += bError;
            errors.meanE += eError;
            ++terms;
            if (bError > errors.worstB) {
                errors.worstB = bError;
                errors.worstBAt = point.label;
            }
            errors.worstE = std::max(errors.worstE, eError);
        }
    }
    errors.meanB /= static_cast<double>(terms);
    errors.meanE /= static_cast<double>(terms);
    return errors;
}

double signedError(const Rgb& value, const Rgb& reference) {
    return ((value.x / reference.x - 1) + (value.y / reference.y - 1) + (value.z / reference.z - 1)) / 3;
}

std::string signedPercent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.2f%%", 100 * fraction);
    return text;
}

AccuracyTarget accuracyTarget(SolverMethod method) {
    if (method == SolverMethod::Hierarchical) return {0.005, 0.015, "0.5% / 1.5%"};
    return {};
}

ReferenceTrace traceReferences(const Scene& scene, const RayCaster& rays, std::vector<AccuracyPoint>& points,
                               double wantedError, std::chrono::duration<double> perPoint) {
    ReferenceTrace trace;
    const auto start = std::chrono::steady_clock::now();
    const PathTracer tracer(scene, rays);
    for (std::size_t k = 0; k < points.size(); ++k) {
        ReferenceRunOptions runOptions;
        runOptions.seed = 1000 + k;
        ReferenceRun run(tracer, points[k].at, runOptions);
        ReferenceStop stop;
        stop.relativeStandardError = wantedError;
        stop.time = perPoint;
        points[k].reference = run.runUntil(stop);
        trace.worstError = std::max(trace.worstError, points[k].reference.relativeStandardError());
        trace.paths += points[k].reference.samples;
    }
    trace.seconds = secondsSince(start);
    return trace;
}

} // namespace radiant::app
