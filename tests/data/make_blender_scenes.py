#!/usr/bin/env python3
"""Writes small glTF scenes shaped like Blender 3.4's exporter output at its defaults (Y up, every
material doubleSided, emission via KHR_materials_emissive_strength, lamps as KHR_lights_punctual,
cameras as core glTF cameras), and the external-file cases the loader must refuse.

    python3 tests/data/make_blender_scenes.py

Writes tests/data/blender/*.gltf (read by tests/unit/test_blender_scenes.cpp) and
tests/data/regression-gltf/external_* (read by tests/unit/test_fuzz_regressions.cpp), and copies the
latter into the glTF fuzzer's seed corpus.
"""
import base64
import json
import math
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
BLENDER = os.path.join(HERE, "blender")
REGRESSION = os.path.join(HERE, "regression-gltf")
CORPUS = os.path.join(HERE, "..", "fuzz", "corpus", "fuzz_gltf_loader")
GENERATOR = "Khronos glTF Blender I/O v3.4.50 (as written by tests/data/make_blender_scenes.py)"

# Blender's default plane: 2 m x 2 m in Blender's XY plane facing +Z, which the exporter turns into
# glTF's XZ plane facing +Y.
PLANE = [(-1, 0, 1), (1, 0, 1), (-1, 0, -1), (1, 0, -1)]
PLANE_TRIANGLES = [(0, 1, 3), (0, 3, 2)]


def cube_faces(half):
    """Blender's default cube (2 m), each face its own four corners, wound counter-clockwise seen
    from outside: the exporter's outward normals."""
    h = half
    faces = [
        [(h, -h, -h), (h, h, -h), (h, h, h), (h, -h, h)],      # +x
        [(-h, -h, h), (-h, h, h), (-h, h, -h), (-h, -h, -h)],  # -x
        [(-h, h, -h), (-h, h, h), (h, h, h), (h, h, -h)],      # +y
        [(-h, -h, h), (-h, -h, -h), (h, -h, -h), (h, -h, h)],  # -y
        [(-h, -h, h), (h, -h, h), (h, h, h), (-h, h, h)],      # +z
        [(h, -h, -h), (-h, -h, -h), (-h, h, -h), (h, h, -h)],  # -z
    ]
    positions, triangles = [], []
    for face in faces:
        base = len(positions)
        positions += face
        triangles += [(base, base + 1, base + 2), (base, base + 2, base + 3)]
    return positions, triangles


def scaled(points, s):
    return [(x * s, y * s, z * s) for x, y, z in points]


class Gltf:
    """Builds one glTF with every buffer inline (a data: URI), as the exporter's embedded mode."""

    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": GENERATOR}, "scene": 0, "scenes": [{"name": "Scene", "nodes": []}],
                    "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": []}
        self.raw = b""

    def _view(self, data):
        while len(self.raw) % 4:
            self.raw += b"\0"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.raw), "byteLength": len(data)})
        self.raw += data
        return len(self.doc["bufferViews"]) - 1

    def primitive(self, positions, triangles, material):
        flat = [c for p in positions for c in p]
        view = self._view(struct.pack("<%df" % len(flat), *flat))
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        self.doc["accessors"].append({"bufferView": view, "componentType": 5126, "count": len(positions), "type": "VEC3",
                                      "min": lo, "max": hi})
        indices = [i for t in triangles for i in t]
        view = self._view(struct.pack("<%dH" % len(indices), *indices))
        self.doc["accessors"].append({"bufferView": view, "componentType": 5123, "count": len(indices), "type": "SCALAR"})
        n = len(self.doc["accessors"])
        return {"attributes": {"POSITION": n - 2}, "indices": n - 1, "material": material}

    def material(self, name, colour, emission=None, double_sided=True, texture=None):
        m = {"name": name, "doubleSided": double_sided,
             "pbrMetallicRoughness": {"baseColorFactor": list(colour) + [1], "metallicFactor": 0, "roughnessFactor": 0.5}}
        if texture is not None:
            del m["pbrMetallicRoughness"]["baseColorFactor"]  # Blender writes none beside an image
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": texture}
        if emission is not None:
            m["emissiveFactor"] = [1, 1, 1]
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": emission}}
            self.doc.setdefault("extensionsUsed", [])
            if "KHR_materials_emissive_strength" not in self.doc["extensionsUsed"]:
                self.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def write(self, path):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.raw),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(self.raw).decode()}]
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)


def plane_lamp():
    """The default plane, left facing up, as a double-sided ceiling lamp 1 m above a 2 m x 2 m floor."""
    g = Gltf()
    lamp = g.material("Emission", (0, 0, 0), emission=10)
    floor = g.material("Floor", (0.5, 0.5, 0.5))
    g.node({"name": "Lamp", "mesh": g.mesh("Plane", [g.primitive(PLANE, PLANE_TRIANGLES, lamp)]), "translation": [0, 1, 0]})
    g.node({"name": "Floor", "mesh": g.mesh("Plane.001", [g.primitive(PLANE, PLANE_TRIANGLES, floor)])})
    g.write(os.path.join(BLENDER, "plane_lamp.gltf"))


def cube_room():
    """Blender's cube as a room, normals outward as the cube comes, with a small double-sided lamp
    inside: everything reflectance 0.5 (the closed enclosure's energy balance is exact then)."""
    g = Gltf()
    walls = g.material("Walls", (0.5, 0.5, 0.5))
    lamp = g.material("Emission", (0.5, 0.5, 0.5), emission=10)
    positions, triangles = cube_faces(1)
    g.node({"name": "Cube", "mesh": g.mesh("Cube", [g.primitive(positions, triangles, walls)])})
    g.node({"name": "Lamp", "mesh": g.mesh("Plane", [g.primitive(scaled(PLANE, 0.25), PLANE_TRIANGLES, lamp)]),
            "translation": [0, 0.5, 0]})
    g.write(os.path.join(BLENDER, "cube_room.gltf"))


