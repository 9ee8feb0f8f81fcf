#!/usr/bin/env python3
"""Writes small glTF scenes lit by KHR_lights_punctual lights, shaped like Blender's exporter output
(make_blender_scenes.py's builder), for tests/unit/test_punctual_lights.cpp, and copies one of each
light type into the glTF fuzzer's seed corpus:

    python3 tests/data/make_light_scenes.py

Every light is white unless named otherwise, in candela (lux for the sun), so 179 cd is 1 W/sr per
band at Radiance's 179 lm/W. The rooms are 4 m x 3 m x 4 m (x and z in [-2, 2], y in [0, 3]) with
single-sided walls facing in.
"""
import math
import os
import shutil

from make_blender_scenes import Gltf

HERE = os.path.dirname(os.path.abspath(__file__))
LIGHTS = os.path.join(HERE, "lights")
CORPUS = os.path.join(HERE, "..", "fuzz", "corpus", "fuzz_gltf_loader")

# Inside faces of the room, each wound counter-clockwise seen from inside (normal pointing in).
ROOM = {
    "Floor": [(-2, 0, -2), (-2, 0, 2), (2, 0, 2), (2, 0, -2)],      # +y
    "Ceiling": [(-2, 3, -2), (2, 3, -2), (2, 3, 2), (-2, 3, 2)],    # -y
    "West": [(-2, 0, -2), (-2, 3, -2), (-2, 3, 2), (-2, 0, 2)],     # +x
    "East": [(2, 0, -2), (2, 0, 2), (2, 3, 2), (2, 3, -2)],         # -x
    "North": [(-2, 0, -2), (2, 0, -2), (2, 3, -2), (-2, 3, -2)],    # +z
    "South": [(-2, 0, 2), (-2, 3, 2), (2, 3, 2), (2, 0, 2)],        # -z
}
QUAD = [(0, 1, 2), (0, 2, 3)]
# Looking straight down (the node's local -z onto world -y): a quarter turn about +x.
DOWN = [-0.7071067811865476, 0, 0, 0.7071067811865476]


def lights_extension(g, lights):
    g.doc.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}


def room(g, reflectance):
    """The room's six faces, each its own node and material (reflectance[name], default 0)."""
    for name, quad in ROOM.items():
        rho = reflectance.get(name, 0.0)
        material = g.material(name, (rho, rho, rho), double_sided=False)
        g.node({"name": name, "mesh": g.mesh(name, [g.primitive(quad, QUAD, material)])})


def point_room(file, reflectance, colour=(1, 1, 1), intensity=179.0):
    g = Gltf()
    room(g, reflectance)
    lights_extension(g, [{"name": "Bulb", "type": "point", "color": list(colour), "intensity": intensity}])
    g.node({"name": "Bulb", "translation": [0.5, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    g.write(os.path.join(LIGHTS, file))


def spot_floor():
    """A 10 m floor under a spot 2 m up at the origin, pointing down: cone 0.3 rad inner, 0.5 outer."""
    g = Gltf()
    floor = g.material("Floor", (0.5, 0.5, 0.5), double_sided=False)
    g.node({"name": "Floor", "mesh": g.mesh("Floor", [g.primitive([(-5, 0, -5), (-5, 0, 5), (5, 0, 5), (5, 0, -5)], QUAD, floor)])})
    lights_extension(g, [{"name": "Spot", "type": "spot", "intensity": 179.0,
                          "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}}])
    g.node({"name": "Spot", "translation": [0, 2, 0], "rotation": DOWN, "extensions": {"KHR_lights_punctual": {"light": 0}}})
    g.write(os.path.join(LIGHTS, "spot_floor.gltf"))


def sun_floor():
    """A 10 m floor and a 2 m square roof 1 m above its middle (facing up), under a 1000 lx sun
    60 degrees from the zenith, shining towards -x."""
    g = Gltf()
    floor = g.material("Floor", (0.5, 0.5, 0.5), double_sided=False)
    roof = g.material("Roof", (0.5, 0.5, 0.5), double_sided=False)
    g.node({"name": "Floor", "mesh": g.mesh("Floor", [g.primitive([(-5, 0, -5), (-5, 0, 5), (5, 0, 5), (5, 0, -5)], QUAD, floor)])})
    g.node({"name": "Roof", "mesh": g.mesh("Roof", [g.primitive([(-1, 1, -1), (-1, 1, 1), (1, 1, 1), (1, 1, -1)], QUAD, roof)])})
    lights_extension(g, [{"name": "Sun", "type": "directional", "intensity": 1000.0}])
    # The node's axes as a matrix: local -z along d, local +y in the xy plane, local x = y cross z.
    theta = math.radians(60)
    d = (-math.sin(theta), -math.cos(theta), 0.0)          # where the light goes (local -z)
    up = (-math.cos(theta), math.sin(theta), 0.0)           # local +y, perpendicular to d
    x = (up[1] * -d[2] - up[2] * -d[1], up[2] * -d[0] - up[0] * -d[2], up[0] * -d[1] - up[1] * -d[0])  # y x z
    z = (-d[0], -d[1], -d[2])
    matrix = [x[0], x[1], x[2], 0, up[0], up[1], up[2], 0, z[0], z[1], z[2], 0, 0, 5, 0, 1]
    g.node({"name": "Sun", "matrix": matrix, "extensions": {"KHR_lights_punctual": {"light": 0}}})
    g.write(os.path.join(LIGHTS, "sun_floor.gltf"))


def dark_room():
    """The grey room with neither an emitting surface nor a light."""
    g = Gltf()
    room(g, {name: 0.5 for name in ROOM})
    g.write(os.path.join(LIGHTS, "dark_room.gltf"))


def main():
    os.makedirs(LIGHTS, exist_ok=True)
    # Black: the probe reads the bulb's direct light alone, E = I cos(theta) / r^2.
    point_room("point_black_room.gltf", {})
    # Only the floor reflects: it sees no other lit surface, so its B = rho H exactly.
    point_room("point_grey_floor.gltf", {"Floor": 0.5})
    # Uniformly grey and closed: sum A B = rho / (1 - rho) x 4 pi I, and the reference tracer.
    point_room("point_grey_room.gltf", {name: 0.5 for name in ROOM})
    # A coloured bulb of 100 cd: the colour's luminance-weighted Y keeps 100 cd.
    point_room("point_coloured_room.gltf", {}, colour=(1, 0.5, 0.25), intensity=100.0)
    spot_floor()
    sun_floor()
    dark_room()
    # Seeds for the glTF fuzzer's light parsing: one of each type.
    for name in ("point_black_room.gltf", "spot_floor.gltf", "sun_floor.gltf"):
        shutil.copy(os.path.join(LIGHTS, name), os.path.join(CORPUS, "lights_" + name))


if __name__ == "__main__":
    main()
