// Motion paths (scene/motion_path.h): parsing, the pose of each motion, and determinism bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "cpu/scene/test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/light_orbit.h"
#include "scene/motion_path.h"
#include "scene/orbit_target.h"

namespace viz::scene {
namespace {

using test::expectInputError;

constexpr double kDeg = std::numbers::pi / 180.0;

bool sameBits(glm::dvec3 a, glm::dvec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameBits(const Pose& a, const Pose& b) {
    if (!sameBits(a.camera.position, b.camera.position) || !sameBits(a.camera.forward, b.camera.forward) ||
        !sameBits(a.camera.up, b.camera.up) || a.lights.size() != b.lights.size())
        return false;
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        if (!sameBits(a.lights[i].position, b.lights[i].position) || !sameBits(a.lights[i].direction, b.lights[i].direction))
            return false;
    return true;
}

double angleBetween(glm::dvec3 a, glm::dvec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

TEST(MotionPath, ParsesEachMotionAndCombinations) {
    const MotionPath p = parseMotionPath("camera-orbit:30deg,camera-dolly:25%,light-orbit,light-sweep:0.5rad");
    ASSERT_EQ(p.motions.size(), 4u);
    EXPECT_EQ(p.motions[0].kind, MotionKind::CameraOrbit);
    EXPECT_DOUBLE_EQ(p.motions[0].amount, 30.0 * kDeg);
    EXPECT_EQ(p.motions[1].kind, MotionKind::CameraDolly);
    EXPECT_TRUE(p.motions[1].percent);
    EXPECT_DOUBLE_EQ(p.motions[1].amount, 0.25);
    EXPECT_EQ(p.motions[2].kind, MotionKind::LightOrbit);
    EXPECT_DOUBLE_EQ(p.motions[2].amount, 2.0 * std::numbers::pi);  // default: a full turn
    EXPECT_EQ(p.motions[3].kind, MotionKind::LightSweep);
    EXPECT_DOUBLE_EQ(p.motions[3].amount, 0.5);
    EXPECT_TRUE(p.movesCamera());
    EXPECT_TRUE(p.movesLight());
    EXPECT_FALSE(parseMotionPath("light-sweep:20deg").movesCamera());
    const MotionPath dolly = parseMotionPath("camera-dolly:-1.5");
    EXPECT_FALSE(dolly.motions[0].percent);
    EXPECT_DOUBLE_EQ(dolly.motions[0].amount, -1.5);
    EXPECT_EQ(describeMotionPath(parseMotionPath("camera-orbit:30deg,light-sweep:20deg")),
              "camera orbit 30 deg, light sweep +-20 deg");
}

TEST(MotionPath, BadTextIsOneLineNamingTheProblem) {
    expectInputError([] { parseMotionPath("camera-orbt:30deg"); }, "unknown motion 'camera-orbt'");
    expectInputError([] { parseMotionPath("camera-orbit:30"); }, "camera-orbit:30deg");
    expectInputError([] { parseMotionPath("camera-orbit:deg"); }, "got 'deg'");
    expectInputError([] { parseMotionPath("camera-orbit:nandeg"); }, "got 'nandeg'");
    expectInputError([] { parseMotionPath("camera-orbit:1e9deg"); }, "more than 100 turns");
    expectInputError([] { parseMotionPath("light-sweep"); }, "light-sweep needs an angle");
    expectInputError([] { parseMotionPath("camera-dolly"); }, "camera-dolly needs a distance");
    expectInputError([] { parseMotionPath("camera-dolly:2m"); }, "'2m' is not a number");
    expectInputError([] { parseMotionPath("camera-orbit:30deg,"); }, "an empty motion");
    expectInputError([] { parseMotionPath(""); }, "path is empty");
    expectInputError([] { parseMotionPath("/no/such/keys.json"); }, "cannot be read");
}

TEST(MotionPath, FrameZeroIsTheSceneForEveryMotion) {
    const Scene scene = makeTestScene();
    const Pose original{scene.camera, scene.lights};
    for (const char* text : {"camera-orbit:30deg", "camera-dolly:25%", "light-orbit", "light-sweep:20deg",
                             "camera-orbit:-90deg,camera-dolly:1,light-sweep:5deg,light-orbit:45deg"})
        EXPECT_TRUE(sameBits(poseAt(parseMotionPath(text), scene, 0, 16), original)) << text;
}

TEST(MotionPath, SamePathAndIndexGiveTheSamePoseBitForBit) {
    const Scene scene = makeBuiltinScene("grate");
    const MotionPath path = parseMotionPath("camera-orbit:30deg,camera-dolly:10%,light-sweep:20deg");
    const MotionPath again = parseMotionPath("camera-orbit:30deg,camera-dolly:10%,light-sweep:20deg");
    // Frame 7 alone, after every earlier frame, and from a second parse: one pose.
    const Pose alone = poseAt(path, scene, 7, 24);
    for (int i = 0; i < 7; ++i) (void)poseAt(path, scene, i, 24);
    EXPECT_TRUE(sameBits(poseAt(path, scene, 7, 24), alone));
    EXPECT_TRUE(sameBits(poseAt(again, scene, 7, 24), alone));
    EXPECT_FALSE(sameBits(poseAt(path, scene, 8, 24), alone));
}

TEST(MotionPath, CameraOrbitTurnsAboutTheOrbitTargetKeepingItInView) {
    const Scene scene = makeTestScene();
    const glm::dvec3 target = orbitTarget(scene);
    const MotionPath path = parseMotionPath("camera-orbit:360deg");
    const Pose half = poseAt(path, scene, 4, 8);  // 180 degrees
    EXPECT_NEAR(glm::length(half.camera.position - target), glm::length(scene.camera.position - target), 1e-9);
    EXPECT_NEAR(half.camera.position.y, scene.camera.position.y, 1e-12);  // about the vertical axis
    const glm::dvec3 before = scene.camera.position - target, after = half.camera.position - target;
    EXPECT_NEAR(after.x, -before.x, 1e-9);
    EXPECT_NEAR(after.z, -before.z, 1e-9);
    // The view turns with the eye: the target stays on the view axis, up stays orthogonal to it.
    EXPECT_NEAR(glm::length(glm::cross(half.camera.forward, target - half.camera.position)), 0.0, 1e-9);
    EXPECT_GT(glm::dot(half.camera.forward, target - half.camera.position), 0.0);
    EXPECT_NEAR(glm::dot(half.camera.forward, half.camera.up), 0.0, 1e-12);
    // A 30 degree orbit in 3 frames: 0, 10, 20 degrees about the vertical.
    const Pose third = poseAt(parseMotionPath("camera-orbit:30deg"), scene, 2, 3);
    const auto horizontal = [&target](glm::dvec3 p) { return glm::dvec3(p.x - target.x, 0.0, p.z - target.z); };
    EXPECT_NEAR(angleBetween(horizontal(third.camera.position), horizontal(scene.camera.position)), 20.0 * kDeg, 1e-9);
}

TEST(MotionPath, CameraDollyGoesInAndComesBack) {
    const Scene scene = makeTestScene();
    const MotionPath path = parseMotionPath("camera-dolly:2");
    const Pose in = poseAt(path, scene, 5, 10);  // the turning point
    EXPECT_NEAR(glm::length(in.camera.position - scene.camera.position), 2.0, 1e-12);
    EXPECT_GT(glm::dot(in.camera.position - scene.camera.position, scene.camera.forward), 0.0);
    EXPECT_TRUE(sameBits(in.camera.forward, scene.camera.forward));
    // Symmetric about the turning point; by percent, a fraction of the orbit target's distance.
    EXPECT_NEAR(glm::length(poseAt(path, scene, 2, 10).camera.position - poseAt(path, scene, 8, 10).camera.position), 0.0, 1e-12);
    const Pose percent = poseAt(parseMotionPath("camera-dolly:50%"), scene, 5, 10);
    EXPECT_NEAR(glm::length(percent.camera.position - scene.camera.position), 0.5 * orbitDistance(scene), 1e-9);
}

TEST(MotionPath, LightOrbitFollowsTheWindowsOrbit) {
    const Scene scene = makeBuiltinScene("grate");
    const MotionPath path = parseMotionPath("light-orbit");
    for (int i : {1, 3, 6}) {
        const Light expected = orbitLight(scene.lights[0], orbitTarget(scene), double(i) / 8.0);
        const Pose pose = poseAt(path, scene, i, 8);
        EXPECT_TRUE(sameBits(pose.lights[0].position, expected.position)) << i;
        EXPECT_TRUE(sameBits(pose.lights[0].direction, expected.direction)) << i;
        EXPECT_TRUE(sameBits(pose.camera.position, scene.camera.position));
    }
}

TEST(MotionPath, LightSweepSwingsBothWaysAndASpotKeepsItsAim) {
    // The test scene's spot hangs straight above its aim: it swings about the camera's right axis.
    const Scene scene = makeTestScene();
    const Light& spot = scene.lights[0];
    const glm::dvec3 aim = lightAim(spot, orbitTarget(scene));
    const MotionPath path = parseMotionPath("light-sweep:20deg");
    const Pose quarter = poseAt(path, scene, 2, 8), threeQuarters = poseAt(path, scene, 6, 8);
    EXPECT_NEAR(angleBetween(quarter.lights[0].position - aim, spot.position - aim), 20.0 * kDeg, 1e-9);
    EXPECT_NEAR(angleBetween(threeQuarters.lights[0].position - aim, spot.position - aim), 20.0 * kDeg, 1e-9);
    EXPECT_NEAR(angleBetween(quarter.lights[0].position - aim, threeQuarters.lights[0].position - aim), 40.0 * kDeg, 1e-9);
    for (const Pose* p : {&quarter, &threeQuarters})
        EXPECT_NEAR(glm::length(glm::cross(p->lights[0].direction, aim - p->lights[0].position)), 0.0, 1e-9);
    // A directional light (colonnade's sun) turns its direction about the vertical: its elevation stays,
    // its azimuth moves by the sweep's angle.
    const Scene colonnade = makeBuiltinScene("colonnade");
    ASSERT_EQ(colonnade.lights[0].type, LightType::Directional);
    const glm::dvec3 before = glm::normalize(colonnade.lights[0].direction);
    const glm::dvec3 after = poseAt(path, colonnade, 2, 8).lights[0].direction;
    EXPECT_NEAR(after.y, before.y, 1e-12);
    EXPECT_NEAR(angleBetween(glm::dvec3(after.x, 0, after.z), glm::dvec3(before.x, 0, before.z)), 20.0 * kDeg, 1e-9);
}

TEST(MotionPath, LightMotionsNeedAMovableFirstLight) {
    Scene dark = makeTestScene();
    dark.lights.clear();
    expectInputError([&] { poseAt(parseMotionPath("light-sweep:20deg"), dark, 1, 4); }, "the scene has none");
    const Scene area = makeTestAreaLightScene();
    expectInputError([&] { poseAt(parseMotionPath("light-orbit"), area, 1, 4); }, "is an area light");
    // A camera path does not care.
    EXPECT_NO_THROW(poseAt(parseMotionPath("camera-orbit:10deg"), area, 1, 4));
}

TEST(MotionPath, KeyframesInterpolateBetweenKeys) {
    const MotionPath path = parseKeyframes(R"({"keyframes": [
        {"t": 0, "camera": {"position": [0, 1, 4], "target": [0, 1, 0]}, "light": {"position": [0, 3, 0]}},
        {"t": 1, "camera": {"position": [4, 1, 0], "target": [0, 1, 0]}, "light": {"position": [2, 3, 0]}},
        {"t": 3, "camera": {"position": [0, 1, -4], "target": [0, 1, 0]}, "light": {"position": [2, 3, 2]}}]})",
                                           "keys.json");
    ASSERT_EQ(path.keyframes.size(), 3u);
    EXPECT_TRUE(path.movesCamera());
    EXPECT_TRUE(path.movesLight());
    const Scene scene = makeTestScene();
    // 7 frames over t = 0..3: frame 2 at t = 1 (the middle key), frame 4 at t = 2.
    const Pose key = poseAt(path, scene, 2, 7);
    EXPECT_TRUE(sameBits(key.camera.position, glm::dvec3(4, 1, 0)));
    EXPECT_NEAR(glm::length(key.camera.forward - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(key.camera.up, key.camera.forward), 0.0, 1e-12);
    const Pose between = poseAt(path, scene, 4, 7);
    EXPECT_NEAR(glm::length(between.camera.position - glm::dvec3(2, 1, -2)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(between.lights[0].position - glm::dvec3(2, 3, 1)), 0.0, 1e-12);
    EXPECT_TRUE(sameBits(poseAt(path, scene, 6, 7).camera.position, glm::dvec3(0, 1, -4)));
    EXPECT_TRUE(sameBits(poseAt(path, scene, 0, 1).camera.position, glm::dvec3(0, 1, 4)));
}

TEST(MotionPath, KeyframeFileMistakesAreNamed) {
    const auto parse = [](const std::string& json) { return [json] { parseKeyframes(json, "k.json"); }; };
    expectInputError(parse("{"), "k.json");
    expectInputError(parse(R"({"keyframes": []})"), "non-empty array 'keyframes'");
    expectInputError(parse(R"({"frames": []})"), "unknown member 'frames'");
    expectInputError(parse(R"({"keyframes": [{"t": 0, "camera": {"position": [0, 0, 1]}}]})"),
                     "needs 'position' and 'target'");
    expectInputError(parse(R"({"keyframes": [{"t": 0, "camera": {"position": [0, 0, 1], "target": [0, 0, 1]}}]})"),
                     "'target' is at 'position'");
    expectInputError(parse(R"({"keyframes": [{"t": 1, "light": {"position": [0, 1, 0]}},
                                              {"t": 1, "light": {"position": [0, 2, 0]}}]})"),
                     "keyframe 2: 't' must be greater");
    expectInputError(parse(R"({"keyframes": [{"t": 0, "light": {"position": [0, 1, 0]}},
                                              {"t": 1, "light": {"direction": [0, -1, 0]}}]})"),
                     "every keyframe gives the same");
    expectInputError(parse(R"({"keyframes": [{"t": 0, "light": {"position": [0, 1]}}]})"), "array of 3 numbers");
    expectInputError(parse(R"({"keyframes": [{"t": 0, "light": {"colour": [1, 1, 1]}}]})"), "unknown member 'colour'");
    expectInputError(parse(R"({"keyframes": [{"t": 0}]})"), "move nothing");
}

