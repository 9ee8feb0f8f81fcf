#include "radiometry/scene/GltfLoader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "radiometry/common/Error.h"
#include "radiometry/common/NumberText.h"
#include "radiometry/scene/GltfAccessors.h"
#include "radiometry/scene/GltfCameras.h"
#include "radiometry/scene/GltfExternalFiles.h"
#include "radiometry/scene/GltfLights.h"
#include "radiometry/scene/GltfMaterials.h"
#include "radiometry/scene/GltfReaderError.h"
#include "radiometry/scene/TriangleMerging.h"

namespace radiant {
namespace {

/// tinygltf's messages can span lines; ours are one line.
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
    return text;
}

bool hasBinaryMagic(std::span<const unsigned char> bytes) {
    return bytes.size() >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F';
}

/// File-system callbacks for bytes from memory: every external URI is refused, so loading
/// untrusted bytes (a fuzzer's, a network's) never reads or probes other files.
tinygltf::FsCallbacks noFileSystem() {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = [](const std::string&, void*) { return false; };
    callbacks.ExpandFilePath = [](const std::string& path, void*) { return path; };
    callbacks.ReadWholeFile = [](std::vector<unsigned char>*, std::string* error, const std::string& path, void*) {
        if (error) *error += "external file '" + path + "' refused: only self-contained glTF loads from memory";
        return false;
    };
    callbacks.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; };
    callbacks.user_data = nullptr;
    return callbacks;
}

glm::dmat4 localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glTF
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));  // glTF: x, y, z, w
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

struct Instance {
    int node = 0;
    glm::dmat4 world{1.0};
};

/// The same faces seen from behind: corners reversed but still fanning from the first, so the
/// ray caster's triangles of both sides coincide exactly.
std::vector<Face> reversed(std::vector<Face> faces) {
    for (Face& face : faces) {
        std::reverse(face.vertices.begin() + 1, face.vertices.end());
        face.updateGeometry();
    }
    return faces;
}

class Loader {
public:
    Loader(const std::string& path, const SceneLoadOptions& options) : path_(path), options_(options) {}
    Loader(std::span<const unsigned char> bytes, const std::string& name, const SceneLoadOptions& options)
        : path_(name), options_(options), memory_(bytes), fromMemory_(true) {}

    LoadedScene run() {
        readModel();
        const std::vector<Instance> instances = collectInstances();
        checkTriangleBudget(instances);
        for (const Instance& instance : instances) addNode(instance);
        countIgnoredLights();
        if (droppedTriangles_ > 0)
            result_.warnings.push_back(path_ + ": dropped " + std::to_string(droppedTriangles_) +
                                       " zero-area triangle(s), the first in " + firstDropped_);
        if (result_.scene.surfaces.empty()) throw RadiantError({path_, ""}, "no triangles to light (no triangle primitives in the scene)");
        result_.scene.name = path_;
        result_.scene.warnings = result_.warnings;
        return std::move(result_);
    }

private:
    void readModel() {
        if (fromMemory_) return readModelFromMemory();
        const std::vector<unsigned char> bytes = detail::readSceneFile(path_, options_.fileByteBudget);
        if (bytes.empty()) throw RadiantError({path_, ""}, "is empty, not a glTF file");
        if (bytes.size() > std::numeric_limits<unsigned int>::max())
            throw BudgetError({path_, ""}, "is " + threeDigits(static_cast<double>(bytes.size())) + " bytes; a glTF file is limited to 4 GiB");
        // Absolute, so tinygltf's fallback to the current directory ("./" + uri) is the only
        // relative candidate and the file system below refuses it.
        std::error_code ec;
        const std::filesystem::path folder = std::filesystem::absolute(path_, ec).parent_path();
        detail::checkExternalFiles(bytes, folder, path_, options_.fileByteBudget, result_.warnings);
        tinygltf::TinyGLTF reader;
        reader.SetFsCallbacks(detail::sceneFolderFileSystem(options_.fileByteBudget));
        std::string error, warning;
        const auto length = static_cast<unsigned int>(bytes.size());
        const bool ok = hasBinaryMagic(bytes)
                            ? reader.LoadBinaryFromMemory(&model_, &error, &warning, bytes.data(), length, folder.string())
                            : reader.LoadASCIIFromString(&model_, &error, &warning, reinterpret_cast<const char*>(bytes.data()), length, folder.string());
        if (!ok) throw RadiantError({path_, ""}, detail::gltfReaderErrorLine(error));
        addReaderWarnings(warning);
    }

