// Running one technique on one scene, headless: the common path of `render`, the no-display default and
// the tests. Owns the GL context when the technique needs one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "debug/technique.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace viz {
class HeadlessContext;
}

namespace airlight {

struct RenderRequest {
    std::string scene;      // built-in name or .gltf/.glb path
    std::string technique;
    int width = 160;
    int height = 120;
    viz::Settings settings;
    std::string stopAfter;  // stage id or empty
    viz::scene::LoadOptions load;  // what a file lacking a light gets (--no-default-light)
    // What the caller writes or shows: the intermediates a stage draws only on demand are drawn for
    // these (StageInfo::onDemand; `render --layer polyvol.mesh`).
    std::vector<std::string> views;
    bool allViews = false;  // every intermediate is wanted (the headless default render writes them all)
};

class RenderJob {
public:
    explicit RenderJob(const RenderRequest& request);  // loads and validates; throws InputError
    ~RenderJob();
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    const viz::FrameOutput& run();
    const viz::FrameOutput& lastOutput() const { return mOutput; }
    // Frame index along an animation for the next run() (FrameInput::frame).
    void setFrame(int frame) { mInput.frame = frame; }
    // One setting for the next run() (an animated sub-step parameter); the name must be the technique's.
    // One of the technique's settings (a control's name too: it goes to FrameInput::controls).
    void setSetting(const std::string& name, double value);
    const viz::scene::Scene& scene() const { return mScene; }
    // The scene the next run() renders: a caller may move its camera and lights between runs (animate
    // does, frame by frame), as the window does; techniques read the scene at every run.
    viz::scene::Scene& scene() { return mScene; }
    const viz::Technique& technique() const { return *mTechnique; }

    // "airlight", "final" or an intermediate id; layer selects a cube face / array layer.
    viz::Image layerImage(const std::string& layer, int arrayLayer = -1) const;
    const viz::Intermediate* findIntermediate(const std::string& id) const;
    // One line per output of the last run (L_air, the final image) that has NaN, Inf or negative
    // pixels: "TECHNIQUE (stage S): L_air has 3 NaN of 76800 pixels". Empty when all are clean.
    std::vector<std::string> badPixelWarnings() const;

private:
    viz::scene::Scene mScene;
    std::unique_ptr<viz::HeadlessContext> mContext;
    std::unique_ptr<viz::Technique> mTechnique;
    viz::FrameInput mInput;
    viz::FrameOutput mOutput;
};

int stageIndex(const viz::Technique& technique, const std::string& stageId);  // InputError if unknown

// Exposure that maps the 99.5th percentile of the brightest channel to 1 (1 for a black image).
float autoExposure(const viz::Image& image);

}  // namespace airlight
