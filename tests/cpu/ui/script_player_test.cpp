// The window's script player (app/script_player.h) against a recording host: what each action does to
// the window on which frame, written out by hand from the script language's definition (ui_script.h).
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "core/error.h"
#include "script_player.h"
#include "temp_dir.h"

namespace airlight {
namespace {

namespace fs = std::filesystem;
using viz::ui::Rect;

// Records every call as one line; rectangles by name; widgets scroll into view when revealed.
class RecordingHost : public ScriptHost {
public:
    std::map<std::string, Rect> rects;
    std::map<std::string, bool> widgets;  // name -> revealed
    std::vector<std::string> calls;
    bool statsWritable = true;

    std::optional<Rect> scriptRect(const std::string& name) const override {
        const auto it = rects.find(name);
        return it == rects.end() ? std::nullopt : std::optional<Rect>(it->second);
    }
    std::string knownNames() const override {
        std::string names;
        for (const auto& [name, r] : rects) names += (names.empty() ? "" : ", ") + name;
        return names;
    }
    bool isWidget(const std::string& name) const override { return widgets.count(name) > 0; }
    void revealWidget(const std::string& name) override { calls.push_back("reveal " + name); }
    void pressKey(int key, int modifiers) override {
        calls.push_back("key " + std::to_string(key) + ((modifiers & GLFW_MOD_SHIFT) ? " shift" : ""));
    }
    void typeText(const std::string& text) override { calls.push_back("type " + text); }
    void dropFile(const std::string& path) override { calls.push_back("drop " + path); }
    void hoverAt(glm::vec2 p) override { calls.push_back("hover " + at(p)); }
    void dragTo(glm::vec2 p) override { calls.push_back("drag " + at(p)); }
    void leftButton(bool press, glm::vec2 p) override { calls.push_back((press ? "press " : "release ") + at(p)); }
    void wheel(float notches) override { calls.push_back("wheel " + std::to_string(int(notches))); }
    void screenshot(const std::string& path, bool image) override { calls.push_back((image ? "screenshot " : "sidecar ") + path); }
    bool appendStats(const std::string& path) override {
        calls.push_back("stats " + path);
        return statsWritable;
    }
    static std::string at(glm::vec2 p) { return std::to_string(int(p.x)) + "," + std::to_string(int(p.y)); }
    // The calls since the last look.
    std::vector<std::string> take() { return std::exchange(calls, {}); }
};

class ScriptPlayerTest : public ::testing::Test {
protected:
    ScriptPlayer play(const std::string& text) {
        const viz::testing::TempDir temp("script_player");
        const fs::path p = temp / "script.txt";
        std::ofstream(p) << text;
        return ScriptPlayer(parseScript(p.string()), "script.txt");
    }
    using Calls = std::vector<std::string>;
    RecordingHost host;
};

TEST_F(ScriptPlayerTest, AClickPressesOnOneFrameAndReleasesOnTheNextAtItsFraction) {
    host.rects["ok"] = Rect{{100, 200}, {140, 220}};
    ScriptPlayer p = play("click ok 0.25 0.5\n");
    EXPECT_FALSE(p.leftButtonDown());
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 110,210", "press 110,210"}));
    EXPECT_EQ(p.leftButtonDown(), std::optional<bool>(true)) << "the widgets see the button held";
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 110,210", "release 110,210"}));
    EXPECT_FALSE(p.leftButtonDown()) << "the real button counts again";
    EXPECT_FALSE(p.step(host)) << "done";
    EXPECT_TRUE(host.take().empty());
}

TEST_F(ScriptPlayerTest, ADragMovesAQuarterOfTheWayOnEachOfFourFramesOntoAnotherTarget) {
    host.rects["handle"] = Rect{{0, 0}, {10, 10}};
    host.rects["view"] = Rect{{100, 100}, {300, 200}};
    ScriptPlayer p = play("drag handle 0 0 1 1 view\n");
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 0,0", "press 0,0"}));
    for (const char* step : {"drag 75,50", "drag 150,100", "drag 225,150", "drag 300,200"}) {
        ASSERT_TRUE(p.step(host));
        EXPECT_EQ(host.take(), Calls{step});
        EXPECT_EQ(p.leftButtonDown(), std::optional<bool>(true));
    }
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"release 300,200"});
    EXPECT_FALSE(p.leftButtonDown());
    EXPECT_FALSE(p.step(host));
}

TEST_F(ScriptPlayerTest, FramesWaitAndAHeldKeyStaysDownForItsFrames) {
    ScriptPlayer p = play("frames 3\nhold W 2\nkey Shift+S\n");
    for (int f = 0; f < 3; ++f) {
        ASSERT_TRUE(p.step(host));
        EXPECT_TRUE(host.take().empty()) << "frame " << f;
    }
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"key " + std::to_string(GLFW_KEY_W)});
    EXPECT_EQ(p.heldKey(), GLFW_KEY_W);
    EXPECT_FALSE(p.heldShift());
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(p.heldKey(), GLFW_KEY_W) << "still down on its second frame";
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(p.heldKey(), -1) << "released";
    EXPECT_TRUE(host.take().empty());
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"key " + std::to_string(GLFW_KEY_S) + " shift"});
    EXPECT_FALSE(p.step(host));
}

TEST_F(ScriptPlayerTest, AWidgetIsScrolledIntoViewBeforeItIsClicked) {
    host.rects["slider"] = Rect{{10, 900}, {110, 920}};
    host.widgets["slider"] = false;
    ScriptPlayer p = play("click slider\n");
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"reveal slider"});
    host.rects["slider"] = Rect{{10, 300}, {110, 320}};  // where the panel scrolled it
    ASSERT_TRUE(p.step(host));
    EXPECT_TRUE(host.take().empty()) << "the new rectangle is known the frame after";
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 60,310", "press 60,310"}));
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 60,310", "release 60,310"}));
}

TEST_F(ScriptPlayerTest, ScreenshotsAndStatsTakeNoFrameAndOtherActionsOneEach) {
    host.rects["final"] = Rect{{0, 0}, {200, 100}};
    ScriptPlayer p = play("screenshot a.png\nsidecar b.png\nstats s.jsonl\nhover final 0.5 0.5\nwheel final 2\n"
                          "type abc\ndrop x.glb\n");
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"screenshot a.png", "sidecar b.png", "stats s.jsonl", "hover 100,50"}));
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), (Calls{"hover 100,50", "wheel 2"}));
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"type abc"});
    ASSERT_TRUE(p.step(host));
    EXPECT_EQ(host.take(), Calls{"drop x.glb"});
    EXPECT_FALSE(p.step(host));
}

TEST_F(ScriptPlayerTest, ANameNotOnScreenAndStatsThatCannotBeWrittenAreErrorsNamingTheLine) {
    host.rects["final"] = Rect{{0, 0}, {10, 10}};
    ScriptPlayer p = play("frames 1\nclick nowhere\n");
    ASSERT_TRUE(p.step(host));
    try {
        p.step(host);
        FAIL() << "no error";
    } catch (const viz::InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("script.txt:2"), std::string::npos) << m;
        EXPECT_NE(m.find("nothing named 'nowhere'"), std::string::npos) << m;
        EXPECT_NE(m.find("final"), std::string::npos) << "names what is on screen: " << m;
    }
    host.statsWritable = false;
    ScriptPlayer q = play("# a comment\nstats /no/such/folder/s.jsonl\n");
    EXPECT_THROW(q.step(host), viz::InputError);
}

}  // namespace
}  // namespace airlight
