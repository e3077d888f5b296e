// The interface every technique implements (reference, raymarch, slices, polyvol, minmax, vsv, ivsv).
// A technique declares ordered stages; each stage publishes named intermediates. run() starts at stage 0
// (or, when its caller vouches that the earlier stages' inputs did not change, at FrameInput::
// resumeAtStage, republishing what they published last time: debug/stage_reuse.h) and stops after the
// requested stage, at the stepping cursor's sub-step.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "debug/timing.h"
#include "scene/scene.h"

namespace viz {

// How an intermediate is best shown.
enum class ViewKind { Color, Scalar, Signed, BitField, Mask, Depth, Mesh, Buffer };
const char* viewKindName(ViewKind kind);

struct ParamInfo {
    std::string name;  // "samples", "jitter", "shadow_map", ...
    std::string help;  // one line
    double defaultValue = 0.0;
    double minValue = 0.0;
    double maxValue = 0.0;
    bool integer = true;
    // Named values: choices[i] stands for the value i (e.g. weighting=physical); empty for plain numbers.
    std::vector<std::string> choices{};
    // A per-axis form: `name=AxBxC` sets these parameters in order (e.g. voxels -> voxels_alpha,
    // voxels_theta, voxels_phi); empty when the parameter takes one number only.
    std::vector<std::string> components{};
};

struct StageInfo {
    std::string id;                          // "raymarch.march": stable, used by lessons and tests
    std::string label;                       // "Ray march"
    std::string purpose;                     // one line
    std::vector<std::string> params;         // names of the ParamInfo this stage reads
    std::vector<std::string> intermediates;  // ids of what it publishes
    int substeps = 1;
    // Stepping inside the stage: the parameter that stops it after sub-step k (planes drawn, mipmap
    // levels, scan passes, VPLs, ...; 0 or -1 = all, as its ParamInfo says), and the parameter whose
    // value is the number of sub-steps when that depends on the settings (else `substeps`).
    std::string substepParam{};
    std::string substepCountParam{};
    // Intermediates the stage draws only for a caller that shows them (FrameInput::views), beyond what
    // its settings ask for: polyvol's orbit view of its light volume mesh, say. Drawing one costs time
    // inside the stage, so a caller that does not show it (the report) does not pay for it.
    std::vector<std::string> onDemand{};
};

// A plot a technique publishes with an intermediate (singular values, basis functions, per-plane values
// along a ray, ...): the window draws it with axes, ticks and a legend (viz/plot) in place of the
// intermediate's image, which stays what `airlight render --layer` writes.
struct PlotCurve {
    std::string name;                // legend entry
    std::vector<glm::dvec2> points;  // data units, drawn in order
    bool lines = true, markers = false;
    int colour = -1;                 // index into the categorical palette; -1: the curve's own index
};
struct PlotData {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<PlotCurve> curves;
};

// A value an intermediate stores to mean "nothing here" rather than a measurement (minmax's -1 outside
// the spot's cone, vsv's -1 for "no occluder", 0 for a hole in an ISM): the window shows it in the
// sentinel hatch with its meaning in the colour bar's legend, and leaves it out of the value range, the
// histogram and the NaN / Inf / negative counts. It applies to every channel of the intermediate.
struct Sentinel {
    float value = 0.0f;
    std::string meaning;  // "outside the spot's cone"
};

// One quantity of an intermediate that packs several into its channels (polyvol's crossings: faces
// crossed, signed count, clamped faces): the window shows one channel at a time, picked by name, with
// its own units, range and colour map.
struct ChannelInfo {
    std::string name;   // "faces crossed"
    std::string units;  // "count"
    ViewKind kind = ViewKind::Scalar;
    float rangeMin = 0.0f, rangeMax = 1.0f;
};

// A published intermediate: either a CPU image or a GL texture owned by the technique (valid until the
// next run()). Meshes and buffers carry a GL name and a short description of their layout.
struct Intermediate {
    std::string id;       // "raymarch.shadow_map"
    std::string label;    // "Shadow map"
    std::string note;     // one-line explanation
    std::string units;    // "scene units", "W/(m^2 sr)", ...
    ViewKind kind = ViewKind::Scalar;
    float rangeMin = 0.0f, rangeMax = 1.0f;  // suggested display range
    std::shared_ptr<const Image> image;      // CPU storage, or
    unsigned glTexture = 0;                  // GL texture name (GL_TEXTURE_2D, or a cube map/array: layers)
    unsigned glTarget = 0;
    glm::ivec3 extent{0};
    // An orbit view (render::MeshView): the window turns it by dragging (the technique's mesh_yaw and
    // mesh_pitch parameters).
    bool orbit = false;
    // Plots of the same data, stacked top to bottom in the window's view (empty: the image is shown).
    std::vector<PlotData> plots{};
    // Shows the picked pixel's ray (the technique's pick_x / pick_y): a walk, a voxel column, per-VPL
    // terms, the planes along it. The ray inspector lists these by id.
    bool rayView = false;
    std::vector<Sentinel> sentinels{};
    // A picture the technique draws (a chart, an orbit view, a schematic): its colours are explained in
    // its note, not by a colour map, and the window's colour bar says so.
    bool picture = false;
    // Empty: the channels are one quantity (a colour, or a scalar in r). Else channel i (r, g, b, a) is
    // channels[i]; the window starts on the first.
    std::vector<ChannelInfo> channels{};
};

using Settings = std::map<std::string, double>;

// A mark a technique can draw in one of its algorithm-space intermediates for a screen pixel (the
// window's linked cursors: the epipolar row of the pixel in a rectified map, say). A segment from
// `from` to `to` (equal: a point) in the intermediate's data uv: [0,1]^2 over its columns and its rows
// as stored (row 0 = the first row; a GL texture, and each layer of a GL array or cube map, shows it at
// the bottom).
struct ViewMarker {
    glm::vec2 from{0.0f}, to{0.0f};
    std::string label;  // short, e.g. "slice 37"
    // The layer (array layer, cube face 0..5 = +X -X +Y -Y +Z -Z) the mark belongs to; -1: every layer.
    int layer = -1;
};

// Which stages run for a scene and settings, and for each one left out, why.
struct StagePlan {
    std::string stage;
    bool runs = true;
    std::string why;  // for a skipped stage: the reason; for a running one: optional detail
};
struct FeaturePlan {
    std::string feature;  // shader feature / code path, e.g. "SPOT_FALLOFF"
    bool enabled = true;
    std::string why;
};
struct Plan {
    std::vector<StagePlan> stages;
    std::vector<FeaturePlan> features;
};

// One point of a technique's quality sweep (`airlight report`): a short label and the settings that
// differ from the defaults.
struct QualitySetting {
    std::string label;  // "N=64", "planes=128 rgba8"
    Settings settings;
};

// What a technique promises for one class of stiff case (viz/report/stiff_suite.h): its relative L2
// error against the reference stays below `relativeL2` at its stiffSettings(), for the reason given.
struct StiffBound {
    double relativeL2 = 0.0;
    std::string why;
};

struct FrameInput {
    const scene::Scene* scene = nullptr;
    int width = 0;
    int height = 0;
    Settings settings;          // already validated and completed with defaults
    int stopAfterStage = -1;    // index into stages(); -1 = run everything
    // The stepping cursor's sub-step inside stage stopAfterStage: 1 .. the count substepValues() lists
    // for it (the last runs the stage whole); 0 runs the stage whole. It is not a setting: a stage's
    // sub-step parameter in `settings` (the CLI's --set planes_drawn=7) applies only where the cursor
    // does not step that stage (Technique::substepLimit).
    int substep = 0;
    // Stage-level reuse (app/run_scheduler.h): the caller vouches that stages before resumeAtStage would
    // compute what this instance's previous run computed for them (same scene, camera, size and every
    // parameter they read, StageInfo::params), so the technique may keep their results and skip them.
    // substepOnly: stage resumeAtStage itself differs only in the cursor's sub-step (it may then redo only
    // what the sub-step changes). A technique is free to ignore both; FrameOutput::firstStageRun says
    // what it did.
    int resumeAtStage = 0;
    bool substepOnly = false;
    // The on-demand intermediates (StageInfo::onDemand) the caller will show.
    std::vector<std::string> views{};
};

struct FrameOutput {
    Image airlight;             // RGB float, L_air alone (empty if the run stopped before it exists)
    Image final;                // RGB float, surface * exp(-sigma_t d) + L_air
    std::vector<Intermediate> intermediates;
    Timing timing;
    Plan plan;
    // What the run found that plan() could not know (it depends on the image size or the frame): a
    // promise a setting makes that this frame does not keep, with the figure. `render` prints each as a
    // note; the window shows the first in its header.
    std::vector<std::string> notes;
    int lastStageRun = -1;
    // The first stage this run computed (> 0: the earlier ones were carried over from the previous run
    // of the same instance, FrameInput::resumeAtStage; timing lists only the stages that ran).
    int firstStageRun = 0;
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual std::string id() const = 0;
    virtual std::string description() const = 0;        // one line
    virtual const std::vector<StageInfo>& stages() const = 0;
    virtual const std::vector<ParamInfo>& params() const = 0;
    virtual bool needsGl() const = 0;                   // GPU techniques need a current GL 4.5 context
    virtual Plan plan(const scene::Scene& scene, const Settings& settings) const = 0;
    virtual FrameOutput run(const FrameInput& input) = 0;
    // The quality knobs `airlight report` sweeps, cheapest first; `quick` asks for a short sweep that
    // still spans the technique's error range. A technique without knobs reports its defaults.
    virtual std::vector<QualitySetting> qualitySweep(bool quick) const {
        (void)quick;
        return {{"default", {}}};
    }
    // The settings the stiff-case suite runs with (the accurate end of the technique's knobs), and the
    // bound it promises per case class. No bound: the technique does not handle that class, and then it
    // must say so in plan() and refuse (InputError) or fall back to a correct path.
    virtual Settings stiffSettings() const { return {}; }
    // The paper's own configuration where Airlight's defaults depart from it (`--preset paper`; the report
    // shows it beside the defaults). Empty: the defaults are the paper's, or there is no paper.
    virtual Settings paperSettings() const { return {}; }
    // Marks for the screen pixel `pixel` (column, row 0 at the top, of the last run's frame) in the
    // intermediate `intermediateId` of the last run; empty when the technique cannot map it there. GPU
    // techniques may read their textures (the GL context is current).
    virtual std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& intermediateId) const {
        (void)pixel;
        (void)intermediateId;
        return {};
    }
    virtual std::optional<StiffBound> stiffBound(const std::string& caseClass) const {
        (void)caseClass;
        return std::nullopt;
    }
    // Stepping inside stage `stage` (its StageInfo::substepParam): the parameter's value for each
    // sub-step in order, the last one running the stage whole. Empty: no sub-steps with these (complete)
    // settings. The default gives 1 .. count - 1 and then the parameter's default ("all"), count being
    // the value of StageInfo::substepCountParam or else StageInfo::substeps. Techniques whose count or
    // order depends on the scene-independent settings in another way (levels from a map size, passes
    // from a grid size, coarse to fine) override it.
    virtual std::vector<double> substepValues(int stage, const Settings& settings) const;
    // The value of stage `stage`'s sub-step parameter for this run: the cursor's (substepValues at
    // input.substep) when the run stops inside that stage with a sub-step, else the settings' value.
    double substepLimit(const FrameInput& input, int stage) const;
};

