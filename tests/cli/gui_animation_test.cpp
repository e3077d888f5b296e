// The window while an animation plays (P): the light and the clock move, the temporal view and its
// score, recording the focused view as a GIF (E), and the comparison grid playing along.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
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
    }
    EXPECT_EQ(gpuTiles, 6);
    for (const auto& t : stopped.at("comparison")) {
        SCOPED_TRACE(t.dump());
        EXPECT_EQ(t.at("played_frames").get<int>(), 0);
        EXPECT_TRUE(t.contains("relative_l2")) << "the still frame's error is back";
    }
}

}  // namespace
}  // namespace viz::testing
