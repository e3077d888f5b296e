// The loader against hostile and broken files: each case is a minimal hand-written document reproducing
// one finding of a fuzz campaign (out-of-bounds reads from offsets that wrap 64 bits, stack overflow from
// deep JSON, exponential visits of a node graph that is not a tree, folders and FIFOs as URIs, counts
// that exhaust memory, non-finite and negative values) or of real sample models (zero-length normals,
// no light, no medium). Every one must end in a one-line InputError or a finite scene, never a crash,
// a hang, an out-of-range read (the asan preset runs this file) or another exception.
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/validate.h"
#include "test_util.h"

namespace viz::scene {
namespace {

using test::expectInputError;
using test::hasNote;

// A one-triangle document over a 36-byte buffer given as a data URI (base64 of 9 floats, written out
// here), a point light, a camera and a medium. Fields are spliced in as raw JSON so each test breaks
// exactly one thing.
struct Tiny {
    std::string accessor = R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"})";
    std::string view = R"({"buffer": 0, "byteLength": 36})";
    std::string buffer;  // empty: the data URI
    std::string nodes = R"([{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]},
        {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 2, 0]}])";
    std::string sceneNodes = "[0, 1, 2]";
    std::string light = R"({"type": "point", "intensity": 5})";
    std::string primitive = R"({"attributes": {"POSITION": 0}})";
    std::string extraAccessors;   // appended to "accessors"
    std::string extraViews;       // appended to "bufferViews"
    std::string materials;        // the "materials" array, or empty
    std::string assetExtras = "{}";
    std::string sceneExtras = R"({"medium": {"sigma_s": 0.1}})";

    std::string json() const {
        // (0,0,0), (1,0,0), (0,1,0) as little-endian floats.
        const std::string data =
            "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
        std::string j = "{\"asset\": {\"version\": \"2.0\", \"extras\": " + assetExtras + "},\n";
        j += "\"scenes\": [{\"nodes\": " + sceneNodes + ", \"extras\": " + sceneExtras + "}],\n";
        j += "\"nodes\": " + nodes + ",\n";
        j += R"("cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 50}}],)";
        j += "\n\"extensions\": {\"KHR_lights_punctual\": {\"lights\": [" + light + "]}},\n";
        j += "\"meshes\": [{\"name\": \"tri\", \"primitives\": [" + primitive + "]}],\n";
        if (!materials.empty()) j += "\"materials\": " + materials + ",\n";
        j += "\"accessors\": [" + accessor + extraAccessors + "],\n";
        j += "\"bufferViews\": [" + view + extraViews + "],\n";
        j += "\"buffers\": [" + (buffer.empty() ? "{\"byteLength\": 36, \"uri\": \"" + data + "\"}" : buffer) + "]}\n";
        return j;
    }
};

// The base document's nodes, with extra fields on the mesh node (e.g. a transform to break).
std::string meshNodeWith(const std::string& fields) {
    return R"([{"mesh": 0, )" + fields + R"(}, {"camera": 0, "translation": [0, 0, 3]},
        {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 2, 0]}])";
}

class GltfHardening : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTempDir("hard"); }
    std::string write(const std::string& name, const std::string& text) {
        test::writeText(mDir / name, text);
        return (mDir / name).string();
    }
    std::string write(const Tiny& doc) { return write("doc.gltf", doc.json()); }
    std::filesystem::path mDir;
};

TEST_F(GltfHardening, TheBaseDocumentLoads) {
    const Scene s = loadGltf(write(Tiny{}));
    EXPECT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.lights.size(), 1u);
}

// ---- ranges that wrapped the old checks ----

TEST_F(GltfHardening, AccessorByteOffsetNear2To64) {
    Tiny d;
    d.accessor = R"({"bufferView": 0, "byteOffset": 18446744073709551604, "componentType": 5126, "count": 3, "type": "VEC3"})";
    expectInputError([&] { loadGltf(write(d)); }, "out of range of bufferView 0");
}

TEST_F(GltfHardening, BufferViewByteOffsetNear2To64) {
    Tiny d;
    d.view = R"({"buffer": 0, "byteOffset": 18446744073709551552, "byteLength": 36})";
    expectInputError([&] { loadGltf(write(d)); }, "out of range of buffer 0");
}

TEST_F(GltfHardening, AccessorCountNear2To62) {
    Tiny d;
    d.accessor = R"({"bufferView": 0, "componentType": 5126, "count": 4611686018427387904, "type": "VEC3"})";
    expectInputError([&] { loadGltf(write(d)); }, "out of range of bufferView 0");
}

