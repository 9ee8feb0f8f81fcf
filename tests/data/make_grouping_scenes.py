#!/usr/bin/env python3
"""Writes the finely tessellated scenes of issue #20 item 5 (patch counts must follow the requested
patch area, not the triangles) into tests/data/grouping/:

- rounded_cube_room.gltf: a rounded cube as a subdivided, bevelled Blender cube exports: the
  superellipsoid x^4 + y^4 + z^4 = 1 (2 m across), every side a 16 x 16 grid of quads split into
  triangles, the grid lines crowding towards the edges as a bevel's do (3,072 triangles from 6e-5
  to 0.019 m^2, mean 0.0057), reflectance 0.5, floating 0.2 m above the floor of a closed 3 m cube
  room (walls facing inward, reflectance 0.5) lit by a 0.6 m square ceiling lamp 1 cm below the
  ceiling (50 W/m^2, black).
- bevelled_box_room.gltf: a box as Blender's cube exports after "subdivide" (12 cuts) and a bevel of
  its edges (radius 0.15 m, 4 segments): 1.2 m across, every side a 16 x 16 grid (12 x 12 on its
  flat face, 2 bevel rows on each side), so 3,072 triangles; the flat faces and the bevel's strips
  are exactly planar, the corners are spherical. Reflectance 0.5, 0.3 m above the floor of the
  rounded cube's room.
- bevelled_box_furnace.gltf: the same box seen from inside (triangles facing inward), emitting
  1 W/m^2 and reflecting 0.5: a convex furnace, B = E / (1 - rho) = 2 W/m^2 on every patch.
- cylinder_room.gltf: a cylinder (radius 0.4 m, 1 m tall, 48 segments, its side in 4 rows) whose caps
  are fans of 4 rings, 336 triangles each, as one primitive, 0.1 m above the floor of the same room.
- sphere_room.gltf: a UV sphere (radius 0.5 m, 32 segments x 16 rings, 960 triangles, reflectance
  0.5) outward, its centre 1 m above the floor of the rounded cube's room: a lit curved object.
- furnace_sphere.gltf: the inside of a closed UV sphere (radius 1 m, 32 segments x 16 rings,
  triangles facing inward, tiny ones at the poles and large ones at the equator) that emits
  1 W/m^2 and reflects 0.5: the furnace, B = E / (1 - rho) = 2 W/m^2 on every patch.

Materials are single-sided with exact SI values in extras.radiant. Read by
tests/unit/test_meshing_tessellated.cpp and tests/unit/test_triangle_grouping.cpp.
    python3 tests/data/make_grouping_scenes.py
"""
import base64
import json
import math
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "grouping")
GRID = 16  # quads along each side of the rounded cube's faces


def rounded_cube(half, lift):
    """Positions and counter-clockwise (seen from outside) triangles of the superellipsoid
    |x|^4 + |y|^4 + |z|^4 = half^4 over a GRID x GRID grid on each side, lifted by `lift` in y."""
    positions, index = [], {}

    def vertex(p):
        key = tuple(round(c * 1e6) for c in p)  # grid points shared by two or three sides
        if key not in index:
            norm = sum(c ** 4 for c in p) ** 0.25
            x, y, z = (half * c / norm for c in p)
            index[key] = len(positions)
            positions.append((x, y + lift, z))
        return index[key]

    def graded(i):  # grid lines crowd towards the edges, as a bevel's segments do
        return math.sin(math.pi / 2 * (-1 + 2 * i / GRID))

    triangles = []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0:
                u_axis, v_axis = v_axis, u_axis  # keep the winding counter-clockwise from outside

            def point(i, j):
                p = [0.0, 0.0, 0.0]
                p[axis] = sign
                p[u_axis] = graded(i)
                p[v_axis] = graded(j)
                return vertex(p)

            for i in range(GRID):
                for j in range(GRID):
                    a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
                    triangles += [(a, b, c), (a, c, d)]
    return positions, triangles


