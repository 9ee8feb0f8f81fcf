#pragma once
// A colour triple (or a point, a normal) in the commands' JSON: [x, y, z].
#include <nlohmann/json.hpp>

#include "radiometry/units/Quantity.h"

namespace radiant::app {

/// [v.x, v.y, v.z] as `Json` (nlohmann::json, or ordered_json where the keys' order is the output's).
template <class Json = nlohmann::ordered_json>
Json rgbArray(const Rgb& v) {
    return Json::array({v.x, v.y, v.z});
}

} // namespace radiant::app
