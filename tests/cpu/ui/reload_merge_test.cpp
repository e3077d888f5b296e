// keepUserEdits: the three-way merge of the medium and the lights across a reload of the scene file,
// checked value by value against what each side did: a value only the user changed is the user's, a value
// the file changed is the file's (also when the user changed it: then it is counted as replaced), and a
// file whose lights changed in number, type or name takes every light from the file and says which edits
// were dropped.
#include <gtest/gtest.h>

#include "reload_merge.h"

namespace airlight {
namespace {

using viz::scene::Light;
using viz::scene::LightType;
using viz::scene::Scene;

Scene twoLights() {
    Scene s;
    s.medium = {0.1, 0.01, 0.2};
    s.lights.push_back(Light{.name = "sun", .type = LightType::Directional, .direction = {0.0, -1.0, 0.0}, .intensity = 3.0});
    s.lights.push_back(Light{.name = "lamp", .type = LightType::Point, .position = {1.0, 2.0, 3.0}, .intensity = 50.0});
    return s;
}

TEST(ReloadMerge, AnEditTheFileLeftAloneIsKeptAndTheFileWinsWhatItChanged) {
    const Scene loaded = twoLights();
    const SceneLighting base = lightingOf(loaded);
    Scene mine = loaded;
    mine.medium.sigma_s = 0.5;               // user only
    mine.lights[1].position = {4.0, 5.0, 6.0};  // user only
    mine.lights[0].intensity = 7.0;          // user and file
    Scene theirs = loaded;
    theirs.medium.g = 0.6;                   // file only
    theirs.lights[0].intensity = 9.0;        // file, over the user's
    theirs.lights[1].intensity = 20.0;       // file only
    const ReloadMerge m = keepUserEdits(base, mine, theirs);
    EXPECT_EQ(theirs.medium.sigma_s, 0.5);
    EXPECT_EQ(theirs.medium.sigma_a, 0.01);
    EXPECT_EQ(theirs.medium.g, 0.6);
    EXPECT_EQ(theirs.lights[1].position, glm::dvec3(4.0, 5.0, 6.0));
    EXPECT_EQ(theirs.lights[1].intensity, 20.0);
    EXPECT_EQ(theirs.lights[0].intensity, 9.0);
    EXPECT_EQ(theirs.lights[0].direction, glm::dvec3(0.0, -1.0, 0.0));
    EXPECT_EQ(m.kept, 2);
    EXPECT_EQ(m.replaced, 1);
    EXPECT_TRUE(m.lightsRematched);
    EXPECT_NE(m.summary.find("kept your edits (medium sigma_s, light 2 position)"), std::string::npos) << m.summary;
    EXPECT_NE(m.summary.find("the file changed light 1 intensity too"), std::string::npos) << m.summary;
}

TEST(ReloadMerge, NoEditsMeansTheFileAsItIsNowAndNothingToSay) {
    const Scene loaded = twoLights();
    Scene theirs = loaded;
    theirs.medium.sigma_s = 0.9;
    theirs.lights[1].position = {0.0, 0.0, 0.0};
    const Scene expected = theirs;
    const ReloadMerge m = keepUserEdits(lightingOf(loaded), loaded, theirs);
    EXPECT_EQ(theirs.medium.sigma_s, expected.medium.sigma_s);
    EXPECT_EQ(theirs.lights[1].position, expected.lights[1].position);
    EXPECT_EQ(m.kept + m.replaced, 0);
    EXPECT_EQ(m.summary, "");
}

TEST(ReloadMerge, LightsChangedInTheFileTakeTheFilesAndNameTheDroppedEdits) {
    const Scene loaded = twoLights();
    Scene mine = loaded;
    mine.lights[1].intensity = 1.0;
    mine.medium.sigma_a = 0.02;
    for (int variant = 0; variant < 3; ++variant) {
        Scene theirs = loaded;
        if (variant == 0) theirs.lights.pop_back();                    // one fewer
        if (variant == 1) theirs.lights[1].type = LightType::Spot;     // another type
        if (variant == 2) theirs.lights[1].name = "bulb";              // renamed
        const Scene fromFile = theirs;
        const ReloadMerge m = keepUserEdits(lightingOf(loaded), mine, theirs);
        EXPECT_FALSE(m.lightsRematched) << variant;
        ASSERT_EQ(theirs.lights.size(), fromFile.lights.size());
        for (std::size_t i = 0; i < theirs.lights.size(); ++i) EXPECT_EQ(theirs.lights[i].intensity, fromFile.lights[i].intensity);
        EXPECT_EQ(theirs.medium.sigma_a, 0.02) << "the medium is still merged";
        EXPECT_NE(m.summary.find("your edits of light 2 are not carried over"), std::string::npos) << m.summary;
    }
}

}  // namespace
}  // namespace airlight
