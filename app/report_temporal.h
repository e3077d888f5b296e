// `airlight report --temporal`: each scene's settings rendered on every frame of a motion path, with the
// reference on the same frames (from its on-disk cache, keyed by scene content, camera and light pose,
// size and settings), scored by report/temporal_error.h; flicker heat maps and the temporal plot.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "debug/technique.h"
#include "report/report_table.h"
#include "scene/motion_path.h"
#include "scene/scene.h"
#include "ui/font.h"

namespace airlight {

constexpr int kTemporalFrames = 12;       // frames per path by default
constexpr int kQuickTemporalFrames = 6;   // with --quick
constexpr int kMaxTemporalFrames = 240;

// The path a scene moves along when --path is not given: a light sweep of +-10 degrees where the first
// light can move (a sun's shafts sweep through the colonnade's windows and between the forest's trunks),
// a camera orbit of 10 degrees where it cannot (tv-room's area light) and on grate (whose spot hangs on the
// vertical axis: the orbit turns minmax's epipolar slices and moves the slice planes across the shadows).
std::string defaultMotionPath(const std::string& sceneName, const viz::scene::Scene& scene);

// Which settings the path renders: every sweep setting and paper preset; with --quick only each
// technique's first sweep setting (its cheapest, the one the plan savings time too): the paper presets
// (polyvol's adaptive 1024 map above all) would take the quick report past its 3-minute budget.
bool measuredAlongPath(bool quick, bool paperPreset, int indexInSeries);

struct TemporalJob {
    std::size_t row = 0;          // index into the report's rows
    std::string technique;        // technique id
    viz::Settings settings;       // complete
};

// Every pose first (a path that cannot move the scene throws InputError), then the reference on every
// frame, then each job on every frame after one warm-up run on frame 0: fills rows[job.row].temporal and
// writes its flicker heat map into `dir` (stem-series-setting-flicker.png, scaled like the error maps by
// `exposure` * 10). `step` is called before each frame of the reference and before each job.
void runTemporal(const viz::scene::Scene& scene, const viz::scene::MotionPath& path, int frames, int width,
                 int height, const viz::Settings& referenceSettings, const std::vector<TemporalJob>& jobs,
                 std::vector<viz::report::ReportRow>& rows, const std::filesystem::path& dir, const std::string& stem,
                 float exposure, const std::function<void(const std::string&)>& step);

// Temporal RMS against time per frame for one scene, one series per technique (its front joined), the
// scene's front over all techniques ringed; written as a PNG like the error-against-time plot.
void writeTemporalPlot(const viz::ui::FontAtlas& font, const std::vector<viz::report::ReportRow>& rows,
                       const viz::report::ScenePage& page, const std::vector<std::string>& techniques, int width,
                       int height, const std::filesystem::path& file);

}  // namespace airlight
