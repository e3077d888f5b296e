#include "commands.h"
#include "input_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

#include "command_options.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/text.h"
#include "gl/work_counters.h"
#include "gui.h"
#include "lesson.h"
#include "platform/window_glfw.h"
#include "render_job.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf_writer.h"
#include "scene/motion_path.h"
#include "scene/scene_source.h"
#include "session_state.h"
#include "techniques/registry.h"

namespace airlight {

using viz::InputError;

namespace {

constexpr const char* kRenderHelp = R"(usage: airlight render --scene S --technique T --size WxH --out F.exr|F.png [options]

  --scene S          built-in scene name (see 'airlight list scenes') or a .gltf/.glb file
                     (default: the default scene)
  --technique T      technique id (see 'airlight list techniques'; default: raymarch)
  --size WxH         image size in pixels, each side 1..8192 (default: 320x240)
  --out F            output file: .exr (32-bit float, linear RGB) or .png (8-bit sRGB)
  --layer L          airlight (L_air alone), final (default), or an intermediate id
                     (see 'airlight list stages T')
  --layer-index K    array layer / cube face of an intermediate with layers (default 0)
  --set name=value   set a technique parameter (repeatable; see 'airlight list params T')
  --preset paper     start from the technique's paper configuration (--set still wins); default: ours
  --stop-after ID    stop after this stage (see 'airlight list stages T')
  --exposure X|auto  PNG only: scale applied before the sRGB encode (default: auto for colour
                     layers, the intermediate's display range otherwise)
  --quiet            print nothing on success
  --strict           exit 3 (and write nothing) when L_air or the final image has NaN, Inf or
                     negative pixels; without it they are a warning on stderr
  --no-default-light a .gltf/.glb without a light is an error (default: a spot light is added above
                     the model, with a note)
  --count-work       a counting run: every shader counts its work (shadow-map lookups and texels, ray
                     samples, closed-form segments, tree nodes, fragments, voxels; units no GPU
                     changes) and each stage's counts are printed after the timing, which then
                     means nothing; the image is the same
  --count-pixel X,Y  a counting run for pixel X,Y alone (row 0 at the top; per-pixel stages only)
)";

constexpr const char* kListHelp = R"(usage: airlight list scenes | techniques | stages T | params T
)";

constexpr const char* kPlanHelp = R"(usage: airlight plan --scene S --technique T [--set name=value]...

Prints which stages of technique T run for scene S and which shader features are compiled in,
and for each one left out, why. --no-default-light: a .gltf/.glb without a light is an error.
)";

constexpr const char* kExportHelp = R"(usage: airlight export-scene NAME OUT.gltf|OUT.glb

Writes scene NAME (a built-in name or a .gltf/.glb file) as glTF 2.0: buffers and images embedded,
lights as KHR_lights_punctual, area lights as emissive meshes, the medium in scenes[0].extras.medium.
)";

constexpr const char* kGuiHelp = R"(usage: airlight gui [--scene S] [--technique T] [--size WxH] [--set name=value]...
                    [--state FILE] [--script FILE] [--export-dir DIR] [--screenshot OUT.png [--frames N]]
                    [--lesson NAME] [--ui-scale S] [--path P [--path-frames N]]

Opens the window: the final frame beside one intermediate. Its keys are listed below.

--state FILE          load the session (scene, camera, medium, technique, parameters, view) from FILE
                      at start; F5 saves it there, F9 loads it again, and it is saved on exit. A FILE
                      that does not exist yet starts a new session; one that is not a session is an
                      error and is left untouched.
                      Without --state the file is ~/.local/state/airlight/session.json.
--script FILE         replay window actions (click NAME [FX FY], key NAME, hold NAME N, frames N,
                      screenshot PATH; one per line), then exit (after writing --screenshot if given)
--ui-scale S          text and widgets S times larger (0.5 to 4; default 1, times the display's HiDPI
                      scale) for a projector; Ctrl+= and Ctrl+- change it in the window, F11 is full screen
