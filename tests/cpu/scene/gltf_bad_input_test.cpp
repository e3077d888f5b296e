// Every kind of bad glTF input throws viz::InputError with a one-line message naming the problem.
// The files are generated here from a small valid document with one thing broken at a time.
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "test_util.h"

namespace viz::scene {
namespace {

using test::expectInputError;

std::string base64(const std::vector<unsigned char>& data) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        const unsigned v = (unsigned(data[i]) << 16) | (unsigned(data[i + 1]) << 8) | data[i + 2];
        for (int k = 3; k >= 0; --k) out += kAlphabet[(v >> (6 * k)) & 63];
    }
    if (i + 1 == data.size()) {
        const unsigned v = unsigned(data[i]) << 16;
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == data.size()) {
        const unsigned v = (unsigned(data[i]) << 16) | (unsigned(data[i + 1]) << 8);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += "=";
    }
    return out;
}

// A one-triangle document with a point light, a camera and a medium; each field can be broken.
struct Doc {
    std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string mode = "4";
    std::string extensionsRequired;  // e.g. "\"KHR_draco_mesh_compression\""
    std::string medium = R"({"sigma_s": 0.1, "sigma_a": 0.0, "g": 0.0})";
    bool light = true;
    std::string bufferUri;           // empty: a data URI of the positions
    long declaredByteLength = -1;    // -1: the real size
    int accessorCount = 3;
    long viewLength = -1;            // -1: the buffer size
    std::string material;            // JSON of one material, or empty for none

    std::string json() const {
        std::vector<unsigned char> bytes(positions.size() * 4);
        std::memcpy(bytes.data(), positions.data(), bytes.size());
        const long size = long(bytes.size());
        const std::string uri = bufferUri.empty() ? "data:application/octet-stream;base64," + base64(bytes) : bufferUri;
        std::string j = "{\"asset\": {\"version\": \"2.0\"},\n";
        if (!extensionsRequired.empty()) {
            j += "\"extensionsUsed\": [" + extensionsRequired + "], \"extensionsRequired\": [" + extensionsRequired + "],\n";
        }
        j += "\"scenes\": [{\"nodes\": [0, 1" + std::string(light ? ", 2" : "") + "], \"extras\": {\"medium\": " + medium +
             "}}],\n";
        j += "\"nodes\": [{\"mesh\": 0}, {\"camera\": 0, \"translation\": [0, 0, 3]}, "
             "{\"extensions\": {\"KHR_lights_punctual\": {\"light\": 0}}, \"translation\": [0, 2, 0]}],\n";
        j += "\"cameras\": [{\"type\": \"perspective\", \"perspective\": {\"yfov\": 0.8, \"znear\": 0.1, \"zfar\": 50}}],\n";
        j += "\"extensions\": {\"KHR_lights_punctual\": {\"lights\": [{\"type\": \"point\", \"intensity\": 5}]}},\n";
        j += "\"meshes\": [{\"name\": \"tri\", \"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": " + mode +
             std::string(material.empty() ? "" : ", \"material\": 0") + "}]}],\n";
        if (!material.empty()) j += "\"materials\": [" + material + "],\n";
        j += "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": " + std::to_string(accessorCount) +
             ", \"type\": \"VEC3\"}],\n";
        j += "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": " + std::to_string(viewLength >= 0 ? viewLength : size) + "}],\n";
        j += "\"buffers\": [{\"byteLength\": " + std::to_string(declaredByteLength >= 0 ? declaredByteLength : size) +
             ", \"uri\": \"" + uri + "\"}]}\n";
        return j;
    }
};

class GltfBadInput : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTempDir("bad"); }
    std::string write(const std::string& name, const std::string& text) {
        test::writeText(mDir / name, text);
        return (mDir / name).string();
    }
    std::filesystem::path mDir;
};

