// The stepping cursor's rules (app/step_cursor.h) on every registered technique, walked key by key: S from
// the complete frame visits every stage in its declared order and comes back; a stage with sub-steps is
// entered at its first; D walks them to the stage whole and no further; Home and End jump; every frame but
// the complete one says where it stopped.
#include <gtest/gtest.h>

#include "step_cursor.h"
#include "techniques/registry.h"

namespace airlight {
namespace {

const std::map<int, int> kNoRunCounts;

TEST(StepCursor, SWalksEveryStageInOrderAndWrapsToTheCompleteFrame) {
    for (const std::string& id : viz::techniqueIds()) {
        const auto t = viz::makeTechnique(id);
        const viz::Settings settings = viz::completeSettings(*t, {});
        const int n = int(t->stages().size());
        ASSERT_GE(n, 2) << id;
        StepCursor c;  // the window opens on the complete frame
        EXPECT_EQ(stageShownBy(*t, c), n - 1) << id;
        EXPECT_EQ(stoppedEarly(*t, settings, c, kNoRunCounts), "") << id;
        for (int k = 0; k < n - 1; ++k) {
            c = stageStepped(*t, settings, c, 1);
            ASSERT_EQ(c.stage, k) << id;
            EXPECT_EQ(stageShownBy(*t, c), k) << id;
            const bool hasSubsteps = !t->substepValues(k, settings).empty();
            const SubstepAt pos = substepAt(*t, settings, c, kNoRunCounts);
            EXPECT_EQ(pos.at, hasSubsteps ? 1 : 0) << id << " stage " << k << ": entered at its first sub-step";
            const std::string why = stoppedEarly(*t, settings, c, kNoRunCounts);
            EXPECT_NE(why.find(t->stages()[std::size_t(k)].id), std::string::npos) << id << ": " << why;
        }
        c = stageStepped(*t, settings, c, 1);
        EXPECT_EQ(c, StepCursor{}) << id << ": after the last stage, the complete frame";
        // Shift+S walks back the same way.
        for (int k = n - 2; k >= 0; --k) {
            c = stageStepped(*t, settings, c, -1);
            ASSERT_EQ(c.stage, k) << id;
        }
        EXPECT_EQ(stageStepped(*t, settings, c, -1), StepCursor{}) << id << ": before stage 1, the complete frame";
    }
}

TEST(StepCursor, DWalksTheSubstepsToTheStageWholeAndHomeAndEndJump) {
    int stagesWithSubsteps = 0;
    for (const std::string& id : viz::techniqueIds()) {
        const auto t = viz::makeTechnique(id);
        const viz::Settings settings = viz::completeSettings(*t, {});
        const int n = int(t->stages().size());
        for (int stage = 0; stage < n - 1; ++stage) {
            const int count = int(t->substepValues(stage, settings).size());
            StepCursor c{stage, count > 0 ? 1 : 0};
            if (count == 0) {
                const SubstepMove m = substepMovedTo(*t, settings, c, kNoRunCounts, 1);
                EXPECT_EQ(m.cursor, c) << id;
                EXPECT_NE(m.notice.find("has no sub-steps"), std::string::npos) << id << ": " << m.notice;
                continue;
            }
            ++stagesWithSubsteps;
            // Shift+D at the first says so and stays.
            SubstepMove m = substepMovedTo(*t, settings, c, kNoRunCounts, 0);
            EXPECT_EQ(m.cursor, c);
            EXPECT_NE(m.notice.find("already at the first"), std::string::npos) << m.notice;
            for (int k = 2; k <= count; ++k) {
                m = substepMovedTo(*t, settings, c, kNoRunCounts, substepAt(*t, settings, c, kNoRunCounts).at + 1);
                ASSERT_EQ(m.notice, "") << id << " stage " << stage << " k " << k;
                c = m.cursor;
                EXPECT_EQ(substepAt(*t, settings, c, kNoRunCounts).at, k) << id;
                EXPECT_EQ(c.stage, stage) << id;
            }
            // The last sub-step is the stage whole: no sub-step left in the cursor, nothing cut short.
            EXPECT_EQ(c, (StepCursor{stage, 0})) << id << " stage " << stage;
            EXPECT_EQ(stoppedEarly(*t, settings, c, kNoRunCounts).find("at sub-step"), std::string::npos);
            m = substepMovedTo(*t, settings, c, kNoRunCounts, count + 1);
            EXPECT_EQ(m.cursor, c);
            EXPECT_NE(m.notice.find("already at the last"), std::string::npos) << m.notice;
            // Home, then End.
            m = substepMovedTo(*t, settings, c, kNoRunCounts, 1);
            EXPECT_EQ(m.cursor, (StepCursor{stage, 1})) << id;
            if (count > 1) {
                const std::string why = stoppedEarly(*t, settings, m.cursor, kNoRunCounts);
                EXPECT_NE(why.find("at sub-step 1/" + std::to_string(count)), std::string::npos) << why;
            }
            m = substepMovedTo(*t, settings, m.cursor, kNoRunCounts, count);
            EXPECT_EQ(m.cursor, (StepCursor{stage, 0})) << id;
        }
    }
    EXPECT_GE(stagesWithSubsteps, 6) << "every technique steps at least one stage";
}

// A run that counts fewer sub-steps than listed (minmax's walk has as many nodes as the picked ray
// visits) bounds D and End by its own count.
TEST(StepCursor, ARunsOwnCountBoundsTheSubsteps) {
    const auto t = viz::makeTechnique("minmax");
    const viz::Settings settings = viz::completeSettings(*t, {});
    int stage = -1;
    for (int k = 0; k < int(t->stages().size()) && stage < 0; ++k)
        if (t->stages()[std::size_t(k)].substepsPerRun) stage = k;
    ASSERT_GE(stage, 0) << "minmax counts its walk's sub-steps per run";
    const std::map<int, int> counts{{stage, 5}};
    const StepCursor c{stage, 5};
    EXPECT_EQ(substepAt(*t, settings, c, counts).count, 5);
    const SubstepMove m = substepMovedTo(*t, settings, c, counts, 6);
    EXPECT_NE(m.notice.find("already at the last sub-step of " + t->stages()[std::size_t(stage)].id + " (5/5)"),
              std::string::npos)
        << m.notice;
}

TEST(StepCursor, OneSpellingForTheCompleteFrame) {
    const auto t = viz::makeTechnique("raymarch");
    const int n = int(t->stages().size());
    EXPECT_EQ(normalisedCursor(*t, {n - 1, 0}), StepCursor{});
    EXPECT_EQ(normalisedCursor(*t, {n + 3, 0}), StepCursor{});
    EXPECT_EQ(normalisedCursor(*t, {-1, 2}), (StepCursor{n - 1, 2}));
    EXPECT_EQ(normalisedCursor(*t, {1, 0}), (StepCursor{1, 0}));
}

// A sub-step parameter set away from its default (on the command line or in a session) cuts its stage
// short even on the complete frame, and the frame says so.
TEST(StepCursor, ASubstepParameterAwayFromItsDefaultIsNamed) {
    const auto t = viz::makeTechnique("slices");
    viz::Settings settings = viz::completeSettings(*t, {});
    settings["planes_drawn"] = 3;
    const std::string why = stoppedEarly(*t, settings, {}, kNoRunCounts);
    EXPECT_NE(why.find("planes_drawn=3 cuts slices.planes short"), std::string::npos) << why;
}

}  // namespace
}  // namespace airlight
