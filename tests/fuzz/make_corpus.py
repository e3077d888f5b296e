# Regenerates the fuzz seeds (corpus/) and the hand-written regressions (regressions/) next to this script.
#   python3 tests/fuzz/make_corpus.py [AIRLIGHT]      (AIRLIGHT: default build/ci/app/airlight)
# Seeds: every built-in scene exported by `airlight export-scene` as .gltf and .glb (a .gltf over
# MAX_GLTF_SEED bytes is left out, its .glb kept), then small hand-made files, one feature each.
# Regressions: minimal files for inputs that once crashed or hung the loader. Crash files copied in by
# hand (tests/fuzz/README.md) are left alone; only the files named here are rewritten.
# Every seed is self-contained: the fuzzer hands the loader one file and no folder, so buffers and
# images must be data: URIs or the GLB's own chunk.
import base64, json, os, struct, subprocess, sys, tempfile, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MAX_GLTF_SEED = 100_000
MEDIUM = {"sigma_s": 0.1, "sigma_a": 0.01, "g": 0.2}


def data_uri(data, mime="application/octet-stream"):
    return "data:%s;base64,%s" % (mime, base64.b64encode(bytes(data)).decode())


def png(width, height, rgba):
    """An 8-bit RGBA PNG from a flat list of width*height (r, g, b, a) tuples."""
    rows = b"".join(b"\0" + bytes(c for px in rgba[y * width:(y + 1) * width] for c in px) for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")


def glb(document, binary=b""):
    """A GLB container: the JSON chunk (space-padded) and, when there are bytes, the BIN chunk."""
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    if binary:
        binary = bytes(binary) + b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


class Doc:
    """Builds one glTF document whose accessors all live in one buffer."""

    FORMATS = {5120: "b", 5121: "B", 5122: "h", 5123: "H", 5125: "I", 5126: "f"}
    WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}

    def __init__(self):
        self.bin = bytearray()
        self.json = {"asset": {"version": "2.0", "generator": "airlight make_corpus.py"},
                     "bufferViews": [], "accessors": []}

    def view(self, data, **extra):
        self.bin += b"\0" * (-len(self.bin) % 4)
        self.json["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data), **extra})
        self.bin += data
        return len(self.json["bufferViews"]) - 1

    def accessor(self, values, kind="VEC3", component=5126, view=True, **extra):
        flat = [c for v in values for c in (v if isinstance(v, (tuple, list)) else (v,))]
        entry = {"componentType": component, "count": len(flat) // self.WIDTH[kind], "type": kind, **extra}
        if view:
            entry["bufferView"] = self.view(struct.pack("<%d%s" % (len(flat), self.FORMATS[component]), *flat))
        if kind == "VEC3" and component == 5126 and flat:
            entry["min"] = [min(flat[i::3]) for i in range(3)]
            entry["max"] = [max(flat[i::3]) for i in range(3)]
        self.json["accessors"].append(entry)
        return len(self.json["accessors"]) - 1

    def add(self, key, item):
        self.json.setdefault(key, []).append(item)
        return len(self.json[key]) - 1

    def light(self, light, node=None):
        lights = self.json.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        lights.append(light)
        used = self.json.setdefault("extensionsUsed", [])
        if "KHR_lights_punctual" not in used:
            used.append("KHR_lights_punctual")
        return self.add("nodes", {**(node or {}), "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})

    def image(self, data):
        self.add("images", {"uri": data_uri(data, "image/png")})
        return self.add("textures", {"source": len(self.json["images"]) - 1})

    def scene(self, medium=MEDIUM, **extra):
        scene = {"nodes": list(range(len(self.json.get("nodes", [])))), **extra}
        if medium is not None:
            scene["extras"] = {"medium": medium}
        self.json["scenes"] = [scene]
        return self

    def gltf(self):
        document = dict(self.json, buffers=[{"byteLength": len(self.bin), "uri": data_uri(self.bin)}])
        return json.dumps(document, separators=(",", ":")).encode()

    def glb(self):
        return glb(dict(self.json, buffers=[{"byteLength": len(self.bin)}]), self.bin)


TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
QUAD = [(-1.0, 2.0, -1.0), (1.0, 2.0, -1.0), (1.0, 2.0, 1.0), (-1.0, 2.0, 1.0)]  # faces -Y with QUAD_INDICES
QUAD_INDICES = [0, 1, 2, 0, 2, 3]
POINT = {"type": "point", "intensity": 20.0, "color": [1.0, 0.9, 0.8]}
ABOVE = {"translation": [0.3, 0.3, 2.0]}


def triangle_doc(light=True, **primitive):
    doc = Doc()
    attributes = {"POSITION": doc.accessor(TRIANGLE)}
    doc.add("meshes", {"name": "triangle", "primitives": [{"attributes": attributes, **primitive}]})
    doc.add("nodes", {"name": "triangle", "mesh": 0})
    if light:
        doc.light(POINT, ABOVE)
    return doc.scene()


def quad_doc(material, uvs=None):
    doc = Doc()
    attributes = {"POSITION": doc.accessor(QUAD)}
    if uvs:
        attributes["TEXCOORD_0"] = doc.accessor(uvs, "VEC2")
    doc.add("materials", material)
    indices = doc.accessor(QUAD_INDICES, "SCALAR", 5123)
    doc.add("meshes", {"primitives": [{"attributes": attributes, "indices": indices, "material": 0}]})
    doc.add("nodes", {"mesh": 0})
    return doc


def checker(size, on, off):
    return png(size, size, [on if (x + y) % 2 else off for y in range(size) for x in range(size)])


def edge_cases():
    """Small valid files, one feature each (name -> bytes)."""
    out = {}
    out["one_triangle.gltf"] = triangle_doc().gltf()
    out["one_triangle.glb"] = triangle_doc().glb()
    out["one_triangle_no_light_default_light.gltf"] = triangle_doc(light=False).gltf()
    out["one_triangle_no_medium.gltf"] = triangle_doc().scene(medium=None).gltf()
    glb_json_only = triangle_doc()
    out["glb_without_bin_chunk.glb"] = glb(json.loads(glb_json_only.gltf()))

    doc = triangle_doc(light=False)
    doc.light({"type": "directional", "intensity": 3.0}, {"rotation": [-0.3826834, 0.0, 0.0, 0.9238795]})
    doc.add("cameras", {"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.1, "aspectRatio": 1.5}})
    doc.add("nodes", {"camera": 0, "translation": [0.3, 0.3, 4.0]})
    out["directional_light_camera_no_zfar.gltf"] = doc.scene().gltf()

    doc = triangle_doc(light=False)
    cookie = doc.image(checker(4, (255, 255, 255, 255), (0, 0, 0, 255)))
    doc.light({"type": "spot", "intensity": 50.0, "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.5},
               "extras": {"cookie": cookie}}, ABOVE)
    out["spot_light_cookie_png.gltf"] = doc.scene().gltf()

    uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    doc = quad_doc({"name": "glow", "emissiveFactor": [1.0, 0.6, 0.3], "emissiveTexture": {"index": 0},
                    "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5.0}}}, uvs)
    doc.image(checker(2, (255, 200, 100, 255), (255, 255, 255, 255)))
    doc.json["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    out["emissive_quad_area_light.gltf"] = doc.scene().gltf()

    # Maps the loader leaves out: a normal map, and a texture reached only through MSFT_texture_dds
    # whose image no decoder reads; the base colour is texture 2, renumbered to 0 on load.
    doc = quad_doc({"name": "mapped", "normalTexture": {"index": 0},
                    "pbrMetallicRoughness": {"baseColorTexture": {"index": 2},
                                             "metallicRoughnessTexture": {"index": 1}}}, uvs)
    doc.image(checker(2, (128, 128, 255, 255), (128, 128, 255, 255)))
    doc.add("images", {"uri": data_uri(b"DDS |\0\0\0" + bytes(24), "image/png")})
    doc.add("textures", {"extensions": {"MSFT_texture_dds": {"source": len(doc.json["images"]) - 1}}})
    doc.image(checker(2, (200, 60, 60, 255), (60, 200, 60, 255)))
    doc.json["extensionsUsed"] = ["MSFT_texture_dds"]
    doc.light(POINT, ABOVE)
    out["unused_normal_map_and_dds_only_texture.gltf"] = doc.scene().gltf()
    out["emissive_quad_area_light.glb"] = doc.glb()

    doc = triangle_doc(material=0)
    doc.add("materials", {"emissiveFactor": [0.5, 0.5, 0.5]})
    out["emissive_triangle_not_rectangle.gltf"] = doc.gltf()

    doc = Doc()
    base = doc.accessor(TRIANGLE)
    moved = doc.view(struct.pack("<B", 2)), doc.view(struct.pack("<3f", 0.0, 2.0, 0.0))
    doc.json["accessors"][base]["sparse"] = {"count": 1, "indices": {"bufferView": moved[0], "componentType": 5121},
                                             "values": {"bufferView": moved[1]}}
    doc.json["accessors"][base]["max"][1] = 2.0
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": base}}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, ABOVE)
    out["sparse_accessor_positions.gltf"] = doc.scene().gltf()

    doc = Doc()
    zeros = doc.accessor([(0.0, 0.0, 0.0)] * 3, view=False)
    picks = doc.view(struct.pack("<2H", 1, 2)), doc.view(struct.pack("<6f", 1.0, 0.0, 0.0, 0.0, 1.0, 0.0))
    doc.json["accessors"][zeros]["sparse"] = {"count": 2, "indices": {"bufferView": picks[0], "componentType": 5123},
                                              "values": {"bufferView": picks[1]}}
    doc.json["accessors"][zeros]["max"] = [1.0, 1.0, 0.0]
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": zeros}}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, ABOVE)
    out["sparse_accessor_without_buffer_view.gltf"] = doc.scene().gltf()

    for bits, component in ((8, 5121), (16, 5123), (32, 5125)):
        doc = Doc()
        indices = doc.accessor([0, 1, 2, 2, 1, 3], "SCALAR", component)
        positions = doc.accessor(TRIANGLE + [(1.0, 1.0, 0.0)])
        doc.add("meshes", {"primitives": [{"attributes": {"POSITION": positions}, "indices": indices}]})
        doc.add("nodes", {"mesh": 0})
        doc.light(POINT, ABOVE)
        out["indices_%dbit.gltf" % bits] = doc.scene().gltf()

    doc = Doc()
    positions = doc.accessor(QUAD)
    bytes_uv = doc.accessor([(0, 0), (255, 0), (255, 255), (0, 255)], "VEC2", 5121, normalized=True)
    short_uv = doc.accessor([(0, 0), (65535, 0), (65535, 65535), (0, 65535)], "VEC2", 5123, normalized=True)
    doc.image(png(3, 2, [(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255)] * 2))
    doc.add("materials", {"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1.0],
                                                   "baseColorTexture": {"index": 0}}})
    indices = doc.accessor(QUAD_INDICES, "SCALAR", 5121)
    doc.add("meshes", {"primitives": [
        {"attributes": {"POSITION": positions, "TEXCOORD_0": bytes_uv}, "indices": indices, "material": 0},
        {"attributes": {"POSITION": positions, "TEXCOORD_0": short_uv}, "indices": indices, "material": 0}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, {"translation": [0.0, 0.0, 0.0]})
    out["normalized_uvs_base_color_texture.gltf"] = doc.scene().gltf()

    doc = triangle_doc(light=False)
    doc.json["nodes"][0] = {"name": "root", "translation": [1.0, 0.0, 0.0], "scale": [2.0, 2.0, 2.0],
                            "children": [1, 2]}
    doc.add("nodes", {"name": "rotated", "rotation": [0.0, 0.7071068, 0.0, 0.7071068], "mesh": 0, "children": [3]})
    doc.add("nodes", {"name": "instance", "translation": [0.0, 3.0, 0.0], "mesh": 0})
    doc.add("nodes", {"name": "grandchild", "translation": [0.0, 0.0, -2.0], "mesh": 0})
    doc.light(POINT, {"translation": [0.0, 5.0, 3.0]})
    doc.scene(nodes=[0, 4])
    out["node_hierarchy_trs_instancing.gltf"] = doc.gltf()

    doc = Doc()
    positions = doc.accessor(TRIANGLE)
    normals = doc.accessor([(0.0, 0.0, 1.0)] * 3)
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": positions, "NORMAL": normals}}]})
    mirror = [-1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0.5, 0, 0, 1.0]  # column-major, x flipped, moved +x
    doc.add("nodes", {"name": "mirrored", "matrix": mirror, "mesh": 0})
    doc.light(POINT, ABOVE)
    out["mirrored_matrix_with_normals.gltf"] = doc.scene().gltf()

    doc = Doc()
    interleaved = b"".join(struct.pack("<6f", *p, 0.0, 0.0, 1.0) for p in TRIANGLE)
    view = doc.view(interleaved, byteStride=24)
    doc.add("accessors", {"bufferView": view, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 0.0]})
    doc.add("accessors", {"bufferView": view, "byteOffset": 12, "componentType": 5126, "count": 3, "type": "VEC3"})
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, ABOVE)
    out["interleaved_byte_stride.gltf"] = doc.scene().gltf()

    doc = triangle_doc()
    others = [{"attributes": {"POSITION": 0}, "mode": mode} for mode in (0, 1, 2, 3, 5, 6)]
    doc.json["meshes"][0]["primitives"] += others
    out["primitive_modes_points_lines_strips.gltf"] = doc.gltf()

    doc = Doc()
    positions = doc.accessor(TRIANGLE)
    normals = doc.accessor([(0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)])
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": positions, "NORMAL": normals}}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, ABOVE)
    out["zero_length_normal.gltf"] = doc.scene().gltf()

    doc = triangle_doc()
    doc.json["scenes"] = [{"nodes": [0]}, {"nodes": [0, 1], "extras": {"medium": MEDIUM}}]
    doc.json["scene"] = 1
    out["two_scenes_default_is_second.gltf"] = doc.gltf()

    doc = triangle_doc()
    doc.scene(medium={"sigma_s": 0.2, "sigma_a": "thick", "g": -0.3, "colour": [1, 2, 3]})
    out["medium_unknown_key_and_string.gltf"] = doc.gltf()
    return out


def regressions():
    """Minimal files for inputs that once crashed or hung the loader (name -> bytes)."""
    out = {}
    doc = triangle_doc()
    doc.json["accessors"][0]["byteOffset"] = 18446744073709551604  # 2^64 - 12: offset + size wraps to 0
    out["accessor_byte_offset_wraps_2p64.gltf"] = doc.gltf()
    doc = triangle_doc()
    doc.json["bufferViews"][0]["byteOffset"] = 18446744073709551552  # 2^64 - 64
    out["buffer_view_byte_offset_wraps_2p64.gltf"] = doc.gltf()
    doc = triangle_doc()
    doc.json["accessors"][0]["count"] = 4611686018427387904  # 2^62: count * 12 wraps
    out["accessor_count_2p62_size_wraps.gltf"] = doc.gltf()

    text = triangle_doc().gltf().decode()
    deep = "[" * 20000 + "]" * 20000
    nested = text.replace('"asset":{', '"asset":{"extras":%s,' % deep, 1)
    out["asset_extras_json_nested_20000_deep.gltf"] = nested.encode()

    doc = triangle_doc(light=False)
    doc.json["nodes"] = [{"children": [i + 1, i + 1]} for i in range(64)] + [{"mesh": 0}]
    doc.light(POINT, ABOVE)
    doc.scene(nodes=[0, 65])
    out["node_children_repeated_64_levels.gltf"] = doc.gltf()

    for name, uri in (("dot", "."), ("dotdot", "..")):
        document = json.loads(triangle_doc().gltf())
        document["buffers"][0]["uri"] = uri
        out["buffer_uri_%s.gltf" % name] = json.dumps(document, separators=(",", ":")).encode()

    doc = Doc()
    positions = doc.accessor(TRIANGLE)
    indices = doc.accessor([0, 1, 2147483647], "SCALAR", 5125)
    doc.add("meshes", {"primitives": [{"attributes": {"POSITION": positions}, "indices": indices}]})
    doc.add("nodes", {"mesh": 0})
    doc.light(POINT, ABOVE)
    out["index_value_int32_max.gltf"] = doc.scene().gltf()

    doc = triangle_doc(material=0)
    doc.add("materials", {"pbrMetallicRoughness": {"baseColorFactor": [-1.0, 0.5, -0.25, 1.0]}})
    out["base_color_factor_negative.gltf"] = doc.gltf()

    text = triangle_doc().gltf().decode()
    out["light_intensity_1e400.gltf"] = text.replace('"intensity":20.0', '"intensity":1e400', 1).encode()
    assert b"1e400" in out["light_intensity_1e400.gltf"]
    # Finite as a double, but not as a float, and intensity x colour overflows.
    out["light_intensity_1p7e308.gltf"] = text.replace('"intensity":20.0', '"intensity":1.7e308', 1).encode()
    return out


def builtin_scenes(airlight):
    """Every built-in scene as .gltf and .glb, exported by the app (name -> bytes)."""
    listing = subprocess.run([airlight, "list", "scenes"], check=True, capture_output=True, text=True).stdout
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in (line.split()[0] for line in listing.splitlines() if line.strip()):
            for ext in ("glb", "gltf"):
                path = os.path.join(tmp, "%s.%s" % (name, ext))
                subprocess.run([airlight, "export-scene", name, path], check=True, capture_output=True)
                data = open(path, "rb").read()
                if ext == "gltf":
                    data = self_contained(json.loads(data), tmp)
                    if len(data) > MAX_GLTF_SEED:
                        print("make_corpus: %s.gltf has %d bytes, kept only as .glb" % (name, len(data)))
                        continue
                out["builtin_%s.%s" % (name, ext)] = data
    return out


def self_contained(document, folder):
    """The document with every external buffer and image turned into a data: URI, as compact JSON."""
    for key, mime in (("buffers", "application/octet-stream"), ("images", "image/png")):
        for item in document.get(key, []):
            uri = item.get("uri")
            if uri and not uri.startswith("data:"):
                item["uri"] = data_uri(open(os.path.join(folder, uri), "rb").read(), item.get("mimeType", mime))
    return json.dumps(document, separators=(",", ":")).encode()


def write(folder, files):
    os.makedirs(folder, exist_ok=True)
    for name, data in sorted(files.items()):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    return sum(len(d) for d in files.values())


def main():
    airlight = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "ci", "app", "airlight")
    seeds = edge_cases()
    if os.access(airlight, os.X_OK):
        seeds.update(builtin_scenes(airlight))
    else:
        print("make_corpus: %s not found, built-in scenes left as they are" % airlight)
    corpus_bytes = write(os.path.join(HERE, "corpus"), seeds)
    fixed = regressions()
    regression_bytes = write(os.path.join(HERE, "regressions"), fixed)
    print("make_corpus: %d seeds (%d bytes), %d regressions (%d bytes)" %
          (len(seeds), corpus_bytes, len(fixed), regression_bytes))


if __name__ == "__main__":
    main()