--path P              what P (play) moves: a motion path as 'airlight animate' takes it (camera-orbit:30deg,
                      camera-dolly:20%, light-orbit, light-sweep:20deg, several joined by commas, or a
                      keyframe .json), looping over --path-frames N frames (default 120) at 30 frames a
                      second of play, from the camera and lights as they are when play starts. Without
                      it P turns the first light about its aim point.
--export-dir DIR      where E (the intermediate view as EXR and PNG) and F12 (the window) write
                      (default airlight-exports/)
--lesson NAME         open the lesson player beside the views: lessons/NAME.md or a path to a .md file
                      (also 'airlight --lesson NAME' and 'airlight lesson NAME'). PageUp/PageDown step,
                      T try it, B back to the step, Space play/pause a step's animation. --size renders
                      every step at that size.
--screenshot OUT.png  after N frames (default 1; and once a CPU technique's result has arrived) write
                      the window to OUT.png and its views' rectangles (window pixels, origin top-left)
                      to OUT.json, then exit. Runs under xvfb-run without a monitor.
)";

void printNotes(const viz::scene::Scene& scene) {
    for (const std::string& note : scene.notes) std::fprintf(stderr, "airlight: note: %s\n", note.c_str());
}

// A counting run's work per stage: the counters that are not zero, then the whole frame's.
void printWork(const viz::FrameOutput& out, const std::optional<glm::ivec2>& pixel) {
    if (pixel)
        std::printf("work of pixel %d,%d (counting run):\n", pixel->x, pixel->y);
    else
        std::printf("work (counting run):\n");
    for (const auto& s : out.timing.stages) {
        std::printf("  %-26s", s.stage.c_str());
        bool any = false;
        for (std::size_t c = 0; c < s.work.size(); ++c) {
            if (s.work[c] == 0) continue;
            std::printf(" %s %llu", viz::gl::WorkCounters::name(int(c)), static_cast<unsigned long long>(s.work[c]));
            any = true;
        }
        std::printf(any ? "\n" : " (nothing counted)\n");
    }
    std::printf("  %-26s", "total");
    const viz::WorkCounts total = out.timing.totalWork();
    for (std::size_t c = 0; c < total.size(); ++c)
        std::printf(" %s %llu", viz::gl::WorkCounters::name(int(c)), static_cast<unsigned long long>(total[c]));
    std::printf("\n");
}

void printTiming(const viz::FrameOutput& out) {
    std::printf("timing (%s):", out.timing.clock.c_str());
    for (const auto& s : out.timing.stages) std::printf(" %s %.2f ms;", s.stage.c_str(), s.milliseconds);
    std::printf(" total %.2f ms\n", out.timing.totalMilliseconds());
}

// Colour layers: auto exposure unless given. Other intermediates: their display range, or the finite
// min..max of the data when no range was suggested.
viz::Image displayable(const viz::Image& image, const viz::Intermediate* info, const std::string& exposure,
                       float* exposureOut) {
    const bool colour = !info || info->kind == viz::ViewKind::Colour;
    if (colour) {
        *exposureOut = exposure.empty() || exposure == "auto" ? autoExposure(image)
                                                              : float(parseNumber(exposure, "--exposure"));
        if (image.channels >= 3) return image;
        return viz::toDisplay(image, 0.0f, 1.0f);
    }
    *exposureOut = 1.0f;
    float lo = info->rangeMin, hi = info->rangeMax;
    if (!(hi > lo)) {
        lo = std::numeric_limits<float>::max(), hi = -lo;
        for (float v : image.pixels)
            if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        if (!(hi > lo)) hi = lo + 1.0f;
    }
    if (info->kind == viz::ViewKind::Signed) {
        const float m = std::max(std::fabs(lo), std::fabs(hi));
        lo = -m, hi = m;
    }
    viz::Image grey = image;
    if (grey.channels > 1) {  // show the first channel of multi-channel scalar data
        viz::Image first(image.width, image.height, 1);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) first.at(x, y) = image.at(x, y, 0);
        grey = first;
    }
    return viz::toDisplay(grey, lo, hi);
}

