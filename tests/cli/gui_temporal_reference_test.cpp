// The window's temporal view against the reference (issue 19): while a --path plays and a temporal view is
// shown, the reference's frames of the loop are rendered beside it, and the error change view scores the
// part of the error that changes from frame to frame, as `report --temporal` does. Checked against the
// figure computed here from `animate`'s frames of the technique and of the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "cli/sidecar_views.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSettings = "--set samples=4 --set jitter=off";
constexpr const char* kPath = "--path camera-orbit:10deg";

double mean(const Image& image) {
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    return sum / double(image.pixels.size());
}

class GuiTemporalReference : public WindowCliTest {
protected:
    // animate's L_air frames of `technique` on the 2-frame loop, 32x24 (EXR, linear).
    std::vector<Image> animatedFrames(const std::string& technique, const fs::path& dir) {
        const std::string settings = technique == "reference" ? "" : kSettings;
        const RunResult r = run("animate --scene grate --technique " + technique + " " + settings + " " + kPath +
                            " --frames 2 --size 32x24 --layer airlight --exr --quiet --out " + dir.string() + "/");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return {readImage((dir / "frame_0000.exr").string()), readImage((dir / "frame_0001.exr").string())};
    }

    // A loop of 2 frames plays 0, 1, 0, 1, ...: every pair of frames shown is {0, 1}, whose error change
    // d = e1 - e0 (or its negative) is the same in every pair. raymarch's temporal RMS against the
    // reference is therefore sqrt(mean d^2) / 2 / mean(R), with mean(R) the reference's mean over the
    // frames added: between mean(R0) and mean(R1), whatever the count of each. The bounds, from animate's
    // frames (1e-4 for the window's camera, normalised by its controller).
    std::pair<double, double> scoreBounds() {
        const std::vector<Image> test = animatedFrames("raymarch", path("raymarch"));
        const std::vector<Image> reference = animatedFrames("reference", path("reference"));
        double squares = 0.0;
        for (std::size_t i = 0; i < test[0].pixels.size(); ++i) {
            const double d = (double(test[1].pixels[i]) - double(reference[1].pixels[i])) -
                             (double(test[0].pixels[i]) - double(reference[0].pixels[i]));
            squares += d * d;
        }
        const double rms = 0.5 * std::sqrt(squares / double(test[0].pixels.size()));
        const double m0 = mean(reference[0]), m1 = mean(reference[1]);
        EXPECT_GT(rms, 0.0) << "the error changes between the two frames";
        return {rms / std::max(m0, m1) * (1.0 - 1e-4), rms / std::min(m0, m1) * (1.0 + 1e-4)};
    }
};

// The main views: before a temporal view is shown no reference frame is asked for; with the change view
// shown the loop's two reference frames are rendered, and the error change view's score is the one the
// frames of `animate` give (scoreBounds).
TEST_F(GuiTemporalReference, TheErrorChangeViewScoresTheFlickerAgainstTheReferenceFrames) {
    const ScopedCacheDir cache(path("cache"));
    const fs::path script = writeText(
        "play.txt", "frames 1\nkey P\nframes 3\nscreenshot " + path("before.png").string() +
                        "\nclick \"view:L_air change per frame\"\nframes 8\nclick \"view:Error change per frame\"\n"
                        "frames 6\nscreenshot " + path("after.png").string() + "\n");
    const RunResult r = run(std::string("gui --scene grate --technique raymarch --size 32x24 ") + kSettings + " " + kPath +
                            " --path-frames 2 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json before = nlohmann::json::parse(readFile(path("before.json")));
    const nlohmann::json after = nlohmann::json::parse(readFile(path("after.json")));
    EXPECT_EQ(before.at("animation").at("reference_frames").at("total"), 0) << "no temporal view shown: no reference run";
    const nlohmann::json& a = after.at("animation");
    ASSERT_TRUE(a.at("playing").get<bool>());
    EXPECT_EQ(a.at("reference_frames").at("ready"), 2) << a.dump();
    EXPECT_EQ(a.at("reference_frames").at("total"), 2);
    EXPECT_EQ(a.at("reference_frames").at("error"), "");
    EXPECT_GT(a.at("reference_frames").at("seconds_per_frame").get<double>(), 0.0) << "computed, not read from a cache";
    ASSERT_GE(a.at("temporal_error_pairs").get<int>(), 4) << a.dump();
    const double windowScore = a.at("temporal_error_rms").get<double>();

    const auto [lo, hi] = scoreBounds();
    EXPECT_GE(windowScore, lo);
    EXPECT_LE(windowScore, hi);
    // The motion's own change is gone: the camera turning moves the shafts far more than their error.
    EXPECT_LT(windowScore, a.at("temporal_change_rms").get<double>());

    bool titled = false;
    for (const auto& v : after.at("views")) {
        const std::string title = v.at("title").get<std::string>();
        if (title.find("Error change per frame: flicker ") != std::string::npos) {
            titled = true;
            EXPECT_EQ(title.find("reference frames"), std::string::npos) << "every reference frame is in: " << title;
        }
    }
    EXPECT_TRUE(titled) << after.at("views").dump();
}

// The comparison grid plays a camera path along with the window (every GPU tile's L_air changes from frame
// to frame) and, the loop's reference frames rendered at its size, each tile scores its error's change:
// raymarch's tile gives the figure of `animate`'s frames.
TEST_F(GuiTemporalReference, TheComparisonGridPlaysTheCameraPathAndScoresEachTilesFlicker) {
    const ScopedCacheDir cache(path("cache"));
    const fs::path script = writeText("grid.txt", "frames 1\nkey G\nframes 2\nkey P\nframes 8\nscreenshot " +
                                                      path("grid.png").string() + "\n");
    const RunResult r = run(std::string("gui --scene grate --technique raymarch --size 32x24 ") + kSettings + " " + kPath +
                            " --path-frames 2 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(readFile(path("grid.json")));
    ASSERT_TRUE(j.contains("comparison")) << j.dump();
    EXPECT_EQ(j.at("animation").at("reference_frames").at("ready"), 2) << j.at("animation").dump();
    const auto [lo, hi] = scoreBounds();
    int gpuTiles = 0;
    for (const auto& t : j.at("comparison")) {
        SCOPED_TRACE(t.dump());
        if (t.at("technique") == "reference") continue;
        ++gpuTiles;
        EXPECT_GT(t.at("change_rms").get<double>(), 0.0) << "the camera turned: every tile's L_air changed";
        ASSERT_GE(t.at("error_change_pairs").get<int>(), 3);
        EXPECT_TRUE(t.contains("error_change_rms"));
        // The tile's caption ranks by the same figure: its image is named after it, titled with the caption.
        const std::string title = sidecarViewTitle(j, "comparison:" + t.at("technique").get<std::string>());
        char figure[32];
        std::snprintf(figure, sizeof figure, "flicker %.3g", t.at("error_change_rms").get<double>());
        EXPECT_NE(title.find(figure), std::string::npos) << title << " lacks " << figure;
        if (t.at("technique") == "raymarch") {
            EXPECT_LT(t.at("error_change_rms").get<double>(), t.at("change_rms").get<double>());
            EXPECT_GE(t.at("error_change_rms").get<double>(), lo);
            EXPECT_LE(t.at("error_change_rms").get<double>(), hi);
        }
    }
    EXPECT_EQ(gpuTiles, 6);
    EXPECT_NE(sidecarViewTitle(j, "comparison:reference").find("path frames 2/2"), std::string::npos);
}

}  // namespace
}  // namespace viz::testing
