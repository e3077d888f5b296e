// End-to-end tests of the airlight command line: exit codes, one-line errors, output files.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_fixture.h"
#include "core/image_io.h"
#include "report/error_metrics.h"

namespace fs = std::filesystem;
using viz::testing::CliTest;
using viz::testing::readFile;
using viz::testing::RunResult;

namespace {

// A small valid glTF (one triangle pair floor + a spot light + camera), with pieces replaceable for the
// bad-input cases. The buffer holds 4 vec3 positions (48 bytes) and 6 uint16 indices (12 bytes).
std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const unsigned v = unsigned(bytes[i]) << 16 | (i + 1 < bytes.size() ? unsigned(bytes[i + 1]) << 8 : 0u) |
                           (i + 2 < bytes.size() ? unsigned(bytes[i + 2]) : 0u);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[v & 63] : '=';
    }
    return out;
}

struct GltfParts {
    std::vector<float> positions{-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    std::vector<unsigned short> indices{0, 2, 1, 0, 3, 2};
    std::string medium = R"({"sigma_s": 0.2, "sigma_a": 0.05, "g": 0.3})";
    bool camera = true;
    bool light = true;
    int indexCount = 6;
    int mode = 4;          // 4 = TRIANGLES, 0 = POINTS
    int bufferBytes = -1;  // -1: the true length
    std::string uri;       // empty: embedded data URI
};

std::string makeGltf(const GltfParts& p) {
    std::vector<unsigned char> bytes(p.positions.size() * 4 + p.indices.size() * 2);
    std::memcpy(bytes.data(), p.positions.data(), p.positions.size() * 4);
    std::memcpy(bytes.data() + p.positions.size() * 4, p.indices.data(), p.indices.size() * 2);
    const int byteLength = p.bufferBytes >= 0 ? p.bufferBytes : int(bytes.size());
    const std::string uri = p.uri.empty() ? "data:application/octet-stream;base64," + base64(bytes) : p.uri;
    std::ostringstream s;
    s << R"({"asset": {"version": "2.0"},)";
    if (p.light) s << R"("extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "intensity": 20, "spot": {"outerConeAngle": 0.6}}]}},)";
    s << R"("scene": 0, "scenes": [{"nodes": [0)" << (p.camera ? ", 1" : "") << (p.light ? ", 2" : "")
      << R"(], "extras": {"medium": )" << p.medium << R"(}}],)";
    s << R"("nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 1.5, 4]},)"
      << R"({"translation": [0, 3, 0], "rotation": [-0.7071068, 0, 0, 0.7071068], "extensions": {"KHR_lights_punctual": {"light": 0}}}],)";
    s << R"("cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.05, "zfar": 50}}],)";
    s << R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": )" << p.mode << "}]}],";
    s << R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": )" << p.positions.size() / 3
      << R"(, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},)"
      << R"({"bufferView": 1, "componentType": 5123, "count": )" << p.indexCount << R"(, "type": "SCALAR"}],)";
    s << R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" << p.positions.size() * 4 << "},"
      << R"({"buffer": 0, "byteOffset": )" << p.positions.size() * 4 << R"(, "byteLength": )" << p.indices.size() * 2
      << "}],";
    s << R"("buffers": [{"byteLength": )" << byteLength << R"(, "uri": ")" << uri << R"("}]})";
    return s.str();
}

bool allFinite(const viz::Image& image) {
    for (float v : image.pixels)
        if (!std::isfinite(v)) return false;
    return true;
}

}  // namespace

TEST_F(CliTest, HelpOnEveryCommand) {
    for (const std::string cmd : {"--help", "render --help", "list --help", "plan --help", "export-scene --help",
                                  "gui --help"}) {
        const RunResult r = run(cmd);
        EXPECT_EQ(r.exitCode, 0) << cmd;
        EXPECT_NE(r.out.find("usage: airlight"), std::string::npos) << cmd << ": " << r.out;
    }
}

