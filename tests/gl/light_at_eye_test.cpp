// A light at the eye itself (a flashlight held at the camera): every camera ray starts at the light, the
// airlight integral diverges like the integral of 1/t^2 at t = 0, and minmax's epipolar frame has no axis.
// Each technique must still give finite, non-negative images: minmax marches that light's rays (its plan
// says so) and the reference takes the closed forms' floor on the light-to-ray distance (docs/numerics.md,
// "Rays through the light"). Before, minmax gave NaN on every pixel and the reference Inf with a spot.
#include <gtest/gtest.h>

#include <algorithm>

#include "gl/technique_test_util.h"
#include "scene/builtin_scenes.h"

namespace viz::testing {
namespace {

class LightAtEyeTest : public TechniqueTest {};

bool nonNegative(const Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(), [](float v) { return v >= 0.0f; });
}

TEST_F(LightAtEyeTest, EveryTechniqueStaysFiniteWithASpotOrAPointLightAtTheEye) {
    for (const scene::LightType type : {scene::LightType::Spot, scene::LightType::Point}) {
        scene::Scene scene = scene::makeBuiltinScene("grate");
        ASSERT_FALSE(scene.lights.empty());
        scene.lights.resize(1);
        scene::Light& light = scene.lights[0];
        light.type = type;
        // The camera where the light is, looking along it.
        scene.camera.position = light.position;
        scene.camera.forward = light.direction;
        scene.camera.up = glm::normalize(glm::cross(glm::cross(light.direction, glm::dvec3(0, 0, 1)), light.direction));
        const std::string kind = type == scene::LightType::Spot ? "spot" : "point";
        for (const std::string& id : techniqueIds()) {
            Settings given;
            if (id == "polyvol") given = {{"shadow_map", 128.0}};
            const FrameOutput out = render(scene, id, given, 24, 18);
            EXPECT_TRUE(allFinite(out.airlight)) << kind << " " << id;
            EXPECT_TRUE(allFinite(out.final)) << kind << " " << id;
            EXPECT_TRUE(nonNegative(out.airlight)) << kind << " " << id;
            EXPECT_TRUE(std::any_of(out.airlight.pixels.begin(), out.airlight.pixels.end(), [](float v) { return v > 0.0f; }))
                << kind << " " << id << ": the medium in front of the light scatters";
        }
        const auto minmax = makeTechnique("minmax");
        const Plan plan = minmax->plan(scene, completeSettings(*minmax, {}));
        const FeaturePlan brute = feature(plan, "BRUTE_FORCE_LIGHTS");
        EXPECT_TRUE(brute.enabled) << kind;
        EXPECT_NE(brute.why.find("sits at the eye"), std::string::npos) << brute.why;
    }
}

}  // namespace
}  // namespace viz::testing