void writeLayer(const RenderJob& job, const std::string& layer, int layerIndex, const std::string& path,
                const std::string& exposure) {
    const viz::Image image = job.layerImage(layer, layerIndex);
    if (viz::extensionOf(path) == ".png") {
        float e = 1.0f;
        const viz::Image shown = displayable(image, job.findIntermediate(layer), exposure, &e);
        viz::writeImage(shown, path, e);
    } else {
        viz::writeImage(image, path);
    }
}

}  // namespace

int runRender(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kRenderHelp, stdout);
        return 0;
    }
    CommonOptions o = parseOptions(
        args, "render", " --scene --technique --size --out --layer --layer-index --set --preset --stop-after --exposure --quiet --no-default-light --strict --count-work --count-pixel ");
    if (o.out.empty()) throw InputError("render needs --out F.exr or --out F.png");
    const std::string ext = viz::extensionOf(o.out);
    if (ext != ".exr" && ext != ".png") throw InputError("--out '" + o.out + "' must end in .exr or .png");
    const std::filesystem::path outPath(o.out);
    if (outPath.has_parent_path() && !std::filesystem::is_directory(outPath.parent_path()))
        throw InputError("--out '" + o.out + "': folder '" + outPath.parent_path().string() + "' does not exist");

    o.request.views = {o.layer};
    if (o.countPixel && (o.countPixel->x >= o.request.width || o.countPixel->y >= o.request.height))
        throw InputError("--count-pixel " + std::to_string(o.countPixel->x) + "," + std::to_string(o.countPixel->y) +
                         " lies outside the " + std::to_string(o.request.width) + "x" + std::to_string(o.request.height) +
                         " image");
    // Before the job compiles anything: every program of a counting run counts.
    viz::gl::WorkCounters::setEnabled(o.countWork);
    if (o.countPixel) viz::gl::WorkCounters::countPixel(glm::ivec2(o.countPixel->x, o.request.height - 1 - o.countPixel->y));
    RenderJob job(o.request);
    if (!o.quiet) printNotes(job.scene());
    const viz::FrameOutput& out = job.run();
    for (const std::string& note : out.notes) std::fprintf(stderr, "airlight: note: %s\n", note.c_str());
    // No image leaves silently wrong: NaN, Inf and negative pixels are counted before anything is written.
    const std::vector<std::string> bad = job.badPixelWarnings();
    for (const std::string& line : bad) std::fprintf(stderr, "airlight: warning: %s\n", line.c_str());
    if (!bad.empty() && o.strict) {
        std::fprintf(stderr, "airlight: error: --strict: bad pixels, %s not written\n", o.out.c_str());
        return 3;
    }
    writeLayer(job, o.layer, o.layerIndex, o.out, o.exposure);
    if (!o.quiet) {
        printTiming(out);
        if (o.countWork) printWork(out, o.countPixel);
        std::printf("wrote %s (%s, %dx%d)\n", o.out.c_str(), o.layer.c_str(), o.request.width, o.request.height);
    }
    return 0;
}