TEST_F(GltfHardening, StrideTimesCountOverflows) {
    // 252 * (2^62) wraps 64 bits to a small number.
    Tiny d;
    d.view = R"({"buffer": 0, "byteLength": 36, "byteStride": 252})";
    d.accessor = R"({"bufferView": 0, "componentType": 5126, "count": 4611686018427387905, "type": "VEC3"})";
    expectInputError([&] { loadGltf(write(d)); }, "out of range of bufferView 0");
}

TEST_F(GltfHardening, StrideSmallerThanTheElement) {
    Tiny d;
    d.view = R"({"buffer": 0, "byteLength": 36, "byteStride": 4})";
    expectInputError([&] { loadGltf(write(d)); }, "byteStride 4 is smaller than");
}

TEST_F(GltfHardening, IndexAt2To31Minus1) {
    // One UNSIGNED_INT index of 2^31-1 (bytes FF FF FF 7F) in a second buffer view.
    Tiny d;
    d.buffer = R"({"byteLength": 48, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA////fwAAAAAAAAAA"})";
    d.extraViews = R"(, {"buffer": 0, "byteOffset": 36, "byteLength": 12})";
    d.extraAccessors = R"(, {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"})";
    d.primitive = R"({"attributes": {"POSITION": 0}, "indices": 1})";
    expectInputError([&] { loadGltf(write(d)); }, "index 2147483647 is out of range (3 vertices)");
}

// ---- JSON depth ----

TEST_F(GltfHardening, DeepJsonInAssetExtrasIsRefusedBeforeParsing) {
    Tiny d;
    d.assetExtras = std::string(20000, '[') + std::string(20000, ']');
    expectInputError([&] { loadGltf(write(d)); }, "JSON nested deeper than 64");
}

TEST_F(GltfHardening, DeepJsonInsideAGlb) {
    Tiny d;
    d.sceneExtras = std::string(5000, '[') + std::string(5000, ']');
    std::string json = d.json();
    while (json.size() % 4) json += ' ';
    std::vector<unsigned char> glb(20 + json.size());
    const std::uint32_t header[5] = {0x46546C67u, 2u, std::uint32_t(glb.size()), std::uint32_t(json.size()), 0x4E4F534Au};
    std::memcpy(glb.data(), header, 20);
    std::memcpy(glb.data() + 20, json.data(), json.size());
    expectInputError([&] { loadGltfFromMemory(glb, "deep.glb", "", true); }, "JSON nested deeper than 64");
}

TEST_F(GltfHardening, NestingOf64IsAccepted) {
    // The limit counts the document's own two levels: 60 more still load.
    Tiny d;
    d.assetExtras = std::string(60, '[') + std::string(60, ']');
    EXPECT_NO_THROW(loadGltf(write(d)));
}

// ---- the node graph ----

TEST_F(GltfHardening, RepeatedChildrenWouldVisit2To63Nodes) {
    // nodes[i].children = [i+1, i+1] for 64 levels: a DAG, not a tree.
    Tiny d;
    std::string nodes = "[";
    for (int i = 0; i < 64; ++i) nodes += "{\"mesh\": 0, \"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
    nodes += R"({"mesh": 0}, {"camera": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    d.nodes = nodes;
    d.sceneNodes = "[0, 65, 66]";
    expectInputError([&] { loadGltf(write(d)); }, "node 1 is a child of both node 0 and node 0");
}

TEST_F(GltfHardening, ANodeWithTwoParents) {
    Tiny d;
    d.nodes = R"([{"children": [2]}, {"children": [2]}, {"mesh": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    d.sceneNodes = "[0, 1, 3]";
    expectInputError([&] { loadGltf(write(d)); }, "node 2 is a child of both node 0 and node 1");
}

TEST_F(GltfHardening, ACycle) {
    Tiny d;
    d.nodes = R"([{"mesh": 0, "children": [1]}, {"children": [0]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    d.sceneNodes = "[2]";
    expectInputError([&] { loadGltf(write(d)); }, "is its own ancestor");
}

TEST_F(GltfHardening, ARootThatIsAlsoAChild) {
    Tiny d;
    d.nodes = R"([{"mesh": 0, "children": [1]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    d.sceneNodes = "[0, 1]";
    expectInputError([&] { loadGltf(write(d)); }, "node 1 is a root of scene 0 and a child of node 0");
}

