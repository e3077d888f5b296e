// `airlight gui --screenshot`: the window under a (virtual) display writes a screenshot and the
// rectangles of its views, and the views hold the rendered images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

// What the window exported equals what `render` wrote, pixel for pixel (RGB).
void expectSameImage(const std::string& window, const std::string& cliPath) {
    const Image gui = readImage(window);
    const Image cli = readImage(cliPath);
    ASSERT_EQ(gui.width, cli.width);
    ASSERT_EQ(gui.height, cli.height);
    for (int y = 0; y < cli.height; ++y)
        for (int x = 0; x < cli.width; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_EQ(gui.at(x, y, c), cli.at(x, y, c)) << x << "," << y;
}

class GuiCli : public WindowCliTest {
protected:
    // Opens the window with `options`, opens the comparison grid (G) once the first frames are in and
    // returns the screenshot's sidecar; `name` names the files.
    nlohmann::json comparisonGrid(const std::string& name, const std::string& options) {
        const fs::path script = writeText(name + ".txt", "frames 2\nkey G\nframes 1\n");
        const RunResult r = run("gui " + options + " --script " + script.string() + " --screenshot " +
                                path(name + ".png").string());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return nlohmann::json::parse(readFile(path(name + ".json")));
    }
};

// Mean and spread of the pixels inside a rectangle (window pixels).
void regionStats(const Image& image, const nlohmann::json& rect, double& mean, double& spread) {
    const int x0 = int(std::ceil(rect[0].get<double>())), y0 = int(std::ceil(rect[1].get<double>()));
    const int x1 = int(rect[2].get<double>()), y1 = int(rect[3].get<double>());
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const double v = image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
            sum += v, sum2 += v * v, ++n;
        }
    mean = sum / std::max(n, 1);
    spread = std::sqrt(std::max(0.0, sum2 / std::max(n, 1) - mean * mean));
}