    /// tinygltf's warnings, less those about external images checkExternalFiles already named.
    void addReaderWarnings(const std::string& warning) {
        std::string kept;
        for (std::size_t start = 0; start < warning.size();) {
            std::size_t end = warning.find('\n', start);
            if (end == std::string::npos) end = warning.size();
            const std::string line = warning.substr(start, end - start);
            start = end + 1;
            if (line.empty() || line.rfind("File not found", 0) == 0 || line.rfind("Failed to load external 'uri' for image", 0) == 0) continue;
            kept += (kept.empty() ? "" : "\n") + line;
        }
        if (!kept.empty()) result_.warnings.push_back(path_ + ": " + oneLine(kept));
    }

    /// Lights no node of the scene places shine nowhere; each is named.
    void countIgnoredLights() {
        for (std::size_t l = 0; l < model_.lights.size(); ++l) {
            if (placedLights_.count(static_cast<int>(l))) continue;
            const tinygltf::Light& light = model_.lights[l];
            const std::string name = light.name.empty() ? "light " + std::to_string(l) : "light " + std::to_string(l) + " '" + light.name + "'";
            result_.warnings.push_back(path_ + ": " + name + " (KHR_lights_punctual) is placed by no node of the scene; ignored");
        }
        result_.ignoredLights = model_.lights.size() - placedLights_.size() + unusableLights_;
    }

    void readModelFromMemory() {
        if (memory_.empty()) throw RadiantError({path_, ""}, "is empty, not a glTF file");
        if (memory_.size() > std::numeric_limits<unsigned int>::max())
            throw BudgetError({path_, ""}, "is " + threeDigits(static_cast<double>(memory_.size())) + " bytes; glTF from memory is limited to 4 GiB");
        const auto length = static_cast<unsigned int>(memory_.size());
        tinygltf::TinyGLTF reader;
        reader.SetFsCallbacks(noFileSystem());
        std::string error, warning;
        const bool ok = hasBinaryMagic(memory_)
                            ? reader.LoadBinaryFromMemory(&model_, &error, &warning, memory_.data(), length, "")
                            : reader.LoadASCIIFromString(&model_, &error, &warning, reinterpret_cast<const char*>(memory_.data()), length, "");
        if (!ok) throw RadiantError({path_, ""}, detail::gltfReaderErrorLine(error));
        addReaderWarnings(warning);
    }

