// The window's session file: a round trip keeps everything, and any broken file gives the defaults with
// a one-line reason naming the file, never a crash.
#include <tuple>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "session_state.h"
#include "temp_dir.h"

namespace airlight {
namespace {

namespace fs = std::filesystem;

SessionState sample() {
    SessionState s;
    s.scene = "stiff/grazing-sun";
    s.technique = "slices";
    s.width = 200, s.height = 150;
    viz::scene::Camera c;
    c.position = {1.5, 2.0, -3.25};
    c.forward = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
    c.up = glm::normalize(glm::dvec3(0.0, 1.0, -0.1) - glm::dot(glm::dvec3(0.0, 1.0, -0.1), c.forward) * c.forward);
    c.yfov = 0.7, c.znear = 0.02, c.zfar = 75.0;
    s.camera = c;
    s.orbitTarget = {0.0, 1.0, -8.0};
    s.medium = viz::scene::Medium{0.2, 0.03, -0.4};
    s.settings["slices"] = {{"planes", 256}, {"accum", 1}};
    s.settings["raymarch"] = {{"samples", 1024}};
    s.view = "slices.accumulation";
    s.viewZoom = 12.5;
    s.viewCenter = {0.25, 0.75};
    s.exposure = -1.5f;
    s.exposureSet = true;
    return s;
}

TEST(SessionState, RoundTripKeepsEverything) {
    const SessionState a = sample();
    std::string problem;
    const SessionState b = sessionFromJson(sessionToJson(a), problem);
    EXPECT_EQ(problem, "");
    EXPECT_EQ(b.scene, a.scene);
    EXPECT_EQ(b.technique, a.technique);
    EXPECT_EQ(b.width, a.width);
    EXPECT_EQ(b.height, a.height);
    ASSERT_TRUE(b.camera.has_value());
    EXPECT_EQ(b.camera->position, a.camera->position);
    EXPECT_NEAR(glm::length(b.camera->forward - a.camera->forward), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(b.camera->up - a.camera->up), 0.0, 1e-12);
    EXPECT_EQ(b.camera->yfov, a.camera->yfov);
    EXPECT_EQ(b.camera->zfar, a.camera->zfar);
    EXPECT_EQ(b.orbitTarget, a.orbitTarget);
    ASSERT_TRUE(b.medium.has_value());
    EXPECT_EQ(b.medium->g, a.medium->g);
    EXPECT_EQ(b.settings, a.settings);
    EXPECT_EQ(b.view, a.view);
    EXPECT_EQ(b.viewZoom, a.viewZoom);
    EXPECT_EQ(b.viewCenter, a.viewCenter);
    EXPECT_EQ(b.exposure, a.exposure);
    EXPECT_TRUE(b.exposureSet);
}

// Named values are written by name and read by name or number; an unknown name is a broken file.
TEST(SessionState, NamedSettingsAreWrittenAsNamesAndReadEitherWay) {
    const SessionState a = sample();  // slices accum = 1: "rgba8-mask"
    const std::string text = sessionToJson(a);
    EXPECT_NE(text.find("\"rgba8-mask\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"planes\": 256"), std::string::npos) << text;
    nlohmann::json j = nlohmann::json::parse(text);
    j["settings"]["slices"]["accum"] = 2;  // a number still reads
    j["settings"]["slices"]["weighting"] = "artistic";
    std::string problem;
    SessionState b = sessionFromJson(j.dump(), problem);
    EXPECT_EQ(problem, "");
    EXPECT_EQ(b.settings["slices"]["accum"], 2.0);
    EXPECT_EQ(b.settings["slices"]["weighting"], 0.0);
    j["settings"]["slices"]["accum"] = "rgba9";
    b = sessionFromJson(j.dump(), problem);
    EXPECT_NE(problem.find("rgba9"), std::string::npos) << problem;
    EXPECT_NE(problem.find("rgba8-mask"), std::string::npos) << problem;  // the known names
    EXPECT_TRUE(b.settings.empty());
}

TEST(SessionState, TheLessonPositionRoundTripsAndABadOneGivesTheDefaults) {
    SessionState a = sample();
    a.lesson = "lessons/02-ray-marching.md";
    a.lessonStep = 3;
    a.lessonTryIt = true;
    std::string problem;
    const SessionState b = sessionFromJson(sessionToJson(a), problem);
    EXPECT_EQ(problem, "");
    EXPECT_EQ(b.lesson, a.lesson);
    EXPECT_EQ(b.lessonStep, 3);
    EXPECT_TRUE(b.lessonTryIt);
    // Without a lesson the file holds none, and reads back without one.
    const SessionState c = sessionFromJson(sessionToJson(sample()), problem);
    EXPECT_EQ(problem, "");
    EXPECT_TRUE(c.lesson.empty());
    EXPECT_EQ(sessionToJson(sample()).find("lesson"), std::string::npos);
    // A negative step: the defaults and a reason.
    std::string text = sessionToJson(a);
    const std::string step = "\"step\": 3";
    text.replace(text.find(step), step.size(), "\"step\": -1");
    const SessionState d = sessionFromJson(text, problem);
    EXPECT_NE(problem.find("lesson step"), std::string::npos) << problem;
    EXPECT_TRUE(d.lesson.empty());
}

TEST(SessionState, LightPlacementsRoundTripAndApplyOnlyToAsManyLights) {
    SessionState a = sample();
    a.lights = {{{1.0, 2.5, -3.0}, glm::normalize(glm::dvec3(0.1, -1.0, 0.2)), 250.0},
                {{0.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, 3.5}};
    std::string problem;
    const SessionState b = sessionFromJson(sessionToJson(a), problem);
    EXPECT_EQ(problem, "");
    ASSERT_EQ(b.lights.size(), 2u);
    EXPECT_EQ(b.lights[0].position, a.lights[0].position);
    EXPECT_NEAR(glm::length(b.lights[0].direction - a.lights[0].direction), 0.0, 1e-15);
    EXPECT_EQ(b.lights[1].intensity, 3.5);
    // Older files have no lights: none come back, and the scene's own stay.
    EXPECT_EQ(sessionToJson(sample()).find("\"lights\""), std::string::npos);

    viz::scene::Scene scene;
    scene.lights.resize(2);
    scene.lights[0].name = "key";
    ASSERT_TRUE(applyLightPlacements(b.lights, scene));
    EXPECT_EQ(scene.lights[0].position, a.lights[0].position);
    EXPECT_EQ(scene.lights[1].intensity, 3.5);
    EXPECT_EQ(scene.lights[0].name, "key");  // only the placement and brightness change
    EXPECT_EQ(lightPlacements(scene)[0].position, a.lights[0].position);
    viz::scene::Scene other;
    other.lights.resize(1);
    const glm::dvec3 before = other.lights[0].position;
    EXPECT_FALSE(applyLightPlacements(b.lights, other));
    EXPECT_EQ(other.lights[0].position, before);

    // A zero direction or a negative intensity: the defaults and a reason.
    std::string text = sessionToJson(a);
    const std::string intensity = "\"intensity\": 3.5";
    text.replace(text.find(intensity), intensity.size(), "\"intensity\": -1");
    const SessionState c = sessionFromJson(text, problem);
    EXPECT_NE(problem.find("intensity"), std::string::npos) << problem;
    EXPECT_TRUE(c.lights.empty());
}

TEST(SessionState, BrokenFilesGiveTheDefaultsAndAReasonNamingTheFile) {
    const viz::testing::TempDir temp("state");
    const fs::path dir = temp.path();
    const std::string good = sessionToJson(sample());
    const std::vector<std::pair<std::string, std::string>> broken = {
        {"truncated", good.substr(0, good.size() / 2)},
        {"empty", ""},
        {"not an object", "[1, 2, 3]"},
        {"wrong version", std::string(good).replace(good.find("\"version\": 1"), 12, "\"version\": 9")},
        {"wrong type", std::string(good).replace(good.find("\"yfov\": 0.7"), 11, "\"yfov\": \"x\"")},
        {"binary", std::string("\x00\xff\xfe garbage", 11)},
    };
    for (const auto& [what, text] : broken) {
        const fs::path file = dir / "session.json";
        std::ofstream(file, std::ios::binary) << text;
        std::string problem;
        const SessionState s = loadSession(file.string(), problem);
        EXPECT_NE(problem.find(file.string()), std::string::npos) << what << ": " << problem;
        EXPECT_NE(problem.find("nothing loaded"), std::string::npos) << what;
        EXPECT_EQ(problem.find('\n'), std::string::npos) << what;
        EXPECT_EQ(s.scene, SessionState{}.scene) << what;
        EXPECT_FALSE(s.camera.has_value()) << what;
    }
    std::string problem;
    loadSession((dir / "missing.json").string(), problem);
    EXPECT_NE(problem.find("missing.json"), std::string::npos);
    EXPECT_NE(problem.find("does not exist yet"), std::string::npos) << problem;
    // A folder under the name is neither read nor moved aside.
    fs::create_directories(dir / "folder.json");
    loadSession((dir / "folder.json").string(), problem);
    EXPECT_NE(problem.find("is not a regular file"), std::string::npos) << problem;
    EXPECT_TRUE(fs::is_directory(dir / "folder.json"));
    EXPECT_FALSE(fs::exists(dir / "folder.json.broken"));
    // Saving creates the folder and replaces the file whole.
    saveSession((dir / "deeper" / "s.json").string(), sample());
    const SessionState back = loadSession((dir / "deeper" / "s.json").string(), problem);
    EXPECT_EQ(problem, "");
    EXPECT_EQ(back.technique, "slices");
    fs::remove_all(dir);
}

// A broken file is moved aside whole (the window then saves a fresh one over the name, and the
// user's hand edit survives as .broken); hostile nesting and magnitudes are reasons, not crashes.
TEST(SessionState, BrokenFilesAreMovedAsideAndHostileOnesRefused) {
    const viz::testing::TempDir temp("state_aside");
    const fs::path dir = temp.path();
    const std::string good = sessionToJson(sample());
    std::string deepLayout = std::string(good);
    {
        // A view_grid layout nested 40,000 deep (the session's JSON itself stays shallow).
        std::string layout;
        for (int i = 0; i < 40000; ++i) layout += "x(0.5,";
        layout += "0";
        for (int i = 0; i < 40000; ++i) layout += "," + std::to_string(i + 1) + ")";
        nlohmann::json j = nlohmann::json::parse(good);
        j["view_grid"] = {{"layout", layout}, {"focused", 0}, {"maximised", -1}, {"views", nlohmann::json::array()}};
        deepLayout = j.dump();
    }
    std::string farLight;
    {
        nlohmann::json j = nlohmann::json::parse(good);
        j["lights"] = {{{"position", {1e300, 0, 0}}, {"direction", {0, -1, 0}}, {"intensity", 1.0}}};
        farLight = j.dump();
    }
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {"hand edit with a typo", good.substr(0, good.size() - 3) + ",}", "malformed JSON"},
        {"JSON nested 100000 deep", std::string(100000, '[') + std::string(100000, ']'), "JSON nested deeper than 32"},
        {"layout nested 40000 deep", deepLayout, "layout nested deeper than 32"},
        {"light at 1e300", farLight, "beyond 1e15"},
    };
    for (const auto& [what, text, reason] : cases) {
        const fs::path file = dir / "session.json";
        fs::remove(dir / "session.json.broken");
        std::ofstream(file, std::ios::binary) << text;
        std::string problem;
        const SessionState s = loadSession(file.string(), problem);
        EXPECT_NE(problem.find(reason), std::string::npos) << what << ": " << problem.substr(0, 300);
        EXPECT_NE(problem.find("moved to"), std::string::npos) << what << ": " << problem.substr(0, 300);
        EXPECT_EQ(s.scene, SessionState{}.scene) << what;
        EXPECT_FALSE(fs::exists(file)) << what;
        std::ifstream aside(dir / "session.json.broken", std::ios::binary);
        const std::string kept((std::istreambuf_iterator<char>(aside)), std::istreambuf_iterator<char>());
        EXPECT_EQ(kept, text) << what << ": the broken file must survive byte for byte";
    }
    fs::remove_all(dir);
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Moving aside never overwrites an earlier broken file: each goes to the first free name.
TEST(SessionState, EachBrokenFileIsMovedAsideToANameThatHoldsNothingYet) {
    const viz::testing::TempDir temp("state_aside_twice");
    const fs::path file = temp.path() / "session.json";
    for (const std::string text : {"first {", "second [", "third \"", "fourth ,"}) {
        std::ofstream(file, std::ios::binary) << text;
        std::string problem;
        (void)loadSession(file.string(), problem);
        EXPECT_FALSE(fs::exists(file)) << text;
    }
    EXPECT_EQ(contents(temp.path() / "session.json.broken"), "first {");
    EXPECT_EQ(contents(temp.path() / "session.json.broken.2"), "second [");
    EXPECT_EQ(contents(temp.path() / "session.json.broken.3"), "third \"");
    EXPECT_EQ(contents(temp.path() / "session.json.broken.4"), "fourth ,");
}

// The file named with --state: read without being touched; anything but a session, or a name that holds
// nothing yet, is an InputError naming it, and the file stays byte for byte (a mistyped `--state
// scene.gltf` must never be renamed). A missing name is a new session.
TEST(SessionState, AFileNamedAtStartIsNeverMovedAndMustBeASession) {
    const viz::testing::TempDir temp("state_named");
    const fs::path dir = temp.path();
    const std::string good = sessionToJson(sample());
    std::ofstream(dir / "good.json", std::ios::binary) << good;
    const SessionRead ok = loadNamedSession((dir / "good.json").string());
    EXPECT_EQ(ok.file, SessionRead::File::Loaded);
    EXPECT_EQ(ok.problem, "");
    EXPECT_EQ(ok.state.technique, "slices");

    const SessionRead fresh = loadNamedSession((dir / "new.json").string());
    EXPECT_EQ(fresh.file, SessionRead::File::Missing);
    EXPECT_NE(fresh.problem.find("new.json"), std::string::npos) << fresh.problem;
    EXPECT_FALSE(fs::exists(dir / "new.json")) << "reading creates nothing";

    const std::vector<std::pair<std::string, std::string>> others = {
        {"scene.gltf", R"({"asset": {"version": "2.0"}})"},
        {"passwd", "root:x:0:0:root:/root:/bin/bash\n"},
        {"half.json", good.substr(0, good.size() / 2)},
        {"newer.json", std::string(good).replace(good.find("\"version\": 1"), 12, "\"version\": 9")},
    };
    for (const auto& [name, text] : others) {
        const fs::path file = dir / name;
        std::ofstream(file, std::ios::binary) << text;
        const SessionRead r = readSession(file.string());
        EXPECT_EQ(r.file, SessionRead::File::Broken) << name;
        EXPECT_NE(r.problem.find(name), std::string::npos) << r.problem;
        try {
            (void)loadNamedSession(file.string());
            ADD_FAILURE() << name << " was taken for a session";
        } catch (const viz::InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.string()), std::string::npos) << what;
            EXPECT_NE(what.find("not an Airlight session"), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        EXPECT_EQ(contents(file), text) << name << " is left as it was";
        EXPECT_FALSE(fs::exists(file.string() + ".broken")) << name;
    }
    // A folder under the name is refused too, and stays a folder.
    fs::create_directories(dir / "folder.json");
    EXPECT_THROW((void)loadNamedSession((dir / "folder.json").string()), viz::InputError);
    EXPECT_TRUE(fs::is_directory(dir / "folder.json"));
}

TEST(SessionState, SavingWhereNothingCanBeWrittenIsAnInputError) {
    EXPECT_THROW(saveSession("/proc/airlight/session.json", sample()), viz::InputError);
}

}  // namespace
}  // namespace airlight