TEST_F(GuiCli, ScreenshotShowsTheRenderedViewsWhereTheSidecarSays) {
    const fs::path shot = path("window.png");
    const RunResult r = run("gui --scene grate --technique raymarch --size 80x60 --set samples=32 --screenshot " +
                            shot.string() + " --frames 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image image = readImage(shot.string());
    const nlohmann::json j = nlohmann::json::parse(readFile(path("window.json")));
    EXPECT_EQ(j.at("window")[0].get<int>(), image.width);
    EXPECT_EQ(j.at("window")[1].get<int>(), image.height);
    EXPECT_EQ(j.at("technique"), "raymarch");
    EXPECT_GE(j.at("frames").get<int>(), 2);
    ASSERT_EQ(j.at("views").size(), 2u);
    EXPECT_EQ(j.at("views")[0].at("name"), "final");
    EXPECT_EQ(j.at("views")[1].at("name"), "airlight");
    // Each view holds a picture (light and shadow), not a flat fill; beside each picture its cell is flat
    // (the gap between the cells holds the divider).
    for (const auto& view : j.at("views")) {
        double mean = 0.0, spread = 0.0;
        regionStats(image, view.at("rect"), mean, spread);
        EXPECT_GT(spread, 0.05) << view.at("name");
        EXPECT_GT(mean, 0.01) << view.at("name");
    }
    const auto& a = j.at("views")[0].at("rect");
    const auto& b = j.at("views")[1].at("rect");
    const auto& cellA = j.at("views")[0].at("cell_rect");
    const auto& cellB = j.at("views")[1].at("cell_rect");
    const double margins[2][2] = {{a[2].get<double>() + 1.0, cellA[2].get<double>() - 1.0},
                                  {cellB[0].get<double>() + 1.0, b[0].get<double>() - 1.0}};
    int checked = 0;
    for (const auto& m : margins) {
        if (m[1] - m[0] < 2.0) continue;
        double mean = 0.0, spread = 0.0;
        regionStats(image, nlohmann::json::array({m[0], a[1], m[1], a[3]}), mean, spread);
        EXPECT_LT(spread, 1e-3);
        ++checked;
    }
    EXPECT_GE(checked, 1) << "the 80x60 pictures leave room beside them in their cells";
}

TEST_F(GuiCli, ASavedSessionIsRestoredAndAFileThatIsNotOneIsRefusedUntouched) {
    const fs::path state = writeText("session.json", R"({
  "version": 1, "scene": "grate", "technique": "slices", "size": [64, 48],
  "camera": {"position": [0.0, 1.0, 6.0], "forward": [0.0, 0.1, -1.0], "up": [0.0, 1.0, 0.0],
             "yfov": 0.9, "znear": 0.05, "zfar": 40.0, "target": [0.0, 1.5, 0.0]},
  "medium": {"sigma_s": 0.2, "sigma_a": 0.01, "g": 0.3},
  "settings": {"slices": {"planes": 48}},
  "view": "slices.shadow_map", "exposure": -1.0, "exposure_set": true
})");
    const RunResult r = run("gui --state " + state.string() + " --screenshot " + path("a.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json a = nlohmann::json::parse(readFile(path("a.json")));
    EXPECT_EQ(a.at("scene"), "grate");
    EXPECT_EQ(a.at("technique"), "slices");
    EXPECT_EQ(a.at("views")[1].at("name"), "slices.shadow_map");
    const std::string before = readFile(state);

    EXPECT_EQ(readFile(state), before);

    // A file named with --state that is not a session (a truncated one, or a mistyped path to some other
    // JSON or text file) stops the window before it opens with one line naming the file; the file is
    // left byte for byte where it was, never moved aside or saved over, and no screenshot is written.
    const std::vector<std::pair<std::string, std::string>> notSessions = {
        {"broken.json", before.substr(0, before.size() / 3)},
        {"scene.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}]})"},
        {"notes.txt", "root:x:0:0:root:/root:/bin/bash\n"},
    };
    for (const auto& [name, text] : notSessions) {
        const fs::path file = writeText(name, text);
        const fs::path shot = path(name + ".png");
        const RunResult b = run("gui --state " + file.string() + " --screenshot " + shot.string());
        EXPECT_EQ(b.exitCode, 2) << name << ": " << b.err;
        EXPECT_NE(b.err.find(name), std::string::npos) << b.err;
        EXPECT_NE(b.err.find("not an Airlight session"), std::string::npos) << b.err;
        EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << "one line: " << b.err;
        EXPECT_EQ(readFile(file), text) << name << " must be left as it was";
        EXPECT_FALSE(fs::exists(file.string() + ".broken")) << name;
        EXPECT_FALSE(fs::exists(shot)) << name;
    }

    // A name that holds nothing yet starts a new session there, with the defaults.
    const fs::path fresh = path("fresh.json");
    const RunResult c = run("gui --state " + fresh.string() + " --screenshot " + path("c.png").string());
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_NE(c.err.find("fresh.json"), std::string::npos) << c.err;
    EXPECT_NE(c.err.find("a new session"), std::string::npos) << c.err;
    const nlohmann::json cj = nlohmann::json::parse(readFile(path("c.json")));
    EXPECT_EQ(cj.at("scene"), "colonnade");  // the built-in default scene
    EXPECT_EQ(cj.at("technique"), "raymarch");  // the window's default
}

// F9 loads a session saved on another scene: the window switches to that scene, size, technique and
// camera; a session whose scene no longer loads leaves the window as it was, saying why.
TEST_F(GuiCli, F9SwitchesToTheSavedSessionsScene) {
    const fs::path state = path("other.json");
    const RunResult saved = run("gui --scene terrain --technique minmax --size 48x36 --state " + state.string() +
                                " --script " + writeText("save.txt", "frames 2\nkey F5\nframes 1\n").string());
    ASSERT_EQ(saved.exitCode, 0) << saved.err;
    const nlohmann::json session = nlohmann::json::parse(readFile(state));
    ASSERT_EQ(session.at("scene"), "terrain");

    const fs::path load = writeText("load.txt", "frames 2\nkey F9\nframes 3\nsidecar " + path("loaded.json").string() + "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --state " + state.string() +
                            " --script " + load.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(readFile(path("loaded.json")));
    EXPECT_EQ(j.at("scene"), "terrain");
    EXPECT_EQ(j.at("technique"), "minmax");
    EXPECT_EQ(j.at("size"), nlohmann::json::array({48, 36}));
    EXPECT_EQ(j.at("camera").at("position"), session.at("camera").at("position"));
    EXPECT_NE(j.at("notice").get<std::string>().find("session loaded"), std::string::npos) << j.at("notice");

    nlohmann::json gone = session;
    gone["scene"] = path("gone.gltf").string();
    const fs::path goneState = writeText("gone.json", gone.dump(2));
    const RunResult g = run("gui --scene grate --technique raymarch --size 32x24 --state " + goneState.string() +
                            " --script " + writeText("load2.txt", "frames 2\nkey F9\nframes 2\nsidecar " +
                                                                      path("kept.json").string() + "\n").string());
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const nlohmann::json k = nlohmann::json::parse(readFile(path("kept.json")));
    EXPECT_EQ(k.at("scene"), "grate");
    EXPECT_EQ(k.at("technique"), "raymarch");
    EXPECT_EQ(k.at("size"), nlohmann::json::array({32, 24}));
    EXPECT_NE(k.at("notice").get<std::string>().find("gone.gltf"), std::string::npos) << k.at("notice");
    EXPECT_NE(k.at("notice").get<std::string>().find("the current session stays"), std::string::npos) << k.at("notice");
}

TEST_F(GuiCli, AScriptClicksWidgetsAndSidebarItemsByName) {
    const fs::path script = writeText("actions.txt", R"S(# switch technique, raise sigma_s on its log slider, show the shadow map
click technique:slices
frames 2
click "sigma_s (scattering)" 0.9 0.5
frames 2
click "view:Spot shadow map"
screenshot )S" + path("mid.png").string() + R"S(
frames 1
)S");
    const RunResult r = run("gui --scene grate --size 80x60 --script " + script.string() + " --screenshot " +
                            path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("mid.png")));
    const nlohmann::json j = nlohmann::json::parse(readFile(path("end.json")));
    EXPECT_EQ(j.at("technique"), "slices");
    // 0.9 of the way along the log slider's declared range, 1e-7 to 1e3: 1e-7 * 1e10^0.9 = 100 (pixel
    // rounding aside).
    EXPECT_NEAR(std::log10(j.at("medium").at("sigma_s").get<double>()), 2.0, 0.05);
    EXPECT_EQ(j.at("medium").at("g").get<double>(), 0.2);  // untouched, exactly the scene's value
    EXPECT_EQ(j.at("views")[1].at("name"), "slices.shadow_map");
}

// The light panel moves and turns the first light: a spot's elevation slider at a quarter of its range
// points it 45 degrees down, its position drag is there, and the technique runs with the moved light.
TEST_F(GuiCli, TheLightPanelTurnsTheLight) {
    // (A script scrolls the panel to the widget it clicks, as a user would.)
    const fs::path script =
        writeText("light.txt", "frames 2\nclick \"Light placement\"\nframes 1\n"
                               "click \"direction elevation (deg)\" 0.25 0.5\nframes 2\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 40x30 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("light.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(readFile(path("light.json")));
    ASSERT_EQ(j.at("lights").size(), 1u);
    const auto& d = j.at("lights")[0].at("direction");
    const double x = d[0].get<double>(), y = d[1].get<double>(), z = d[2].get<double>();
    EXPECT_NEAR(std::sqrt(x * x + y * y + z * z), 1.0, 1e-9);
    EXPECT_NEAR(y, -std::sqrt(0.5), 0.03) << "45 degrees below the horizon (pixel rounding aside)";
}

// A light of intensity 0 opens (the slider's range once came from the light's own value and aborted the
// window); ticking "on" brings it back and the slider then moves it over its declared range.
TEST_F(GuiCli, ALightOfIntensityZeroOpensAndCanBeSwitchedOn) {
    ASSERT_EQ(run("export-scene grate " + path("grate.gltf").string()).exitCode, 0);
    nlohmann::json doc = nlohmann::json::parse(readFile(path("grate.gltf")));
    doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 0.0;
    writeText("dark.gltf", doc.dump());
    const fs::path script = writeText("on.txt", "frames 2\nscreenshot " + path("off.png").string() +
                                                    "\nclick on\nframes 2\nclick intensity 0.75 0.5\nframes 2\n");
    const RunResult r = run("gui --scene " + path("dark.gltf").string() +
                            " --technique raymarch --size 40x30 --set samples=16 --script " + script.string() +
                            " --screenshot " + path("on.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json off = nlohmann::json::parse(readFile(path("off.json")));
    const nlohmann::json on = nlohmann::json::parse(readFile(path("on.json")));
    EXPECT_EQ(off.at("lights")[0].at("intensity").get<double>(), 0.0);
    // Three quarters along a log scale from 1e-6 to 1e12: 1e7.5, whatever the light was.
    EXPECT_NEAR(std::log10(on.at("lights")[0].at("intensity").get<double>()), 7.5, 0.2);
}

// The medium's coefficients: log sliders over declared ranges (1e-7 to 1e3 per scene unit) and 0 as a box
// unticked. A stiff case's 5e-7 stays exact until a widget changes it; unticking "scatters" makes sigma_s 0
// and ticking it brings 5e-7 back exactly; the middle of the slider is 1e-2 whatever the scene had;
// unticking "absorbs" makes sigma_a 0.
TEST_F(GuiCli, TheMediumsCoefficientsSlideOverDeclaredRangesAndABoxSwitchesThemOff) {
    const std::string shot = "\nframes 2\nscreenshot ";
    const fs::path script = writeText("medium.txt", "frames 2\nscreenshot " + path("start.png").string() +
                                                        "\nclick scatters" + shot + path("off.png").string() +
                                                        "\nclick scatters" + shot + path("back.png").string() +
                                                        "\nclick \"sigma_s (scattering)\" 0.5 0.5" + shot +
                                                        path("middle.png").string() + "\nclick absorbs\nframes 2\n");
    const RunResult r = run("gui --scene stiff/extinction-1e-6 --technique raymarch --size 40x30 --set samples=8 --script " +
                            script.string() + " --screenshot " + path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto medium = [&](const char* name) { return nlohmann::json::parse(readFile(path(name))).at("medium"); };
    EXPECT_EQ(medium("start.json").at("sigma_s").get<double>(), 5e-7);
    EXPECT_EQ(medium("off.json").at("sigma_s").get<double>(), 0.0);
    EXPECT_EQ(medium("back.json").at("sigma_s").get<double>(), 5e-7);
    EXPECT_NEAR(std::log10(medium("middle.json").at("sigma_s").get<double>()), -2.0, 0.1);
    EXPECT_EQ(medium("middle.json").at("sigma_a").get<double>(), 5e-7);
    EXPECT_EQ(medium("end.json").at("sigma_a").get<double>(), 0.0);
}

// Where GL timer queries measure the work the window times the main views' GPU stages with gl::GpuTimer,
// which does not wait for the GPU; AIRLIGHT_GPU_TIMER=1 asks for it here (its times mean nothing on
// llvmpipe). The sidecar's timing names the clock and gives every stage run a time, stepping included;
// ivsv on grate runs vsv inside its gather (nested stages). Without it the window waits for each stage.
TEST_F(GuiCli, TheWindowTimesGpuStagesWithoutWaitingWhereAskedTo) {
    const fs::path script = writeText("timer.txt", "frames 3\nkey S\nframes 2\nscreenshot " + path("step.png").string() +
                                                       "\nkey Shift+S\nframes 3\n");
    const std::string args = "gui --scene grate --technique ivsv --size 40x30 --set vpls=4 --script " + script.string();
    ::setenv("AIRLIGHT_GPU_TIMER", "1", 1);
    const RunResult r = run(args + " --screenshot " + path("ring.png").string());
    ::unsetenv("AIRLIGHT_GPU_TIMER");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto timing = [&](const char* name) { return nlohmann::json::parse(readFile(path(name))).at("timing"); };
    const nlohmann::json ring = timing("ring.json"), step = timing("step.json");  // before the plain run's
    const RunResult plain = run(args + " --screenshot " + path("plain.png").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    EXPECT_EQ(ring.at("clock").get<std::string>().rfind("GL_TIMESTAMP ring", 0), 0u) << ring.at("clock");
    EXPECT_EQ(step.at("clock"), ring.at("clock"));
    EXPECT_EQ(ring.at("stages").size(), 7u) << ring.dump();  // vpls .. compose
    EXPECT_EQ(step.at("stages").size(), 1u) << step.dump();  // S: stopped after the first stage
    for (const nlohmann::json& s : ring.at("stages")) EXPECT_GE(s.at("ms").get<double>(), 0.0) << s.dump();
    EXPECT_EQ(timing("plain.json").at("clock"), "glFinish+steady_clock");
    EXPECT_EQ(timing("plain.json").at("stages").size(), 7u);
}

// In fly mode W A S D Q E belong to the camera: S and Shift+S do not step the stage, E does not export a
// view, and holding S moves the camera back. Back in orbit mode (C) Shift+S steps again.
TEST_F(GuiCli, InFlyModeTheMovementKeysOnlyMoveTheCamera) {
    const fs::path exports = path("exports");
    const fs::path script = writeText("fly.txt", "frames 2\nscreenshot " + path("before.png").string() +
                                                     "\nkey C\nkey S\nkey Shift+S\nkey E\nhold S 4\nframes 2\nscreenshot " +
                                                     path("fly.png").string() + "\nkey C\nkey Shift+S\nframes 2\n");
    const RunResult r = run("gui --scene grate --technique slices --size 40x30 --set planes=16 --export-dir " +
                            exports.string() + " --script " + script.string() + " --screenshot " + path("orbit.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json before = nlohmann::json::parse(readFile(path("before.json")));
    const nlohmann::json fly = nlohmann::json::parse(readFile(path("fly.json")));
    const nlohmann::json orbit = nlohmann::json::parse(readFile(path("orbit.json")));
    EXPECT_EQ(fly.at("stage"), "slices.compose") << "S in fly mode must not step the stage";
    EXPECT_EQ(fly.at("camera").at("mode"), "fly");
    // Held S moves the camera against its forward direction.
    glm::dvec3 moved{0.0}, forward{0.0};
    for (int i = 0; i < 3; ++i) {
        moved[i] = fly.at("camera").at("position")[i].get<double>() - before.at("camera").at("position")[i].get<double>();
        forward[i] = before.at("camera").at("forward")[i].get<double>();
    }
    EXPECT_LT(glm::dot(moved, forward), 0.0) << "holding S in fly mode moves the camera back";
    EXPECT_FALSE(fs::exists(exports)) << "E in fly mode must not export";
    EXPECT_NE(orbit.at("stage"), "slices.compose") << "Shift+S in orbit mode steps";
}

// The scene pickers load a built-in scene or a stiff case with its own camera and medium.
TEST_F(GuiCli, TheScenePickersLoadABuiltinSceneAndAStiffCase) {
    const fs::path script = writeText("pick.txt", "frames 1\nclick scene\nframes 1\nclick \"scene/colonnade\"\nframes 2\n"
                                                  "screenshot " + path("picked.png").string() + "\n"
                                                  "click \"stiff case\"\nframes 1\nclick \"stiff case/stiff/extinction-50\"\n"
                                                  "frames 2\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 40x30 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("stiff.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json picked = nlohmann::json::parse(readFile(path("picked.json")));
    EXPECT_EQ(picked.at("scene"), "colonnade");
    const nlohmann::json stiff = nlohmann::json::parse(readFile(path("stiff.json")));
    EXPECT_EQ(stiff.at("medium").at("sigma_s").get<double>() + stiff.at("medium").at("sigma_a").get<double>(), 50.0)
        << "extinction 50 per unit";
}

// Picking a scene while the comparison grid is open: the grid's tiles were queued for drawing when the
// pick closed the grid and released their textures (a GL error, and a read of freed tiles, found by the
// window fuzz). The scene now loads before the next frame is laid out.
TEST_F(GuiCli, PickingASceneWithTheComparisonGridOpenDrawsNoReleasedTexture) {
    const fs::path stats = path("stats.jsonl");
    const fs::path script = writeText("pick.txt", "frames 1\nkey G\nframes 3\nclick scene\nframes 1\n"
                                                  "click \"scene/colonnade\"\nframes 3\nstats " + stats.string() + "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 24x18 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("after.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(readFile(stats)).at("gl_errors").get<long>(), 0);
    EXPECT_EQ(nlohmann::json::parse(readFile(path("after.json"))).at("scene"), "colonnade");
}

// Dragging an orbit view (polyvol's light volume with wireframe=3) turns its own camera: mesh_yaw and
// mesh_pitch change by 0.4 degrees per pixel dragged, the main camera stays.
TEST_F(GuiCli, DraggingAnOrbitViewTurnsItsCamera) {
    const fs::path script = writeText("orbit.txt", "frames 1\nclick \"view:Light volume mesh\"\nframes 2\n"
                                                   "screenshot " + path("before.png").string() + "\n"
                                                   "drag polyvol.mesh 0.3 0.5 0.7 0.6\nframes 2\nscreenshot " +
                                                   path("turned.png").string() + "\nwheel polyvol.mesh 2\nframes 2\n");
    const RunResult r = run("gui --scene grate --technique polyvol --size 40x30 --set wireframe=3 --set shadow_map=64 "
                            "--script " + script.string() + " --screenshot " + path("after.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json before = nlohmann::json::parse(readFile(path("before.json")));
    const nlohmann::json after = nlohmann::json::parse(readFile(path("turned.json")));
    const nlohmann::json zoomed = nlohmann::json::parse(readFile(path("after.json")));
    const double yaw0 = before.at("settings").at("mesh_yaw").get<double>(),
                 yaw1 = after.at("settings").at("mesh_yaw").get<double>();
    const double pitch0 = before.at("settings").at("mesh_pitch").get<double>(),
                 pitch1 = after.at("settings").at("mesh_pitch").get<double>();
    EXPECT_LT(yaw1, yaw0 - 5.0) << "dragged right: the orbit turns the other way";
    EXPECT_GT(pitch1, pitch0 + 1.0) << "dragged down: the orbit camera rises";
    EXPECT_EQ(after.at("views").size(), before.at("views").size());
    // The wheel over it moves its own camera in (mesh_zoom, 1.25 a notch); the view's texture zoom stays 1.
    EXPECT_NEAR(zoomed.at("settings").at("mesh_zoom").get<double>(),
                after.at("settings").at("mesh_zoom").get<double>() * 1.25 * 1.25, 1e-9);
    for (const auto& v : zoomed.at("views"))
        if (v.at("name") == "polyvol.mesh") {
            EXPECT_EQ(v.at("zoom").get<double>(), 1.0);
        }
}

// Stepping as a student does it: the window opens on the complete frame; S goes to the first stage (it
// wraps), a stage with sub-steps is entered at its first, End and Home jump, D past the last says so and
// changes nothing; the sub-step is the cursor's, never a setting; every view warns while stopped early.
TEST_F(GuiCli, SteppingStopsAtAStageAndInsideItAtASubstep) {
    const std::string shot = "\nframes 1\nscreenshot ";
    const fs::path script = writeText(
        "step.txt", "frames 1\nscreenshot " + path("s0.png").string() + "\nkey S" + shot + path("s1.png").string() +
                        "\nkey S\nkey S" + shot + path("s3.png").string() + "\nkey End\nkey D" + shot +
                        path("end.png").string() + "\nkey Shift+D\nkey Shift+D" + shot + path("back.png").string() +
                        "\nkey Home\nkey Shift+D" + shot + path("home.png").string() + "\nkey Shift+S\nkey Shift+S\nkey Shift+S" +
                        shot + path("wrap.png").string() + "\nclick timeline 0.01 0.5\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique slices --size 40x30 --set planes=16 --script " +
                            script.string() + " --screenshot " + path("click.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto shotJson = [&](const char* name) { return nlohmann::json::parse(readFile(path(name))); };
    const auto title = [](const nlohmann::json& j) { return j.at("views")[0].at("title").get<std::string>(); };
    const nlohmann::json s0 = shotJson("s0.json");
    EXPECT_EQ(s0.at("stage"), "slices.compose");
    EXPECT_EQ(s0.at("stopped_early"), "");
    EXPECT_EQ(title(s0).find("stopped"), std::string::npos) << title(s0);
    const nlohmann::json s1 = shotJson("s1.json");
    EXPECT_EQ(s1.at("stage"), "slices.shadow_maps") << "S from the complete frame goes to the first stage";
    EXPECT_NE(title(s1).find("stopped after stage 1/5"), std::string::npos) << title(s1);
    const nlohmann::json s3 = shotJson("s3.json");
    EXPECT_EQ(s3.at("stage"), "slices.planes");
    EXPECT_EQ(s3.at("substep"), 1) << "a stage is entered at its first sub-step";
    EXPECT_EQ(s3.at("substep_count"), 16);
    EXPECT_EQ(s3.at("last_stage_run"), 2);
    // L_air does not exist yet: the view shows what the planes stage published.
    EXPECT_EQ(s3.at("views")[1].at("name"), "slices.accumulation");
    const nlohmann::json end = shotJson("end.json");
    EXPECT_EQ(end.at("substep"), 16);
    EXPECT_NE(end.at("notice").get<std::string>().find("already at the last sub-step"), std::string::npos)
        << end.at("notice");
    const nlohmann::json back = shotJson("back.json");
    EXPECT_EQ(back.at("substep"), 14);
    EXPECT_EQ(back.at("settings").at("planes_drawn").get<double>(), 0.0) << "the sub-step is not a setting";
    EXPECT_NE(back.at("stopped_early").get<std::string>().find("sub-step 14/16"), std::string::npos);
    EXPECT_EQ(back.at("first_stage_run"), 2) << "a sub-step re-runs its stage only";
    const nlohmann::json home = shotJson("home.json");
    EXPECT_EQ(home.at("substep"), 1);
    EXPECT_NE(home.at("notice").get<std::string>().find("already at the first sub-step"), std::string::npos);
    const nlohmann::json wrap = shotJson("wrap.json");
    EXPECT_EQ(wrap.at("stage"), "slices.compose") << "Shift+S from the first stage wraps to the complete frame";
    EXPECT_EQ(wrap.at("stopped_early"), "");
    const nlohmann::json click = shotJson("click.json");
    EXPECT_EQ(click.at("stage"), "slices.shadow_maps") << "the timeline's left end is the first stage";
}

// A run stepped into the planes stage shows that stage's views in the final frame's and L_air's panes;
// the one slices draws only on demand (the last plane alone) is then asked for and drawn, once: its pane
// has an image and the following frames run nothing (the stage times stay those of one run). It stayed
// empty before, asked for by its chosen content ("final") only.
TEST_F(GuiCli, AStageViewStandingInIsDrawnOnDemandOnce) {
    const fs::path script = writeText("stand_in.txt", "frames 1\nkey S\nkey S\nkey S\nframes 1\nkey D\nkey D\nframes 3\n"
                                                      "screenshot " + path("a.png").string() + "\nframes 4\n");
    const RunResult r = run("gui --scene colonnade --technique slices --size 64x48 --set planes=16 --script " +
                            script.string() + " --screenshot " + path("b.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json a = nlohmann::json::parse(readFile(path("a.json")));
    const nlohmann::json b = nlohmann::json::parse(readFile(path("b.json")));
    EXPECT_EQ(a.at("substep"), 3);
    bool plane = false;
    for (const auto& v : a.at("views"))
        if (v.at("name") == "slices.plane") {
            plane = true;
            EXPECT_EQ(v.at("content"), "final") << "it stands in for the final frame";
            EXPECT_EQ(v.at("size"), nlohmann::json::array({64, 48})) << "drawn, not an empty pane";
        }
    EXPECT_TRUE(plane) << a.at("views").dump();
    EXPECT_EQ(a.at("timing"), b.at("timing")) << "no run after the one that drew it";
}

// minmax's walk is stepped node by node as far as the picked ray's walk goes, not a fixed 64 sub-steps (the
// centre's walk on grate has more): End stops on its last node N, D past it says so, and `render` agrees
// that the walk has N nodes:
// trace_steps=N draws the whole walk (the image of trace_steps=0) and trace_steps=N-1 does not.
TEST_F(GuiCli, SteppingMinmaxsWalkEndsOnThePickedRaysLastNode) {
    const fs::path script = writeText("walk.txt", "key Shift+S\nframes 1\nscreenshot " + path("first.png").string() +
                                                      "\nkey End\nframes 1\nkey D\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique minmax --size 40x30 --script " + script.string() +
                            " --screenshot " + path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json first = nlohmann::json::parse(readFile(path("first.json")));
    const nlohmann::json end = nlohmann::json::parse(readFile(path("end.json")));
    EXPECT_EQ(first.at("stage"), "minmax.traverse");
    EXPECT_EQ(first.at("substep"), 1);
    const int nodes = first.at("substep_count").get<int>();
    ASSERT_GE(nodes, 2) << "the picked pixel (the centre) is walked";
    EXPECT_EQ(end.at("substep"), nodes);
    EXPECT_EQ(end.at("substep_count"), nodes);
    EXPECT_NE(end.at("notice").get<std::string>().find("already at the last sub-step"), std::string::npos) << end.at("notice");

    const auto trace = [&](int steps) {
        const fs::path out = path("trace" + std::to_string(steps) + ".exr");
        EXPECT_EQ(run("render --scene grate --technique minmax --size 40x30 --layer minmax.trace --set trace_steps=" +
                      std::to_string(steps) + " --out " + out.string()).exitCode, 0);
        return readImage(out.string());
    };
    const Image whole = trace(0), last = trace(nodes), before = trace(nodes - 1);
    EXPECT_EQ(last.pixels, whole.pixels) << "trace_steps=" << nodes << " draws every node of the walk";
    EXPECT_NE(before.pixels, whole.pixels) << "trace_steps=" << nodes - 1 << " leaves the last node out";
}

// Stepping the vsv scan pass by pass and moving on leaves nothing behind: the complete frame afterwards is
// the one `render` writes (the old window kept scan_passes=2 as a setting and drew a wrong gather).
TEST_F(GuiCli, LeavingAStageRestoresTheCompleteFrame) {
    const fs::path script = writeText("leak.txt", "key Shift+S\nkey Shift+S\nframes 1\nkey D\nkey D\nframes 1\nscreenshot " +
                                                      path("scan.png").string() + "\nkey S\nkey S\nframes 1\nkey E\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique vsv --size 40x30 --export-dir " + path("exports").string() +
                            " --script " + script.string() + " --screenshot " + path("after.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json scan = nlohmann::json::parse(readFile(path("scan.json")));
    EXPECT_EQ(scan.at("stage"), "vsv.scan");
    EXPECT_EQ(scan.at("substep"), 3);
    const nlohmann::json after = nlohmann::json::parse(readFile(path("after.json")));
    EXPECT_EQ(after.at("stage"), "vsv.compose");
    EXPECT_EQ(after.at("stopped_early"), "");
    EXPECT_EQ(after.at("settings").at("scan_passes").get<double>(), -1.0);
    ASSERT_EQ(run("render --scene grate --technique vsv --size 40x30 --layer airlight --out " + path("cli.exr").string())
                  .exitCode, 0);
    expectSameImage((path("exports") / "grate-vsv-airlight.exr").string(), path("cli.exr").string());
}

// E and F12 write what render writes; exporting again after a change never writes over an earlier
// export: the next gets the first free number (-2, -3, ...).
TEST_F(GuiCli, ExportingAViewWritesWhatRenderWrites) {
    const fs::path script = writeText("export.txt", "key E\nkey F12\nframes 1\nkey Up\nframes 1\nkey E\nkey F12\nframes 1\n"
                                                    "key E\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 40x30 --set samples=64 --export-dir " +
                            path("exports").string() + " --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("exports") / "grate-raymarch-airlight.png"));
    EXPECT_TRUE(fs::exists(path("exports") / "grate-raymarch-window.png"));
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 40x30 --set samples=64 --layer airlight --out " +
                  path("cli.exr").string()).exitCode, 0);
    expectSameImage((path("exports") / "grate-raymarch-airlight.exr").string(), path("cli.exr").string());
    for (const char* later : {"grate-raymarch-airlight-2.exr", "grate-raymarch-airlight-2.png", "grate-raymarch-window-2.png",
                              "grate-raymarch-window-2.json", "grate-raymarch-airlight-3.exr"})
        EXPECT_TRUE(fs::exists(path("exports") / later)) << later;
    EXPECT_FALSE(fs::exists(path("exports") / "grate-raymarch-window-3.png"));
    // The first export is still the first frame's, bit for bit.
    expectSameImage((path("exports") / "grate-raymarch-airlight.exr").string(), path("cli.exr").string());
}

TEST_F(GuiCli, TheComparisonGridShowsEveryTechniqueWithItsErrorAndTime) {
    const nlohmann::json j = comparisonGrid("compare", "--scene grate --size 32x24");
    const RunResult list = run("list techniques");
    int techniques = 0;
    for (char c : list.out) techniques += c == '\n';
    ASSERT_EQ(int(j.at("comparison").size()), techniques);
    for (const auto& tile : j.at("comparison")) {
        EXPECT_EQ(tile.at("failure"), "") << tile.at("technique");
        EXPECT_TRUE(tile.at("relative_l2").is_number()) << tile.at("technique");
        EXPECT_EQ(tile.at("nan_inf_pixels"), 0) << tile.at("technique");
        if (tile.at("technique") != "reference") {
            EXPECT_GT(tile.at("milliseconds").get<double>(), 0.0);
        }
    }
    // The grid and, inside it after the tiles, the plot of error against time.
    const nlohmann::json* grid = nullptr;
    const nlohmann::json* plot = nullptr;
    for (const auto& v : j.at("views")) {
        if (v.at("name") == "comparison") grid = &v;
        if (v.at("name") == "comparison.error_vs_time") plot = &v;
    }
    ASSERT_TRUE(grid && plot);
    const auto& g = grid->at("rect");
    const auto& p = plot->at("rect");
    EXPECT_GE(p[0].get<double>(), g[0].get<double>());
    EXPECT_LE(p[2].get<double>(), g[2].get<double>() + 1.0);
    EXPECT_GE(p[1].get<double>(), g[1].get<double>());
    EXPECT_LE(p[3].get<double>(), g[3].get<double>() + 1.0);
    EXPECT_GT(p[2].get<double>() - p[0].get<double>(), 100.0);
}

// On a view with silhouette pixels (report/first_hits.h) each tile gives its error again without them:
// the count and the error over the rest, both worked out here from what `render` writes (the traced and
// rasterised distances, the reference's and raymarch's L_air) with a loop of the test's own.
TEST_F(GuiCli, TheComparisonGridGivesEachErrorWithoutTheSilhouettePixels) {
    const nlohmann::json j = comparisonGrid("forest", "--scene forest --size 80x60");
    auto layer = [&](const std::string& technique, const std::string& id, const std::string& extra) {
        const fs::path out = path(technique + "-" + id + ".exr");
        EXPECT_EQ(run("render --scene forest --technique " + technique + " --size 80x60 --layer " + id + extra +
                      " --quiet --out " + out.string()).exitCode, 0);
        return readImage(out.string());
    };
    const Image traced = layer("reference", "reference.distance", "");
    const Image drawn = layer("raymarch", "raymarch.distance", " --stop-after raymarch.surface");
    const Image reference = layer("reference", "airlight", ""), raymarch = layer("raymarch", "airlight", "");
    std::size_t silhouettes = 0;
    double diff2 = 0.0, ref2 = 0.0;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x) {
            if (!(std::abs(traced.at(x, y) - drawn.at(x, y)) <= 1e-3f * traced.at(x, y))) {
                ++silhouettes;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                const double a = raymarch.at(x, y, c), b = reference.at(x, y, c);
                diff2 += (a - b) * (a - b);
                ref2 += b * b;
            }
        }
    ASSERT_GT(silhouettes, 0u) << "forest at 80x60 has no silhouette pixel any more";
    ASSERT_LT(silhouettes, 80u * 60u / 100u);
    // The heading over the grid (in whichever form fits the window) says how many pixels were left out.
    EXPECT_NE(sidecarViewTitle(j, "comparison").find(std::to_string(silhouettes) + " silhouette pixels"), std::string::npos)
        << sidecarViewTitle(j, "comparison");
    for (const auto& tile : j.at("comparison")) {
        const std::string technique = tile.at("technique");
        EXPECT_EQ(tile.at("silhouette_pixels").get<std::size_t>(), silhouettes) << technique;
        if (technique == "reference") continue;
        // Leaving the silhouettes out lowers every technique's error on this view.
        EXPECT_LT(tile.at("relative_l2_agreeing").get<double>(), tile.at("relative_l2").get<double>()) << technique;
        EXPECT_NE(sidecarViewTitle(j, "comparison:" + technique).find("w/o " + std::to_string(silhouettes) + " silhouettes"),
                  std::string::npos) << technique;
        if (technique == "raymarch") {
            EXPECT_NEAR(tile.at("relative_l2_agreeing").get<double>(), std::sqrt(diff2 / ref2), 1e-5 * std::sqrt(diff2 / ref2));
        }
    }
}

TEST_F(GuiCli, BadScriptsAreOneLineErrorsNamingTheLine) {
    const fs::path unknown = writeText("unknown.txt", "frames 1\njump somewhere\n");
    expectUserError(run("gui --script " + unknown.string()), "unknown.txt:2");
    const fs::path missing = writeText("missing.txt", "frames 1\nclick \"no such widget\"\n");
    expectUserError(run("gui --scene grate --size 40x30 --script " + missing.string()), "missing.txt:2");
}

TEST_F(GuiCli, ScreenshotOptionsAreChecked) {
    expectUserError(run("gui --screenshot " + path("x.jpg").string()), ".png");
    expectUserError(run("gui --screenshot " + path("x.png").string() + " --frames 0"), "--frames");
    const fs::path state = writeText("same.json", "{}");
    expectUserError(run("gui --state " + state.string() + " --screenshot " + path("same.png").string()), "state file");
    EXPECT_EQ(readFile(state), "{}");
    EXPECT_FALSE(fs::exists(path("x.png")));
}

// Without a display the window command fails in one line that says which: none set, or one set that
// cannot be reached (a stale DISPLAY), with GLFW's reason, before anything is written.
TEST_F(CliTest, GuiWithoutAReachableDisplaySaysWhichDisplayAndWhy) {
    const ScopedEnv noWayland("WAYLAND_DISPLAY", nullptr);
    {
        const ScopedEnv noX("DISPLAY", nullptr);
        const RunResult r = run("gui --scene grate --screenshot " + path("a.png").string());
        expectUserError(r, "no display: set DISPLAY");
        EXPECT_EQ(r.err.find("cannot connect"), std::string::npos) << r.err;
    }
    {
        const ScopedEnv staleX("DISPLAY", ":987");  // no X server listens there
        const RunResult r = run("gui --scene grate --screenshot " + path("b.png").string());
        expectUserError(r, "cannot connect to display ':987' (GLFW: ");
        EXPECT_EQ(r.err.find("no display"), std::string::npos) << r.err;
        const RunResult l = run("gui --lesson 01-airlight-integral --screenshot " + path("c.png").string());
        expectUserError(l, "export the lesson with 'airlight lesson 01-airlight-integral --export DIR'");
    }
    EXPECT_FALSE(fs::exists(path("a.png")) || fs::exists(path("b.png")) || fs::exists(path("c.png")));
}

}  // namespace
}  // namespace viz::testing
