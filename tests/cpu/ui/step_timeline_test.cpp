// The stepping timeline's layout and hit-testing (app/step_timeline.h), on the real techniques: every
// position along it names a cursor whose mark lies back inside the same segment, the ends are the first
// stage and the complete frame, and a stage whose sub-steps a run counts says "up to" until it has run.
#include <gtest/gtest.h>

#include <cmath>

#include "step_timeline.h"
#include "techniques/registry.h"

namespace airlight {
namespace {

const TimelineSegment& segmentOf(const std::vector<TimelineSegment>& segments, int stage) {
    for (const TimelineSegment& s : segments)
        if (s.stage == stage) return s;
    ADD_FAILURE() << "no segment for stage " << stage;
    return segments.front();
}

// Exhaustive over the pixels of a 1000-wide timeline: the cursor under x, and the mark drawn for that
// cursor, fall in the same segment (inside a stage with sub-steps, the mark is on the sub-step under x);
// the cursor never goes backwards as x grows.
TEST(StepTimeline, EveryPositionMapsToACursorMarkedInsideItsSegment) {
    for (const std::string& id : viz::techniqueIds()) {
        const auto t = viz::makeTechnique(id);
        const viz::Settings settings = viz::completeSettings(*t, {});
        const auto segments = timelineSegments(*t, settings, 0.0f, 1000.0f);
        ASSERT_EQ(segments.size(), t->stages().size()) << id;
        EXPECT_FLOAT_EQ(segments.front().x0, 0.0f);
        EXPECT_NEAR(segments.back().x1, 1000.0f, 1e-3f) << id;
        EXPECT_EQ(timelineCursorAt(segments, -50.0f).stage, 0) << id << ": left of the start is stage 1";
        EXPECT_EQ(timelineCursorAt(segments, 2000.0f).stage, -1) << id << ": right of the end is the frame";
        std::pair<int, int> previous{0, 0};
        for (int px = 0; px < 1000; ++px) {
            const float x = float(px) + 0.5f;
            const StepCursor c = timelineCursorAt(segments, x);
            const int stage = c.stage < 0 ? segments.back().stage : c.stage;
            const TimelineSegment& s = segmentOf(segments, stage);
            EXPECT_TRUE(x >= s.x0 - 1e-3f && x <= s.x1 + 1e-3f) << id << " x " << x;
            const float mark = timelineMarkX(segments, c);
            EXPECT_TRUE(mark >= s.x0 - 1e-3f && mark <= s.x1 + 1e-3f) << id << " x " << x << " mark " << mark;
            const int substep = c.substep <= 0 ? s.substeps : c.substep;
            const std::pair<int, int> at{stage, substep};
            EXPECT_GE(at, previous) << id << " x " << x;
            previous = at;
            if (s.substeps > 1) {
                EXPECT_TRUE(substep >= 1 && substep <= s.substeps) << id << " x " << x;
                // The mark is the middle of the sub-step under the pointer: within half a sub-step of x.
                EXPECT_LE(std::abs(mark - x), 0.5f * (s.x1 - s.x0) / float(s.substeps) + 1e-3f) << id << " x " << x;
            }
        }
    }
}

// minmax's walk lists 2 * columns - 1 sub-steps, but a run counts the picked ray's nodes: until the
// traverse has run the timeline says "up to"; after, it shows the run's count, never more than listed.
TEST(StepTimeline, AStageWhoseRunCountsItsSubstepsSaysUpToUntilItHasRun) {
    const auto t = viz::makeTechnique("minmax");
    const viz::Settings settings = viz::completeSettings(*t, {});
    int traverse = -1;
    for (std::size_t i = 0; i < t->stages().size(); ++i)
        if (t->stages()[i].id == "minmax.traverse") traverse = int(i);
    ASSERT_GE(traverse, 0);
    const int listed = int(t->substepValues(traverse, settings).size());
    ASSERT_GT(listed, 1);

    const TimelineSegment before = segmentOf(timelineSegments(*t, settings, 0.0f, 800.0f), traverse);
    EXPECT_TRUE(before.upTo);
    EXPECT_EQ(before.substeps, listed);

    const TimelineSegment after = segmentOf(timelineSegments(*t, settings, 0.0f, 800.0f, {{traverse, 28}}), traverse);
    EXPECT_FALSE(after.upTo);
    EXPECT_EQ(after.substeps, 28);
    const TimelineSegment capped =
        segmentOf(timelineSegments(*t, settings, 0.0f, 800.0f, {{traverse, listed + 5}}), traverse);
    EXPECT_EQ(capped.substeps, listed) << "a run's count is at most what the stage lists";

    // Stages whose counts follow from the settings alone are exact: no "up to" anywhere else but polyvol's
    // refinement (a scene lit by VPLs alone has smaller cube grids than the 2D map's).
    for (const std::string& id : viz::techniqueIds()) {
        const auto other = viz::makeTechnique(id);
        for (const TimelineSegment& s : timelineSegments(*other, viz::completeSettings(*other, {}), 0.0f, 800.0f))
            if (!(id == "minmax" && s.stage == traverse) &&
                other->stages()[std::size_t(s.stage)].id != "polyvol.volume") {
                EXPECT_FALSE(s.upTo) << id << " stage " << s.stage;
            }
    }
}

}  // namespace
}  // namespace airlight