TEST_F(GltfBadInput, ValidDocumentLoads) {
    // The base document is valid: each test below breaks exactly one thing.
    const Scene s = loadGltf(write("ok.gltf", Doc{}.json()));
    EXPECT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.lights.size(), 1u);
}

TEST_F(GltfBadInput, MissingFile) {
    const std::string msg = expectInputError([&] { loadGltf((mDir / "nothere.gltf").string()); }, "no such file");
    EXPECT_NE(msg.find("nothere.gltf"), std::string::npos);
}

TEST_F(GltfBadInput, MalformedJson) {
    const std::string path = write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    const std::string msg = expectInputError([&] { loadGltf(path); }, "malformed JSON");
    EXPECT_NE(msg.find("broken.gltf"), std::string::npos);
}

TEST_F(GltfBadInput, UnsupportedRequiredExtension) {
    Doc d;
    d.extensionsRequired = "\"KHR_draco_mesh_compression\"";
    const std::string path = write("draco.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "requires unsupported extension 'KHR_draco_mesh_compression'");
}

// A real Draco file's accessors have no bufferView (the data is in the extension's compressed view), which
// tinygltf reported first ("accessor[0] invalid bufferView", seen on a public Draco Box.glb): the required
// extension is named before tinygltf parses anything.
TEST_F(GltfBadInput, ARequiredExtensionIsNamedBeforeAnythingItChanges) {
    Doc d;
    d.extensionsRequired = "\"KHR_draco_mesh_compression\"";
    std::string json = d.json();
    const std::string view = "{\"bufferView\": 0, ";
    ASSERT_NE(json.find(view), std::string::npos);
    json.replace(json.find(view), view.size(), "{");
    const std::string msg = expectInputError([&] { loadGltf(write("draco.gltf", json)); },
                                             "requires unsupported extension 'KHR_draco_mesh_compression'");
    EXPECT_NE(msg.find("Airlight reads KHR_lights_punctual"), std::string::npos) << msg;
    d.extensionsRequired = "7";
    expectInputError([&] { loadGltf(write("seven.gltf", d.json())); }, "extensionsRequired holds a number, not a name");
}

TEST_F(GltfBadInput, MissingBufferFile) {
    Doc d;
    d.bufferUri = "missing.bin";
    const std::string path = write("nobuffer.gltf", d.json());
    // The message names the buffer and its file.
    expectInputError([&] { loadGltf(path); }, "buffer 0: file 'missing.bin' does not exist");
}

TEST_F(GltfBadInput, ShortExternalBuffer) {
    // The .bin file holds 36 bytes but the buffer declares 72.
    Doc d;
    d.bufferUri = "short.bin";
    d.declaredByteLength = 72;
    std::string bytes(36, '\0');
    test::writeText(mDir / "short.bin", bytes);
    const std::string path = write("short.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "missing or short buffer");
}

TEST_F(GltfBadInput, AccessorOutOfRangeOfBufferView) {
    Doc d;
    d.accessorCount = 4;  // 48 bytes from a 36-byte view
    const std::string path = write("accessor.gltf", d.json());
    const std::string msg = expectInputError([&] { loadGltf(path); }, "out of range of bufferView 0");
    EXPECT_NE(msg.find("accessor 0"), std::string::npos);
}

TEST_F(GltfBadInput, BufferViewOutOfRangeOfBuffer) {
    Doc d;
    d.viewLength = 48;  // the buffer has 36 bytes
    const std::string path = write("view.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "out of range of buffer 0");
}

TEST_F(GltfBadInput, NanVertex) {
    Doc d;
    d.positions[4] = std::numeric_limits<float>::quiet_NaN();
    const std::string path = write("nan.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "vertex 1 is NaN or Inf");
}

TEST_F(GltfBadInput, InfVertex) {
    Doc d;
    d.positions[8] = std::numeric_limits<float>::infinity();
    const std::string path = write("inf.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "vertex 2 is NaN or Inf");
}

TEST_F(GltfBadInput, NoTriangles) {
    Doc d;
    d.mode = "0";  // POINTS: skipped, which leaves nothing
    const std::string path = write("points.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "no triangles");
}

TEST_F(GltfBadInput, NoLightIsAnErrorWithoutTheDefaultLight) {
    Doc d;
    d.light = false;
    const std::string path = write("dark.gltf", d.json());
    LoadOptions refuse;
    refuse.defaultLight = false;
    expectInputError([&] { loadGltf(path, refuse); }, "no light");
}

TEST_F(GltfBadInput, NegativeSigmaS) {
    Doc d;
    d.medium = R"({"sigma_s": -0.1, "sigma_a": 0.0, "g": 0.0})";
    const std::string path = write("sigmas.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "medium.sigma_s = -0.1 is outside [0, 1e12]");
}

TEST_F(GltfBadInput, NegativeSigmaA) {
    Doc d;
    d.medium = R"({"sigma_s": 0.1, "sigma_a": -0.5, "g": 0.0})";
    const std::string path = write("sigmaa.gltf", d.json());
    expectInputError([&] { loadGltf(path); }, "medium.sigma_a = -0.5 is outside [0, 1e12]");
}

TEST_F(GltfBadInput, AsymmetryOutOfRange) {
    for (const char* g : {"1.0", "-1.0", "1.5"}) {
        Doc d;
        d.medium = std::string(R"({"sigma_s": 0.1, "sigma_a": 0.0, "g": )") + g + "}";
        const std::string path = write("g.gltf", d.json());
        expectInputError([&] { loadGltf(path); }, "|g| < 1");
    }
}

// An emissive mesh that is not a planar rectangle glows on the surface but lights nothing: a note
// names it, and the file's own light stays the only light.
TEST_F(GltfBadInput, EmissiveTriangleIsNotARectangle) {
    Doc d;
    d.material = R"({"emissiveFactor": [1, 1, 1]})";
    const Scene s = loadGltf(write("emissive.gltf", d.json()));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_TRUE(test::hasNote(s, "is not a planar rectangle"));
    EXPECT_TRUE(test::hasNote(s, "'tri'"));
    EXPECT_TRUE(test::hasNote(s, "shades as an emissive surface"));
}

TEST_F(GltfBadInput, EmissiveNonRectangularQuad) {
    // Two triangles over 4 distinct vertices, but a trapezoid.
    Doc d;
    d.positions = {0, 0, 0, 2, 0, 0, 1.5f, 1, 0, 0, 0, 0, 1.5f, 1, 0, 0.5f, 1, 0};
    d.accessorCount = 6;
    d.material = R"({"emissiveFactor": [1, 1, 1]})";
    const std::string path = write("trapezoid.gltf", d.json());
    const Scene s = loadGltf(path);
    EXPECT_TRUE(test::hasNote(s, "do not form a rectangle"));
    EXPECT_EQ(s.lights.size(), 1u);
}

TEST_F(GltfBadInput, NoMediumUsesDefaultsWithNote) {
    Doc d;
    d.medium = "null";
    const std::string text = d.json();
    // Remove the extras entirely.
    std::string noExtras = text;
    const auto at = noExtras.find(", \"extras\"");
    noExtras.erase(at, noExtras.find("}}]", at) + 1 - at);
    const Scene s = loadGltf(write("nomedium.gltf", noExtras));
    // Optical depth 0.5 across the bounding box: the triangle spans (0,0,0)..(1,1,0), diagonal sqrt(2).
    EXPECT_NEAR(s.medium.sigma_s, 0.5 / std::sqrt(2.0), 1e-12);
    EXPECT_EQ(s.medium.sigma_a, 0.0);
    EXPECT_EQ(s.medium.g, 0.0);
    bool noted = false;
    for (const auto& n : s.notes) noted |= n.find("no medium") != std::string::npos;
    EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace viz::scene
