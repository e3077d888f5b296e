// The interface every technique implements (reference, raymarch, slices, polyvol, minmax, vsv, ivsv).
// A technique declares ordered stages; each stage publishes named intermediates. run() starts at stage 0
// (or, when its caller vouches that the earlier stages' inputs did not change, at FrameInput::
// resumeAtStage, republishing what they published last time: debug/stage_reuse.h) and stops after the
// requested stage, at the stepping cursor's sub-step.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/intermediate.h"
#include "debug/params.h"
#include "debug/plan.h"
#include "debug/timing.h"
#include "scene/scene.h"

namespace viz {

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
    // Its outputs stay in the technique instance between runs (its own textures, which no later stage
    // writes), so a run resuming after it (FrameInput::resumeAtStage) republishes them instead of running
    // it (debug/stage_runner.h). A stage that leaves its results in locals of run() cannot.
    bool keepsOutputs = false;
    // The listed sub-steps are a maximum: a run counts its own (FrameOutput::substepCounts), which can be
    // fewer (minmax's walk has as many nodes as the picked ray visits). Until the stage has run, a
    // timeline says "up to" the listed count.
    bool substepsPerRun = false;
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

// A technique's table of stiff bounds by case class, looked up: the bound, or none.
std::optional<StiffBound> boundOf(const std::map<std::string, StiffBound>& bounds, const std::string& caseClass);

// settings[name], or `fallback` where the settings do not hold it.
inline double settingOr(const Settings& settings, const std::string& name, double fallback) {
    const auto it = settings.find(name);
    return it == settings.end() ? fallback : it->second;
}

// One stabilising option (Technique::stabilisingOptions): `off` and `on` differ in the option alone.
struct StabilisingOption {
    std::string name;  // "plane_grid=world"
    std::string what;  // what moves without it, in a few words
    Settings off, on;
};

struct FrameInput {
    const scene::Scene* scene = nullptr;
    int width = 0;
    int height = 0;
    Settings settings;          // already validated and completed with defaults, less the controls
    FrameControls controls{};   // the picked pixel, orbit camera and clock (setRunSettings fills both)
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
    bool shows(const std::string& id) const { return std::find(views.begin(), views.end(), id) != views.end(); }
    // Frame index along an animation (a motion path's frame i, the window's animation counter); 0 for a
    // still. Read only by options whose noise changes from frame to frame (raymarch jitter_time=per-frame,
    // ivsv subsets=per-frame); every other output is a function of the scene and the settings alone.
    int frame = 0;
    // Whether the caller reads FrameOutput::airlight and ::final (CPU images). A caller that uses the
    // technique's textures alone (vsv's and ivsv's inner runs for each other's lights) asks for none and
    // a GPU technique then saves two read-backs per frame; the intermediates are published either way.
    bool readBack = true;
    // The caller's clock for the stages, instead of the technique's own (null): the window's gl::GpuTimer
    // on a GPU, whose records carry the latest time known for each stage rather than waiting for it.
    StageTimer* timer = nullptr;
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
    // Stages whose number of sub-steps depends on the run, not on the settings alone (minmax's walk: the
    // picked ray's nodes): stage index -> this run's count, at most what substepValues lists. A stage not
    // in it has the listed count.
    std::map<int, int> substepCounts;
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
    // The points the sweep adds on a scene with an area light: more virtual point lights per emitter
    // (the shared `area_samples`, or ivsv's own `vpls`), each count at the defaults and, where another
    // knob sets how finely each VPL's ray is integrated, at one other value of it
    // (SceneViewPasses::areaSampleSweep), so that the front reaches below the error the default VPL count
    // leaves near the emitter. Empty: no VPL count to add (vsv hands an area light to an inner ivsv at
    // its defaults).
    virtual std::vector<QualitySetting> areaLightSweep(bool quick) const {
        (void)quick;
        return {};
    }
    // What `airlight report` and `bench` set beneath every setting they time: the debugger's own
    // recordings off (slices' ray_planes), which the window wants on and a measurement of the technique's
    // cost must not count. A setting that names one of these keeps its own value.
    virtual Settings measurementSettings() const { return {}; }
    // The settings the stiff-case suite runs with (the accurate end of the technique's knobs), and the
    // bound it promises per case class. No bound: the technique does not handle that class, and then it
    // must say so in plan() and refuse (InputError) or fall back to a correct path.
    virtual Settings stiffSettings() const { return {}; }
    // The paper's own configuration where Airlight's defaults depart from it (`--preset paper`; the report
    // shows it beside the defaults). Empty: the defaults are the paper's, or there is no paper.
    virtual Settings paperSettings() const { return {}; }
    // Options that trade a little of something for less flicker under motion, each as a pair of settings
    // that differ only in it (`airlight report --temporal` measures both along each scene's path and
    // tabulates what the option buys). Only those that can matter on `scene` (ivsv's VPL subsets need an
    // area light). Empty: none.
    // Whether a run with these (complete) settings reads FrameInput::frame: its output then changes from
    // frame to frame of an animation even where nothing moves (the window re-runs it while playing).
    virtual bool readsFrame(const Settings& settings) const {
        (void)settings;
        return false;
    }
    virtual std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const {
        (void)scene;
        return {};
    }
    // The shared controls it reads (debug/params.h): the window drives these, and asks here rather than
    // looking for parameter names.
    virtual Controls controls() const { return {}; }
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

// The start of every plan: each stage, in order, running (plan() then turns off what the scene does not
// need, saying why).
Plan planEveryStage(const std::vector<StageInfo>& stages);

// Sets a run's settings from complete ones (completeSettings): the control names among them go to
// input.controls, the rest to input.settings, so a technique meets the controls only as typed fields.
void setRunSettings(FrameInput& input, Settings complete);
// A run request for the whole pipeline (or up to stage stopAfterStage) with setRunSettings's split.
FrameInput frameInput(const scene::Scene* scene, int width, int height, Settings complete, int stopAfterStage = -1);

// The picked pixel (FrameInput::controls, pickParam) in the run's image: -1 is the centre, values past the edge
// clamp to the last column or row.
glm::ivec2 pickedPixel(const FrameInput& input);

// The technique's declared parameter `name`, or null.
const ParamInfo* findParam(const Technique& technique, const std::string& name);

// Fills in defaults and rejects unknown names and out-of-range values with an InputError.
Settings completeSettings(const Technique& technique, const Settings& given);

// `given` with the technique's measurementSettings() beneath it: what `report` and `bench` time.
Settings measuredSettings(const Technique& technique, Settings given);

// The intermediates among `shown` that a stage of `technique` draws only on demand (StageInfo::onDemand),
// sorted, once each: what FrameInput::views should ask for. `everything`: all of them.
std::vector<std::string> onDemandAmong(const Technique& technique, const std::vector<std::string>& shown,
                                       bool everything = false);

// The index of the stage that publishes intermediate `id` (StageInfo::intermediates), or -1. A numbered
// sibling of a declared id is that stage's too: the shared passes publish one shadow map per light or area
// sample as `prefix.shadow_map`, `prefix.shadow_map.1`, `prefix.shadow_map.2`, ... and declare the first.
int stageOfIntermediate(const std::vector<StageInfo>& stages, const std::string& id);

}  // namespace viz