def bevelled_box(half, radius, lift, inward):
    """A box of half-size `half` whose edges are rounded with `radius`: the points of the cube's
    surface grid mapped to the inner box [-a, a]^3 (a = half - radius) plus `radius` along the
    direction from the nearest inner point, so the flat part stays put. Grid lines per side: 12
    uniform ones across the flat part, then bevel rows at 22.5 and 45 degrees."""
    a = half - radius
    flat = [-a + 2 * a * k / 12 for k in range(13)]
    bevel = [a + radius * math.tan(math.pi / 8), half]
    lines = [-b for b in reversed(bevel)] + flat + bevel
    grid = len(lines) - 1
    positions, index = [], {}

    def vertex(p):
        key = tuple(round(c * 1e6) for c in p)
        if key not in index:
            c = [max(-a, min(a, x)) for x in p]
            d = [x - y for x, y in zip(p, c)]
            n = math.sqrt(sum(x * x for x in d))
            q = [y + radius * x / n for x, y in zip(d, c)]
            index[key] = len(positions)
            positions.append((q[0], q[1] + lift, q[2]))
        return index[key]

    triangles = []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0:
                u_axis, v_axis = v_axis, u_axis

            def point(i, j):
                p = [0.0, 0.0, 0.0]
                p[axis] = sign * half
                p[u_axis] = lines[i]
                p[v_axis] = lines[j]
                return vertex(p)

            for i in range(grid):
                for j in range(grid):
                    a_, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
                    triangles += [(a_, b, c), (a_, c, d)]
    if inward:
        triangles = [(x, z, y) for x, y, z in triangles]
    return positions, triangles


def cylinder(radius, height, segments, rows, rings, lift):
    """A closed cylinder standing on y = lift, its caps fans of `rings` rings around their centres."""
    positions, triangles = [], []

    def rim(y, r):
        start = len(positions)
        for k in range(segments):
            angle = 2 * math.pi * k / segments
            positions.append((r * math.cos(angle), y, -r * math.sin(angle)))
        return start

    side = [rim(lift + height * j / rows, radius) for j in range(rows + 1)]
    for j in range(rows):
        for k in range(segments):
            a, b = side[j] + k, side[j] + (k + 1) % segments
            c, d = side[j + 1] + (k + 1) % segments, side[j + 1] + k
            triangles += [(a, b, c), (a, c, d)]  # counter-clockwise from outside
    for y, up, outer in ((lift + height, True, side[rows]), (lift, False, side[0])):
        ring_start = [rim(y, radius * ring / rings) for ring in range(1, rings)] + [outer]
        positions.append((0.0, y, 0.0))
        centre = len(positions) - 1

        def oriented(t):
            return t if up else (t[0], t[2], t[1])

        for k in range(segments):
            triangles.append(oriented((centre, ring_start[0] + k, ring_start[0] + (k + 1) % segments)))
        for ring in range(rings - 1):
            for k in range(segments):
                a, b = ring_start[ring] + k, ring_start[ring] + (k + 1) % segments
                c, d = ring_start[ring + 1] + (k + 1) % segments, ring_start[ring + 1] + k
                triangles += [oriented((a, d, c)), oriented((a, c, b))]
    return positions, triangles


def uv_sphere(radius, segments, rings, inward):
    positions = [(0.0, radius, 0.0)]
    for ring in range(1, rings):
        polar = math.pi * ring / rings
        for seg in range(segments):
            azimuth = 2 * math.pi * seg / segments
            positions.append((radius * math.sin(polar) * math.cos(azimuth), radius * math.cos(polar),
                              -radius * math.sin(polar) * math.sin(azimuth)))
    positions.append((0.0, -radius, 0.0))
    south = len(positions) - 1

    def at(ring, seg):
        return 1 + (ring - 1) * segments + seg % segments

    triangles = []
    for seg in range(segments):
        triangles.append((0, at(1, seg), at(1, seg + 1)))
        triangles.append((south, at(rings - 1, seg + 1), at(rings - 1, seg)))
    for ring in range(1, rings - 1):
        for seg in range(segments):
            a, b = at(ring, seg), at(ring, seg + 1)
            c, d = at(ring + 1, seg + 1), at(ring + 1, seg)
            triangles += [(a, d, c), (a, c, b)]
    if inward:
        triangles = [(a, c, b) for a, b, c in triangles]
    return positions, triangles


