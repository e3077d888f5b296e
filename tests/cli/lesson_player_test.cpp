// The lesson player in the window (`airlight --lesson NAME`), under a (virtual) display: each run replays a
// script and reads the screenshot's sidecar JSON, whose "lesson" object says where the player stands and
// whether the window shows the step. What a step should show is read from the lesson file here, with a
// parser of our own, and the stage list from `airlight list stages`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class LessonPlayer : public WindowCliTest {
protected:

    json sidecar(const std::string& png) { return json::parse(readFile(path(png.substr(0, png.size() - 4) + ".json"))); }

    // The last stage of a technique, as `airlight list stages` prints it (stage lines are not indented).
    std::string lastStage(const std::string& technique) {
        const RunResult r = run("list stages " + technique);
        std::istringstream in(r.out);
        std::string line, last;
        while (std::getline(in, line))
            if (!line.empty() && line[0] != ' ') last = line.substr(0, line.find(' '));
        return last;
    }
};

// What a step asks for, read straight from the lesson's text (scene and technique carry over).
struct StepSpec {
    std::string title, scene, technique, stage, rightView = "airlight";
};

std::vector<StepSpec> readSteps(const fs::path& file) {
    std::vector<StepSpec> steps;
    std::istringstream in(readFile(file));
    std::string line;
    bool block = false;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            StepSpec next;
            if (!steps.empty()) next.scene = steps.back().scene, next.technique = steps.back().technique;
            next.title = line.substr(3);
            steps.push_back(next);
        } else if (line == "```airlight") {
            block = true;
        } else if (line == "```") {
            block = false;
        } else if (block) {
            const std::size_t colon = line.find(':');
            const std::string key = line.substr(0, colon);
            std::string value = line.substr(colon + 1);
            value = value.substr(value.find_first_not_of(' '));
            if (key == "scene") steps.back().scene = value;
            if (key == "technique") steps.back().technique = value;
            if (key == "stage") steps.back().stage = value;
            if (key == "views") {
                std::string v;
                std::istringstream words(value);
                while (std::getline(words, v, ',')) {
                    v = v.substr(v.find_first_not_of(' '));
                    if (v != "final") {
                        steps.back().rightView = v;
                        break;
                    }
                }
            }
        }
    }
    return steps;
}

fs::path lessonFile(const std::string& name) { return fs::path(VIZ_SOURCE_DIR) / "lessons" / (name + ".md"); }

