// libFuzzer target: arbitrary bytes as a .gltf (JSON text) or .glb (binary, by its magic) through
// radiant::loadGltfFromMemory, so our validation (indices, accessors, materials, budgets) runs on
// whatever tinygltf accepts. The only acceptable outcomes are a scene or a RadiantError; any other
// exception, crash or sanitizer report is a bug. Build and run with scripts/fuzz.
#include <cstddef>
#include <cstdint>
#include <span>

#include "radiometry/common/Error.h"
#include "radiometry/scene/GltfLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    radiant::SceneLoadOptions options;
    options.triangleBudget = 200'000;  // keep each input fast; the budget check itself is under test
    try {
        (void)radiant::loadGltfFromMemory(std::span<const unsigned char>(data, size), "fuzz-input", options);
    } catch (const radiant::RadiantError&) {
        // The clean refusal every bad file must end in.
    }
    return 0;
}
