// Each technique's stabilising options (Technique::stabilisingOptions) lower its temporal RMS
// (report/temporal_error.h) along a motion path, against the reference rendered on the same frames: the
// direction the report's "Stabilising options" table measures at full size, here on a small case. And the
// frame index (FrameInput::frame) changes a still frame only where an option asks for per-frame noise.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "gl/technique_test_util.h"
#include "report/temporal_error.h"
#include "scene/builtin_scenes.h"
#include "scene/motion_path.h"

namespace viz::testing {
namespace {

class StabilisingOptions : public TechniqueTest {};

std::string settingsSummary(const Settings& s) {
    std::string text;
    for (const auto& [name, value] : s) text += name + "=" + std::to_string(value) + " ";
    return text;
}

struct StabilisingCase {
    std::string technique, option, scene, path;
};

// Temporal RMS of `settings` along the path, frame i rendered with FrameInput::frame = i.
double temporalRms(const std::string& technique, const Settings& settings, const scene::Scene& base,
                   const std::vector<scene::Pose>& poses, const std::vector<Image>& reference, int w, int h) {
    auto t = makeTechnique(technique);
    scene::Scene moving = base;
    report::TemporalAccumulator accumulator;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        scene::applyPose(poses[i], moving);
        const FrameOutput out = runTechnique(*t, moving, settings, w, h, -1, int(i));
        accumulator.add(out.airlight, reference[i]);
    }
    return accumulator.finish().temporalRms;
}

TEST_F(StabilisingOptions, EachLowersItsTechniquesTemporalError) {
    constexpr int kW = 80, kH = 60, kFrames = 6;
    // Scenes and paths where each option's motion shows: a spot light (grate) turned about by the camera,
    // the sun moving over colonnade, tv-room's area light seen from an orbiting camera.
    std::vector<StabilisingCase> cases = {
        {"raymarch", "jitter_time=constant (white)", "grate", "camera-orbit:10deg"},
        {"raymarch", "jitter_time=constant (blue)", "grate", "camera-orbit:10deg"},
        {"slices", "plane_grid=world", "grate", "camera-orbit:10deg"},
        {"minmax", "slice_frame=fixed", "colonnade", "light-sweep:10deg"},
        {"ivsv", "subsets=fixed", "tv-room", "camera-orbit:10deg"},
    };
    std::map<std::string, std::vector<Image>> references;
    for (const StabilisingCase& c : cases) {
        SCOPED_TRACE(c.technique + " " + c.option + " on " + c.scene);
        const scene::Scene base = scene::makeBuiltinScene(c.scene);
        const scene::MotionPath path = scene::parseMotionPath(c.path);
        std::vector<scene::Pose> poses;
        for (int i = 0; i < kFrames; ++i) poses.push_back(scene::poseAt(path, base, i, kFrames));
        // The reference frames, once per scene and path. tv-room's area light with 2 x 2 cells: against 4 x 4
        // its temporal RMS moved from 0.1026 -> 0.0773 to 0.1027 -> 0.0776, and the test from 57 s to 39 s.
        std::vector<Image>& reference = references[c.scene + " " + c.path];
        if (reference.empty()) {
            auto t = makeTechnique("reference");
            scene::Scene moving = base;
            for (const scene::Pose& pose : poses) {
                scene::applyPose(pose, moving);
                reference.push_back(runTechnique(*t, moving, {{"area_samples", 2}}, kW, kH).airlight);
            }
        }
        const auto options = makeTechnique(c.technique)->stabilisingOptions(base);
        const auto it = std::find_if(options.begin(), options.end(), [&](const StabilisingOption& o) { return o.name == c.option; });
        ASSERT_NE(it, options.end()) << "no such option";
        const double off = temporalRms(c.technique, it->off, base, poses, reference, kW, kH);
        const double on = temporalRms(c.technique, it->on, base, poses, reference, kW, kH);
        std::printf("%-8s %-30s %-10s %-20s temporal RMS %.4g -> %.4g (%.2fx)\n", c.technique.c_str(), c.option.c_str(),
                    c.scene.c_str(), c.path.c_str(), off, on, off / on);
        EXPECT_LT(on, off);
    }
}

TEST_F(StabilisingOptions, OnlyPerFrameNoiseReadsTheFrameIndex) {
    const scene::Scene scene = scene::makeBuiltinScene("grate");
    struct Variant {
        std::string technique;
        Settings settings;
        bool perFrame;
    };
    const std::vector<Variant> variants = {
        {"raymarch", {{"samples", 8}, {"jitter", 1}, {"jitter_time", 0}}, false},
        {"raymarch", {{"samples", 8}, {"jitter", 1}, {"jitter_time", 1}}, true},
        {"raymarch", {{"samples", 8}, {"jitter", 2}, {"jitter_time", 0}}, false},
        {"raymarch", {{"samples", 8}, {"jitter", 2}, {"jitter_time", 1}}, true},
        {"slices", {{"planes", 32}, {"plane_grid", 1}}, false},
        {"minmax", {{"slice_frame", 1}}, false},
    };
    for (const Variant& v : variants) {
        auto t = makeTechnique(v.technique);
        const Image a = runTechnique(*t, scene, v.settings, 48, 36, -1, 0).airlight;
        const Image b = runTechnique(*t, scene, v.settings, 48, 36, -1, 3).airlight;
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_EQ(a.pixels != b.pixels, v.perFrame) << v.technique << " " << settingsSummary(v.settings);
    }
}

}  // namespace
}  // namespace viz::testing
