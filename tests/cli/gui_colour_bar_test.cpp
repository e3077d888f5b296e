// Every image view explains its colours: the colour bar under each view of every technique on every
// built-in scene has finite ticks inside the range the view maps (at the places that range puts them,
// computed here from the ticks alone), the declared sentinels are not counted as negative pixels, and
// the bar's colour strip, read back from a screenshot, runs from the map's first colour to its last.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

using nlohmann::json;

class GuiColourBar : public WindowCliTest, public ::testing::WithParamInterface<const char*> {
protected:
    std::vector<std::string> words(const std::string& args) {
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        std::vector<std::string> out;
        std::istringstream lines(r.out);
        for (std::string line; std::getline(lines, line);) {
            std::istringstream w(line);
            std::string first;
            if (w >> first) out.push_back(line);
        }
        return out;
    }
    std::vector<std::string> scenes() {
        std::vector<std::string> names;
        for (const std::string& line : words("list scenes")) names.push_back(line.substr(0, line.find(' ')));
        return names;
    }
    // How many entries the Views list can have: final, L_air and every declared intermediate.
    int entries(const std::string& technique) {
        int n = 2;
        for (const std::string& line : words("list stages " + technique))
            if (line.find("intermediate ") != std::string::npos) ++n;
        return n;
    }
};

// Where a tick sits along a ramp from lo to hi, linear or log10 (the diverging map is checked apart).
double placeOf(double v, double lo, double hi, bool logarithmic) {
    if (logarithmic) return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (v - lo) / (hi - lo);
}

void checkBar(const json& view, const std::string& where) {
    const std::string content = view.at("content");
    const json& bar = view.at("colour_bar");
    ASSERT_TRUE(bar.at("lo").is_number() && bar.at("hi").is_number()) << where << bar.dump();
    const double lo = bar.at("lo"), hi = bar.at("hi");
    EXPECT_LT(lo, hi) << where;
    const json& display = view.at("display");
    const int mode = display.at("mode");  // DisplayMode: 2 grey, 3 signed, 4 ramp, 8 heat
    if (mode == 2 || mode == 4 || mode == 8) {
        // The bar spans exactly the range the shader maps (a log scale moves a non-positive end up).
        if (!display.at("log").get<bool>()) {
            EXPECT_FLOAT_EQ(float(lo), display.at("lo").get<float>()) << where;
        }
        EXPECT_FLOAT_EQ(float(hi), display.at("hi").get<float>()) << where;
    }
    if (mode == 3) {
        const double top = std::max(std::abs(display.at("lo").get<double>()), std::abs(display.at("hi").get<double>()));
        EXPECT_FLOAT_EQ(float(hi), float(top)) << where;
        EXPECT_FLOAT_EQ(float(lo), float(-top)) << where;
    }
    if (bar.at("kind") == "ramp") {
        const json& ticks = bar.at("ticks");
        ASSERT_GE(ticks.size(), 2u) << where;
        ASSERT_EQ(ticks.size(), bar.at("tick_labels").size()) << where;
        double previous = -1.0;
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            ASSERT_TRUE(ticks[i].is_number()) << where << " tick " << i;
            const double t = ticks[i], at = bar.at("tick_at")[i];
            const double slack = 1e-5 * (hi - lo);
            EXPECT_GE(t, lo - slack) << where;
            EXPECT_LE(t, hi + slack) << where;
            EXPECT_FALSE(bar.at("tick_labels")[i].get<std::string>().empty()) << where;
            EXPECT_GT(at, previous) << where << ": ticks out of order";
            previous = at;
            if (mode != 3) {
                EXPECT_NEAR(at, placeOf(t, lo, hi, bar.at("log")), 1e-4) << where << " tick " << t;
            } else if (!bar.at("log").get<bool>()) {
                EXPECT_NEAR(at, (t - lo) / (hi - lo), 1e-4) << where << " tick " << t;
            }
        }
    } else if (bar.at("kind") == "picture") {
        // A technique's own drawing: no map, and the caption sends the reader to the note.
        EXPECT_TRUE(bar.at("ticks").empty()) << where;
        EXPECT_NE(bar.at("caption").get<std::string>().find("note"), std::string::npos) << where;
    } else {
        EXPECT_EQ(bar.at("kind"), "classes") << where;
        EXPECT_FALSE(bar.at("classes").empty()) << where;
    }
    // Sentinels declared by the technique are never counted as negative pixels: these intermediates
    // hold no negative value but their sentinel -1.
    for (const char* id : {"minmax.rectified", "minmax.tree", "vsv.occluder_alpha"}) {
        if (content != id) continue;
        EXPECT_EQ(view.at("negative_pixels"), 0) << where;
        EXPECT_EQ(view.at("title").get<std::string>().find("negative"), std::string::npos) << where;
        bool declared = false;
        for (const json& l : bar.at("legend")) declared = declared || (l.at("sentinel") && l.at("value") == -1.0);
        EXPECT_TRUE(declared) << where << ": the legend names the sentinel -1";
    }
    for (const json& l : bar.at("legend")) EXPECT_GE(l.at("pixels").get<long>(), 0) << where;
    // minmax's charts of the picked row and ray are drawings: no colour map pretends to explain them.
    for (const char* id : {"minmax.rectified_view", "minmax.pyramid", "minmax.trace"}) {
        if (content == id) {
            EXPECT_EQ(bar.at("kind"), "picture") << where;
        }
    }
}