TEST(MotionPath, KeyframeFileIsReadFromDisk) {
    const auto dir = test::freshTempDir("motion");
    test::writeText(dir / "spin.JSON", R"({"keyframes": [{"t": 0, "light": {"direction": [0, -1, 0]}},
                                                          {"t": 1, "light": {"direction": [1, -1, 0]}}]})");
    const MotionPath path = parseMotionPath((dir / "spin.JSON").string());
    EXPECT_EQ(path.keyframes.size(), 2u);
    EXPECT_FALSE(path.movesCamera());
    const Pose end = poseAt(path, makeTestScene(), 1, 2);
    EXPECT_NEAR(glm::length(end.lights[0].direction - glm::normalize(glm::dvec3(1, -1, 0))), 0.0, 1e-12);
    std::filesystem::remove_all(dir);
}

TEST(LightOrbit, WholeTurnsAreWhereItStartedAndNegativeTurnsGoBack) {
    const Scene scene = makeBuiltinScene("grate");
    const Light& light = scene.lights[0];
    const glm::dvec3 centre = orbitTarget(scene);
    for (double turn : {0.0, 1.0, -2.0}) {
        const Light same = orbitLight(light, centre, turn);
        EXPECT_TRUE(sameBits(same.position, light.position) && sameBits(same.direction, light.direction)) << turn;
    }
    const Light forward = orbitLight(light, centre, 0.1), back = orbitLight(light, centre, -0.9);
    EXPECT_NEAR(glm::length(forward.position - back.position), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(forward.direction - back.direction), 0.0, 1e-9);
}

}  // namespace
}  // namespace viz::scene