def room_quads(width, height, depth):
    """The six walls of [-w/2, w/2] x [0, h] x [-d/2, d/2], counter-clockwise seen from inside."""
    x0, x1, y0, y1, z0, z1 = -width / 2, width / 2, 0.0, height, -depth / 2, depth / 2
    outward = {
        "floor": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        "ceiling": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        "wall west": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        "wall east": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        "wall north": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        "wall south": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
    }
    return [(name, list(reversed(quad))) for name, quad in outward.items()]


def material(name, rho, exitance=None):
    radiant = {"reflectance": [rho] * 3}
    if exitance:
        radiant["exitance_W_m2"] = [exitance] * 3
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [rho] * 3 + [1]}, "extras": {"radiant": radiant}}


def write(path, scene_name, surfaces, materials):
    """surfaces: (name, material index, positions, triangles)."""
    raw = b""
    accessors, views, meshes, nodes = [], [], [], []
    for name, mat, points, tris in surfaces:
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
                                                      "indices": len(accessors) - 1, "material": mat}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_grouping_scenes.py"},
        "scene": 0,
        "scenes": [{"name": scene_name, "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(raw), "uri": "data:application/octet-stream;base64," + base64.b64encode(raw).decode()}],
    }
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, path), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def main():
    surfaces = [(name, 0, quad, [(0, 1, 2), (0, 2, 3)]) for name, quad in room_quads(3.0, 3.0, 3.0)]
    s, y = 0.3, 3.0 - 0.01
    surfaces.append(("ceiling lamp", 1, [(-s, y, -s), (s, y, -s), (s, y, s), (-s, y, s)], [(0, 1, 2), (0, 2, 3)]))
    positions, triangles = rounded_cube(1.0, 1.2)
    surfaces.append(("rounded cube", 2, positions, triangles))
    write("rounded_cube_room.gltf", "rounded cube room", surfaces,
          [material("grey walls", 0.5), material("lamp", 0.0, 50.0), material("grey cube", 0.5)])

    room = [(name, 0, quad, [(0, 1, 2), (0, 2, 3)]) for name, quad in room_quads(3.0, 3.0, 3.0)]
    room.append(surfaces[6])
    positions, triangles = bevelled_box(0.6, 0.15, 0.9, inward=False)
    write("bevelled_box_room.gltf", "bevelled box room", room + [("bevelled box", 2, positions, triangles)],
          [material("grey walls", 0.5), material("lamp", 0.0, 50.0), material("grey box", 0.5)])
    positions, triangles = bevelled_box(0.6, 0.15, 0.0, inward=True)
    write("bevelled_box_furnace.gltf", "bevelled box furnace", [("box inside", 0, positions, triangles)],
          [material("glowing grey", 0.5, 1.0)])
    positions, triangles = cylinder(0.4, 1.0, 48, 4, 4, 0.1)
    write("cylinder_room.gltf", "cylinder room", room + [("cylinder", 2, positions, triangles)],
          [material("grey walls", 0.5), material("lamp", 0.0, 50.0), material("grey cylinder", 0.5)])

    positions, triangles = uv_sphere(0.5, 32, 16, inward=False)
    positions = [(x, y + 1.0, z) for x, y, z in positions]
    write("sphere_room.gltf", "sphere room", room + [("sphere", 2, positions, triangles)],
          [material("grey walls", 0.5), material("lamp", 0.0, 50.0), material("grey sphere", 0.5)])

    positions, triangles = uv_sphere(1.0, 32, 16, inward=True)
    write("furnace_sphere.gltf", "furnace sphere", [("sphere inside", 0, positions, triangles)],
          [material("glowing grey", 0.5, 1.0)])


if __name__ == "__main__":
    main()
