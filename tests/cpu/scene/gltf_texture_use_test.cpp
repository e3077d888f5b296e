// Which textures and images the loader reads: only those a material's base colour or emission or a
// spot light's cookie draws. Real models ship normal and metallic-roughness maps, and images reached
// only through an extension (a DDS behind MSFT_texture_dds); those are neither decoded nor required to
// exist, and the textures kept are renumbered without changing what each material or light shows.
// Each document is tests/data/scene/box.gltf (one 2x2 PNG drawn by the material and the spot's cookie)
// with textures and images added around it.
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "test_util.h"

namespace viz::scene {
namespace {

using Json = nlohmann::json;
using test::expectInputError;
using test::hasNote;

// The 2x2 PNG in box.gltf: red, green / blue, white with alpha 128.
const std::vector<std::uint8_t> kBoxPixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

// Bytes no image decoder reads (the start of a DDS header, then zeros) in a data URI labelled PNG, so
// that tinygltf hands them to the loader's decoder (a DDS label it would not even read).
const char* kNotAnImage = "data:image/png;base64,RERTIHwAAAAHEAgAAAAAAAAAAAAAAAAAAAAAAA==";

class GltfTextureUse : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = test::freshTempDir("texuse");
        std::ifstream in(test::dataPath("box.gltf"));
        mDoc = Json::parse(in);
    }
    Scene load() {
        test::writeText(mDir / "doc.gltf", mDoc.dump(1));
        return loadGltf((mDir / "doc.gltf").string());
    }
    Json& material() { return mDoc["materials"][0]; }
    Json& cookie() { return mDoc["extensions"]["KHR_lights_punctual"]["lights"][0]["extras"]["cookie"]; }
    std::filesystem::path mDir;
    Json mDoc;
};

TEST_F(GltfTextureUse, MapsNothingDrawsAreNeitherDecodedNorRequiredToExist) {
    // Texture 1: a normal map whose file is missing; texture 2: only a DDS through an extension.
    mDoc["images"].push_back({{"uri", "missing_normal.png"}});
    mDoc["images"].push_back({{"uri", kNotAnImage}});
    mDoc["textures"].push_back({{"source", 1}});
    mDoc["textures"].push_back({{"extensions", {{"MSFT_texture_dds", {{"source", 2}}}}}});
    material()["normalTexture"] = {{"index", 1}};
    material()["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 2}};
    const Scene s = load();
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].rgba8, kBoxPixels);
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].cookie, 0);
    EXPECT_TRUE(hasNote(s, "2 textures of 3 and 2 images of 3 not loaded")) << "the note says what was left out";
}

TEST_F(GltfTextureUse, EverythingDrawnLoadsWithoutANote) {
    const Scene s = load();
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_FALSE(hasNote(s, "not loaded"));
}

TEST_F(GltfTextureUse, TexturesKeptAreRenumberedAndStillShowTheirOwnImage) {
    // Two unused textures first, over an image nothing can decode; the PNG's texture is now number 2.
    mDoc["images"].push_back({{"uri", kNotAnImage}});
    mDoc["textures"] = Json::array({{{"source", 1}}, {{"source", 1}}, {{"source", 0}}});
    material()["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 2;
    cookie() = 2;
    const Scene s = load();
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 2);
    EXPECT_EQ(s.textures[0].rgba8, kBoxPixels);
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    EXPECT_EQ(s.lights[0].cookie, 0);
}

TEST_F(GltfTextureUse, EmissionAndCookieCountAsDrawn) {
    // The material draws no base colour texture; the PNG is reached by emission and the cookie, and the
    // undecodable image by whichever of them is tested: each must be decoded, so each is an error.
    for (const char* user : {"emission", "cookie"}) {
        SCOPED_TRACE(user);
        SetUp();
        material()["pbrMetallicRoughness"].erase("baseColorTexture");
        mDoc["images"].push_back({{"uri", kNotAnImage}});
        mDoc["textures"].push_back({{"source", 1}});
        material()["emissiveTexture"] = {{"index", std::string(user) == "emission" ? 1 : 0}};
        cookie() = std::string(user) == "cookie" ? 1 : 0;
        expectInputError([&] { load(); }, "image 1 is not a PNG, JPEG or other decodable image");
    }
}

TEST_F(GltfTextureUse, AMissingFileThatIsDrawnIsStillNamed) {
    mDoc["images"][0] = {{"uri", "albedo.png"}};
    expectInputError([&] { load(); }, "image 0: file 'albedo.png' does not exist");
}

// tinygltf reads an index as a 32-bit int, so 2^32 becomes texture 0; the loader must not then use a
// texture it never loaded.
TEST_F(GltfTextureUse, AnIndexTinygltfTruncatesIsAnError) {
    mDoc["images"].push_back({{"uri", kNotAnImage}});
    mDoc["textures"] = Json::array({{{"source", 1}}, {{"source", 0}}});
    material()["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 4294967296LL;
    cookie() = 1;
    expectInputError([&] { load(); }, "is not a plain integer in range");
}

}  // namespace
}  // namespace viz::scene
