// The user's own scene file in the window: File > Open with path completion, a drop on the window, and
// the automatic reload when the file changes on disk (the camera, the views and the user's edits of values
// the file left alone are kept).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

class GuiSceneFile : public WindowCliTest {
protected:
    // grate written as glTF, with its medium's scattering set to `sigmaS` (and its grate moved up by
    // `lift` when not 0).
    fs::path sceneFile(const std::string& name, double sigmaS, double lift = 0.0) {
        const fs::path p = path(name);
        if (!fs::exists(path("grate.gltf"))) {
            EXPECT_EQ(run("export-scene grate " + path("grate.gltf").string()).exitCode, 0);
        }
        nlohmann::json j = nlohmann::json::parse(readFile(path("grate.gltf")));
        j["scenes"][0]["extras"]["medium"]["sigma_s"] = sigmaS;
        if (lift != 0.0)
            for (auto& node : j["nodes"])
                if (node.value("name", "") == "grate") node["translation"] = {0.0, lift, 0.0};
        std::ofstream(p) << j.dump();
        return p;
    }
    nlohmann::json sidecar(const std::string& name) { return nlohmann::json::parse(readFile(path(name))); }
    // sceneFile with a point light "lamp" added (and the spot's intensity set when not 0).
    fs::path twoLightFile(const std::string& name, double sigmaS, double spotIntensity = 0.0) {
        const fs::path p = sceneFile(name, sigmaS);
        nlohmann::json j = nlohmann::json::parse(readFile(p));
        auto& lights = j["extensions"]["KHR_lights_punctual"]["lights"];
        if (spotIntensity != 0.0) lights[0]["intensity"] = spotIntensity;
        lights.push_back({{"name", "lamp"}, {"type", "point"}, {"intensity", 50.0}, {"color", {1.0, 1.0, 1.0}}});
        j["nodes"].push_back({{"name", "lamp"}, {"translation", {1.5, 3.0, 1.0}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
        j["scenes"][0]["nodes"].push_back(j["nodes"].size() - 1);
        std::ofstream(p) << j.dump();
        return p;
    }
    // Script lines: pick the lamp in the panel and drag it with the gizmo.
    static constexpr const char* kMoveTheLamp =
        "click light\nframes 1\nclick \"light/2: lamp (point)\"\nframes 2\ndrag gizmo:position 0.5 0.5 0.5 0.5 cell:0\nframes 3\n";
};

// Typing a prefix, Tab to complete it, Enter to open: the file's scene, named by the file.
TEST_F(GuiSceneFile, OpenCompletesThePathAndLoadsTheFile) {
    const fs::path file = sceneFile("my_hall.gltf", 0.3);
    const std::string prefix = path("my_h").string();
    const fs::path script = writeText("open.txt", "frames 2\nclick \"open glTF##path\"\ntype " + prefix +
                                                      "\nkey Tab\nframes 1\nkey Enter\nframes 3\n");
    const RunResult r = run("gui --scene colonnade --technique raymarch --size 32x24 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("opened.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = sidecar("opened.json");
    EXPECT_EQ(j.at("scene_source"), file.string());
    EXPECT_DOUBLE_EQ(j.at("medium").at("sigma_s").get<double>(), 0.3);
    EXPECT_EQ(j.at("scene_title"), "my_hall.gltf (glTF scene grate)") << "named by the file, not only its glTF scene";
}

// A dropped scene file opens; a dropped file of another kind is a one-line error and the scene stays.
TEST_F(GuiSceneFile, ADroppedSceneFileOpensAndAnythingElseIsRefused) {
    const fs::path file = sceneFile("dropped.gltf", 0.2);
    const fs::path text = writeText("notes.txt", "not a scene");
    const fs::path script = writeText("drop.txt", "frames 2\ndrop " + text.string() + "\nframes 1\nscreenshot " +
                                                      path("refused.png").string() + "\ndrop " + file.string() +
                                                      "\nframes 3\n");
    const RunResult r = run("gui --scene colonnade --technique raymarch --size 32x24 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("dropped.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json refused = sidecar("refused.json");
    EXPECT_EQ(refused.at("scene"), "colonnade");
    EXPECT_NE(refused.at("error").get<std::string>().find("not a .gltf or .glb file"), std::string::npos) << refused.at("error");
    EXPECT_EQ(sidecar("dropped.json").at("scene_source"), file.string());
}

// The file changes on disk while the window shows it: the window reloads it and keeps its camera.
TEST_F(GuiSceneFile, AFileChangedOnDiskIsReloadedKeepingTheCamera) {
    const fs::path file = sceneFile("live.gltf", 0.1);
    const fs::path script = writeText("live.txt", "frames 2\nkey R\nwheel final 2\nframes 2\nscreenshot " +
                                                      path("before.png").string() + "\nframes 400\n");
    // Edit the file once the window has shown it (an editor saving it).
    std::thread editor([&] {
        for (int i = 0; i < 600 && !fs::exists(path("before.json")); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        sceneFile("live.gltf", 0.4);
    });
    const RunResult r = run("gui --scene " + file.string() + " --technique raymarch --size 32x24 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("after.png").string());
    editor.join();
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json before = sidecar("before.json"), after = sidecar("after.json");
    EXPECT_DOUBLE_EQ(before.at("medium").at("sigma_s").get<double>(), 0.1);
    EXPECT_DOUBLE_EQ(after.at("medium").at("sigma_s").get<double>(), 0.4) << "the edit was not reloaded";
    EXPECT_EQ(after.at("camera"), before.at("camera")) << "the reload must keep the user's camera";
    EXPECT_NE(after.at("notice").get<std::string>().find("reloaded live.gltf"), std::string::npos) << after.at("notice");
}

// Every light is editable: with a second light picked in the panel, the gizmo moves that light and leaves
// the first where it was.
TEST_F(GuiSceneFile, TheGizmoMovesTheLightPickedInThePanel) {
    twoLightFile("two_lights.gltf", 0.12);
    const fs::path script = writeText("pick.txt", "frames 2\nscreenshot " + path("before.png").string() + "\n" + kMoveTheLamp);
    const RunResult r = run("gui --scene " + path("two_lights.gltf").string() + " --technique raymarch --size 64x48 "
                            "--set samples=16 --script " + script.string() + " --screenshot " + path("after.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json before = sidecar("before.json"), after = sidecar("after.json");
    ASSERT_EQ(after.at("lights").size(), 2u);
    EXPECT_EQ(after.at("selected_light"), 1);
    EXPECT_EQ(after.at("lights")[0].at("position"), before.at("lights")[0].at("position")) << "the spot stays";
    EXPECT_NE(after.at("lights")[1].at("position"), before.at("lights")[1].at("position")) << "the lamp moved";
}

// A reload keeps what the user edited and the file did not: the lamp moved with the gizmo stays where the
// user put it while the file's new medium and the spot's new intensity come in.
TEST_F(GuiSceneFile, AReloadKeepsTheUsersEditsOfValuesTheFileLeftAlone) {
    const fs::path file = twoLightFile("edited.gltf", 0.12);
    const fs::path script = writeText("edit.txt", "frames 2\n" + std::string(kMoveTheLamp) + "screenshot " +
                                                      path("moved.png").string() + "\nframes 400\n");
    std::thread editor([&] {
        for (int i = 0; i < 600 && !fs::exists(path("moved.json")); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        twoLightFile("edited.gltf", 0.4, 77.0);
    });
    const RunResult r = run("gui --scene " + file.string() + " --technique raymarch --size 64x48 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("after.png").string());
    editor.join();
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json moved = sidecar("moved.json"), after = sidecar("after.json");
    const std::string notice = after.at("notice").get<std::string>();
    ASSERT_NE(notice.find("reloaded edited.gltf"), std::string::npos) << notice;
    EXPECT_NE(notice.find("kept your edits (light 2 position)"), std::string::npos) << notice;
    EXPECT_DOUBLE_EQ(after.at("medium").at("sigma_s").get<double>(), 0.4) << "the file's new medium";
    ASSERT_EQ(after.at("lights").size(), 2u);
    EXPECT_EQ(after.at("lights")[1].at("position"), moved.at("lights")[1].at("position")) << "the user's lamp";
    EXPECT_DOUBLE_EQ(after.at("lights")[0].at("intensity").get<double>(), 77.0) << "the file's new spot";
}

// A difference view against the reference follows a reload that moved geometry only (same lights and
// medium): its reference runs again, so raymarch and the reference still agree.
TEST_F(GuiSceneFile, ADifferenceViewFollowsAReloadThatMovedGeometry) {
    const fs::path file = sceneFile("moved.gltf", 0.12);
    const fs::path script = writeText("diff.txt", "frames 2\nkey F\nframes 30\nscreenshot " + path("before.png").string() +
                                                      "\nframes 400\n");
    std::thread editor([&] {
        for (int i = 0; i < 600 && !fs::exists(path("before.json")); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        sceneFile("moved.gltf", 0.12, 2.5);  // the grate up by 2.5: other shadows, the same lights
    });
    const RunResult r = run("gui --scene " + file.string() + " --technique raymarch --size 32x24 --set samples=64 --script " +
                            script.string() + " --screenshot " + path("after.png").string());
    editor.join();
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto differenceL2 = [](const nlohmann::json& j) {
        for (const auto& v : j.at("views"))
            if (v.contains("difference") && v.at("difference").contains("relative_l2"))
                return v.at("difference").at("relative_l2").get<double>();
        return -1.0;
    };
    const nlohmann::json before = sidecar("before.json"), after = sidecar("after.json");
    ASSERT_NE(after.at("notice").get<std::string>().find("reloaded"), std::string::npos) << after.at("notice");
    const double agreeBefore = differenceL2(before), agreeAfter = differenceL2(after);
    std::printf("raymarch vs reference, relative L2 of L_air: %.4f before, %.4f after the reload\n", agreeBefore, agreeAfter);
    EXPECT_GT(agreeBefore, 0.0);
    EXPECT_LT(agreeAfter, 2.0 * agreeBefore + 0.01) << "the difference view kept the reference of the old geometry";
}

}  // namespace
}  // namespace viz::testing
