// Presentation mode: --ui-scale and Ctrl+= / Ctrl+- scale text and widgets for a projector; titles too
// long for their view are shortened in the middle (the full text shows while hovered), never cut.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

class GuiPresentation : public WindowCliTest {};

TEST_F(GuiPresentation, TheUiScaleComesFromTheOptionAndTheKeys) {
    const fs::path script = writeText("scale.txt", "frames 2\nscreenshot " + path("start.png").string() +
                                                       "\nkey Ctrl+=\nframes 1\nscreenshot " + path("up.png").string() +
                                                       "\nkey Ctrl+-\nkey Ctrl+-\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 32x24 --set samples=8 --ui-scale 1.5 --script " +
                            script.string() + " --screenshot " + path("down.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto scale = [&](const std::string& name) {
        return nlohmann::json::parse(readFile(path(name))).at("ui_scale").get<double>();
    };
    EXPECT_DOUBLE_EQ(scale("start.json"), 1.5);
    EXPECT_NEAR(scale("up.json"), 1.5 * 1.25, 1e-6);
    EXPECT_NEAR(scale("down.json"), 1.5 / 1.25, 1e-6);  // float arithmetic in the window
    const nlohmann::json start = nlohmann::json::parse(readFile(path("start.json")));
    EXPECT_DOUBLE_EQ(start.at("exposure").get<double>(), nlohmann::json::parse(readFile(path("up.json"))).at("exposure").get<double>())
        << "Ctrl+= is the UI scale, not the exposure";
}

TEST_F(GuiPresentation, ABadUiScaleIsAOneLineError) {
    for (const char* bad : {"0.1", "9", "big"}) {
        const RunResult r = run(std::string("gui --scene grate --ui-scale ") + bad + " --screenshot " + path("x.png").string());
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find("--ui-scale"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(path("x.png")));
    }
}

// At 1280x720 and scale 1.5 the default views' titles fit whole; at scale 3 they are shortened in the
// middle (the sidecar counts them), and the window still draws.
TEST_F(GuiPresentation, TitlesAreShortenedInTheMiddleNotCut) {
    const RunResult r15 = run("gui --scene grate --technique minmax --size 32x24 --ui-scale 1.5 --screenshot " +
                              path("a.png").string());
    ASSERT_EQ(r15.exitCode, 0) << r15.err;
    const RunResult r3 = run("gui --scene grate --technique minmax --size 32x24 --ui-scale 3 --screenshot " +
                             path("b.png").string());
    ASSERT_EQ(r3.exitCode, 0) << r3.err;
    const nlohmann::json a = nlohmann::json::parse(readFile(path("a.json")));
    const nlohmann::json b = nlohmann::json::parse(readFile(path("b.json")));
    int views = 0;
    for (const auto& v : a.at("views")) {
        if (!v.contains("title_elided")) continue;
        ++views;
        EXPECT_FALSE(v.at("title_elided").get<bool>()) << v.at("title") << " is shortened at scale 1.5";
    }
    EXPECT_GE(views, 2);
    EXPECT_EQ(a.at("titles_elided"), 0);
    // The grid leaves the scene and parameter panel room for six lines of text (about 160 px at 1.5; it
    // used to be hidden there).
    ASSERT_FALSE(a.at("parameters_panel").is_null()) << "no room for the parameter panel at scale 1.5";
    const auto& p = a.at("parameters_panel");
    EXPECT_GE(p[3].get<double>() - p[1].get<double>(), 120.0);
    EXPECT_GT(b.at("titles_elided").get<int>(), 0) << "at scale 3 the titles cannot fit whole";
}

}  // namespace
}  // namespace viz::testing