TEST_F(GltfHardening, ManyInstancesAreRefusedBeforeAllocation) {
    // 30,000 nodes instancing one mesh: over the 20,000-primitive limit, refused while counting.
    Tiny d;
    std::string nodes = "[", roots = "[";
    for (int i = 0; i < 30000; ++i) {
        nodes += "{\"mesh\": 0},";
        roots += std::to_string(i) + ",";
    }
    nodes += R"({"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    roots += "30000]";
    d.nodes = nodes;
    d.sceneNodes = roots;
    expectInputError([&] { loadGltf(write(d)); }, "more than the limits allow");
}

// ---- URIs ----

TEST_F(GltfHardening, BufferUriNamingTheFolder) {
    for (const char* uri : {".", "./"}) {
        Tiny d;
        d.buffer = std::string(R"({"byteLength": 36, "uri": ")") + uri + "\"}";
        expectInputError([&] { loadGltf(write(d)); }, "names the file's folder");
    }
}

TEST_F(GltfHardening, BufferUriLeavingTheFolder) {
    for (const char* uri : {"..", "../x.bin", "a/../../x.bin", "%2E%2E/x.bin"}) {
        Tiny d;
        d.buffer = std::string(R"({"byteLength": 36, "uri": ")") + uri + "\"}";
        expectInputError([&] { loadGltf(write(d)); }, "leaves the file's folder");
    }
}

TEST_F(GltfHardening, BufferUriNamingASubfolder) {
    std::filesystem::create_directories(mDir / "sub");
    Tiny d;
    d.buffer = R"({"byteLength": 36, "uri": "sub"})";
    expectInputError([&] { loadGltf(write(d)); }, "buffer 0: file 'sub' names a folder");
}

TEST_F(GltfHardening, BufferUriNamingAFifoDoesNotBlock) {
    ASSERT_EQ(::mkfifo((mDir / "pipe.bin").c_str(), 0600), 0);
    Tiny d;
    d.buffer = R"({"byteLength": 36, "uri": "pipe.bin"})";
    expectInputError([&] { loadGltf(write(d)); }, "is not a regular file");
}

TEST_F(GltfHardening, AbsoluteUriIsRefused) {
    Tiny d;
    d.buffer = R"({"byteLength": 36, "uri": "/etc/hostname"})";
    expectInputError([&] { loadGltf(write(d)); }, "is an absolute path");
}

TEST_F(GltfHardening, MissingImageIsNamed) {
    Tiny d;
    d.materials = R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
    d.primitive = R"({"attributes": {"POSITION": 0}, "material": 0})";
    std::string json = d.json();
    json.insert(json.rfind('}'), ", \"textures\": [{\"source\": 0}], \"images\": [{\"uri\": \"albedo.png\"}]");
    expectInputError([&] { loadGltf(write("img.gltf", json)); }, "image 0: file 'albedo.png' does not exist");
}

// tinygltf hands an image in a bufferView to the decoder as `byteLength` bytes from the view's offset
// without checking the buffer holds them (a fuzzed GLB read 1178 bytes past a 762-byte buffer in
// stb_image). The view is checked against the buffer first.
TEST_F(GltfHardening, ImageBufferViewPastItsBufferIsRefusedBeforeDecoding) {
    for (const char* view : {R"({"buffer": 0, "byteLength": 4096})", R"({"buffer": 0, "byteOffset": 30, "byteLength": 7})",
                             R"({"buffer": 0, "byteOffset": 18446744073709551600, "byteLength": 20})"}) {
        SCOPED_TRACE(view);
        Tiny d;
        d.extraViews = std::string(", ") + view;
        d.materials = R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
        d.primitive = R"({"attributes": {"POSITION": 0}, "material": 0})";
        std::string json = d.json();
        json.insert(json.rfind('}'), R"(, "textures": [{"source": 0}], "images": [{"bufferView": 1, "mimeType": "image/png"}])");
        const std::string message = expectInputError([&] { loadGltf(write("img.gltf", json)); }, "image 0: bufferView 1");
        EXPECT_NE(message.find("runs past the end of buffer 0 (36 bytes)"), std::string::npos) << message;
    }
}

TEST_F(GltfHardening, ExternalFilesRefusedFromMemoryWithoutAFolder) {
    Tiny d;
    d.buffer = R"({"byteLength": 36, "uri": "tri.bin"})";
    const std::string json = d.json();
    expectInputError([&] { loadGltfFromMemory({json.begin(), json.end()}, "mem.gltf", "", false); },
                     "cannot be read here (data: URIs only)");
}

