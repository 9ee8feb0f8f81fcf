#include <chrono>
#include <string>
#include <vector>

#include "app/bench/BenchTable.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/SceneLibrary.h"

namespace radiant::app {

BenchTable benchScenes(const BenchOptions& options) {
    BenchTable table;
    table.title = "Scenes: load cornell-box.gltf and mesh it";
    table.columns = {"max patch area (cm^2)", "load (s, median)", "mesh (s, median)", "load + mesh (s)", "patches", "vertices"};
    const int repeats = options.quick ? 3 : 9;
    std::vector<double> areasCm2{100, 10, 1};
    if (!options.quick) areasCm2.push_back(0.25);

    for (const double areaCm2 : areasCm2) {
        std::vector<double> loadSeconds, meshSeconds;
        std::size_t patches = 0, vertices = 0;
        for (int r = 0; r < repeats; ++r) {
            auto start = std::chrono::steady_clock::now();
            const LoadedScene loaded = loadScene("cornell-box");
            loadSeconds.push_back(secondsSince(start));
            start = std::chrono::steady_clock::now();
            const PatchMesh mesh = meshScene(loaded.scene, {areaCm2 * 1e-4});
            meshSeconds.push_back(secondsSince(start));
            patches = mesh.size();
            vertices = mesh.vertices.size();
        }
        const double load = median(loadSeconds), mesh = median(meshSeconds);
        table.rows.push_back({formatNumber(areaCm2), formatNumber(load), formatNumber(mesh), formatNumber(load + mesh),
                              std::to_string(patches), std::to_string(vertices)});
    }
    table.notes.push_back("Medians over " + std::to_string(repeats) +
                          " repeats; loading parses the glTF and merges its triangles back into quads.");
    return table;
}

} // namespace radiant::app
