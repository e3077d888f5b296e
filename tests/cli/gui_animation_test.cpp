// The window while an animation plays (P): the light and the clock move, the temporal view and its
// score, recording the focused view as a GIF (E), and the comparison grid playing along.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "cli/sidecar_views.h"
#include "core/animation_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

class GuiAnimation : public WindowCliTest {};

// P plays the animation: the first light circles its aim point (a spot keeps aiming at it) and slices'
// `time` (its scrolling noise) follows the clock, 1/30 s per frame under automation; P again pauses.
TEST_F(GuiAnimation, PlayMovesTheLightAndScrollsTheNoiseAndPauseStopsThem) {
    const fs::path script = writeText("play.txt", "frames 1\nkey P\nframes 30\nscreenshot " + path("playing.png").string() +
                                                      "\nkey P\nframes 1\nscreenshot " + path("paused.png").string() +
                                                      "\nframes 5\n");
    const RunResult r = run("gui --scene grate --technique slices --size 40x30 --set planes=16 --script " +
                            script.string() + " --screenshot " + path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json playing = nlohmann::json::parse(readFile(path("playing.json")));
    const nlohmann::json paused = nlohmann::json::parse(readFile(path("paused.json")));
    const nlohmann::json end = nlohmann::json::parse(readFile(path("end.json")));
    EXPECT_TRUE(playing.at("animation").at("playing").get<bool>());
    const double seconds = playing.at("animation").at("seconds").get<double>();
    EXPECT_NEAR(seconds, 1.0, 0.15) << "about 30 frames of 1/30 s";
    EXPECT_EQ(playing.at("settings").at("time").get<double>(), seconds);
    const auto& p = playing.at("lights")[0].at("position");
    EXPECT_GT(std::abs(p[0].get<double>()) + std::abs(p[2].get<double>()), 1e-3) << "the spot moved off its axis";
    EXPECT_FALSE(end.at("animation").at("playing").get<bool>());
    EXPECT_EQ(end.at("lights")[0].at("position"), paused.at("lights")[0].at("position")) << "paused: the light stays";
    EXPECT_EQ(end.at("settings").at("time"), paused.at("settings").at("time"));
}

// While P plays, the temporal view shows L_air's change since the previous frame with a running score in
// its title. On tv-room nothing moves when playing (its light is an area light): raymarch with
// jitter_time=per-frame re-runs every frame (its noise reads the frame index) and scores its noise;
// with jitter_time=constant nothing changes, the window runs nothing new and there is no frame pair.
TEST_F(GuiAnimation, TheTemporalViewShowsTheChangeOfLairWhilePlaying) {
    for (int perFrame : {1, 0}) {
        SCOPED_TRACE(perFrame);
        const std::string stem = "temporal" + std::to_string(perFrame);
        // Without a second frame the view is not in the sidebar to click.
        const std::string show = perFrame ? "click \"view:L_air change per frame\"\n" : "";
        const fs::path script = writeText(stem + ".txt", "frames 1\nkey P\nframes 8\n" + show + "frames 2\nscreenshot " +
                                                             path(stem + ".png").string() + "\n");
        const RunResult r = run("gui --scene tv-room --technique raymarch --size 32x24 --set samples=4 --set area_samples=2 "
                                "--set jitter=white --set jitter_time=" + std::to_string(perFrame) + " --script " +
                                script.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json j = nlohmann::json::parse(readFile(path(stem + ".json")));
        const auto& a = j.at("animation");
        EXPECT_TRUE(a.at("playing").get<bool>());
        bool shown = false;
        for (const auto& v : j.at("views"))
            if (v.at("title").get<std::string>().find("L_air change per frame") != std::string::npos) {
                shown = true;
                EXPECT_NE(v.at("title").get<std::string>().find(": RMS "), std::string::npos) << v.dump();
            }
        if (perFrame) {
            EXPECT_GE(a.at("temporal_pairs").get<int>(), 8) << a.dump();
            EXPECT_GT(a.at("temporal_change_rms").get<double>(), 0.0) << a.dump();
            EXPECT_TRUE(shown) << j.at("views").dump();
        } else {
            EXPECT_EQ(a.at("temporal_pairs").get<int>(), 0) << a.dump();
            EXPECT_FALSE(shown) << "no second frame, no change to show";
        }
    }
}

// E while an animation plays records the focused view: E again writes an animated GIF of the frames it
// saw, at the animation's rate (1/30 s a frame under automation: 30 per second, stored as 3 hundredths).
TEST_F(GuiAnimation, ExportWhilePlayingRecordsTheFocusedViewAsAGif) {
    const fs::path exports = path("exports");
    const fs::path script = writeText("record.txt", "frames 1\nkey P\nframes 2\nkey E\nframes 6\nkey E\nframes 1\n"
                                                    "screenshot " + path("after.png").string() + "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --set samples=8 --export-dir " +
                            exports.string() + " --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<fs::path> gifs;
    for (const auto& e : fs::directory_iterator(exports))
        if (e.path().extension() == ".gif") gifs.push_back(e.path());
    ASSERT_EQ(gifs.size(), 1u);
    const viz::AnimationInfo info = viz::readAnimationInfo(gifs.front().string());
    EXPECT_GE(info.frames, 5);
    EXPECT_LE(info.frames, 7);
    EXPECT_EQ(info.width, 32);
    EXPECT_NEAR(info.fps, 100.0 / 3.0, 1e-6);
    const nlohmann::json j = nlohmann::json::parse(readFile(path("after.json")));
    EXPECT_NE(j.at("notice").get<std::string>().find("recorded"), std::string::npos) << j.at("notice");
}

// The comparison grid plays along: with the grid open, P renders every GPU technique on each played
// frame (grate's spot circling), each tile with the running change of its L_air; P again shows the still
// frame with its errors against the reference once more.
TEST_F(GuiAnimation, TheComparisonGridPlaysEveryTechniqueSideBySide) {
    const fs::path script = writeText("grid_play.txt", "frames 1\nkey G\nframes 2\nkey P\nframes 5\nscreenshot " +
                                                           path("playing.png").string() + "\nkey P\nframes 2\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --set samples=16 --set shadow_map=128 "
                            "--script " + script.string() + " --screenshot " + path("stopped.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json playing = nlohmann::json::parse(readFile(path("playing.json")));
    const nlohmann::json stopped = nlohmann::json::parse(readFile(path("stopped.json")));
    ASSERT_TRUE(playing.contains("comparison")) << playing.dump();
    int gpuTiles = 0;
    for (const auto& t : playing.at("comparison")) {
        SCOPED_TRACE(t.dump());
        EXPECT_EQ(t.at("failure"), "");
        if (t.at("technique") == "reference") {
            EXPECT_FALSE(t.contains("change_rms")) << "the reference keeps the still frame";
            continue;
        }
        ++gpuTiles;
        EXPECT_GE(t.at("played_frames").get<int>(), 5);
        EXPECT_EQ(t.at("change_pairs").get<int>(), t.at("played_frames").get<int>());
        EXPECT_GT(t.at("change_rms").get<double>(), 0.0) << "the spot moved: every technique's L_air changed";
        // Its caption says the same (no --path: no reference frames, so the change of L_air, not flicker).
        char figure[32];
        std::snprintf(figure, sizeof figure, "change %.3g", t.at("change_rms").get<double>());
        const std::string title = sidecarViewTitle(playing, "comparison:" + t.at("technique").get<std::string>());
        EXPECT_NE(title.find(figure), std::string::npos) << title << " lacks " << figure;
    }
    EXPECT_EQ(gpuTiles, 6);
    EXPECT_NE(sidecarViewTitle(playing, "comparison:reference").find("ground truth, still frame"), std::string::npos);
    for (const auto& t : stopped.at("comparison")) {
        SCOPED_TRACE(t.dump());
        EXPECT_EQ(t.at("played_frames").get<int>(), 0);
        EXPECT_TRUE(t.contains("relative_l2")) << "the still frame's error is back";
        if (t.at("technique") != "reference") {
            EXPECT_NE(sidecarViewTitle(stopped, "comparison:" + t.at("technique").get<std::string>())
                          .find("   " + t.at("error").get<std::string>()),
                      std::string::npos);
        }
    }
}

// --path: P plays a motion path instead of the light's orbit. A camera orbit of 90 degrees over 6 frames:
// frame i's eye is the start eye turned by 15 i degrees about the vertical through the camera's target
// (checked with the rotation written out here), and after 6 frames the loop is back at the start exactly.
TEST_F(GuiAnimation, PlayingAPathMovesTheCameraAlongItAndLoops) {
    const fs::path script = writeText("path.txt", "frames 1\nscreenshot " + path("start.png").string() +
                                                      "\nkey P\nframes 2\nscreenshot " + path("mid.png").string() +
                                                      "\nframes 8\nkey P\nframes 1\nscreenshot " + path("end.png").string() +
                                                      "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --set samples=4 --path camera-orbit:90deg "
                            "--path-frames 6 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json start = nlohmann::json::parse(readFile(path("start.json")));
    const nlohmann::json mid = nlohmann::json::parse(readFile(path("mid.json")));
    const nlohmann::json end = nlohmann::json::parse(readFile(path("end.json")));
    const auto vec = [](const nlohmann::json& v) { return glm::dvec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()); };
    const glm::dvec3 eye0 = vec(start.at("camera").at("position")), target = vec(start.at("camera").at("target"));
    const glm::dvec3 light0 = vec(start.at("lights")[0].at("position"));

    // The eye of path frame i: the start eye turned by 90 i / 6 degrees about +Y through the target. The
    // turning sense is the path's own (scene/motion_path.h); the test accepts either, the angle and the
    // axis are what it checks.
    const glm::dvec3 r0 = eye0 - target;
    const auto offBy = [&](const nlohmann::json& sidecar) {
        const int i = sidecar.at("animation").at("path").at("frame").get<int>();
        const double a = glm::radians(90.0) * double(i) / 6.0;
        const glm::dvec3 ccw(r0.x * std::cos(a) + r0.z * std::sin(a), r0.y, -r0.x * std::sin(a) + r0.z * std::cos(a));
        const glm::dvec3 cw(r0.x * std::cos(a) - r0.z * std::sin(a), r0.y, r0.x * std::sin(a) + r0.z * std::cos(a));
        const glm::dvec3 eye = vec(sidecar.at("camera").at("position")) - target;
        return std::min(glm::length(eye - ccw), glm::length(eye - cw)) / glm::length(r0);
    };
    const nlohmann::json& played = mid.at("animation").at("path");
    EXPECT_EQ(played.at("text"), "camera-orbit:90deg");
    EXPECT_EQ(played.at("frames"), 6);
    EXPECT_TRUE(mid.at("animation").at("playing").get<bool>());
    EXPECT_GE(played.at("frame").get<int>(), 1) << "the camera moved";
    EXPECT_LT(offBy(mid), 1e-9);
    EXPECT_EQ(vec(mid.at("lights")[0].at("position")), light0) << "a camera path leaves the lights alone";

    // 2 + 8 frames played and paused: the loop of 6 went round once and stopped on frame (played mod 6),
    // where the camera stays; frame 0 is the start exactly.
    EXPECT_FALSE(end.at("animation").at("playing").get<bool>());
    const int frames = end.at("animation").at("frame").get<int>(), last = end.at("animation").at("path").at("frame").get<int>();
    EXPECT_GE(frames, 6) << "played past one loop";
    EXPECT_EQ(last, frames % 6);
    EXPECT_LT(offBy(end), 1e-9);
    if (last == 0) {
        EXPECT_EQ(end.at("camera").at("position"), start.at("camera").at("position"));
    }
}

// Pausing a path keeps its frame and playing again continues the loop from the same start; moving the
// camera while paused (R: back to the scene's camera) starts the loop again from where the camera is.
TEST_F(GuiAnimation, APausedPathContinuesUnlessTheCameraMoved) {
    const fs::path script = writeText("resume.txt", "frames 1\nscreenshot " + path("start.png").string() +
                                                        "\nkey P\nframes 2\nkey P\nframes 1\nscreenshot " + path("paused.png").string() +
                                                        "\nkey P\nframes 1\nkey P\nframes 1\nscreenshot " + path("continued.png").string() +
                                                        "\nkey R\nframes 1\nkey P\nframes 1\nkey P\nframes 1\nscreenshot " +
                                                        path("restarted.png").string() + "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --set samples=4 --path camera-orbit:120deg "
                            "--path-frames 12 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto sidecar = [&](const char* name) { return nlohmann::json::parse(readFile(path(name))); };
    const auto frameOf = [](const nlohmann::json& j) { return j.at("animation").at("path").at("frame").get<int>(); };
    const nlohmann::json start = sidecar("start.json"), paused = sidecar("paused.json"), continued = sidecar("continued.json"),
                         restarted = sidecar("restarted.json");
    EXPECT_GE(frameOf(paused), 2);
    EXPECT_NE(paused.at("camera").at("position"), start.at("camera").at("position"));
    EXPECT_GT(frameOf(continued), frameOf(paused)) << "the loop went on from its frame";
    EXPECT_NE(continued.at("camera").at("position"), paused.at("camera").at("position"));
    EXPECT_LT(frameOf(restarted), frameOf(continued)) << "R moved the camera: the loop starts again";
    EXPECT_GE(frameOf(restarted), 1);
}

// Picking another scene while a light path plays starts the loop again from that scene's own light (the
// previous scene's light is never carried over): grate's spot, then colonnade's sun, swept.
TEST_F(GuiAnimation, APathFollowsASceneChangeWhilePlaying) {
    const fs::path script = writeText("pick.txt", "frames 1\nkey P\nframes 3\nclick scene\nframes 1\n"
                                                  "click \"scene/colonnade\"\nframes 4\nscreenshot " + path("after.png").string() + "\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 24x18 --set samples=4 --path light-sweep:20deg "
                            "--path-frames 12 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json after = nlohmann::json::parse(readFile(path("after.json")));
    EXPECT_EQ(after.at("scene"), "colonnade");
    EXPECT_TRUE(after.at("animation").at("playing").get<bool>());
    const nlohmann::json& light = after.at("lights")[0];
    EXPECT_EQ(light.at("name"), "sun");
    EXPECT_EQ(light.at("intensity").get<double>(), 10.0);
    const int frame = after.at("animation").at("path").at("frame").get<int>();
    EXPECT_GE(frame, 1) << "the sun is being swept";
    EXPECT_LT(frame, after.at("animation").at("frame").get<int>()) << "the loop started again at the pick";
}

// A path that is not one, or that cannot move the scene (tv-room's first light is an area light, which no
// light motion moves), is a one-line error before the window opens.
TEST_F(GuiAnimation, ABadPathIsAOneLineErrorBeforeTheWindowOpens) {
    for (const std::string& args : {std::string("--scene grate --path camera-orbt:30deg"),
                                    std::string("--scene tv-room --path light-sweep:20deg"),
                                    std::string("--scene grate --path camera-orbit --path-frames 1")}) {
        const RunResult r = run("gui " + args + " --screenshot " + path("x.png").string());
        EXPECT_EQ(r.exitCode, 2) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("path"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(path("x.png")));
    }
}

}  // namespace
}  // namespace viz::testing