TEST_F(GltfHardening, HugeDeclaredBufferIsRefusedBeforeAllocation) {
    Tiny d;
    d.buffer = R"({"byteLength": 4611686018427387904, "uri": "data:application/octet-stream;base64,AAAA"})";
    expectInputError([&] { loadGltf(write(d)); }, "over the 1 GiB limit");
}

// ---- values ----

TEST_F(GltfHardening, NegativeBaseColourFactor) {
    Tiny d;
    d.materials = R"([{"pbrMetallicRoughness": {"baseColorFactor": [0.5, -0.2, 0.5, 1]}}])";
    d.primitive = R"({"attributes": {"POSITION": 0}, "material": 0})";
    expectInputError([&] { loadGltf(write(d)); }, "material 0 baseColorFactor[1] = -0.2 is outside [0, 1]");
}

TEST_F(GltfHardening, NegativeEmissiveFactor) {
    Tiny d;
    d.materials = R"([{"emissiveFactor": [-1, 0, 0]}])";
    d.primitive = R"({"attributes": {"POSITION": 0}, "material": 0})";
    expectInputError([&] { loadGltf(write(d)); }, "material 0 emissiveFactor[0] = -1 is outside [0, 1]");
}

TEST_F(GltfHardening, LightIntensityThatOverflowsGpuFloats) {
    for (const char* intensity : {"1e38", "1e300"}) {
        Tiny d;
        d.light = std::string(R"({"type": "point", "intensity": )") + intensity + "}";
        expectInputError([&] { loadGltf(write(d)); }, "is over the limit of 1e20");
    }
}

TEST_F(GltfHardening, NegativeLightColour) {
    Tiny d;
    d.light = R"({"type": "point", "intensity": 5, "color": [1, -1, 1]})";
    expectInputError([&] { loadGltf(write(d)); }, "light 0 color[1] = -1 must be finite and >= 0");
}

TEST_F(GltfHardening, HugeSigma) {
    Tiny d;
    d.sceneExtras = R"({"medium": {"sigma_s": 1e308}})";
    expectInputError([&] { loadGltf(write(d)); }, "medium.sigma_s = 1e+308 is outside [0, 1e12]");
}

TEST_F(GltfHardening, HugeTranslation) {
    Tiny d;
    d.nodes = meshNodeWith(R"("translation": [1e30, 0, 0])");
    expectInputError([&] { loadGltf(write(d)); }, "node 0 translation has a value 1e+30 that is not finite or beyond 1e15");
}

TEST_F(GltfHardening, ScaleThatMovesVerticesBeyondTheLimit) {
    Tiny d;
    d.nodes = meshNodeWith(R"("scale": [1e14, 1e14, 1e14], "translation": [9.5e14, 0, 0])");
    expectInputError([&] { loadGltf(write(d)); }, "beyond the 1e15 limit");
}

TEST_F(GltfHardening, ZeroQuaternion) {
    Tiny d;
    d.nodes = meshNodeWith(R"("rotation": [0, 0, 0, 0])");
    expectInputError([&] { loadGltf(write(d)); }, "node 0 rotation is a zero quaternion");
}

TEST_F(GltfHardening, ZeroScaleNodeIsSkippedWithANote) {
    Tiny d;
    d.nodes = R"([{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]},
        {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 2, 0]}, {"mesh": 0, "scale": [0, 0, 0]}])";
    d.sceneNodes = "[0, 1, 2, 3]";
    const Scene s = loadGltf(write(d));
    EXPECT_EQ(s.meshes.size(), 1u);
    EXPECT_TRUE(hasNote(s, "node 3 has a singular transform"));
}

TEST_F(GltfHardening, ZeroLengthNormalsAreRepairedWithTheFaceNormal) {
    // NORMAL: (0,0,0) three times. The triangle (0,0,0), (1,0,0), (0,1,0) faces +Z.
    Tiny d;
    d.buffer = R"({"byteLength": 72, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA"})";
    d.extraViews = R"(, {"buffer": 0, "byteOffset": 36, "byteLength": 36})";
    d.extraAccessors = R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})";
    d.primitive = R"({"attributes": {"POSITION": 0, "NORMAL": 1}})";
    const Scene s = loadGltf(write(d));
    ASSERT_EQ(s.meshes[0].normals.size(), 3u);
    for (const glm::vec3& n : s.meshes[0].normals) {
        EXPECT_FLOAT_EQ(n.x, 0.0f);
        EXPECT_FLOAT_EQ(n.y, 0.0f);
        EXPECT_FLOAT_EQ(n.z, 1.0f);
    }
    EXPECT_TRUE(hasNote(s, "3 zero-length normals replaced"));
}

