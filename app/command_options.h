// The options shared by render, plan, gui and animate, parsed in one place so that every command spells
// and checks them alike.
#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "cli_args.h"
#include "render_job.h"

namespace airlight {

constexpr const char* kDefaultTechnique = "raymarch";

struct CommonOptions {
    RenderRequest request;       // request.settings: --set as the chosen technique declares its parameters
    std::vector<std::string> sets;  // --set as given ("name=value"), for a command that runs several techniques
    std::string out;
    std::string layer = "final";
    int layerIndex = -1;
    std::string exposure;
    bool quiet = false;
    bool strict = false;  // render: NaN/Inf/negative pixels are exit 3 instead of a warning
    bool countWork = false;                 // render --count-work: a counting run (gl/work_counters.h)
    std::optional<glm::ivec2> countPixel;   // render --count-pixel X,Y: only that pixel (row 0 at the top)
    std::string screenshot;  // gui only
    int frames = 1;
    std::string state;  // gui only
    std::string script;  // gui only
    std::string exportDir;  // gui only
    std::string lesson;     // gui only
    float uiScale = 1.0f;   // gui only
    bool sceneGiven = false, techniqueGiven = false, sizeGiven = false;
    std::string preset = "default";  // --preset: "paper" starts from the technique's paperSettings()
    bool framesGiven = false;
    std::string path;  // animate, gui: the motion path (scene/motion_path.h)
    int pathFrames = 120;  // gui only: frames of the path's loop (--path-frames)
    int fps = 25;      // animate only
    bool exr = false;  // animate only: EXR frames beside the PNGs
};

// Parses the options; `allowed` lists the flags this command takes (" --scene --size "), any other is an
// InputError. maxFrames bounds --frames. Starts from the default scene and technique at 320x240; with
// --preset paper, the technique's paper settings under those given with --set.
CommonOptions parseOptions(Args& args, const std::string& command, const std::string& allowed,
                           int maxFrames = 1000000);

}  // namespace airlight
