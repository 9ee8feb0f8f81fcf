#!/usr/bin/env python3
"""Writes tests/data/gltf/closed_room.gltf: a closed room as a user brings one, 4 m (x) by 3 m (z)
and 2.5 m high (y up), every wall facing inward, a 0.6 m square ceiling lamp facing down and a
cabinet (0.8 x 1.2 x 0.5 m, five faces facing out) standing on the floor. Materials carry exact SI
values in extras.radiant. Read by tests/gl/test_closed_room.cpp and tests/unit/test_front_picking.cpp.
    python3 tests/data/make_closed_room.py
"""
import base64
import json
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gltf", "closed_room.gltf")

W, D, H = 4.0, 3.0, 2.5  # x, z, y (m)


def box_faces(lo, hi, inward):
    """The six quads of the box [lo, hi], each as four corners counter-clockwise seen from its front
    (inside when `inward`), keyed by name."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    outward = {
        "floor": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],       # -y
        "ceiling": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],     # +y
        "wall west": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],   # -x
        "wall east": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],   # +x
        "wall north": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],  # -z
        "wall south": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # +z
    }
    return {name: (list(reversed(quad)) if inward else quad) for name, quad in outward.items()}


def main():
    surfaces = []  # (name, material index, [quads])
    room = box_faces((0, 0, 0), (W, H, D), inward=True)
    for name in ["floor", "ceiling", "wall west", "wall east", "wall north", "wall south"]:
        surfaces.append((name, {"floor": 1, "ceiling": 0}.get(name, 0), [room[name]]))
    s = 0.3  # lamp half-size; 1 cm below the ceiling, facing down
    lamp_y = H - 0.01
    surfaces.append(("ceiling lamp", 2, [[(W / 2 - s, lamp_y, D / 2 - s), (W / 2 + s, lamp_y, D / 2 - s),
                                          (W / 2 + s, lamp_y, D / 2 + s), (W / 2 - s, lamp_y, D / 2 + s)]]))
    cabinet = box_faces((0.4, 0.0, 0.3), (1.2, 1.2, 0.8), inward=False)
    surfaces.append(("cabinet", 3, [cabinet[n] for n in ["ceiling", "wall west", "wall east", "wall north", "wall south"]]))

    raw = b""
    accessors, views, meshes, nodes = [], [], [], []
    for name, material, quads in surfaces:
        positions = [c for quad in quads for corner in quad for c in corner]
        indices = [i for q in range(len(quads)) for i in (4 * q, 4 * q + 1, 4 * q + 2, 4 * q, 4 * q + 2, 4 * q + 3)]
        p = struct.pack("<%df" % len(positions), *positions)
        views.append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(p)})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": len(positions) // 3,
                          "type": "VEC3", "min": [min(positions[k::3]) for k in range(3)],
                          "max": [max(positions[k::3]) for k in range(3)]})
        raw += p
        i = struct.pack("<%dI" % len(indices), *indices)
        views.append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(i)})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"})
        raw += i
        meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                      "indices": len(accessors) - 1, "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    def material(name, rgb, exitance=None):
        radiant = {"reflectance": rgb}
        if exitance:
            radiant["exitance_W_m2"] = exitance
        return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": rgb + [1]}, "extras": {"radiant": radiant}}

    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_closed_room.py"},
        "scene": 0,
        "scenes": [{"name": "closed room", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [material("white plaster", [0.7, 0.7, 0.7]), material("oak floor", [0.55, 0.35, 0.2]),
                      material("lamp", [0.0, 0.0, 0.0], [400.0, 380.0, 340.0]),
                      material("blue cabinet", [0.15, 0.3, 0.6])],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(raw), "uri": "data:application/octet-stream;base64," + base64.b64encode(raw).decode()}],
    }
    with open(OUT, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