TEST_P(GuiColourBar, EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange) {
    const std::string technique = GetParam();
    const int n = entries(technique);
    int barsChecked = 0;
    for (const std::string& scene : scenes()) {
        std::string script = "frames 1\n";
        for (int k = 0; k < n; ++k)
            script += "key ]\nframes 1\nsidecar " + path(scene + "_" + std::to_string(k) + ".png").string() + "\n";
        // A smaller shadow map keeps the GPU techniques quick (the bars do not depend on it).
        const std::string map = technique == "reference" ? "" : " --set shadow_map=128";
        const RunResult r = run("gui --scene " + scene + " --technique " + technique + " --size 48x36" + map +
                                " --script " + writeText(scene + ".txt", script).string());
        ASSERT_EQ(r.exitCode, 0) << scene << ": " << r.err;
        for (int k = 0; k < n; ++k) {
            const json j = json::parse(readFile(path(scene + "_" + std::to_string(k) + ".json")));
            for (const json& view : j.at("views")) {
                if (!view.value("focused", false)) continue;
                const std::string where = technique + " on " + scene + ", " + view.value("content", "?");
                const bool image = view.at("size")[0].get<int>() > 0 && view.at("plots").get<int>() == 0;
                EXPECT_EQ(view.contains("colour_bar"), image) << where;
                if (!image || !view.contains("colour_bar")) continue;
                checkBar(view, where);
                ++barsChecked;
            }
        }
    }
    EXPECT_GE(barsChecked, 6 * 4) << "too few image views were seen";
}

INSTANTIATE_TEST_SUITE_P(Techniques, GuiColourBar,
                         ::testing::Values("reference", "raymarch", "slices", "polyvol", "minmax", "vsv", "ivsv"),
                         [](const auto& param) { return std::string(param.param); });

// The colour strip as drawn: a grey view's strip goes from black at its left end to white at its right,
// a diverging one from blue through white to red (read from the screenshot, at the ramp's rectangle).
TEST_F(GuiColourBar, TheStripIsDrawnThroughTheViewsColourMap) {
    const RunResult r = run("gui --scene grate --technique raymarch --size 48x36 --script " +
                            writeText("s.txt", "click \"view:Lit fraction\"\nframes 1\nscreenshot " +
                                                   path("grey.png").string() + "\n").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = json::parse(readFile(path("grey.json")));
    const json* lit = nullptr;
    for (const json& v : j.at("views"))
        if (v.value("content", "") == "raymarch.lit_fraction") lit = &v;
    ASSERT_TRUE(lit && lit->contains("colour_bar"));
    EXPECT_EQ(lit->at("display").at("mode"), 2);
    const json& rect = lit->at("colour_bar").at("ramp_rect");
    const Image shot = readImage(path("grey.png").string());
    const auto sample = [&](double f) {
        const int x = int(rect[0].get<double>() + f * (rect[2].get<double>() - rect[0].get<double>()));
        const int y = int(0.5 * (rect[1].get<double>() + rect[3].get<double>()));
        return glm::vec3(shot.at(x, y, 0), shot.at(x, y, 1), shot.at(x, y, 2));
    };
    const glm::vec3 left = sample(0.01), middle = sample(0.5), right = sample(0.99);
    EXPECT_LT(left.x + left.y + left.z, 0.05f);
    EXPECT_GT(right.x + right.y + right.z, 2.7f);
    EXPECT_GT(middle.y, left.y);
    EXPECT_LT(middle.y, right.y);
    EXPECT_NEAR(middle.x, middle.y, 0.01f);  // grey
}

}  // namespace
}  // namespace viz::testing