TEST_F(CliTest, ListsScenesTechniquesStagesAndParams) {
    RunResult r = run("list scenes");
    ASSERT_EQ(r.exitCode, 0);
    for (const char* s : {"colonnade", "grate", "forest", "terrain", "stained-glass", "tv-room"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s;
    r = run("list techniques");
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("reference"), std::string::npos);
    EXPECT_NE(r.out.find("raymarch"), std::string::npos);
    r = run("list params raymarch");
    ASSERT_EQ(r.exitCode, 0);
    for (const char* p : {"samples", "jitter", "shadow_map"}) EXPECT_NE(r.out.find(p), std::string::npos) << p;
    r = run("list stages raymarch");
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("raymarch.march"), std::string::npos);
    // Ranges as typed back: the largest point cloud is 8388608, not 8.38861e+06 (which it rejects).
    r = run("list params ivsv");
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("default 1048576  range [1024, 8388608] integer"), std::string::npos) << r.out;
    expectUserError(run("plan --scene grate --technique ivsv --set points=8388609"),
                    "parameter 'points' = 8388609 is out of range [1024, 8388608]");
    expectUserError(run("plan --scene grate --technique raymarch --set samples=2.5"),
                    "parameter 'samples' must be a whole number, got 2.5");
    EXPECT_EQ(run("plan --scene grate --technique ivsv --set points=8388608").exitCode, 0);
}

TEST_F(CliTest, RenderWritesFiniteExrOfTheRightSize) {
    for (const std::string technique : {"raymarch", "reference"}) {
        for (const std::string layer : {"final", "airlight"}) {
            const fs::path out = path(technique + "_" + layer + ".exr");
            const RunResult r = run("render --scene grate --technique " + technique + " --size 40x30 --layer " + layer +
                                    " --out " + out.string() + " --set " +
                                    (technique == "raymarch" ? "samples=32" : "transition_samples=64"));
            ASSERT_EQ(r.exitCode, 0) << r.err;
            const viz::Image image = viz::readImage(out.string());
            EXPECT_EQ(image.width, 40);
            EXPECT_EQ(image.height, 30);
            EXPECT_EQ(image.channels, 3);
            EXPECT_TRUE(allFinite(image));
            double sum = 0.0;
            for (float v : image.pixels) sum += v;
            EXPECT_GT(sum, 0.0) << technique << " " << layer << " is black";
        }
    }
}