    std::vector<Instance> collectInstances() {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const std::size_t which = model_.defaultScene >= 0 && static_cast<std::size_t>(model_.defaultScene) < model_.scenes.size()
                                          ? static_cast<std::size_t>(model_.defaultScene)
                                          : 0;
            roots = model_.scenes[which].nodes;
        } else {
            // No scene: every node that is nobody's child.
            std::set<int> children;
            for (const auto& node : model_.nodes) children.insert(node.children.begin(), node.children.end());
            for (int n = 0; n < static_cast<int>(model_.nodes.size()); ++n)
                if (!children.count(n)) roots.push_back(n);
        }
        std::vector<Instance> instances;
        for (int root : roots) visit(root, glm::dmat4(1.0), 0, instances);
        return instances;
    }

    void visit(int node, const glm::dmat4& parent, int depth, std::vector<Instance>& instances) {
        if (node < 0 || static_cast<std::size_t>(node) >= model_.nodes.size())
            throw RadiantError({path_, "node " + std::to_string(node)},
                               "out of range (node count " + std::to_string(model_.nodes.size()) + ")");
        if (depth > 256) throw RadiantError({path_, "node " + std::to_string(node)}, "the node hierarchy has a cycle or is deeper than 256");
        // A node may be the child of many nodes, so a small file can expand exponentially.
        if (++nodeVisits_ > kMaxNodeInstances)
            throw BudgetError({path_, "node " + std::to_string(node)},
                              "the node hierarchy expands to more than " + threeDigits(static_cast<double>(kMaxNodeInstances)) + " node instances");
        const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(node)];
        const glm::dmat4 world = parent * localTransform(n);
        if (n.mesh >= 0) instances.push_back({node, world});
        if (n.camera >= 0)
            if (auto camera = detail::readCamera(model_, n.camera, n.name, world, path_, result_.warnings))
                result_.scene.cameras.push_back(std::move(*camera));
        if (const int light = detail::nodeLightIndex(n, n.name.empty() ? "node " + std::to_string(node) : n.name, path_); light >= 0) {
            placedLights_.insert(light);
            if (auto placed = detail::readLight(model_, light, n.name, world, path_, result_.warnings))
                result_.scene.lights.push_back(std::move(*placed));
            else
                ++unusableLights_;
        }
        for (int child : n.children) visit(child, world, depth + 1, instances);
    }

    void checkTriangleBudget(const std::vector<Instance>& instances) const {
        double triangles = 0;
        for (const Instance& instance : instances) {
            const int mesh = model_.nodes[static_cast<std::size_t>(instance.node)].mesh;
            if (static_cast<std::size_t>(mesh) >= model_.meshes.size()) continue;  // reported when read
            for (const auto& primitive : model_.meshes[static_cast<std::size_t>(mesh)].primitives) {
                const auto position = primitive.attributes.find("POSITION");
                const std::size_t count = primitive.indices >= 0 ? detail::accessorCount(model_, primitive.indices)
                                          : position != primitive.attributes.end() ? detail::accessorCount(model_, position->second)
                                                                                    : 0;
                triangles += static_cast<double>(count / 3);
            }
        }
        if (triangles > static_cast<double>(options_.triangleBudget))
            throw BudgetError({path_, ""}, "the scene has " + threeDigits(triangles) + " triangles; the budget is " +
                                               threeDigits(static_cast<double>(options_.triangleBudget)));
    }

    std::size_t sceneMaterial(int gltfMaterial, const SourceLocation& where) {
        if (gltfMaterial >= 0 && static_cast<std::size_t>(gltfMaterial) >= model_.materials.size())
            throw RadiantError(where, "material " + std::to_string(gltfMaterial) + " out of range (material count " +
                                          std::to_string(model_.materials.size()) + ")");
        const auto known = materialOf_.find(gltfMaterial);
        if (known != materialOf_.end()) return known->second;
        Material material;
        if (gltfMaterial < 0) {
            material = {"default", Rgb{0.5}, ExitanceRgb{}};
            result_.warnings.push_back(where.str() + ": no material; using reflectance 0.5");
        } else {
            material = detail::convertMaterial(model_, static_cast<std::size_t>(gltfMaterial), path_, result_.warnings);
        }
        result_.scene.materials.push_back(std::move(material));
        materialOf_[gltfMaterial] = result_.scene.materials.size() - 1;
        return result_.scene.materials.size() - 1;
    }

    std::string uniqueName(std::string name) {
        const int seen = ++nameUses_[name];
        return seen == 1 ? name : name + " (" + std::to_string(seen) + ")";
    }

    void addNode(const Instance& instance) {
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(instance.node)];
        if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
            throw RadiantError({path_, "node " + std::to_string(instance.node)},
                               "mesh " + std::to_string(node.mesh) + " out of range (mesh count " + std::to_string(model_.meshes.size()) + ")");
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
        // A mirroring transform flips the winding; glTF says the front face flips with it.
        const bool mirrored = glm::determinant(glm::dmat3(instance.world)) < 0;
        const auto trianglePrimitives = std::count_if(mesh.primitives.begin(), mesh.primitives.end(), [](const tinygltf::Primitive& p) {
            return p.mode < 0 || p.mode == TINYGLTF_MODE_TRIANGLES;
        });
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const SourceLocation where{path_, "mesh " + std::to_string(node.mesh) + ", primitive " + std::to_string(p)};
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES) {
                result_.warnings.push_back(where.str() + ": mode " + std::to_string(mode) +
                                           " is not a triangle list (mode 4); skipped");
                continue;
            }
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) throw RadiantError(where, "has no POSITION attribute");
            std::vector<glm::dvec3> positions = detail::readPositions(model_, position->second, where);
            std::vector<std::uint32_t> indices;
            if (primitive.indices >= 0) {
                indices = detail::readIndices(model_, primitive.indices, where);
                for (std::uint32_t index : indices)
                    if (index >= positions.size())
                        throw RadiantError(where, "index " + std::to_string(index) + " out of range (vertex count " +
                                                      std::to_string(positions.size()) + ")");
            } else {
                indices.resize(positions.size());
                for (std::uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
            }
            if (indices.size() % 3 != 0)
                result_.warnings.push_back(where.str() + ": " + std::to_string(indices.size()) +
                                           " indices is not a multiple of 3; the last " + std::to_string(indices.size() % 3) + " ignored");
            for (glm::dvec3& v : positions) v = glm::dvec3(instance.world * glm::dvec4(v, 1.0));

            std::vector<std::array<std::uint32_t, 3>> triangles;
            triangles.reserve(indices.size() / 3);
            for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
                std::array<std::uint32_t, 3> tri{indices[t], indices[t + 1], indices[t + 2]};
                if (mirrored) std::swap(tri[1], tri[2]);
                const glm::dvec3 a = positions[tri[0]], b = positions[tri[1]], c = positions[tri[2]];
                const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
                // Zero area relative to the triangle's size (collinear or repeated corners).
                if (!(glm::length(glm::cross(b - a, c - a)) > 1e-12 * longest * longest)) {
                    if (droppedTriangles_++ == 0) firstDropped_ = where.element + " (triangle " + std::to_string(t / 3) + ")";
                    continue;
                }
                triangles.push_back(tri);
            }
            if (triangles.empty()) continue;

            std::string name = !node.name.empty() ? node.name : !mesh.name.empty() ? mesh.name : "mesh " + std::to_string(node.mesh);
            Surface surface;
            surface.material = sceneMaterial(primitive.material, where);
            // Blender splits an object by material into primitives of one mesh: name each part
            // after its material ("Room/Floor"), not by a counter ("Room (2)").
            if (trianglePrimitives > 1) name += "/" + result_.scene.materials[surface.material].name;
            surface.name = uniqueName(std::move(name));
            surface.faces = detail::mergeTriangles(positions, triangles, options_.groupCoplanarTriangles);
            surface.origin = where.element;
            const bool doubleSided = primitive.material >= 0 && model_.materials[static_cast<std::size_t>(primitive.material)].doubleSided;
            if (!doubleSided) {
                result_.scene.surfaces.push_back(std::move(surface));
                continue;
            }
            Surface back;
            back.name = uniqueName(surface.name + " (back)");
            back.material = surface.material;
            back.faces = reversed(surface.faces);
            back.origin = surface.origin + ", back side (doubleSided)";
            surface.side = FaceSide::Front;
            back.side = FaceSide::Back;
            result_.scene.surfaces.push_back(std::move(surface));
            result_.scene.surfaces.push_back(std::move(back));
        }
    }

    std::string path_;
    SceneLoadOptions options_;
    std::span<const unsigned char> memory_;
    bool fromMemory_ = false;
    tinygltf::Model model_;
    LoadedScene result_;
    std::map<int, std::size_t> materialOf_;
    std::map<std::string, int> nameUses_;
    std::set<int> placedLights_;
    std::size_t unusableLights_ = 0;
    static constexpr std::size_t kMaxNodeInstances = 100'000;
    std::size_t nodeVisits_ = 0;
    std::size_t droppedTriangles_ = 0;
    std::string firstDropped_;
};

} // namespace

LoadedScene loadGltf(const std::string& path, const SceneLoadOptions& options) { return Loader(path, options).run(); }

LoadedScene loadGltfFromMemory(std::span<const unsigned char> bytes, const std::string& name, const SceneLoadOptions& options) {
    return Loader(bytes, name, options).run();
}

} // namespace radiant
