// Export: every built-in scene goes through .gltf and .glb and loads back identical; failures leave no
// file behind.
//
// Values are compared exactly: vertex data travels as the same 32-bit floats in a binary buffer, and
// every double (lights, camera, medium, material factors) is written in JSON in shortest round-trip
// form and parsed back to the same double. Directions load back untouched because the loader only
// renormalises vectors that are off unit length by more than 1e-14; area lights are recomputed from
// the same float corners by the same function.
#include <algorithm>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_writer.h"
#include "scene/scene_source.h"
#include "test_util.h"

namespace viz::scene {
namespace {

namespace fs = std::filesystem;

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        SCOPED_TRACE("mesh " + std::to_string(i));
        EXPECT_EQ(a.meshes[i].name, b.meshes[i].name);
        EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
        EXPECT_EQ(a.meshes[i].normals, b.meshes[i].normals);
        EXPECT_EQ(a.meshes[i].uvs, b.meshes[i].uvs);
        EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
        EXPECT_EQ(a.meshes[i].material, b.meshes[i].material);
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        SCOPED_TRACE("material " + std::to_string(i));
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].baseColorFactor, b.materials[i].baseColorFactor);
        EXPECT_EQ(a.materials[i].baseColorTexture, b.materials[i].baseColorTexture);
        EXPECT_EQ(a.materials[i].emissiveFactor, b.materials[i].emissiveFactor);
        EXPECT_EQ(a.materials[i].emissiveStrength, b.materials[i].emissiveStrength);
        EXPECT_EQ(a.materials[i].emissiveTexture, b.materials[i].emissiveTexture);
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        SCOPED_TRACE("texture " + std::to_string(i));
        EXPECT_EQ(a.textures[i].name, b.textures[i].name);
        EXPECT_EQ(a.textures[i].width, b.textures[i].width);
        EXPECT_EQ(a.textures[i].height, b.textures[i].height);
        EXPECT_EQ(a.textures[i].rgba8, b.textures[i].rgba8);
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        SCOPED_TRACE("light " + std::to_string(i));
        const Light &x = a.lights[i], &y = b.lights[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.type, y.type);
        EXPECT_EQ(x.position, y.position);
        EXPECT_EQ(x.direction, y.direction);
        EXPECT_EQ(x.colour, y.colour);
        EXPECT_EQ(x.intensity, y.intensity);
        EXPECT_EQ(x.cookie, y.cookie);
        if (x.type == LightType::Spot) {
            EXPECT_EQ(x.innerConeAngle, y.innerConeAngle);
            EXPECT_EQ(x.outerConeAngle, y.outerConeAngle);
        }
        EXPECT_EQ(x.halfU, y.halfU);
        EXPECT_EQ(x.halfV, y.halfV);
        EXPECT_EQ(x.radiance, y.radiance);
        EXPECT_EQ(x.emissionTexture, y.emissionTexture);
        EXPECT_EQ(x.mesh, y.mesh);
    }
    EXPECT_EQ(a.camera.name, b.camera.name);
    EXPECT_EQ(a.camera.position, b.camera.position);
    EXPECT_EQ(a.camera.forward, b.camera.forward);
    EXPECT_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.yfov, b.camera.yfov);
    EXPECT_EQ(a.camera.znear, b.camera.znear);
    EXPECT_EQ(a.camera.zfar, b.camera.zfar);
    EXPECT_EQ(a.camera.aspectRatio, b.camera.aspectRatio);
    EXPECT_EQ(a.medium.sigma_s, b.medium.sigma_s);
    EXPECT_EQ(a.medium.sigma_a, b.medium.sigma_a);
    EXPECT_EQ(a.medium.g, b.medium.g);
    EXPECT_EQ(sceneContentHash(a), sceneContentHash(b));
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class GltfWriter : public ::testing::TestWithParam<std::string> {};

TEST_P(GltfWriter, RoundTripsEveryBuiltinScene) {
    const fs::path dir = test::freshTempDir("write");
    const Scene original = makeBuiltinScene(GetParam());
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path path = dir / (GetParam() + ext);
        writeGltf(original, path.string());
        const Scene loaded = loadGltf(path.string());
        EXPECT_TRUE(loaded.notes.empty()) << loaded.notes.front();
        expectSameScene(original, loaded);
    }
    // Nothing but the two files: no temporary left over.
    EXPECT_EQ(filesIn(dir), (std::vector<std::string>{GetParam() + ".glb", GetParam() + ".gltf"}));
}

INSTANTIATE_TEST_SUITE_P(Builtin, GltfWriter, ::testing::ValuesIn(builtinSceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string n = param.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

TEST(GltfWriterFiles, TestScenesRoundTrip) {
    const fs::path dir = test::freshTempDir("write");
    for (const Scene& s : {makeTestScene(), makeTestAreaLightScene()}) {
        writeGltf(s, (dir / "t.glb").string());
        expectSameScene(s, loadGltf((dir / "t.glb").string()));
    }
}

TEST(GltfWriterFiles, GltfIsOneSelfContainedFile) {
    const fs::path dir = test::freshTempDir("write");
    writeGltf(makeBuiltinScene("stained-glass"), (dir / "a.gltf").string());
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"a.gltf"});
    // Moved elsewhere it still loads: nothing refers to neighbouring files.
    const fs::path other = test::freshTempDir("write_other");
    fs::rename(dir / "a.gltf", other / "b.gltf");
    EXPECT_EQ(loadGltf((other / "b.gltf").string()).textures.size(), 1u);
}

TEST(GltfWriterFiles, MissingFolderIsAnErrorAndWritesNothing) {
    const fs::path dir = test::freshTempDir("write");
    const fs::path target = dir / "no_such_folder" / "scene.gltf";
    test::expectInputError([&] { writeGltf(makeTestScene(), target.string()); }, "does not exist");
    EXPECT_FALSE(fs::exists(dir / "no_such_folder"));
    EXPECT_TRUE(filesIn(dir).empty());
}

TEST(GltfWriterFiles, FailedWriteLeavesNoPartialFile) {
    // The target name is taken by a folder, so the final rename fails after the data was written.
    const fs::path dir = test::freshTempDir("write");
    fs::create_directory(dir / "taken.glb");
    test::expectInputError([&] { writeGltf(makeTestScene(), (dir / "taken.glb").string()); }, "taken.glb");
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"taken.glb"});
    EXPECT_TRUE(fs::is_directory(dir / "taken.glb"));
}

TEST(GltfWriterFiles, OverwriteReplacesTheWholeFile) {
    const fs::path dir = test::freshTempDir("write");
    const fs::path path = dir / "s.gltf";
    writeGltf(makeBuiltinScene("terrain"), path.string());
    writeGltf(makeTestScene(), path.string());
    expectSameScene(makeTestScene(), loadGltf(path.string()));
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"s.gltf"});
}

TEST(GltfWriterFiles, RejectsOtherExtensions) {
    const fs::path dir = test::freshTempDir("write");
    test::expectInputError([&] { writeGltf(makeTestScene(), (dir / "s.obj").string()); }, ".gltf or .glb");
    EXPECT_TRUE(filesIn(dir).empty());
}

}  // namespace
}  // namespace viz::scene
