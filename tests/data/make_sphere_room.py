#!/usr/bin/env python3
"""Writes tests/data/curved/sphere_room.gltf: a tessellated UV sphere (32 segments x 16 rings,
radius 0.5 m, as Blender's UV sphere exports: triangles, the quads split in two) of reflectance 0.5
standing in a closed 2 m cube room (walls facing inward, reflectance 0.5) lit by a 0.6 m square
ceiling lamp 1 cm below the ceiling (50 W/m^2, black). Materials are single-sided with exact SI
values in extras.radiant, so Gauss-Seidel, hierarchical radiosity and the path tracer solve the same
scene. Issue #20 item 6: hierarchical radiosity lost ~20% on such curved objects. Read by
tests/unit/test_hierarchical_curved.cpp; app/bench/HierarchicalAccuracy.cpp builds the same scene in code.
Also writes curved/sphere_room_double_sided.gltf, the same scene with the sphere's material
"doubleSided": true (Blender's default): its outside must light as the single-sided sphere's, its
inside, a closed cavity, must stay black (tests/unit/test_double_sided.cpp).
    python3 tests/data/make_sphere_room.py
"""
import base64
import json
import math
import os
import struct

FOLDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "curved")

SIZE = 2.0                    # room edge (m), floor at y = 0, x and z in [-1, 1]
RADIUS = 0.5                  # sphere (m)
CENTRE = (0.0, 0.7, 0.0)      # 0.2 m above the floor
SEGMENTS, RINGS = 32, 16


def uv_sphere():
    """Positions and counter-clockwise (seen from outside) triangles of Blender's UV sphere."""
    cx, cy, cz = CENTRE
    positions = [(cx, cy + RADIUS, cz)]
    for ring in range(1, RINGS):
        polar = math.pi * ring / RINGS
        for seg in range(SEGMENTS):
            azimuth = 2 * math.pi * seg / SEGMENTS
            positions.append((cx + RADIUS * math.sin(polar) * math.cos(azimuth), cy + RADIUS * math.cos(polar),
                              cz - RADIUS * math.sin(polar) * math.sin(azimuth)))
    positions.append((cx, cy - RADIUS, cz))
    south = len(positions) - 1

    def at(ring, seg):  # ring 1 .. RINGS - 1
        return 1 + (ring - 1) * SEGMENTS + seg % SEGMENTS

    triangles = []
    for seg in range(SEGMENTS):
        triangles.append((0, at(1, seg), at(1, seg + 1)))
        triangles.append((south, at(RINGS - 1, seg + 1), at(RINGS - 1, seg)))
    for ring in range(1, RINGS - 1):
        for seg in range(SEGMENTS):
            a, b = at(ring, seg), at(ring, seg + 1)
            c, d = at(ring + 1, seg + 1), at(ring + 1, seg)
            triangles += [(a, d, c), (a, c, b)]
    return positions, triangles


def room_quads():
    """The six walls, counter-clockwise seen from inside the room."""
    h = SIZE / 2
    lo, hi = (-h, 0.0, -h), (h, SIZE, h)
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    outward = {
        "floor": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        "ceiling": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        "wall west": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        "wall east": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        "wall north": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        "wall south": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
    }
    return [(name, list(reversed(quad))) for name, quad in outward.items()]


def write(file_name, sphere_double_sided):
    surfaces = []  # (name, material, positions, triangles)
    for name, quad in room_quads():
        surfaces.append((name, 0, quad, [(0, 1, 2), (0, 2, 3)]))
    s, y = 0.3, SIZE - 0.01
    lamp = [(-s, y, -s), (s, y, -s), (s, y, s), (-s, y, s)]  # facing down
    surfaces.append(("ceiling lamp", 1, lamp, [(0, 1, 2), (0, 2, 3)]))
    positions, triangles = uv_sphere()
    surfaces.append(("sphere", 2, positions, triangles))

    raw = b""
    accessors, views, meshes, nodes = [], [], [], []
    for name, material, points, tris in surfaces:
        flat = [c for p in points for c in p]
        data = struct.pack("<%df" % len(flat), *flat)
        views.append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(data)})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": len(points), "type": "VEC3",
                          "min": [min(p[k] for p in points) for k in range(3)],
                          "max": [max(p[k] for p in points) for k in range(3)]})
        raw += data
        indices = [i for t in tris for i in t]
        data = struct.pack("<%dI" % len(indices), *indices)
        views.append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(data)})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"})
        raw += data
        meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                      "indices": len(accessors) - 1, "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    def material(name, rho, exitance=None, double_sided=False):
        radiant = {"reflectance": [rho] * 3}
        if exitance:
            radiant["exitance_W_m2"] = [exitance] * 3
        result = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [rho] * 3 + [1]}, "extras": {"radiant": radiant}}
        if double_sided:
            result["doubleSided"] = True
        return result

    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_sphere_room.py"},
        "scene": 0,
        "scenes": [{"name": "sphere room", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [material("grey walls", 0.5), material("lamp", 0.0, 50.0), material("grey sphere", 0.5, double_sided=sphere_double_sided)],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(raw), "uri": "data:application/octet-stream;base64," + base64.b64encode(raw).decode()}],
    }
    os.makedirs(FOLDER, exist_ok=True)
    with open(os.path.join(FOLDER, file_name), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def main():
    write("sphere_room.gltf", False)
    write("sphere_room_double_sided.gltf", True)


if __name__ == "__main__":
    main()
