// The stepping timeline under the view grid: every stage of the technique as a segment, its sub-steps as
// ticks inside it, the cursor marked. A click or a drag puts the cursor where the pointer is. Layout and
// hit-testing are plain functions (tested); drawing goes into the window's draw lists.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "run_scheduler.h"
#include "ui/text_renderer.h"

namespace airlight {

struct TimelineSegment {
    int stage = 0;
    std::string label;
    int substeps = 0;       // 0: the stage has none
    bool upTo = false;      // `substeps` is the listed maximum; the run will count its own
    float x0 = 0.0f, x1 = 0.0f;
};

// Segments for `technique`'s stages along [x0, x1]: a stage with sub-steps is wider (more to point at).
// `runCounts`: the last run's own sub-step counts (FrameOutput::substepCounts), where they are fewer.
std::vector<TimelineSegment> timelineSegments(const viz::Technique& technique, const viz::Settings& settings,
                                              float x0, float x1, const std::map<int, int>& runCounts = {});
// A stage's sub-steps: as substepValues lists them, or the run's own count where it is fewer.
int substepCountOf(const viz::Technique& technique, int stage, const viz::Settings& settings,
                   const std::map<int, int>& runCounts);
// The cursor under horizontal position x (clamped to the ends): the last stage whole is the complete
// frame ({-1, 0}); inside a stage with sub-steps, the sub-step under x.
StepCursor timelineCursorAt(const std::vector<TimelineSegment>& segments, float x);
// Where the cursor's mark goes.
float timelineMarkX(const std::vector<TimelineSegment>& segments, StepCursor cursor);

// Draws the timeline into `r`: segments (the current one highlighted), sub-step ticks, stage labels as
// far as they fit, and the cursor's mark.
void drawTimeline(viz::ui::DrawList& background, viz::ui::DrawList& text, const viz::ui::Rect& r,
                  const std::vector<TimelineSegment>& segments, StepCursor cursor, float scale);

}  // namespace airlight
