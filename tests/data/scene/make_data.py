# Regenerates the tiny glTF test files next to this script (box.gltf, transforms.gltf, quad.glb).
# Run: python3 tests/data/scene/make_data.py
import base64, json, struct, zlib, os
out = os.path.dirname(os.path.abspath(__file__))

def png_rgba(w, h, pixels):
    raw = b''.join(b'\x00' + bytes(sum((list(pixels[y*w+x]) for x in range(w)), [])) for y in range(h))
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    return b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 6, 0, 0, 0)) + \
        chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')

def uri(data, mime='application/octet-stream'):
    return 'data:%s;base64,%s' % (mime, base64.b64encode(data).decode())

# ---- box.gltf: unit cube, camera, spot light with cookie, medium, textured material ----
cube = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
tris = [0,1,3, 0,3,2, 4,6,7, 4,7,5, 0,4,5, 0,5,1, 2,3,7, 2,7,6, 0,2,6, 0,6,4, 1,5,7, 1,7,3]
pos = b''.join(struct.pack('<3f', *p) for p in cube)
idx = b''.join(struct.pack('<H', i) for i in tris)
uvs = b''.join(struct.pack('<2f', (x + 0.5), (y + 0.5)) for (x, y, z) in cube)
buf = pos + idx + uvs
img = png_rgba(2, 2, [(255,0,0,255), (0,255,0,255), (0,0,255,255), (255,255,255,128)])
box = {
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "scene": 0,
  "scenes": [{"name": "box", "nodes": [0, 1, 2], "extras": {"medium": {"sigma_s": 0.1, "sigma_a": 0.02, "g": 0.3}}}],
  "nodes": [
    {"name": "cube", "mesh": 0},
    {"name": "cam", "camera": 0, "translation": [0, 1, 5]},
    {"name": "lamp", "translation": [0, 3, 0], "rotation": [-0.7071067811865476, 0, 0, 0.7071067811865476],
     "extensions": {"KHR_lights_punctual": {"light": 0}}}],
  "cameras": [{"name": "main", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "aspectRatio": 1.5}}],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "spot", "type": "spot", "color": [1.0, 0.5, 0.25], "intensity": 30.0,
     "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}, "extras": {"cookie": 0}}]}},
  "meshes": [{"name": "cube", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0}]}],
  "materials": [{"name": "paint", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.25, 1.0], "baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"name": "tiny", "uri": uri(img, 'image/png')}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": [-0.5]*3, "max": [0.5]*3},
    {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"},
    {"bufferView": 2, "componentType": 5126, "count": 8, "type": "VEC2"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                  {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)},
                  {"buffer": 0, "byteOffset": len(pos) + len(idx), "byteLength": len(uvs)}],
  "buffers": [{"byteLength": len(buf), "uri": uri(buf)}]
}
open(os.path.join(out, 'box.gltf'), 'w').write(json.dumps(box, indent=1))

# ---- transforms.gltf: a triangle under a scaled, translated parent and a rotated child; also
# instanced at the root, mirrored, and a POINTS primitive that must be skipped; a point light ----
tri = b''.join(struct.pack('<3f', *p) for p in [(1,0,0), (0,1,0), (0,0,1)])
s2 = 0.7071067811865476
nrm = b''.join(struct.pack('<3f', s2, s2, 0.0) for _ in range(3))
buf2 = tri + nrm
tr = {
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "scenes": [{"nodes": [0, 2, 3, 4], "extras": {"medium": {"sigma_s": 0.0, "sigma_a": 0.0, "g": 0.0}}}],
  "nodes": [
    {"name": "parent", "translation": [1, 2, 3], "scale": [2, 1, 1], "children": [1]},
    {"name": "child", "rotation": [0, 0, s2, s2], "mesh": 0},
    {"name": "plain", "mesh": 0},
    {"name": "mirror", "scale": [-1, 1, 1], "mesh": 0},
    {"name": "bulb", "translation": [0, 5, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 10.0}]}},
  "meshes": [{"name": "tri", "primitives": [
      {"attributes": {"POSITION": 0, "NORMAL": 1}},
      {"attributes": {"POSITION": 0}, "mode": 0}]}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,1]},
    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
  "buffers": [{"byteLength": len(buf2), "uri": uri(buf2)}]
}
open(os.path.join(out, 'transforms.gltf'), 'w').write(json.dumps(tr, indent=1))

# ---- quad.glb: binary container, an emissive quad facing +Y (area light) over nothing else ----
quad = [(-1,1,-1), (1,1,-1), (1,1,1), (-1,1,1)]
qp = b''.join(struct.pack('<3f', *p) for p in quad)
qi = b''.join(struct.pack('<I', i) for i in [0, 2, 1, 0, 3, 2])   # faces +Y: (0,2,1) is CCW from above
qbin = qp + qi
qjson = {
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_emissive_strength"],
  "scenes": [{"nodes": [0], "extras": {"medium": {"sigma_s": 0.2, "sigma_a": 0.1, "g": -0.5}}}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"name": "panel", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"name": "glow", "emissiveFactor": [1.0, 0.5, 0.25],
                 "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}}}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1,1,-1], "max": [1,1,1]},
    {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(qp)}, {"buffer": 0, "byteOffset": len(qp), "byteLength": len(qi)}],
  "buffers": [{"byteLength": len(qbin)}]
}
js = json.dumps(qjson).encode()
js += b' ' * ((4 - len(js) % 4) % 4)
qbin += b'\x00' * ((4 - len(qbin) % 4) % 4)
glb = struct.pack('<III', 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(qbin)) + \
      struct.pack('<II', len(js), 0x4E4F534A) + js + struct.pack('<II', len(qbin), 0x004E4942) + qbin
open(os.path.join(out, 'quad.glb'), 'wb').write(glb)
print('ok')