TEST_F(LessonPlayer, OpeningLessonOneShowsItsFirstStep) {
    const std::vector<StepSpec> steps = readSteps(lessonFile("01-airlight-integral"));
    ASSERT_FALSE(steps.empty());
    const RunResult r = run("--lesson 01-airlight-integral --size 40x30 --screenshot " + path("one.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("one.png");
    ASSERT_TRUE(j.contains("lesson"));
    const json& l = j.at("lesson");
    EXPECT_EQ(l.at("step"), 1);
    EXPECT_EQ(l.at("steps").get<std::size_t>(), steps.size());
    EXPECT_EQ(l.at("step_title"), steps[0].title);
    EXPECT_EQ(l.at("error"), "");
    EXPECT_TRUE(l.at("matches_step").get<bool>());
    EXPECT_FALSE(l.at("try_it").get<bool>());
    EXPECT_EQ(j.at("technique"), steps[0].technique);
    EXPECT_EQ(j.at("stage"), steps[0].stage.empty() ? lastStage(steps[0].technique) : steps[0].stage);
    EXPECT_EQ(j.at("views")[1].at("name"), steps[0].rightView);
    // The panel sits right of the views, inside the window.
    const json& panel = l.at("panel");
    EXPECT_GE(panel[0].get<double>(), j.at("views")[1].at("rect")[2].get<double>());
    EXPECT_LE(panel[2].get<double>(), j.at("window")[0].get<double>());
    EXPECT_GT(l.at("prose_height").get<double>(), 0.0);
}

TEST_F(LessonPlayer, NextThreeTimesReachesStepFourAndPreviousGoesBack) {
    const std::vector<StepSpec> steps = readSteps(lessonFile("01-airlight-integral"));
    ASSERT_GE(steps.size(), 4u);
    // Next by key, by key, by its button; then Previous and Next again by key.
    const fs::path script = writeText("next.txt", "key PageDown\nframes 1\nkey PageDown\nframes 1\nclick \"Next (PgDn) >\"\n"
                                                  "frames 1\nscreenshot " + path("four.png").string() +
                                                  "\nkey PageUp\nframes 1\nscreenshot " + path("three.png").string() +
                                                  "\nkey PageDown\nframes 1\n");
    const RunResult r = run("--lesson 01-airlight-integral --size 40x30 --script " + script.string() + " --screenshot " +
                            path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const auto& [png, step] : std::vector<std::pair<std::string, int>>{{"four.png", 4}, {"three.png", 3}, {"end.png", 4}}) {
        const json j = sidecar(png);
        const StepSpec& s = steps[std::size_t(step - 1)];
        EXPECT_EQ(j.at("lesson").at("step"), step) << png;
        EXPECT_EQ(j.at("lesson").at("step_title"), s.title) << png;
        EXPECT_TRUE(j.at("lesson").at("matches_step").get<bool>()) << png;
        EXPECT_EQ(j.at("technique"), s.technique) << png;
        EXPECT_EQ(j.at("stage"), s.stage.empty() ? lastStage(s.technique) : s.stage) << png;
        EXPECT_EQ(j.at("views")[1].at("name"), s.rightView) << png;
    }
    // Step 3 names a pixel: the ray inspector is open on it (scaled from the step's 160x120 to 40x30).
    const json three = sidecar("three.png");
    ASSERT_TRUE(three.contains("inspector"));
    EXPECT_EQ(three.at("inspector").at("pixel")[0], 80 * 40 / 160);
    EXPECT_EQ(three.at("inspector").at("pixel")[1], 40 * 30 / 120);
    EXPECT_FALSE(sidecar("four.png").contains("inspector"));
}

TEST_F(LessonPlayer, TryItChangesAreUndoneByBackAndByLeavingTryIt) {
    const fs::path script = writeText("try.txt", R"S(screenshot )S" + path("step.png").string() + R"S(
key T
frames 1
click samples 0.9 0.5
frames 2
screenshot )S" + path("changed.png").string() + R"S(
key B
frames 2
screenshot )S" + path("back.png").string() + R"S(
click "sigma_s (scattering)" 0.9 0.5
frames 2
key T
frames 2
screenshot )S" + path("untried.png").string() + R"S(
click "sigma_s (scattering)" 0.9 0.5
frames 2
)S");
    const RunResult r = run("--lesson 02-ray-marching --size 40x30 --script " + script.string() + " --screenshot " +
                            path("auto.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json step = sidecar("step.png"), changed = sidecar("changed.png"), back = sidecar("back.png");
    EXPECT_TRUE(step.at("lesson").at("matches_step").get<bool>());
    EXPECT_FALSE(step.at("lesson").at("try_it").get<bool>());
    // Try it on, a parameter changed: the panel says the window differs from the step.
    EXPECT_TRUE(changed.at("lesson").at("try_it").get<bool>());
    EXPECT_FALSE(changed.at("lesson").at("matches_step").get<bool>());
    EXPECT_NE(changed.at("settings").at("samples"), step.at("settings").at("samples"));
    // Back: exactly the step's settings and medium again, try-it still on.
    EXPECT_TRUE(back.at("lesson").at("matches_step").get<bool>());
    EXPECT_TRUE(back.at("lesson").at("try_it").get<bool>());
    EXPECT_EQ(back.at("settings"), step.at("settings"));
    EXPECT_EQ(back.at("medium"), step.at("medium"));
    // Leaving try-it mode undoes the medium change made in it.
    const json untried = sidecar("untried.png");
    EXPECT_FALSE(untried.at("lesson").at("try_it").get<bool>());
    EXPECT_TRUE(untried.at("lesson").at("matches_step").get<bool>());
    EXPECT_EQ(untried.at("medium"), step.at("medium"));
    // A change outside try-it mode switches it on rather than being lost.
    const json autoTry = sidecar("auto.png");
    EXPECT_TRUE(autoTry.at("lesson").at("try_it").get<bool>());
    EXPECT_FALSE(autoTry.at("lesson").at("matches_step").get<bool>());
    EXPECT_NE(autoTry.at("medium"), step.at("medium"));
}

// A step's views fill the grid beside the final frame (up to three); its buttons focus them; a view picked
// from the sidebar is trying something else.
TEST_F(LessonPlayer, TheStepsViewsFillTheGridAndOtherViewsAreTryingSomething) {
    const fs::path lesson = writeText("views.md", "# Views\n\n## one\n```airlight\nscene: grate\ntechnique: raymarch\n"
                                                  "set: samples=8\nviews: final, airlight, raymarch.lit_fraction\n```\ntext\n"
                                                  "## two\n```airlight\nviews: raymarch.shadow_map\n```\ntext\n");
    const fs::path script = writeText("views.txt", "screenshot " + path("first.png").string() +
                                                       "\nclick \"show Lit fraction\"\nframes 2\nscreenshot " +
                                                       path("second.png").string() + "\nclick \"view:Spot shadow map\"\nframes 2\n"
                                                       "screenshot " + path("other.png").string() +
                                                       "\nkey PageDown\nframes 2\n");
    const RunResult r = run("--lesson " + lesson.string() + " --size 40x30 --script " + script.string() + " --screenshot " +
                            path("single.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json first = sidecar("first.png"), second = sidecar("second.png"), other = sidecar("other.png"),
               single = sidecar("single.png");
    // Three columns: the final frame, then the step's two views.
    EXPECT_EQ(first.at("view_grid").at("layout"), "x(0.3333,0,x(0.5,1,2))");
    ASSERT_EQ(first.at("views").size(), 3u);
    EXPECT_EQ(first.at("views")[0].at("name"), "final");
    EXPECT_EQ(first.at("views")[1].at("name"), "airlight");
    EXPECT_EQ(first.at("views")[2].at("name"), "raymarch.lit_fraction");
    EXPECT_TRUE(first.at("views")[1].at("focused").get<bool>());
    EXPECT_TRUE(first.at("lesson").at("matches_step").get<bool>());
    // The button focuses the view already in the grid; nothing is replaced.
    EXPECT_EQ(second.at("views")[1].at("name"), "airlight");
    EXPECT_TRUE(second.at("views")[2].at("focused").get<bool>());
    EXPECT_TRUE(second.at("lesson").at("matches_step").get<bool>());
    EXPECT_FALSE(second.at("lesson").at("try_it").get<bool>());
    // The sidebar shows another view in the focused cell: trying something.
    EXPECT_EQ(other.at("views")[2].at("name"), "raymarch.shadow_map");
    EXPECT_FALSE(other.at("lesson").at("matches_step").get<bool>());
    EXPECT_TRUE(other.at("lesson").at("try_it").get<bool>());
    // A step with one view gets the two-cell grid back.
    EXPECT_EQ(single.at("view_grid").at("layout"), "x(0.5,0,1)");
    ASSERT_EQ(single.at("views").size(), 2u);
    EXPECT_EQ(single.at("views")[1].at("name"), "raymarch.shadow_map");
}

TEST_F(LessonPlayer, AMalformedLessonShowsFileAndLineAndTheWindowStaysUsable) {
    // Line 7 holds the unknown key.
    const fs::path bad = writeText("bad.md", "# Broken\n\n## one\n```airlight\nscene: grate\ntechnique: raymarch\ncolour: red\n```\ntext\n");
    const fs::path script = writeText("use.txt", "screenshot " + path("before.png").string() + "\nkey Tab\nframes 2\n");
    const RunResult r = run("--lesson " + bad.string() + " --size 40x30 --script " + script.string() + " --screenshot " +
                            path("after.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json before = sidecar("before.png"), after = sidecar("after.png");
    const std::string error = after.at("lesson").at("error");
    EXPECT_NE(error.find("bad.md:7:"), std::string::npos) << error;
    EXPECT_NE(error.find("colour"), std::string::npos) << error;
    EXPECT_EQ(after.at("lesson").at("steps"), 0);
    EXPECT_NE(after.at("technique"), before.at("technique"));  // Tab still switches technique
}

TEST_F(LessonPlayer, AStepWhoseSceneFailsToLoadShowsItsErrorAndTheOthersStillApply) {
    const fs::path lesson = writeText("scenes.md", "# Scenes\n\n## one\n```airlight\nscene: grate\ntechnique: raymarch\n"
                                                   "set: samples=8\n```\nfine\n\n## two\n```airlight\nscene: " +
                                                   path("missing.gltf").string() + "\n```\nmissing\n");
    const fs::path script = writeText("go.txt", "key PageDown\nframes 1\nscreenshot " + path("two.png").string() +
                                                    "\nkey PageUp\nframes 1\n");
    const RunResult r = run("--lesson " + lesson.string() + " --size 40x30 --script " + script.string() + " --screenshot " +
                            path("one.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json two = sidecar("two.png"), one = sidecar("one.png");
    EXPECT_EQ(two.at("lesson").at("step"), 2);
    const std::string error = two.at("lesson").at("error");
    EXPECT_NE(error.find("scenes.md:11:"), std::string::npos) << error;  // the step's heading
    EXPECT_NE(error.find("missing.gltf"), std::string::npos) << error;
    EXPECT_FALSE(two.at("lesson").at("matches_step").get<bool>());
    EXPECT_EQ(two.at("scene"), "grate");  // the window keeps the scene it had
    EXPECT_EQ(one.at("lesson").at("step"), 1);
    EXPECT_EQ(one.at("lesson").at("error"), "");
    EXPECT_TRUE(one.at("lesson").at("matches_step").get<bool>());
}

TEST_F(LessonPlayer, EveryStepOfLessonsOneAndTwoAppliesInTheWindow) {
    for (const std::string name : {"01-airlight-integral", "02-ray-marching"}) {
        const std::vector<StepSpec> steps = readSteps(lessonFile(name));
        ASSERT_FALSE(steps.empty()) << name;
        std::string actions;
        for (std::size_t k = 0; k < steps.size(); ++k)
            actions += "screenshot " + path(name + "-" + std::to_string(k + 1) + ".png").string() + "\nkey PageDown\nframes 1\n";
        const fs::path script = writeText(name + ".txt", actions);
        const RunResult r = run("--lesson " + name + " --size 32x24 --script " + script.string());
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        for (std::size_t k = 0; k < steps.size(); ++k) {
            const json j = sidecar(name + "-" + std::to_string(k + 1) + ".png");
            const StepSpec& s = steps[k];
            const json& l = j.at("lesson");
            EXPECT_EQ(l.at("step").get<std::size_t>(), k + 1) << name;
            EXPECT_EQ(l.at("error"), "") << name << " step " << k + 1;
            EXPECT_TRUE(l.at("matches_step").get<bool>()) << name << " step " << k + 1;
            EXPECT_EQ(j.at("scene"), s.scene) << name << " step " << k + 1;
            EXPECT_EQ(j.at("technique"), s.technique) << name << " step " << k + 1;
            EXPECT_EQ(j.at("stage"), s.stage.empty() ? lastStage(s.technique) : s.stage) << name << " step " << k + 1;
            EXPECT_EQ(j.at("views")[1].at("name"), s.rightView) << name << " step " << k + 1;
        }
    }
}

TEST_F(LessonPlayer, TheLessonPositionIsSavedInTheSessionAndRestored) {
    const fs::path state = path("session.json");
    // F5 saves at step 2 in try-it mode; after a step back, F9 returns there.
    const fs::path script = writeText("save.txt", "key PageDown\nframes 1\nkey T\nframes 1\nkey F5\nframes 1\nkey PageUp\n"
                                                  "frames 1\nscreenshot " + path("moved.png").string() + "\nkey F9\nframes 2\n");
    const RunResult first = run("--lesson 02-ray-marching --size 40x30 --state " + state.string() + " --script " +
                                script.string() + " --screenshot " + path("loaded.png").string());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_EQ(sidecar("moved.png").at("lesson").at("step"), 1);
    EXPECT_EQ(sidecar("loaded.png").at("lesson").at("step"), 2);
    EXPECT_TRUE(sidecar("loaded.png").at("lesson").at("try_it").get<bool>());
    const json saved = json::parse(readFile(state));
    ASSERT_TRUE(saved.contains("lesson"));
    EXPECT_EQ(saved.at("lesson").at("step"), 1);  // 0-based in the file
    EXPECT_TRUE(saved.at("lesson").at("try_it").get<bool>());
    EXPECT_EQ(fs::path(saved.at("lesson").at("path").get<std::string>()), lessonFile("02-ray-marching"));
    // Without --lesson, the session opens the lesson where it was.
    const RunResult r = run("gui --state " + state.string() + " --size 40x30 --screenshot " + path("restored.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("restored.png");
    ASSERT_TRUE(j.contains("lesson"));
    EXPECT_EQ(j.at("lesson").at("step"), 2);
    EXPECT_TRUE(j.at("lesson").at("try_it").get<bool>());
}

TEST_F(LessonPlayer, ASubstepAnimationStepsThroughThePlanesAndEndsOnTheStep) {
    const fs::path lesson = writeText("planes.md", "# Planes\n\n## one\n```airlight\nscene: grate\ntechnique: slices\n"
                                                   "set: planes=16\nstage: slices.planes\nviews: slices.accumulation\n"
                                                   "animate: substeps 1s\n```\nPlanes one by one.\n");
    // Automation advances 1/30 s per frame: 10 frames in, part of the way; 40 frames in, done.
    const fs::path script = writeText("play.txt", "frames 10\nscreenshot " + path("mid.png").string() +
                                                      "\nframes 30\nscreenshot " + path("done.png").string() +
                                                      "\nkey Space\nframes 2\n");
    const RunResult r = run("--lesson " + lesson.string() + " --size 40x30 --script " + script.string() + " --screenshot " +
                            path("again.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json mid = sidecar("mid.png"), done = sidecar("done.png"), again = sidecar("again.png");
    // The animation moves the stepping cursor (the sub-step is not a setting).
    const int k = mid.at("substep").get<int>();
    EXPECT_GE(k, 1);
    EXPECT_LT(k, 16);
    EXPECT_EQ(mid.at("substep_count"), 16);
    EXPECT_EQ(mid.at("settings").at("planes_drawn").get<double>(), 0.0);
    EXPECT_TRUE(mid.at("lesson").at("animation").at("playing").get<bool>());
    EXPECT_TRUE(mid.at("lesson").at("matches_step").get<bool>());  // the animation is part of the step
    EXPECT_EQ(mid.at("stage"), "slices.planes");
    EXPECT_EQ(done.at("substep"), 16);  // every plane: the static step
    EXPECT_FALSE(done.at("lesson").at("animation").at("playing").get<bool>());
    // Space plays it again from the first plane.
    EXPECT_TRUE(again.at("lesson").at("animation").at("playing").get<bool>());
    EXPECT_LT(again.at("substep").get<int>(), k);
    EXPECT_GE(again.at("substep").get<int>(), 1);
}

// A substeps animation of minmax's walk goes through the picked ray's nodes, as many as the run counts,
// not the bound the settings list (2 columns - 1); `render` agrees on the count: trace_steps=N draws the
// whole walk and N-1 does not.
TEST_F(LessonPlayer, ASubstepAnimationOfTheWalkEndsOnItsLastNode) {
    const fs::path lesson = writeText("walk.md", "# Walk\n\n## one\n```airlight\nscene: grate\ntechnique: minmax\n"
                                                 "stage: minmax.traverse\nviews: minmax.trace\nanimate: substeps 1s\n```\n"
                                                 "The walk node by node.\n");
    const fs::path script = writeText("walk.txt", "frames 10\nscreenshot " + path("mid.png").string() + "\nframes 30\n");
    const RunResult r = run("--lesson " + lesson.string() + " --size 40x30 --script " + script.string() + " --screenshot " +
                            path("done.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json mid = sidecar("mid.png"), done = sidecar("done.png");
    const int nodes = mid.at("substep_count").get<int>();
    ASSERT_GE(nodes, 2);
    EXPECT_GE(mid.at("substep").get<int>(), 1);
    EXPECT_LT(mid.at("substep").get<int>(), nodes);
    EXPECT_EQ(done.at("substep"), nodes) << "the animation ends on the walk's last node";
    const auto trace = [&](int steps) {
        const fs::path out = path("trace" + std::to_string(steps) + ".exr");
        EXPECT_EQ(run("render --scene grate --technique minmax --size 40x30 --layer minmax.trace --set trace_steps=" +
                      std::to_string(steps) + " --out " + out.string()).exitCode, 0);
        return viz::readImage(out.string());
    };
    const viz::Image whole = trace(0);
    EXPECT_EQ(trace(nodes).pixels, whole.pixels);
    EXPECT_NE(trace(nodes - 1).pixels, whole.pixels);
}

TEST_F(LessonPlayer, ALightOrbitCirclesTheAimPointAndReturnsToTheStart) {
    const fs::path lesson = writeText("orbit.md", "# Orbit\n\n## still\n```airlight\nscene: grate\ntechnique: raymarch\n"
                                                  "set: samples=8\n```\nstill\n\n## moving\n```airlight\nset: samples=8\n"
                                                  "animate: light orbit 1s\n```\nmoving\n");
    const fs::path script = writeText("orbit.txt", "screenshot " + path("still.png").string() + "\nkey PageDown\nframes 8\n"
                                                   "screenshot " + path("moving.png").string() + "\nframes 40\n");
    const RunResult r = run("--lesson " + lesson.string() + " --size 32x24 --script " + script.string() + " --screenshot " +
                            path("back.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json still = sidecar("still.png"), moving = sidecar("moving.png"), back = sidecar("back.png");
    const auto vec = [](const json& a) { return std::vector<double>{a[0], a[1], a[2]}; };
    const std::vector<double> p0 = vec(still.at("lesson").at("light").at("position"));
    const std::vector<double> p1 = vec(moving.at("lesson").at("light").at("position"));
    const std::vector<double> d1 = vec(moving.at("lesson").at("light").at("direction"));
    const std::vector<double> d0 = vec(still.at("lesson").at("light").at("direction"));
    double moved = 0.0;
    for (int i = 0; i < 3; ++i) moved += std::abs(p1[std::size_t(i)] - p0[std::size_t(i)]);
    EXPECT_GT(moved, 1e-3);
    EXPECT_TRUE(moving.at("lesson").at("matches_step").get<bool>());
    // A spot keeps aiming at the same point A of its original axis (as far along it as the orbit centre
    // is from the light) and keeps its distance to it: A lies on the moved axis, |A - p1| = |A - p0|.
    const std::vector<double> c = vec(moving.at("lesson").at("orbit_centre"));
    double reach = 0.0;
    for (int i = 0; i < 3; ++i) reach += (c[std::size_t(i)] - p0[std::size_t(i)]) * (c[std::size_t(i)] - p0[std::size_t(i)]);
    reach = std::sqrt(reach);
    std::vector<double> toAim(3);
    double distance = 0.0, along = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        toAim[i] = p0[i] + d0[i] * reach - p1[i];
        distance += toAim[i] * toAim[i];
        along += toAim[i] * d1[i];
    }
    distance = std::sqrt(distance);
    EXPECT_NEAR(distance, reach, 1e-9 * reach);
    EXPECT_NEAR(along, distance, 1e-9 * reach);  // the moved axis points straight at A
    // A full turn later the light is exactly where it started.
    EXPECT_EQ(back.at("lesson").at("light"), still.at("lesson").at("light"));
    EXPECT_FALSE(back.at("lesson").at("animation").at("playing").get<bool>());
}

// ---- the animate key in the lesson format (no window needed) ----

TEST_F(CliTest, BadAnimationsNameTheFileAndLine) {
    const std::string head = "# T\n\n## one\n```airlight\nscene: grate\ntechnique: ";
    const auto lesson = [&](const std::string& name, const std::string& technique, const std::string& animate) {
        return writeText(name, head + technique + "\nanimate: " + animate + "\n```\ntext\n").string();
    };
    // Line 7 holds the animate key.
    expectUserError(run("lesson " + lesson("word.md", "slices", "substeps fast") + " --export " + path("o1").string()), "word.md:7");
    expectUserError(run("lesson " + lesson("kind.md", "slices", "spin 2s") + " --export " + path("o2").string()), "kind.md:7");
    expectUserError(run("lesson " + lesson("none.md", "raymarch", "substeps 2s") + " --export " + path("o3").string()),
                    "none.md:7");
    expectUserError(run("lesson " + lesson("cpu.md", "reference", "light orbit 2s") + " --export " + path("o4").string()),
                    "cpu.md:7");
    const RunResult ok = run("lesson " + lesson("ok.md", "raymarch", "light orbit 2s") + " --export " + path("o5").string() +
                             " --size 16x12");
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_NE(readFile(path("o5") / "index.html").find("light orbit over 2 s"), std::string::npos);
}

TEST_F(CliTest, AStepsTechniqueStageAndSettingsAreCheckedAtItsHeading) {
    const auto lesson = [&](const std::string& name, const std::string& block) {
        return writeText(name, "# T\n\n## one\n```airlight\nscene: grate\n" + block + "```\ntext\n").string();
    };
    // Line 3 is the step's heading.
    expectUserError(run("lesson " + lesson("tech.md", "technique: marching\n") + " --export " + path("o1").string()),
                    "tech.md:3: step 'one': unknown technique 'marching'");
    expectUserError(run("lesson " + lesson("stage.md", "technique: raymarch\nstage: slices.planes\n") + " --export " +
                        path("o2").string()),
                    "stage.md:3: step 'one': raymarch has no stage 'slices.planes'");
    expectUserError(run("lesson " + lesson("set.md", "technique: raymarch\nset: planes=8\n") + " --export " +
                        path("o3").string()),
                    "set.md:3: step 'one':");
    // The comparison grid would hide a view other than the final frame and L_air.
    expectUserError(run("lesson " + lesson("cmp.md", "technique: raymarch\nviews: final, raymarch.lit_fraction\n"
                                                     "compare: raymarch\n") +
                        " --export " + path("o4").string()),
                    "cmp.md:3: step 'one': compare: shows L_air beside the final frame; the view 'raymarch.lit_fraction'");
}

}  // namespace
}  // namespace viz::testing

namespace viz::testing {
namespace {

// Lesson 7 quotes no timing of its own: its `compare:` steps open the comparison grid with the reference
// and the techniques they name, each run, timed and compared on this machine; the first step without
// one closes the grid.
TEST_F(LessonPlayer, ACompareStepTimesItsTechniquesLiveAndALaterStepClosesTheGrid) {
    const fs::path script = writeText("cmp.txt", "key PageDown\nframes 1\nkey PageDown\nframes 2\nscreenshot " +
                                                     path("cmp.png").string() +
                                                     "\nkey PageDown\nframes 1\nkey PageDown\nframes 1\nkey PageDown\n"
                                                     "frames 2\nscreenshot " + path("after.png").string() + "\n");
    const RunResult r = run("--lesson 07-choosing-a-technique --size 32x24 --script " + script.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("cmp.png");
    EXPECT_EQ(j.at("lesson").at("step"), 3);
    ASSERT_TRUE(j.contains("comparison"));
    std::vector<std::string> names;
    for (const json& t : j.at("comparison")) {
        names.push_back(t.at("technique"));
        EXPECT_EQ(t.at("failure"), "") << t.dump();
        if (t.at("technique") == "reference") continue;
        EXPECT_GT(t.at("milliseconds").get<double>(), 0.0) << t.dump();
        ASSERT_TRUE(t.contains("relative_l2")) << t.dump();
        EXPECT_TRUE(std::isfinite(t.at("relative_l2").get<double>()));
    }
    EXPECT_EQ(names, (std::vector<std::string>{"reference", "raymarch", "slices"}));
    const json after = sidecar("after.png");
    EXPECT_EQ(after.at("lesson").at("step"), 6);
    EXPECT_FALSE(after.contains("comparison"));
}

}  // namespace
}  // namespace viz::testing