TEST_F(GltfHardening, LongValuesAreQuotedShort) {
    // A 100 KB URI is named, elided to at most 120 characters.
    Tiny d;
    d.buffer = R"({"byteLength": 36, "uri": ")" + std::string(100000, 'x') + ".bin\"}";
    const std::string msg = expectInputError([&] { loadGltf(write(d)); }, "does not exist");
    EXPECT_LT(msg.size(), 300u) << msg.substr(0, 400);
}

TEST_F(GltfHardening, NotAGlb) {
    const std::string path = write("fake.glb", "{\"asset\": {\"version\": \"2.0\"}}");
    expectInputError([&] { loadGltf(path); }, "not a binary glTF: the file does not start with 'glTF'");
}

TEST_F(GltfHardening, PathThatIsAFolder) {
    std::filesystem::create_directories(mDir / "dir.gltf");
    expectInputError([&] { loadGltf((mDir / "dir.gltf").string()); }, "names a folder");
}

// ---- what real models lack ----

TEST_F(GltfHardening, MeshesOnlyModelGetsADefaultLightAndMedium) {
    // No light, no medium, no camera, millimetre scale (the triangle is 2 mm across).
    Tiny d;
    d.nodes = R"([{"mesh": 0, "scale": [0.002, 0.002, 0.002]}])";
    d.sceneNodes = "[0]";
    d.sceneExtras = "{}";
    std::string json = d.json();
    const Scene s = loadGltf(write("meshes_only.gltf", json));
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_TRUE(hasNote(s, "no light in 'meshes_only.gltf': added a default spot light"));
    // Above the model, aimed at the bounding box's centre, its cone covering the box's corners.
    const std::vector<glm::vec3>& p = s.meshes[0].positions;
    const glm::dvec3 centre = 0.5 * (glm::dvec3(glm::min(glm::min(p[0], p[1]), p[2])) + glm::dvec3(glm::max(glm::max(p[0], p[1]), p[2])));
    EXPECT_GT(l.position.y, centre.y);
    EXPECT_NEAR(glm::dot(l.direction, glm::normalize(centre - l.position)), 1.0, 1e-12);
    for (const glm::dvec3 corner : {glm::dvec3(0, 0, 0), glm::dvec3(0.002, 0, 0), glm::dvec3(0, 0.002, 0)}) {
        EXPECT_GT(glm::dot(glm::normalize(corner - l.position), l.direction), std::cos(l.outerConeAngle));
    }
    // Irradiance at the centre is the same at any scale, and the medium's optical depth across the
    // box is 0.5 (diagonal 0.002 * sqrt(2)).
    EXPECT_NEAR(l.intensity / glm::dot(centre - l.position, centre - l.position), 10.0, 1e-9);
    EXPECT_NEAR(s.medium.sigma_s * 0.002 * std::sqrt(2.0), 0.5, 1e-6);
    EXPECT_TRUE(hasNote(s, "optical depth 0.5"));
    EXPECT_NO_THROW(validateScene(s));
}

TEST_F(GltfHardening, UnusedLightIsItsOwnMessage) {
    Tiny d;
    d.nodes = R"([{"mesh": 0}])";
    d.sceneNodes = "[0]";
    LoadOptions refuse;
    refuse.defaultLight = false;
    expectInputError([&] { loadGltf(write(d), refuse); }, "light 0 is not used by any node of the scene");
    const Scene s = loadGltf(write(d));
    EXPECT_TRUE(hasNote(s, "light 0 is not used by any node"));
    EXPECT_TRUE(hasNote(s, "added a default spot light"));
}

TEST_F(GltfHardening, UnknownLightExtrasAreNoted) {
    Tiny d;
    d.light = R"({"type": "point", "intensity": 5, "extras": {"cokie": 0}})";
    EXPECT_TRUE(hasNote(loadGltf(write(d)), "light 0: extras key 'cokie' ignored (known: cookie)"));
}

TEST_F(GltfHardening, MediumTyposAreNoted) {
    Tiny d;
    d.sceneExtras = R"({"medium": {"sigma_S": 0.3, "sigma_a": "thick"}})";
    const Scene s = loadGltf(write(d));
    EXPECT_TRUE(hasNote(s, "unknown key 'sigma_S' ignored"));
    EXPECT_TRUE(hasNote(s, "medium.sigma_a is not a number"));
}

}  // namespace
}  // namespace viz::scene
