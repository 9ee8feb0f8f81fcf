#include "radiometry/scene/GltfMaterials.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include <algorithm>

#include <glm/common.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/common/NumberText.h"

namespace radiant::detail {
namespace {

constexpr double kMaxReflectance = 0.999;
/// What an unreadable base colour texture averages to: the grey a primitive without material gets.
constexpr double kMissingTextureMean = 0.5;

std::string rgbText(const Rgb& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", v.x, v.y, v.z);
    return text;
}

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

/// Mean linear colour of a decoded 8- or 16-bit image; false when the image is unusable.
bool imageMean(const tinygltf::Image& image, Rgb& mean) {
    const int channels = image.component;
    const std::size_t bytesPerChannel = image.bits == 16 ? 2 : 1;
    const std::size_t pixels = static_cast<std::size_t>(std::max(image.width, 0)) * static_cast<std::size_t>(std::max(image.height, 0));
    if (channels < 1 || pixels == 0 || (image.bits != 8 && image.bits != 16) ||
        image.image.size() < pixels * static_cast<std::size_t>(channels) * bytesPerChannel)
        return false;
    const double scale = image.bits == 16 ? 65535.0 : 255.0;
    Rgb sum(0.0);
    for (std::size_t p = 0; p < pixels; ++p) {
        Rgb texel;
        for (int c = 0; c < 3; ++c) {
            const std::size_t channel = static_cast<std::size_t>(std::min(c, channels == 2 ? 0 : channels - 1));
            const std::size_t at = (p * static_cast<std::size_t>(channels) + channel) * bytesPerChannel;
            double raw = image.image[at];
            if (bytesPerChannel == 2) {
                std::uint16_t wide;
                std::memcpy(&wide, &image.image[at], 2);
                raw = wide;
            }
            texel[c] = srgbToLinear(raw / scale);  // base colour textures are sRGB encoded
        }
        sum += texel;
    }
    mean = sum / static_cast<double>(pixels);
    return true;
}

bool readRgb(const tinygltf::Value& value, Rgb& out) {
    if (!value.IsArray() || value.ArrayLen() != 3) return false;
    for (int i = 0; i < 3; ++i) {
        const tinygltf::Value& v = value.Get(i);
        if (!v.IsNumber()) return false;
        out[i] = v.GetNumberAsDouble();
    }
    return true;
}

} // namespace

Material convertMaterial(const tinygltf::Model& model, std::size_t index, const std::string& file,
                         std::vector<std::string>& warnings) {
    const tinygltf::Material& source = model.materials[index];
    Material material;
    material.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
    const SourceLocation where{file, "material " + std::to_string(index) + " '" + material.name + "'"};

    const auto& base = source.pbrMetallicRoughness.baseColorFactor;
    Rgb reflectance(base.size() > 0 ? base[0] : 1.0, base.size() > 1 ? base[1] : 1.0, base.size() > 2 ? base[2] : 1.0);
    const int texture = source.pbrMetallicRoughness.baseColorTexture.index;
    if (texture >= 0) {
        const int image = static_cast<std::size_t>(texture) < model.textures.size() ? model.textures[static_cast<std::size_t>(texture)].source : -1;
        const bool hasImage = image >= 0 && static_cast<std::size_t>(image) < model.images.size();
        Rgb mean;
        if (hasImage && imageMean(model.images[static_cast<std::size_t>(image)], mean)) {
            reflectance *= mean;
        } else {
            // The factor alone is often white (Blender writes none beside a texture), which would
            // clamp to 0.999: a mid grey stands in for the texture, and the warning says so.
            reflectance *= kMissingTextureMean;
            const std::string uri = hasImage ? model.images[static_cast<std::size_t>(image)].uri : std::string();
            const std::string what = "base colour texture " + std::to_string(texture) +
                                     (uri.empty() || uri.rfind("data:", 0) == 0 ? std::string() : " '" + uri + "'");
            warnings.push_back(where.str() + ": " + what + " could not be read; using reflectance " + rgbText(reflectance) +
                               " (baseColorFactor x " + numberText(kMissingTextureMean) + ", a mid grey) instead");
        }
    }

    const auto& emissive = source.emissiveFactor;
    Rgb exitance(emissive.size() > 0 ? emissive[0] : 0.0, emissive.size() > 1 ? emissive[1] : 0.0, emissive.size() > 2 ? emissive[2] : 0.0);
    const auto strength = source.extensions.find("KHR_materials_emissive_strength");
    if (strength != source.extensions.end() && strength->second.Has("emissiveStrength") &&
        strength->second.Get("emissiveStrength").IsNumber())
        exitance *= strength->second.Get("emissiveStrength").GetNumberAsDouble();

    // extras.radiant carries exact SI values and wins over the PBR mapping.
    if (source.extras.Has("radiant")) {
        const tinygltf::Value& radiant = source.extras.Get("radiant");
        if (radiant.Has("reflectance") && !readRgb(radiant.Get("reflectance"), reflectance))
            throw RadiantError(where, "extras.radiant.reflectance must be an array of three numbers");
        if (radiant.Has("exitance_W_m2") && !readRgb(radiant.Get("exitance_W_m2"), exitance))
            throw RadiantError(where, "extras.radiant.exitance_W_m2 must be an array of three numbers");
    }

    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(reflectance[c]) || reflectance[c] < 0)
            throw RadiantError(where, "reflectance " + rgbText(reflectance) + " must lie in [0, 1)");
        if (!std::isfinite(exitance[c]) || exitance[c] < 0)
            throw RadiantError(where, "negative or non-finite emission " + rgbText(exitance) + " W/m^2");
    }
    if (reflectance.x >= 1 || reflectance.y >= 1 || reflectance.z >= 1) {
        warnings.push_back(where.str() + ": reflectance " + rgbText(reflectance) +
                           " would create energy; bands >= 1 clamped to 0.999");
        reflectance = glm::min(reflectance, Rgb(kMaxReflectance));
    }
    material.reflectance = reflectance;
    material.exitance = ExitanceRgb{exitance};
    return material;
}

} // namespace radiant::detail