def room_with_camera():
    """One object with two materials (the exporter makes one mesh of two primitives), a lamp, and
    Blender's default camera (39.6 degree field of view) turned to look along -x."""
    g = Gltf()
    floor = g.material("Floor", (0.6, 0.6, 0.6), double_sided=False)
    wall = g.material("Wall", (0.4, 0.4, 0.4), double_sided=False)
    lamp = g.material("Emission", (0, 0, 0), emission=5, double_sided=False)
    wall_quad = [(-1, 0, -1), (-1, 0, 1), (-1, 2, 1), (-1, 2, -1)]  # x = -1, facing +x
    g.node({"name": "Room", "mesh": g.mesh("Room", [g.primitive(PLANE, PLANE_TRIANGLES, floor),
                                                     g.primitive(wall_quad, [(0, 2, 1), (0, 3, 2)], wall)])})
    lamp_quad = [(x, 2, z) for x, _, z in scaled(PLANE, 0.3)]
    g.node({"name": "Lamp", "mesh": g.mesh("Lamp", [g.primitive(lamp_quad, [(0, 3, 1), (0, 2, 3)], lamp)])})
    half = math.sqrt(0.5)
    g.doc["cameras"] = [{"name": "Camera", "type": "perspective",
                         "perspective": {"yfov": 0.6911112070083618, "znear": 0.1, "zfar": 100, "aspectRatio": 1.7777777777777777}}]
    g.node({"name": "Camera", "camera": 0, "translation": [3, 1, 0], "rotation": [0, half, 0, half]})
    g.write(os.path.join(BLENDER, "room_camera.gltf"))


def point_lamp_only():
    """A floor lit only by a Blender point lamp: nothing Radiant reads emits."""
    g = Gltf()
    floor = g.material("Floor", (0.5, 0.5, 0.5))
    g.node({"name": "Floor", "mesh": g.mesh("Plane", [g.primitive(PLANE, PLANE_TRIANGLES, floor)])})
    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"name": "Lamp", "type": "point", "color": [1, 1, 1],
                                                               "intensity": 54.35141306588226}]}}
    g.node({"name": "Lamp", "translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    g.write(os.path.join(BLENDER, "point_lamp_only.gltf"))


def missing_texture():
    """A textured floor whose image (floor.png) was not copied along, under a lamp."""
    g = Gltf()
    floor = g.material("Floor", (1, 1, 1), texture=0)
    lamp = g.material("Emission", (0, 0, 0), emission=10)
    g.doc["textures"] = [{"source": 0}]
    g.doc["images"] = [{"name": "floor", "mimeType": "image/png", "uri": "floor.png"}]
    g.node({"name": "Floor", "mesh": g.mesh("Plane", [g.primitive(PLANE, PLANE_TRIANGLES, floor)])})
    g.node({"name": "Lamp", "mesh": g.mesh("Lamp", [g.primitive(scaled(PLANE, 0.25), PLANE_TRIANGLES, lamp)]),
            "translation": [0, 1, 0]})
    g.write(os.path.join(BLENDER, "missing_texture.gltf"))


def external(name, uri, byte_length=72, image_uri=None):
    """A lit unit square whose buffer (or image) lives in an external file named `uri`."""
    doc = {
        "asset": {"version": "2.0", "generator": GENERATOR},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "square", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"name": "lamp", "emissiveFactor": [1, 1, 1]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
        "buffers": [{"byteLength": byte_length, "uri": uri}],
    }
    if image_uri is not None:
        doc["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0}}
        doc["textures"] = [{"source": 0}]
        doc["images"] = [{"uri": image_uri}]
    return doc


def square_bytes():
    return struct.pack("<12f", 0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0) + struct.pack("<6I", 0, 1, 2, 0, 2, 3)


def external_files():
    """#17: buffer and image URIs that name what is not a file. Each must be refused in one line."""
    cases = {
        "external_directory.gltf": external("directory", "."),
        "external_fifo.gltf": external("fifo", "fifo.bin"),  # the test makes fifo.bin a FIFO in a copy
        "external_dev_zero.gltf": external("dev zero", "../" * 40 + "dev/zero"),
        "external_short.gltf": external("short", "external_short.bin"),
        "external_image_directory.gltf": external("image directory", "external_short.bin", 10, image_uri="."),
    }
    for name, doc in cases.items():
        with open(os.path.join(REGRESSION, name), "w") as f:
            json.dump(doc, f, indent=1)
        shutil.copy(os.path.join(REGRESSION, name), os.path.join(CORPUS, name))
    with open(os.path.join(REGRESSION, "external_short.bin"), "wb") as f:
        f.write(square_bytes()[:10])  # 10 of the 72 bytes byteLength promises
    # Allowed: a buffer in a sibling folder (docs/RELIABILITY.md says why).
    with open(os.path.join(BLENDER, "outside_folder.gltf"), "w") as f:
        json.dump(external("outside", "../gltf/square_external.bin"), f, indent=1)


def main():
    os.makedirs(BLENDER, exist_ok=True)
    plane_lamp()
    cube_room()
    room_with_camera()
    point_lamp_only()
    missing_texture()
    external_files()


if __name__ == "__main__":
    main()
