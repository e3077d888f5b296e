// Settings given on the window's command line reach every technique the window switches to, each read as
// that technique declares its parameters: a named value can stand for different numbers in different
// techniques (epipole=paper is ivsv's second choice, off | paper, and vsv's third, off | march | paper).
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

class GuiSettings : public WindowCliTest {};

// The feature's reason in the sidecar's plan (what the parameter panel's plan section lists).
std::string featureWhy(const nlohmann::json& sidecar, const std::string& feature) {
    for (const nlohmann::json& f : sidecar.at("plan").at("features"))
        if (f.at("feature") == feature) return f.at("why").get<std::string>();
    return {};
}

// Opened on ivsv with epipole=paper, then switched to vsv on a scene with the light's epipole in view: vsv
// runs the paper's rule (its own default is march), said in words by the plan independently of the number.
TEST_F(GuiSettings, ANamedValueIsReadForEachTechniqueTheWindowSwitchesTo) {
    const fs::path script = writeText("switch.txt", "frames 1\nscreenshot " + path("ivsv.png").string() +
                                                        "\nclick technique:vsv\nframes 2\n");
    const RunResult r = run("gui --scene stiff/epipole-at-pixel-centre --technique ivsv --size 32x24 --set epipole=paper "
                            "--script " + script.string() + " --screenshot " + path("vsv.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json ivsv = nlohmann::json::parse(readFile(path("ivsv.json")));
    EXPECT_EQ(ivsv.at("technique"), "ivsv");
    EXPECT_EQ(ivsv.at("settings").at("epipole").get<double>(), 1.0);
    const nlohmann::json vsv = nlohmann::json::parse(readFile(path("vsv.json")));
    ASSERT_EQ(vsv.at("technique"), "vsv");
    EXPECT_EQ(vsv.at("error"), "");
    EXPECT_EQ(vsv.at("settings").at("epipole").get<double>(), 2.0);
    EXPECT_NE(featureWhy(vsv, "EPIPOLE").find("the paper's rule"), std::string::npos) << featureWhy(vsv, "EPIPOLE");
}

// A word another technique refuses leaves the window free to open: opened on vsv with epipole=march (vsv's
// second choice; ivsv has no march), switching to ivsv runs ivsv's default and says which setting it refused.
TEST_F(GuiSettings, AWordATechniqueRefusesIsSaidWhenSwitchingToIt) {
    const fs::path script = writeText("refused.txt", "frames 1\nscreenshot " + path("vsv.png").string() +
                                                         "\nclick technique:ivsv\nframes 2\n");
    const RunResult r = run("gui --scene stiff/epipole-at-pixel-centre --technique vsv --size 32x24 --set epipole=march "
                            "--script " + script.string() + " --screenshot " + path("ivsv.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json vsv = nlohmann::json::parse(readFile(path("vsv.json")));
    EXPECT_EQ(vsv.at("settings").at("epipole").get<double>(), 1.0);
    EXPECT_EQ(vsv.at("settings_error"), "");
    EXPECT_NE(featureWhy(vsv, "EPIPOLE").find("test the shadow map directly"), std::string::npos) << featureWhy(vsv, "EPIPOLE");
    const nlohmann::json ivsv = nlohmann::json::parse(readFile(path("ivsv.json")));
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