// --layer-index picks a cube map's face: a point light's shadow map has six, faces 0 (+X) and 5 (-Z) see
// different parts of the scene, and a seventh is a one-line error that names the range.
TEST_F(CliTest, LayerIndexPicksACubeFaceAndNamesTheRangeWhenPastIt) {
    const std::string render =
        "render --scene stiff/ray-near-light --technique raymarch --size 16x12 --layer raymarch.shadow_map --quiet ";
    std::vector<viz::Image> faces;
    for (const int face : {0, 5}) {
        const fs::path out = path("face" + std::to_string(face) + ".exr");
        const RunResult r = run(render + "--layer-index " + std::to_string(face) + " --out " + out.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        faces.push_back(viz::readImage(out.string()));
        EXPECT_TRUE(allFinite(faces.back()));
    }
    ASSERT_EQ(faces[0].pixels.size(), faces[1].pixels.size());
    EXPECT_NE(faces[0].pixels, faces[1].pixels) << "faces 0 and 5 read back the same image";
    const fs::path out = path("face6.exr");
    expectUserError(run(render + "--layer-index 6 --out " + out.string()),
                    "--layer-index 6 is past the last layer of 'raymarch.shadow_map' (it has 6 layers, 0 to 5)");
    EXPECT_FALSE(fs::exists(out));
}

// `voxels=AxBxC` sets vsv's per-axis parameters in order: the same image as setting each, and a
// different one from the cube `voxels=64` (so the axes really took effect).
TEST_F(CliTest, PerAxisSettingSetsEachComponent) {
    const std::string render = "render --scene grate --technique vsv --size 40x30 --layer airlight --out ";
    const fs::path axes = path("axes.exr"), each = path("each.exr"), cube = path("cube.exr");
    RunResult r = run(render + axes.string() + " --set voxels=64x32x96");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run(render + each.string() + " --set voxels_alpha=64 --set voxels_theta=32 --set voxels_phi=96");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run(render + cube.string() + " --set voxels=64");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const viz::Image a = viz::readImage(axes.string()), b = viz::readImage(each.string()),
                     c = viz::readImage(cube.string());
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_NE(a.pixels, c.pixels);
}

// A named value means what the technique it is set for declares: epipole=paper is vsv's third choice (off,
// march, paper) and ivsv's second (off, paper). The plan's EPIPOLE line says which rule runs, in words
// independent of the numbers; the same word reaches each technique of a bench and a lesson step's
// technique, wherever `technique:` stands in its block.
TEST_F(CliTest, ANamedValueMeansWhatItsTechniqueDeclares) {
    const auto epipoleLine = [&](const std::string& args) {
        const RunResult r = run("plan " + args);
        EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
        const std::size_t at = r.out.find("feature EPIPOLE");
        return at == std::string::npos ? std::string() : r.out.substr(at, r.out.find('\n', at) - at);
    };
    EXPECT_NE(epipoleLine("--scene tv-room --technique ivsv --set epipole=paper").find("compare the fragment with the VPL"),
              std::string::npos);
    EXPECT_NE(epipoleLine("--scene tv-room --technique ivsv --set epipole=off").find("every ray reads the grids"),
              std::string::npos);
    const std::string epipoleInView = "--scene stiff/epipole-at-pixel-centre --technique vsv --set epipole=";
    EXPECT_NE(epipoleLine(epipoleInView + "paper").find("the paper's rule"), std::string::npos);
    EXPECT_NE(epipoleLine(epipoleInView + "march").find("test the shadow map directly"), std::string::npos);
    // --set before --technique: the word waits for the technique.
    EXPECT_NE(epipoleLine("--set epipole=paper --scene tv-room --technique ivsv").find("compare the fragment with the VPL"),
              std::string::npos);
    expectUserError(run("plan --scene tv-room --technique ivsv --set epipole=march"), "'march' is not one of off, paper");

    const fs::path bench = path("bench");
    RunResult r = run("bench --scenes grate --techniques vsv,ivsv --axes size --sizes 24x18 --runs 1 --set epipole=paper "
                      "--out " + bench.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFile(bench / "bench.html").find("default settings with epipole=paper"), std::string::npos);

    const std::string lesson = "# T\n\n## one\n```airlight\nscene: grate\nset: epipole=paper\ntechnique: ivsv\n```\ntext\n"
                               "## two\n```airlight\nset: epipole=paper\ntechnique: vsv\n```\ntext\n";
    r = run("lesson " + writeText("named.md", lesson).string() + " --export " + path("named").string() + " --size 16x12");
    ASSERT_EQ(r.exitCode, 0) << r.err;
}

// `compare` prints the report's figures: zero for an image against itself, the figures of
// viz::report::compareImages for two renders; a size mismatch is a one-line error with no heat map.
TEST_F(CliTest, CompareQuotesTheErrorOfOneImageAgainstAnother) {
    const fs::path coarse = path("coarse.exr"), fine = path("fine.exr"), small = path("small.exr"),
                   heat = path("heat.png");
    const std::string render = "render --scene grate --technique raymarch --layer airlight ";
    ASSERT_EQ(run(render + "--size 40x30 --set samples=8 --out " + coarse.string()).exitCode, 0);
    ASSERT_EQ(run(render + "--size 40x30 --set samples=256 --out " + fine.string()).exitCode, 0);
    ASSERT_EQ(run(render + "--size 20x15 --set samples=8 --out " + small.string()).exitCode, 0);

    RunResult r = run("compare " + fine.string() + " " + fine.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("relative L2 0 "), std::string::npos) << r.out;

    r = run("compare " + coarse.string() + " " + fine.string() + " --heatmap " + heat.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const viz::report::ErrorMetrics m =
        viz::report::compareImages(viz::readImage(coarse.string()), viz::readImage(fine.string()));
    ASSERT_GT(m.relativeL2, 0.0);
    char expected[64];
    std::snprintf(expected, sizeof expected, "relative L2 %.6g ", m.relativeL2);
    EXPECT_NE(r.out.find(expected), std::string::npos) << r.out << " (expected " << expected << ")";
    EXPECT_NE(r.out.find("NaN 0  Inf 0  negative 0"), std::string::npos) << r.out;
    EXPECT_EQ(viz::readImage(heat.string()).width, 40);

    const fs::path noHeat = path("noheat.png");
    r = run("compare " + small.string() + " " + fine.string() + " --heatmap " + noHeat.string());
    expectUserError(r, "20x15");
    EXPECT_FALSE(fs::exists(noHeat));
    expectUserError(run("compare " + fine.string()), "two images");
}

TEST_F(CliTest, RenderWritesPngAndIntermediates) {
    const RunResult r = run("render --scene grate --technique raymarch --size 32x24 --layer raymarch.distance --out " +
                            path("d.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("d.png")));
    const RunResult stop = run("render --scene grate --technique raymarch --size 32x24 --stop-after "
                               "raymarch.surface --layer airlight --out " + path("a.png").string());
    EXPECT_EQ(stop.exitCode, 2) << "L_air does not exist yet after the surface stage";
    EXPECT_FALSE(fs::exists(path("a.png")));
}

TEST_F(CliTest, PlanSaysWhatIsSkippedAndWhy) {
    const RunResult r = run("plan --scene grate --technique raymarch");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("off"), std::string::npos);
    EXPECT_NE(r.out.find("no area light"), std::string::npos) << r.out;
}

// --preset paper starts from the paper's configuration (the plan shows minmax's SVD integrand and
// slices' artistic formula on); --set still wins over it; an unknown preset is a one-line error. terrain:
// suns alone, where the default (integrand=auto) takes the closed form.
TEST_F(CliTest, PaperPresetSetsThePapersChoicesAndSetWins) {
    auto line = [](const std::string& out, const std::string& feature) {
        const std::size_t at = out.find("feature " + feature + " ");
        return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
    };
    // The state column of a feature's line ("feature NAME   on   why..."), not a word of its reason.
    auto state = [&line](const std::string& out, const std::string& feature) {
        std::istringstream words(line(out, feature));
        std::string keyword, name, on;
        words >> keyword >> name >> on;
        return on;
    };
    RunResult r = run("plan --scene terrain --technique minmax");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(state(r.out, "INTEGRAND_SVD"), "off") << r.out;
    EXPECT_NE(line(r.out, "INTEGRAND_SVD").find("integrand=auto"), std::string::npos) << r.out;
    r = run("plan --scene terrain --technique minmax --preset paper");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(state(r.out, "INTEGRAND_SVD"), "on") << r.out;
    EXPECT_NE(line(r.out, "INTEGRAND_SVD").find("rank-4"), std::string::npos) << r.out;
    r = run("plan --scene terrain --technique minmax --preset paper --set integrand=analytic");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(state(r.out, "INTEGRAND_SVD"), "off") << r.out;
    r = run("plan --scene grate --technique slices");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(state(r.out, "PHYSICAL"), "on") << r.out;
    r = run("plan --scene grate --technique slices --preset paper");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(state(r.out, "PHYSICAL"), "off") << r.out;
    r = run("plan --scene grate --technique slices --preset papers");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--preset 'papers'"), std::string::npos) << r.err;
}

// Every built-in scene with every registered technique: finite, non-negative, not black.
TEST_F(CliTest, EveryBuiltinSceneRendersWithEveryTechnique) {
    const RunResult scenes = run("list scenes");
    const RunResult techniques = run("list techniques");
    std::vector<std::string> sceneNames, techniqueNames;
    std::istringstream s(scenes.out), t(techniques.out);
    for (std::string line; std::getline(s, line);) sceneNames.push_back(line.substr(0, line.find(' ')));
    for (std::string line; std::getline(t, line);) techniqueNames.push_back(line.substr(0, line.find(' ')));
    ASSERT_GE(sceneNames.size(), 6u);
    ASSERT_GE(techniqueNames.size(), 2u);
    for (const auto& scene : sceneNames)
        for (const auto& technique : techniqueNames) {
            const fs::path out = path(scene + "_" + technique + ".exr");
            const RunResult r = run("render --scene " + scene + " --technique " + technique +
                                    " --size 48x36 --layer airlight --quiet --out " + out.string());
            ASSERT_EQ(r.exitCode, 0) << scene << " / " << technique << ": " << r.err;
            const viz::Image image = viz::readImage(out.string());
            EXPECT_TRUE(allFinite(image)) << scene << " / " << technique;
            float lo = 0.0f, sum = 0.0f;
            for (float v : image.pixels) lo = std::min(lo, v), sum += v;
            EXPECT_GE(lo, 0.0f) << scene << " / " << technique;
            EXPECT_GT(sum, 0.0f) << scene << " / " << technique << ": no airlight at all";
        }
}

// export-scene writes glTF that loads back to the same image.
TEST_F(CliTest, ExportSceneRoundTripRendersTheSameImage) {
    const RunResult scenes = run("list scenes");
    std::istringstream s(scenes.out);
    for (std::string line; std::getline(s, line);) {
        const std::string scene = line.substr(0, line.find(' '));
        for (const std::string ext : {".gltf", ".glb"}) {
            const fs::path file = path(scene + ext);
            const RunResult e = run("export-scene " + scene + " " + file.string());
            ASSERT_EQ(e.exitCode, 0) << e.err;
            const fs::path a = path(scene + "_a.exr"), b = path(scene + "_b.exr");
            ASSERT_EQ(run("render --scene " + scene + " --technique raymarch --size 40x30 --quiet --out " +
                          a.string()).exitCode, 0);
            const RunResult rb = run("render --scene " + file.string() + " --technique raymarch --size 40x30 --quiet --out " +
                                     b.string());
            ASSERT_EQ(rb.exitCode, 0) << rb.err;
            const viz::Image ia = viz::readImage(a.string()), ib = viz::readImage(b.string());
            ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
            double maxDiff = 0.0, maxValue = 0.0;
            for (std::size_t i = 0; i < ia.pixels.size(); ++i) {
                maxDiff = std::max(maxDiff, double(std::fabs(ia.pixels[i] - ib.pixels[i])));
                maxValue = std::max(maxValue, double(std::fabs(ia.pixels[i])));
            }
            EXPECT_LE(maxDiff, 1e-5 * maxValue) << scene << ext;
        }
    }
}

TEST_F(CliTest, ExportSceneNeverLeavesAPartialFile) {
    const RunResult r = run("export-scene grate " + (mDir / "no_such_dir" / "x.gltf").string());
    expectUserError(r, "no_such_dir");
    EXPECT_FALSE(fs::exists(mDir / "no_such_dir"));
}

TEST_F(CliTest, GltfFileLoadsAndRenders) {
    const fs::path scene = writeText("ok.gltf", makeGltf({}));
    const RunResult r = run("render --scene " + scene.string() + " --technique raymarch --size 32x24 --out " +
                            path("ok.exr").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("ok.exr")));
}

TEST_F(CliTest, NoCameraFramesTheSceneAndSaysSo) {
    GltfParts p;
    p.camera = false;
    const fs::path scene = writeText("nocam.gltf", makeGltf(p));
    const RunResult r = run("render --scene " + scene.string() + " --technique raymarch --size 32x24 --out " +
                            path("nocam.exr").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("no camera"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(path("nocam.exr")));
}

// Each bad input: one clear line, exit code 2, no output file.
TEST_F(CliTest, BadInputIsAOneLineErrorWithExitCode2AndNoOutput) {
    const std::string out = path("never.exr").string();
    const std::string render = "render --technique raymarch --size 32x24 --out " + out + " --scene ";
    struct Case {
        std::string name, args, mentions;
    };
    std::vector<Case> cases;
    cases.push_back({"missing file", render + path("absent.gltf").string(), "absent.gltf"});
    cases.push_back({"malformed JSON", render + writeText("bad.gltf", "{\"asset\": {\"version\": ").string(),
                     "bad.gltf"});
    {
        GltfParts p;
        p.uri = "missing.bin";
        cases.push_back({"missing buffer", render + writeText("nobuf.gltf", makeGltf(p)).string(), "missing.bin"});
    }
    {
        GltfParts p;
        p.bufferBytes = 100;  // longer than the data: the buffer is short
        cases.push_back({"short buffer", render + writeText("short.gltf", makeGltf(p)).string(), "buffer"});
    }
    {
        GltfParts p;
        p.indexCount = 600;  // beyond its buffer view
        cases.push_back({"accessor out of range", render + writeText("acc.gltf", makeGltf(p)).string(), "accessor"});
    }
    {
        GltfParts p;
        p.positions[4] = std::nanf("");
        cases.push_back({"NaN vertex", render + writeText("nan.gltf", makeGltf(p)).string(), "NaN"});
    }
    {
        GltfParts p;
        p.mode = 0;  // points only
        cases.push_back({"no triangles", render + writeText("notri.gltf", makeGltf(p)).string(), "triangle"});
    }
    {
        GltfParts p;
        p.light = false;
        cases.push_back({"no light", "render --no-default-light " + render.substr(7) + writeText("nolight.gltf", makeGltf(p)).string(), "light"});
    }
    {
        GltfParts p;
        p.medium = R"({"sigma_s": -0.1, "sigma_a": 0.0, "g": 0.0})";
        cases.push_back({"negative sigma", render + writeText("negsig.gltf", makeGltf(p)).string(), "sigma_s"});
    }
    {
        GltfParts p;
        p.medium = R"({"sigma_s": 0.1, "sigma_a": 0.0, "g": 1.0})";
        cases.push_back({"|g| >= 1", render + writeText("g1.gltf", makeGltf(p)).string(), "g"});
    }
    cases.push_back({"size 0x0", "render --scene grate --technique raymarch --size 0x0 --out " + out, "0x0"});
    cases.push_back({"size too large", "render --scene grate --technique raymarch --size 8193x10 --out " + out,
                     "8193x10"});
    cases.push_back({"unknown technique", "render --scene grate --technique nope --size 8x8 --out " + out, "nope"});
    cases.push_back({"unknown stage", "render --scene grate --technique raymarch --stop-after nope.stage --size 8x8 --out " +
                                          out, "nope.stage"});
    cases.push_back({"unknown parameter", "render --scene grate --technique raymarch --set bogus=1 --size 8x8 --out " +
                                              out, "bogus"});
    cases.push_back({"parameter out of range", "render --scene grate --technique raymarch --set samples=0 --size 8x8 --out " +
                                                   out, "samples"});
    // A number strtod reads only after skipping a blank is refused like one with a blank after it; a number
    // below the smallest normal double is a number (out of this range), not a "non-finite" one.
    cases.push_back({"blank before a number", "render --scene grate --technique raymarch --set \"samples= 8\" --size 8x8 --out " +
                                                  out, "' 8' is not a finite number"});
    cases.push_back({"underflowing number", "render --scene grate --technique slices --set accum_range=1e-320 --size 8x8 --out " +
                                                out, "'accum_range' = 1e-320 is out of range"});
    cases.push_back({"per-axis value with two axes",
                     "render --scene grate --technique vsv --set voxels=64x32 --size 8x8 --out " + out, "3 numbers"});
    cases.push_back({"per-axis value for a one-number parameter",
                     "render --scene grate --technique raymarch --set samples=4x4x4 --size 8x8 --out " + out, "samples"});
    cases.push_back({"per-axis value for a technique without those axes",
                     "render --scene grate --technique ivsv --set voxels=64x32x96 --size 8x8 --out " + out,
                     "--set voxels: ivsv takes one number, not '64x32x96'"});
    cases.push_back({"unknown scene", "render --scene nowhere --technique raymarch --size 8x8 --out " + out, "nowhere"});
    cases.push_back({"bad output type", "render --scene grate --technique raymarch --size 8x8 --out " +
                                            path("x.jpg").string(), "x.jpg"});
    cases.push_back({"unknown layer", "render --scene grate --technique raymarch --size 8x8 --layer nope.layer --out " +
                                          out, "nope.layer"});
    // A 2D shadow map has layer 0 alone; an image a technique made on the CPU has one layer too.
    cases.push_back({"layer index past the last layer",
                     "render --scene grate --technique vsv --size 8x8 --layer vsv.shadow_map --layer-index 1 --out " + out,
                     "--layer-index 1 is past the last layer of 'vsv.shadow_map' (it has one layer, 0)"});
    cases.push_back({"layer index of a CPU image",
                     "render --scene grate --technique vsv --size 8x8 --layer vsv.voxels --layer-index 3 --out " + out,
                     "--layer-index 3 is past the last layer of 'vsv.voxels'"});
    cases.push_back({"exposure of 0",
                     "render --scene grate --technique raymarch --size 8x8 --exposure 0 --out " + out,
                     "--exposure must be auto or a scale above 0 (1 writes the values as they are), not '0'"});
    cases.push_back({"negative exposure",
                     "render --scene grate --technique raymarch --size 8x8 --exposure -1 --out " + out,
                     "--exposure must be auto or a scale above 0"});
    cases.push_back({"fractional layer index",
                     "render --scene grate --technique vsv --size 8x8 --layer vsv.shadow_map --layer-index 2.5 --out " + out,
                     "--layer-index must be a whole number from 0 to 65536, not '2.5'"});
    cases.push_back({"negative layer index",
                     "render --scene grate --technique vsv --size 8x8 --layer vsv.shadow_map --layer-index -3 --out " + out,
                     "--layer-index must be a whole number"});
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const RunResult r = run(c.args);
        expectUserError(r, c.mentions);
        EXPECT_FALSE(fs::exists(out)) << "partial output left behind";
        for (const auto& entry : fs::directory_iterator(mDir))
            EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
}
