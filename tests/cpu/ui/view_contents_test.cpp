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

// What a view shows of a run, on raymarch's declared stages: the chosen content, the right one of a
// repeated id, L_air with a note for a view the run did not make, and for a run stopped before L_air exists
// what the stage published, an intermediate no other view shows first; and before the final frame, L_air
// in a final-frame view only where no other view shows it.
TEST(ViewContents, AViewShowsItsChoiceOrSaysWhyAndAStoppedRunFillsTheGridWithItsStagesViews) {
    const auto t = viz::makeTechnique("raymarch");
    const auto& stages = t->stages();
    // A complete run: final and L_air present.
    viz::FrameOutput out = runWith({{"raymarch.shadow_map", "Spot shadow map"}, {"raymarch.shadow_map", "Spot shadow map 1"},
                                    {"raymarch.distance", "Distance d"}});
    out.final = viz::Image(2, 2, 3);
    out.airlight = viz::Image(2, 2, 3);
    out.lastStageRun = int(stages.size()) - 1;
    ShownContent c = shownContent(*t, out, "raymarch.shadow_map", 1, {});
    EXPECT_EQ(c.content, "raymarch.shadow_map");
    EXPECT_EQ(c.index, 1) << "the second light's map stays the second";
    EXPECT_EQ(c.standIn, "");
    c = shownContent(*t, out, "raymarch.shadow_map", 2, {});
    EXPECT_EQ(c.index, 0) << "position 2 holds another id now: the first map";
    c = shownContent(*t, out, "final", 5, {});
    EXPECT_EQ(c.content, "final");
    EXPECT_EQ(c.index, -1);
    c = shownContent(*t, out, "minmax.tree", -1, {});
    EXPECT_EQ(c.content, "airlight");
    EXPECT_EQ(c.index, -1);
    EXPECT_EQ(c.standIn, "chosen: minmax.tree, not a view of raymarch");

    // Stopped after the first stage: no final frame, no L_air; the stage's two declared views.
    ASSERT_GE(stages[0].intermediates.size(), 1u);
    const std::string first = stages[0].intermediates[0];
    viz::FrameOutput stopped;
    for (const char* label : {"map 0", "map 1"}) {
        viz::Intermediate i;
        i.id = first;
        i.label = label;
        stopped.intermediates.push_back(i);
    }
    viz::Intermediate unrelated;
    unrelated.id = "raymarch.not_declared_by_stage_0";
    stopped.intermediates.insert(stopped.intermediates.begin(), unrelated);
    stopped.lastStageRun = 0;
    // An L_air view shows the stage's first view; with that shown elsewhere, the next one.
    c = shownContent(*t, stopped, "airlight", -1, {});
    EXPECT_EQ(c.content, first);
    EXPECT_EQ(c.index, 1) << "the first intermediate stage 0 declares, not the one before it";
    c = shownContent(*t, stopped, "airlight", -1, {"final", first});
    EXPECT_EQ(c.index, 1) << "every declared view is shown elsewhere under this id: the first again";
    // A final-frame view beside an L_air view leaves the first to it and shows another of the stage's.
    c = shownContent(*t, stopped, "final", -1, {"airlight"});
    EXPECT_EQ(c.content, first);
    EXPECT_EQ(c.index, 2);
    c = shownContent(*t, stopped, "final", -1, {});
    EXPECT_EQ(c.index, 1) << "no L_air view elsewhere: the final-frame view takes the first";
    // A chosen view after the stop stands in with the stage's view and says why.
    c = shownContent(*t, stopped, "raymarch.lit_fraction", -1, {});
    EXPECT_EQ(c.content, first);
    EXPECT_NE(c.standIn.find("after where the run stops"), std::string::npos) << c.standIn;

    // Stopped in a stage that has made L_air but no final frame yet: a final-frame view shows L_air, unless
    // an L_air view is beside it; then the stage's first view (not the same image twice).
    viz::FrameOutput partial = stopped;
    partial.airlight = viz::Image(2, 2, 3);
    c = shownContent(*t, partial, "final", -1, {});
    EXPECT_EQ(c.content, "airlight");
    c = shownContent(*t, partial, "final", -1, {"airlight"});
    EXPECT_EQ(c.content, first);
    EXPECT_EQ(c.index, 1) << "the L_air view shows L_air itself: the final-frame view takes the stage's first view";
    c = shownContent(*t, partial, "airlight", -1, {"final"});
    EXPECT_EQ(c.content, "airlight") << "the L_air view keeps L_air";
}

}  // namespace
}  // namespace airlight
