#include "radiometry/scene/GltfWriter.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include <glm/common.hpp>
#include <tiny_gltf.h>

#include "radiometry/common/Error.h"

namespace radiant {
namespace {

tinygltf::Value numbers(const Rgb& v) {
    return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(v.x), tinygltf::Value(v.y), tinygltf::Value(v.z)});
}

tinygltf::Material toGltf(const Material& m) {
    tinygltf::Material out;
    out.name = m.name;
    const Rgb& rho = m.reflectance;
    out.pbrMetallicRoughness.baseColorFactor = {rho.x, rho.y, rho.z, 1.0};
    out.pbrMetallicRoughness.metallicFactor = 0.0;
    out.pbrMetallicRoughness.roughnessFactor = 1.0;
    // emissiveFactor is limited to [0, 1]; the strength extension carries the scale in W/m^2.
    const Rgb& e = m.exitance.value();
    const double strength = std::max({e.x, e.y, e.z});
    if (strength > 0) {
        out.emissiveFactor = {e.x / strength, e.y / strength, e.z / strength};
        tinygltf::Value::Object extension{{"emissiveStrength", tinygltf::Value(strength)}};
        out.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(extension);
    }
    tinygltf::Value::Object radiant{{"reflectance", numbers(rho)}, {"exitance_W_m2", numbers(e)}};
    out.extras = tinygltf::Value(tinygltf::Value::Object{{"radiant", tinygltf::Value(radiant)}});
    return out;
}

template <class T>
std::size_t append(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
    const std::size_t offset = bytes.size();
    bytes.resize(offset + values.size() * sizeof(T));
    std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
    return offset;
}

} // namespace

void writeGltf(const Scene& scene, const std::string& path) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Radiant tools/make_assets";
    model.extensionsUsed = {"KHR_materials_emissive_strength"};
    for (const Material& m : scene.materials) model.materials.push_back(toGltf(m));

    tinygltf::Buffer buffer;
    tinygltf::Scene root;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        std::vector<float> positions;
        std::vector<std::uint32_t> indices;
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
        for (const Face& face : surface.faces) {
            const auto first = static_cast<std::uint32_t>(positions.size() / 3);
            for (const glm::dvec3& v : face.vertices) {
                positions.insert(positions.end(), {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
                lo = glm::min(lo, glm::dvec3(glm::vec3(v)));
                hi = glm::max(hi, glm::dvec3(glm::vec3(v)));
            }
            for (std::uint32_t i = 1; i + 1 < face.vertices.size(); ++i) indices.insert(indices.end(), {first, first + i, first + i + 1});
        }
        const auto addView = [&](std::size_t offset, std::size_t length, int target) {
            tinygltf::BufferView view;
            view.buffer = 0;
            view.byteOffset = offset;
            view.byteLength = length;
            view.target = target;
            model.bufferViews.push_back(view);
            return static_cast<int>(model.bufferViews.size() - 1);
        };
        const std::size_t positionOffset = append(buffer.data, positions);
        tinygltf::Accessor position;
        position.bufferView = addView(positionOffset, positions.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
        position.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        position.type = TINYGLTF_TYPE_VEC3;
        position.count = positions.size() / 3;
        position.minValues = {lo.x, lo.y, lo.z};
        position.maxValues = {hi.x, hi.y, hi.z};
        model.accessors.push_back(position);

        const std::size_t indexOffset = append(buffer.data, indices);
        tinygltf::Accessor index;
        index.bufferView = addView(indexOffset, indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        index.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        index.type = TINYGLTF_TYPE_SCALAR;
        index.count = indices.size();
        model.accessors.push_back(index);

        tinygltf::Primitive primitive;
        primitive.attributes["POSITION"] = static_cast<int>(model.accessors.size() - 2);
        primitive.indices = static_cast<int>(model.accessors.size() - 1);
        primitive.material = static_cast<int>(surface.material);
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh mesh;
        mesh.name = surface.name;
        mesh.primitives.push_back(primitive);
        model.meshes.push_back(mesh);

        tinygltf::Node node;
        node.name = surface.name;
        node.mesh = static_cast<int>(s);
        model.nodes.push_back(node);
        root.nodes.push_back(static_cast<int>(s));
    }
    model.buffers.push_back(buffer);
    root.name = scene.name;
    model.scenes.push_back(root);
    model.defaultScene = 0;

    const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, true, binary))
        throw RadiantError({path, ""}, "could not write the glTF file");
}

} // namespace radiant