// Where stepping inside a stage stands: sub-step `at` of `count` (1-based; `count` when the stage runs
// whole). {0, 0}: the stage has no sub-steps.
struct SubstepPosition {
    int at = 0;
    int count = 0;
};
SubstepPosition substepPosition(const Technique& technique, int stage, const Settings& settings);
// Sets the stage's sub-step parameter in `settings` for sub-step `k` (clamped to 1 .. count; count runs
// the stage whole). Returns false (and changes nothing) when the stage has no sub-steps.
bool setSubstep(const Technique& technique, int stage, Settings& settings, int k);

// Fills in defaults and rejects unknown names and out-of-range values with an InputError.
Settings completeSettings(const Technique& technique, const Settings& given);

// "name=value" as a user writes it in --set and lessons: a named value by its name (integrand=svd,
// accum=rgba8), any other value as a number (%g). Unknown names and out-of-range indices stay numbers.
std::string settingText(const std::vector<ParamInfo>& params, const std::string& name, double value);

// The intermediates among `shown` that a stage of `technique` draws only on demand (StageInfo::onDemand),
// sorted, once each: what FrameInput::views should ask for. `everything`: all of them.
std::vector<std::string> onDemandAmong(const Technique& technique, const std::vector<std::string>& shown,
                                       bool everything = false);

// The `force_features` parameter every technique that prunes by scene offers: 1 runs every stage and
// compiles in every feature its plan would leave out for the scene, so `airlight report` can measure
// what each plan saves. The image must not change.
ParamInfo forceFeaturesParam();
// With force = true, turns every skipped stage on and every listed scene-pruned feature on, keeping
// the reason it would have been skipped in `why`. Features chosen by settings are not touched.
void forcePlan(Plan& plan, bool force, const std::vector<std::string>& scenePrunedFeatures);

// Whether the plan lists feature `name` as enabled (false when it does not list it).
bool featureEnabled(const Plan& plan, const std::string& name);

}  // namespace viz
