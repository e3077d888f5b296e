#include "animate_command.h"

#include <chrono>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "command_options.h"
#include "core/animation_io.h"
#include "core/error.h"
#include "render_job.h"
#include "scene/motion_path.h"

namespace airlight {

using viz::InputError;

namespace {

constexpr const char* kAnimateHelp = R"(usage: airlight animate --scene S --technique T --path P --frames N [--size WxH] --out F.gif|F.mp4|DIR/
                        [options]

Renders technique T on scene S at every frame of motion path P and writes the frames as an animated GIF,
an MP4 video (needs ffmpeg on PATH) or numbered PNG frames in folder DIR (DIR/frame_0000.png, ...).
Frame i of N is a pure function of P, i and N: two runs give the same frames.

  --path P           a motion, or several joined by commas (A: an angle such as 30deg or 0.5rad):
                       camera-orbit[:A]  turn the camera about the vertical axis through its orbit target
                                         by A over the animation (default 360deg, a loop)
                       camera-dolly:D    move the camera along its view in by D and back out (scene units,
                                         or P% of the distance to the orbit target)
                       light-orbit[:A]   move the first light A along the window's orbit (P key) cone
                                         (default 360deg)
                       light-sweep:A     swing the first light back and forth by +-A about the vertical
                                         axis through its aim point
                     or a .json file of keyframes (README, "Animations")
  --frames N         number of frames, 1..10000
  --size WxH         image size, each side 1..8192 (default 320x240)
  --out F            F.gif (8-bit, 256 colours per frame, loops), F.mp4 (H.264) or DIR/ (numbered PNGs)
  --fps F            frames per second, 1..100 (default 25; GIF stores delays in 1/100 s, so 30 plays at 33)
  --exr              DIR/ only: also frame_NNNN.exr (32-bit float, linear)
  --layer L          final (default) or airlight (L_air alone)
  --exposure X|auto  scale before the sRGB encode, as for render (default auto: from the first frame,
                     then kept for every frame so that the brightness does not pump)
  --set name=value   set a technique parameter (repeatable); --preset paper as for render
  --strict           exit 3 (and write nothing) when a frame has NaN, Inf or negative pixels
  --quiet            print nothing on success
  --no-default-light a .gltf/.glb without a light is an error
)";

}  // namespace

int runAnimate(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kAnimateHelp, stdout);
        return 0;
    }
    CommonOptions o = parseOptions(args, "animate",
                                   " --scene --technique --size --out --path --frames --fps --exr --layer --set "
                                   "--preset --exposure --quiet --no-default-light --strict ",
                                   kMaxAnimationFrames);
    if (o.path.empty()) throw InputError("animate needs --path, e.g. --path camera-orbit:30deg");
    if (!o.framesGiven) throw InputError("animate needs --frames N (1 to " + std::to_string(kMaxAnimationFrames) + ")");
    if (o.out.empty()) throw InputError("animate needs --out F.gif, F.mp4 or DIR/");
    if (o.layer != "final" && o.layer != "airlight")
        throw InputError("--layer '" + o.layer + "': animate writes final or airlight");
    const viz::scene::MotionPath path = viz::scene::parseMotionPath(o.path);
    float exposure = 0.0f;  // 0: auto, from the first frame
    if (!o.exposure.empty() && o.exposure != "auto") {
        exposure = float(parseNumber(o.exposure, "--exposure"));
        if (!(exposure > 0.0f)) throw InputError("--exposure must be positive or auto");
    }
    (void)viz::animationFormatOf(o.out);  // a bad --out fails before the scene loads

    RenderJob job(o.request);
    if (!o.quiet)
        for (const std::string& note : job.scene().notes) std::fprintf(stderr, "airlight: note: %s\n", note.c_str());
    // Every pose first: a path that cannot move this scene fails before anything is written.
    const viz::scene::Scene base = job.scene();
    std::vector<viz::scene::Pose> poses;
    poses.reserve(std::size_t(o.frames));
    for (int i = 0; i < o.frames; ++i) poses.push_back(viz::scene::poseAt(path, base, i, o.frames));

    viz::AnimationSpec spec;
    spec.width = o.request.width;
    spec.height = o.request.height;
    spec.frames = o.frames;
    spec.fps = o.fps;
    spec.exr = o.exr;
    viz::AnimationWriter writer(o.out, spec);

    const auto start = std::chrono::steady_clock::now();
    std::set<std::string> notesSeen;
    int badFrames = 0;
    for (int i = 0; i < o.frames; ++i) {
        viz::scene::applyPose(poses[std::size_t(i)], job.scene());
        job.setFrame(i);
        const viz::FrameOutput& out = job.run();
        for (const std::string& note : out.notes)
            if (notesSeen.insert(note).second && !o.quiet)
                std::fprintf(stderr, "airlight: note: frame %d: %s\n", i, note.c_str());
        const std::vector<std::string> bad = job.badPixelWarnings();
        if (!bad.empty()) {
            if (o.strict) {
                std::fprintf(stderr, "airlight: error: --strict: frame %d: %s; %s not written\n", i, bad.front().c_str(),
                             o.out.c_str());
                return 3;
            }
            if (badFrames == 0)
                for (const std::string& line : bad) std::fprintf(stderr, "airlight: warning: frame %d: %s\n", i, line.c_str());
            ++badFrames;
        }
        const viz::Image image = job.layerImage(o.layer);
        if (exposure == 0.0f) exposure = autoExposure(image);
        writer.add(image, exposure);
    }
    writer.commit();
    if (badFrames > 1)
        std::fprintf(stderr, "airlight: warning: %d of %d frames have NaN, Inf or negative pixels\n", badFrames, o.frames);
    if (!o.quiet) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("wrote %s (%d frames, %dx%d, %d fps, %s; %s of %s; exposure %g; rendered in %.1f s)\n",
                    o.out.c_str(), o.frames, spec.width, spec.height, spec.fps,
                    viz::scene::describeMotionPath(path).c_str(), o.layer.c_str(), o.request.technique.c_str(),
                    double(exposure), seconds);
    }
    return 0;
}

}  // namespace airlight
