// Settings given on the window's command line reach every technique the window switches to, each read as
// that technique declares its parameters: a named value can stand for different numbers in different
// techniques (epipole=paper is ivsv's second choice, off | paper, and vsv's third, off | march | paper).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

class GuiSettings : public WindowCliTest {
protected:
    // Opens the window on `from` (with `sets`, on a scene with the light's epipole in view) and switches to
    // `to`: the sidecars of a screenshot taken on each, `from`'s first. Empty when the window failed.
    std::pair<nlohmann::json, nlohmann::json> openThenSwitch(const std::string& from, const std::string& to,
                                                             const std::string& sets) {
        const fs::path script = writeText("switch.txt", "frames 1\nscreenshot " + path(from + ".png").string() +
                                                            "\nclick technique:" + to + "\nframes 2\n");
        const RunResult r = run("gui --scene stiff/epipole-at-pixel-centre --technique " + from + " --size 32x24 " +
                                sets + " --script " + script.string() + " --screenshot " + path(to + ".png").string());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (r.exitCode != 0) return {};
        return {nlohmann::json::parse(readFile(path(from + ".json"))), nlohmann::json::parse(readFile(path(to + ".json")))};
    }
};

// The feature's reason in the sidecar's plan (what the parameter panel's plan section lists).
std::string featureWhy(const nlohmann::json& sidecar, const std::string& feature) {
    for (const nlohmann::json& f : sidecar.at("plan").at("features"))
        if (f.at("feature") == feature) return f.at("why").get<std::string>();
    return {};
}

// Opened on ivsv with epipole=paper, then switched to vsv on a scene with the light's epipole in view: vsv
// runs the paper's rule (its own default is march), said in words by the plan independently of the number.
TEST_F(GuiSettings, ANamedValueIsReadForEachTechniqueTheWindowSwitchesTo) {
    const auto [ivsv, vsv] = openThenSwitch("ivsv", "vsv", "--set epipole=paper");
    ASSERT_FALSE(HasFailure());
    EXPECT_EQ(ivsv.at("technique"), "ivsv");
    EXPECT_EQ(ivsv.at("settings").at("epipole").get<double>(), 1.0);
    ASSERT_EQ(vsv.at("technique"), "vsv");
    EXPECT_EQ(vsv.at("error"), "");
    EXPECT_EQ(vsv.at("settings").at("epipole").get<double>(), 2.0);
    EXPECT_NE(featureWhy(vsv, "EPIPOLE").find("the paper's rule"), std::string::npos) << featureWhy(vsv, "EPIPOLE");
}

// A word another technique refuses leaves the window free to open: opened on vsv with epipole=march (vsv's
// second choice; ivsv has no march), switching to ivsv runs ivsv's default and says which setting it refused.
TEST_F(GuiSettings, AWordATechniqueRefusesIsSaidWhenSwitchingToIt) {
    const auto [vsv, ivsv] = openThenSwitch("vsv", "ivsv", "--set epipole=march");
    ASSERT_FALSE(HasFailure());
    EXPECT_EQ(vsv.at("settings").at("epipole").get<double>(), 1.0);
    EXPECT_EQ(vsv.at("settings_error"), "");
    EXPECT_NE(featureWhy(vsv, "EPIPOLE").find("test the shadow map directly"), std::string::npos) << featureWhy(vsv, "EPIPOLE");
    ASSERT_EQ(ivsv.at("technique"), "ivsv");
    EXPECT_EQ(ivsv.at("settings").at("epipole").get<double>(), 1.0);  // its default, paper
    EXPECT_NE(ivsv.at("settings_error").get<std::string>().find("ivsv: --set epipole: 'march' is not one of off, paper"),
              std::string::npos) << ivsv.at("settings_error");
}

// A name no technique has is refused before the window opens; a value the first technique refuses too.
TEST_F(GuiSettings, AnUnknownNameOrAWrongWordIsAOneLineError) {
    // With a screenshot, so that a window that wrongly opens closes again.
    const std::string gui = "gui --scene grate --size 32x24 --screenshot " + path("never.png").string();
    expectUserError(run(gui + " --technique raymarch --set no_such_param=1"), "--set no_such_param: no technique has that parameter");
    expectUserError(run(gui + " --technique ivsv --set epipole=march"), "'march' is not one of off, paper");
    EXPECT_FALSE(fs::exists(path("never.png")));
}

}  // namespace
}  // namespace viz::testing
