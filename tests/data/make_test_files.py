#!/usr/bin/env python3
"""Writes the small glTF files the loader tests read (tests/unit/test_gltf_loader.cpp).

Each file holds one case, good or bad, small enough to read by eye. Run from anywhere:
    python3 tests/data/make_test_files.py
"""
import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "gltf")


def f32(values):
    return struct.pack("<%df" % len(values), *values)


def data_uri(raw):
    return "data:application/octet-stream;base64," + base64.b64encode(raw).decode()


# A unit square in the plane y = 0 facing +y, as two triangles (0 1 2) (0 2 3).
SQUARE = [0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0]
SQUARE_INDICES = [0, 1, 2, 0, 2, 3]


def model(positions, indices=None, index_format="<I", index_type=5125, mode=None, material=None,
          materials=None, extra_buffer_bytes=b"", uri=None, nodes=None, meshes=None):
    """One primitive, one node; every argument changes one thing of the default good file."""
    raw = f32(positions)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(raw)}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(positions) // 3, "type": "VEC3"}]
    primitive = {"attributes": {"POSITION": 0}}
    if indices is not None:
        packed = b"".join(struct.pack(index_format, i) for i in indices)
        while len(raw) % 4:
            raw += b"\0"
        views.append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(packed)})
        accessors.append({"bufferView": 1, "componentType": index_type, "count": len(indices), "type": "SCALAR"})
        raw += packed
        primitive["indices"] = 1
    raw += extra_buffer_bytes
    if mode is not None:
        primitive["mode"] = mode
    primitive["material"] = 0 if material is None else material
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_test_files.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes or [{"name": "square", "mesh": 0}],
        "meshes": meshes or [{"name": "square mesh", "primitives": [primitive]}],
        "materials": materials or [{"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(raw), "uri": uri if uri is not None else data_uri(raw)}],
    }
    return gltf, raw


def write(name, gltf):
    with open(os.path.join(OUT, name), "w") as f:
        json.dump(gltf, f, indent=1)


def write_glb(name, gltf, raw):
    gltf = json.loads(json.dumps(gltf))
    del gltf["buffers"][0]["uri"]
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    binary = raw + b"\0" * (-len(raw) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


def png(width, height, rgb_rows):
    """A tiny RGB8 PNG, written by hand so no image library is needed."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    scanlines = b"".join(b"\0" + bytes(row) for row in rgb_rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(scanlines)) + chunk(b"IEND", b""))


def main():
    os.makedirs(OUT, exist_ok=True)

    # --- good files -------------------------------------------------------------------------
    good, raw = model(SQUARE, SQUARE_INDICES)
    write("square.gltf", good)
    write_glb("square.glb", good, raw)
    for fmt, kind, name in (("<B", 5121, "square_u8.gltf"), ("<H", 5123, "square_u16.gltf")):
        g, _ = model(SQUARE, SQUARE_INDICES, index_format=fmt, index_type=kind)
        write(name, g)
    # Non-indexed: the same two triangles spelled out.
    flat = []
    for i in SQUARE_INDICES:
        flat += SQUARE[3 * i:3 * i + 3]
    g, _ = model(flat)
    write("square_nonindexed.gltf", g)
    # External buffer beside the file.
    g, raw = model(SQUARE, SQUARE_INDICES, uri="square_external.bin")
    write("square_external.gltf", g)
    with open(os.path.join(OUT, "square_external.bin"), "wb") as f:
        f.write(raw)

    # Hierarchy: parent translated by (0, 2, 0) holds a child scaled by 2 and rotated 90 deg about x
    # (quaternion [sin 45, 0, 0, cos 45]); a second root uses a matrix translating by (5, 0, 0).
    g, _ = model(SQUARE, SQUARE_INDICES, nodes=[
        {"name": "parent", "translation": [0, 2, 0], "children": [1]},
        {"name": "child", "mesh": 0, "scale": [2, 2, 2], "rotation": [0.7071067811865476, 0, 0, 0.7071067811865476]},
        {"name": "moved", "mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
    ])
    g["scenes"] = [{"nodes": [0, 2]}]
    write("hierarchy.gltf", g)

    # Names: two nodes named "wall", one unnamed node whose mesh is named, one with neither.
    g, _ = model(SQUARE, SQUARE_INDICES, nodes=[
        {"name": "wall", "mesh": 0}, {"name": "wall", "mesh": 0, "translation": [0, 1, 0]},
        {"mesh": 0, "translation": [0, 2, 0]}, {"mesh": 1, "translation": [0, 3, 0]}])
    g["meshes"].append({"primitives": [dict(g["meshes"][0]["primitives"][0])]})
    g["scenes"] = [{"nodes": [0, 1, 2, 3]}]
    write("names.gltf", g)

    # Two squares side by side as four triangles: two quad faces after merging.
    strip = SQUARE + [2, 0, 1, 2, 0, 0]
    g, _ = model(strip, SQUARE_INDICES + [3, 2, 4, 3, 4, 5])
    write("two_squares.gltf", g)

    # Materials: emissive strength, extras.radiant override, and a texture whose mean is half.
    g, _ = model(SQUARE, SQUARE_INDICES, materials=[{
        "name": "lamp", "emissiveFactor": [1, 0.5, 0.25],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 8}},
        "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1]}}])
    g["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    write("emissive_strength.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES, materials=[{
        "name": "exact", "emissiveFactor": [1, 1, 1],
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1]},
        "extras": {"radiant": {"reflectance": [0.25, 0.5, 0.75], "exitance_W_m2": [100, 200, 300]}}}])
    write("extras_override.gltf", g)
    image = png(2, 1, [[255, 255, 255, 0, 0, 0]])  # white and black: linear mean 0.5
    g, _ = model(SQUARE, SQUARE_INDICES, materials=[{
        "name": "checker", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.6, 0.4, 1], "baseColorTexture": {"index": 0}}}])
    g["textures"] = [{"source": 0}]
    g["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}]
    write("textured.gltf", g)

    # --- bad files --------------------------------------------------------------------------
    text = json.dumps(good, indent=1)
    with open(os.path.join(OUT, "truncated.gltf"), "w") as f:
        f.write(text[: len(text) // 2])
    with open(os.path.join(OUT, "malformed.gltf"), "w") as f:
        f.write('{"asset": {"version": "2.0"}, "nodes": [ , ]}\n')
    # A line break inside a 1 kB base64 data URI: the JSON parser's message quotes everything it read
    # of that string, which the loader must not paste into one error line.
    with open(os.path.join(OUT, "malformed_base64.gltf"), "w") as f:
        payload = base64.b64encode(bytes(range(256)) * 3).decode()
        f.write('{"asset": {"version": "2.0"},\n "buffers": [{"byteLength": 768, "uri": "data:application/octet-stream;base64,'
                + payload + '\n"}]}\n')
    g, _ = model(SQUARE, SQUARE_INDICES, uri="does_not_exist.bin")
    write("missing_buffer.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES)
    g["bufferViews"][0]["byteLength"] = 4096  # the view reaches past its 72-byte buffer
    write("short_buffer.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES)
    g["accessors"][0]["count"] = 40  # 40 positions in a 48-byte view
    write("accessor_overrun.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES)
    g["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9
    write("accessor_missing.gltf", g)
    g, _ = model(SQUARE, [0, 1, 2, 0, 2, 7])
    write("index_out_of_range.gltf", g)
    g, _ = model(SQUARE[:3] + [float("nan"), 0, 1] + SQUARE[6:], SQUARE_INDICES)
    write("nan_position.gltf", g)
    g, _ = model(SQUARE[:3] + [float("inf"), 0, 1] + SQUARE[6:], SQUARE_INDICES)
    write("infinite_position.gltf", g)
    # Two good triangles plus two without area (a repeated corner, three collinear corners).
    g, _ = model(SQUARE + [0.5, 0, 0.5], SQUARE_INDICES + [0, 0, 1, 0, 4, 2])
    write("zero_area.gltf", g)
    # One primitive of lines beside the square.
    g, _ = model(SQUARE, SQUARE_INDICES)
    lines = dict(g["meshes"][0]["primitives"][0])
    lines["mode"] = 1
    g["meshes"][0]["primitives"].append(lines)
    write("lines.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES, materials=[{"name": "too white", "pbrMetallicRoughness": {"baseColorFactor": [1, 1.2, 0.5, 1]}}])
    write("reflectance_one.gltf", g)
    g, _ = model(SQUARE, SQUARE_INDICES, materials=[{"name": "dark lamp", "extras": {"radiant": {"exitance_W_m2": [-1, 0, 0]}}}])
    write("negative_emission.gltf", g)
    # A .glb whose binary chunk is cut short.
    with open(os.path.join(OUT, "square.glb"), "rb") as f:
        whole = f.read()
    with open(os.path.join(OUT, "truncated.glb"), "wb") as f:
        f.write(whole[: len(whole) - 40])


if __name__ == "__main__":
    main()
