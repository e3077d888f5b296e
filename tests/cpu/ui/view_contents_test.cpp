// The views list a run offers (app/view_contents.h): final, L_air, then the run's intermediates in order,
// and the stand-in note for a chosen view the run did not make, each of its four reasons, on raymarch's
// declared stages (shadow maps, surface, march, compose).
#include <gtest/gtest.h>

#include "techniques/registry.h"
#include "view_contents.h"

namespace airlight {
namespace {

viz::FrameOutput runWith(std::initializer_list<std::pair<const char*, const char*>> views) {
    viz::FrameOutput out;
    for (const auto& [id, label] : views) {
        viz::Intermediate i;
        i.id = id;
        i.label = label;
        out.intermediates.push_back(i);
    }
    return out;
}

TEST(ViewContents, FinalAndLairComeFirstThenTheRunsIntermediatesInOrder) {
    const viz::FrameOutput out = runWith({{"t.shadow_map", "Spot shadow map"}, {"t.shadow_map", "Spot shadow map 1"},
                                          {"t.distance", "Distance d"}});
    ASSERT_EQ(contentCount(out), 5);
    EXPECT_EQ(contentId(out, 0), "final");
    EXPECT_EQ(contentId(out, 1), "airlight");
    EXPECT_EQ(contentLabel(out, 0), "Final image");
    EXPECT_EQ(contentLabel(out, 1), "Airlight L_air");
    EXPECT_EQ(contentId(out, 4), "t.distance");
    EXPECT_EQ(contentLabel(out, 3), "Spot shadow map 1");
    EXPECT_EQ(contentIndexOf(out, "final"), 0);
    EXPECT_EQ(contentIndexOf(out, "airlight"), 1);
    EXPECT_EQ(contentIndexOf(out, "t.shadow_map"), 2) << "the first of a repeated id";
    EXPECT_EQ(contentIndexOf(out, "t.distance"), 4);
    EXPECT_EQ(contentIndexOf(out, "t.nothing"), -1);
    EXPECT_EQ(contentCount(viz::FrameOutput{}), 2);
}

TEST(ViewContents, AViewTheRunDidNotMakeSaysWhy) {
    const auto t = viz::makeTechnique("raymarch");
    viz::FrameOutput out;
    out.lastStageRun = 1;  // stopped after the camera view
    EXPECT_EQ(notMadeBecause(*t, out, "minmax.tree"), "chosen: minmax.tree, not a view of raymarch");
    EXPECT_EQ(notMadeBecause(*t, out, "raymarch.lit_fraction"),
              "chosen: raymarch.lit_fraction, made by Ray march, after where the run stops");
    out.lastStageRun = 3;
    out.plan.stages.resize(4);
    out.plan.stages[2].runs = false;
    out.plan.stages[2].why = "sigma_s = 0: no airlight";
    EXPECT_EQ(notMadeBecause(*t, out, "raymarch.airlight"),
              "chosen: raymarch.airlight, not made: Ray march skipped (sigma_s = 0: no airlight)");
    out.plan.stages[2].runs = true;
    EXPECT_EQ(notMadeBecause(*t, out, "raymarch.lit_fraction"), "chosen: raymarch.lit_fraction, not made with these settings");
    // A numbered shadow map is its stage's too.
    out.lastStageRun = -1;
    EXPECT_EQ(notMadeBecause(*t, out, "raymarch.shadow_map.3"),
              "chosen: raymarch.shadow_map.3, made by Shadow maps, after where the run stops");
}

}  // namespace
}  // namespace airlight