int runList(Args& args) {
    if (args.empty()) throw InputError("list needs what to list: scenes, techniques, stages T or params T");
    const std::string what = args.take();
    if (isHelpFlag(what)) {
        std::fputs(kListHelp, stdout);
        return 0;
    }
    if (what == "scenes") {
        for (const std::string& s : viz::scene::builtinSceneNames())
            std::printf("%s%s\n", s.c_str(), s == viz::scene::defaultSceneName() ? "  (default)" : "");
        return 0;
    }
    if (what == "techniques") {
        for (const std::string& id : viz::techniqueIds())
            std::printf("%-10s %s\n", id.c_str(), viz::makeTechnique(id)->description().c_str());
        return 0;
    }
    if (what == "stages" || what == "params") {
        if (args.empty()) throw InputError("list " + what + " needs a technique id");
        const auto technique = viz::makeTechnique(args.take());
        if (what == "stages") {
            for (const auto& s : technique->stages()) {
                std::printf("%s  (%s)  %s\n", s.id.c_str(), s.label.c_str(), s.purpose.c_str());
                for (const auto& i : s.intermediates) std::printf("    intermediate %s\n", i.c_str());
                for (const auto& p : s.params) std::printf("    param %s\n", p.c_str());
            }
        } else {
            for (const auto& p : technique->params()) {
                if (!p.choices.empty()) {
                    // A named parameter: its names (--set takes them, or their index).
                    std::string names;
                    for (std::size_t i = 0; i < p.choices.size(); ++i) names += (i ? " | " : "") + p.choices[i];
                    std::printf("%-20s default %-8s one of %s  %s\n", p.name.c_str(),
                                viz::settingText(technique->params(), p.name, p.defaultValue).substr(p.name.size() + 1).c_str(),
                                names.c_str(), p.help.c_str());
                    continue;
                }
                std::printf("%-20s default %-8s range [%s, %s]%s  %s\n", p.name.c_str(),
                            viz::exactNumber(p.defaultValue).c_str(), viz::exactNumber(p.minValue).c_str(),
                            viz::exactNumber(p.maxValue).c_str(), p.integer ? " integer" : "", p.help.c_str());
            }
        }
        if (!args.empty()) throw InputError("unexpected argument '" + args.peek() + "'");
        return 0;
    }
    throw InputError("cannot list '" + what + "' (scenes, techniques, stages T, params T)");
}

int runPlan(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kPlanHelp, stdout);
        return 0;
    }
    CommonOptions o = parseOptions(args, "plan", " --scene --technique --size --set --preset --no-default-light ");
    const auto technique = viz::makeTechnique(o.request.technique);
    const viz::Settings settings = viz::completeSettings(*technique, o.request.settings);
    const viz::scene::Scene scene = viz::scene::loadScene(o.request.scene, o.request.load);
    printNotes(scene);
    const viz::Plan plan = technique->plan(scene, settings);
    std::printf("%s on %s:\n", technique->id().c_str(), o.request.scene.c_str());
    for (const auto& s : plan.stages)
        std::printf("  stage   %-28s %-4s %s\n", s.stage.c_str(), s.runs ? "runs" : "SKIP", s.why.c_str());
    for (const auto& f : plan.features)
        std::printf("  feature %-28s %-4s %s\n", f.feature.c_str(), f.enabled ? "on" : "off", f.why.c_str());
    return 0;
}

int runExportScene(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kExportHelp, stdout);
        return 0;
    }
    if (args.empty()) throw InputError("export-scene needs a scene name and an output .gltf/.glb path");
    const std::string name = args.take();
    if (args.empty()) throw InputError("export-scene needs an output .gltf/.glb path after the scene name");
    const std::string out = args.take();
    if (!args.empty()) throw InputError("unexpected argument '" + args.peek() + "'");
    const std::string ext = viz::extensionOf(out);
    if (ext != ".gltf" && ext != ".glb") throw InputError("export-scene output '" + out + "' must end in .gltf or .glb");
    const viz::scene::Scene scene = viz::scene::loadScene(name);
    viz::scene::writeGltf(scene, out);
    std::printf("wrote %s\n", out.c_str());
    return 0;
}

