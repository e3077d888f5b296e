#include "step_timeline.h"

#include <algorithm>
#include <cmath>

#include "ui/theme.h"

namespace airlight {

namespace {
using viz::ui::theme::kLabel;
using viz::ui::theme::kSegment;
using viz::ui::theme::kTick;
constexpr glm::vec4 kCurrent = viz::ui::theme::kHighlight;
constexpr glm::vec4 kMark = viz::ui::theme::kAccent;

int lastStage(const std::vector<TimelineSegment>& segments) { return segments.empty() ? -1 : segments.back().stage; }
}  // namespace

int substepCountOf(const viz::Technique& technique, int stage, const viz::Settings& settings,
                   const std::map<int, int>& runCounts) {
    const int listed = int(technique.substepValues(stage, settings).size());
    const auto it = runCounts.find(stage);
    return listed > 0 && it != runCounts.end() ? std::clamp(it->second, 1, listed) : listed;
}

std::vector<TimelineSegment> timelineSegments(const viz::Technique& technique, const viz::Settings& settings,
                                              float x0, float x1, const std::map<int, int>& runCounts) {
    std::vector<TimelineSegment> segments;
    const auto& stages = technique.stages();
    float total = 0.0f;
    std::vector<float> weight;
    for (int k = 0; k < int(stages.size()); ++k) {
        TimelineSegment s;
        s.stage = k;
        s.label = stages[std::size_t(k)].label;
        s.substeps = substepCountOf(technique, k, settings, runCounts);
        s.upTo = stages[std::size_t(k)].substepsPerRun && s.substeps > 1 && !runCounts.count(k);
        weight.push_back(s.substeps > 1 ? 2.0f : 1.0f);
        total += weight.back();
        segments.push_back(s);
    }
    float x = x0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        segments[i].x0 = x;
        x += (x1 - x0) * weight[i] / std::max(total, 1.0f);
        segments[i].x1 = x;
    }
    return segments;
}

StepCursor timelineCursorAt(const std::vector<TimelineSegment>& segments, float x) {
    if (segments.empty()) return {};
    x = std::clamp(x, segments.front().x0, segments.back().x1);
    for (const TimelineSegment& s : segments) {
        if (x > s.x1 && &s != &segments.back()) continue;
        const bool last = s.stage == lastStage(segments);
        if (s.substeps <= 1) return last ? StepCursor{} : StepCursor{s.stage, 0};
        const float f = (x - s.x0) / std::max(s.x1 - s.x0, 1e-6f);
        const int k = std::clamp(int(std::floor(f * float(s.substeps))) + 1, 1, s.substeps);
        return {s.stage, k};
    }
    return {};
}

float timelineMarkX(const std::vector<TimelineSegment>& segments, StepCursor cursor) {
    if (segments.empty()) return 0.0f;
    const int stage = cursor.stage < 0 ? lastStage(segments) : cursor.stage;
    for (const TimelineSegment& s : segments) {
        if (s.stage != stage) continue;
        if (s.substeps <= 1) return s.x1;
        const int k = cursor.substep <= 0 ? s.substeps : std::min(cursor.substep, s.substeps);
        return s.x0 + (s.x1 - s.x0) * (float(k) - 0.5f) / float(s.substeps);
    }
    return segments.back().x1;
}

void drawTimeline(viz::ui::DrawList& background, viz::ui::DrawList& text, const viz::ui::Rect& r,
                  const std::vector<TimelineSegment>& segments, StepCursor cursor, float scale) {
    const int current = cursor.stage < 0 ? lastStage(segments) : cursor.stage;
    for (const TimelineSegment& s : segments) {
        const viz::ui::Rect box{{s.x0 + 1.0f * scale, r.min.y}, {s.x1 - 1.0f * scale, r.max.y}};
        background.rect(box, s.stage == current ? kCurrent : kSegment);
        // Ticks: every sub-step while they are at least 3 px apart, else every n-th.
        if (s.substeps > 1) {
            const float w = (s.x1 - s.x0) / float(s.substeps);
            const int every = std::max(1, int(std::ceil(3.0f * scale / std::max(w, 1e-3f))));
            for (int k = every; k < s.substeps; k += every) {
                const float x = s.x0 + w * float(k);
                text.line({x, r.max.y - 4.0f * scale}, {x, r.max.y}, 1.0f, kTick);
            }
        }
        std::string label = std::to_string(s.stage + 1) + " " + s.label;
        if (s.substeps > 1) label += (s.upTo ? " (up to " : " (") + std::to_string(s.substeps) + ")";
        text.textClipped({box.min.x + 3.0f * scale, r.min.y + 1.0f * scale}, label, kLabel, box.max.x - 2.0f * scale);
    }
    const float x = timelineMarkX(segments, cursor);
    text.line({x, r.min.y - 2.0f * scale}, {x, r.max.y + 2.0f * scale}, 3.0f * scale, kMark);
}

}  // namespace airlight