int runGuiCommand(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kGuiHelp, stdout);
        std::printf("\nKeys and mouse (where a key applies only in one context, it is named):\n%s", plainKeyTable().c_str());
        return 0;
    }
    CommonOptions o = parseOptions(args, "gui", " --scene --technique --size --set --preset --screenshot --frames --state --script --export-dir --lesson --no-default-light --ui-scale --path --path-frames ");
    if (!o.screenshot.empty() && viz::extensionOf(o.screenshot) != ".png")
        throw InputError("--screenshot '" + o.screenshot + "' must end in .png");
    if (o.frames < 1) throw InputError("--frames must be at least 1");
    if (!o.screenshot.empty() && !o.state.empty()) {
        std::filesystem::path sidecar(o.screenshot);
        sidecar.replace_extension(".json");
        if (std::filesystem::weakly_canonical(sidecar) == std::filesystem::weakly_canonical(o.state))
            throw InputError("--screenshot '" + o.screenshot + "' would write its view rectangles over the state file '" +
                             o.state + "'");
    }
    GuiOptions g;
    g.scene = o.request.scene;
    g.technique = o.request.technique;
    g.width = o.request.width;
    g.height = o.request.height;
    SettingsByTechnique given = settingsByTechnique(o.sets, viz::techniqueIds(), "no technique has that parameter");
    g.settings = std::move(given.settings);
    g.settingErrors = std::move(given.errors);
    g.load = o.request.load;
    g.screenshot = o.screenshot;
    g.frames = o.frames;
    if (!o.script.empty()) {
        g.script = parseScript(o.script);  // a bad script fails before the window opens
        g.scriptPath = o.script;
    }
    g.statePath = o.state.empty() ? defaultSessionPath() : o.state;
    g.loadStateAtStart = !o.state.empty();
    g.sceneGiven = o.sceneGiven;
    g.techniqueGiven = o.techniqueGiven;
    g.sizeGiven = o.sizeGiven;
    if (!o.exportDir.empty()) {
        std::error_code ec;
        if (std::filesystem::exists(o.exportDir, ec) && !std::filesystem::is_directory(o.exportDir, ec))
            throw InputError("--export-dir '" + o.exportDir + "' is a file, not a folder");
        g.exportDir = o.exportDir;
    }
    g.uiScale = o.uiScale;
    if (!o.path.empty()) viz::scene::parseMotionPath(o.path);  // a bad path fails before the window opens
    g.path = o.path;
    g.pathFrames = o.pathFrames;
    // An unknown lesson name fails here; a malformed lesson file opens and shows its error in the panel.
    if (!o.lesson.empty()) g.lesson = findLesson(o.lesson);
    // The arguments' own errors first, then whether a window can open at all.
    if (const std::string problem = viz::displayProblem(); !problem.empty())
        throw InputError(problem + ": set DISPLAY to a running X server (or run under xvfb-run), or " +
                         (o.lesson.empty() ? std::string("use 'airlight render'")
                                           : "export the lesson with 'airlight lesson " + o.lesson + " --export DIR'"));
    return runGui(g);
}

int runDefault() {
    const std::string problem = viz::displayProblem();
    if (problem.empty()) {
        GuiOptions g;
        g.scene = viz::scene::defaultSceneName();
        g.technique = kDefaultTechnique;
        g.width = 320;
        g.height = 240;
        return runGui(g);
    }
    const std::string outDir = "out";
    std::printf("airlight: %s: rendering the default scene '%s' with '%s' headlessly into %s/\n", problem.c_str(),
                viz::scene::defaultSceneName().c_str(), kDefaultTechnique, outDir.c_str());
    std::filesystem::create_directories(outDir);
    RenderRequest request;
    request.scene = viz::scene::defaultSceneName();
    request.technique = kDefaultTechnique;
    request.width = 640;
    request.height = 480;
    request.allViews = true;  // every intermediate is written, those drawn on demand too
    RenderJob job(request);
    printNotes(job.scene());
    const viz::FrameOutput& out = job.run();
    writeLayer(job, "final", -1, outDir + "/final.png", "");
    writeLayer(job, "airlight", -1, outDir + "/airlight.png", "");
    writeLayer(job, "final", -1, outDir + "/final.exr", "");
    writeLayer(job, "airlight", -1, outDir + "/airlight.exr", "");
    int written = 4;
    for (const auto& i : out.intermediates) {
        if (i.kind == viz::ViewKind::Mesh || i.kind == viz::ViewKind::Buffer) continue;
        const int layers = i.image ? 1 : std::max(1, i.extent.z);
        for (int l = 0; l < layers; ++l) {
            const std::string file = outDir + "/" + i.id + (layers > 1 ? ".layer" + std::to_string(l) : "") + ".png";
            writeLayer(job, i.id, layers > 1 ? l : -1, file, "");
            ++written;
        }
    }
    printTiming(out);
    std::printf("wrote %d images to %s/\n", written, outDir.c_str());
    return 0;
}

}  // namespace airlight
