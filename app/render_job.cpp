#include "render_job.h"

#include "core/pixel_census.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "gl/debug_output.h"
#include "gl/readback.h"
#include "platform/context_egl.h"
#include "scene/scene_source.h"
#include "techniques/registry.h"

namespace airlight {

using viz::InputError;

int stageIndex(const viz::Technique& technique, const std::string& stageId) {
    const auto& stages = technique.stages();
    std::string known;
    for (std::size_t i = 0; i < stages.size(); ++i) {
        if (stages[i].id == stageId) return static_cast<int>(i);
        known += (i ? ", " : "") + stages[i].id;
    }
    throw InputError("unknown stage '" + stageId + "' for technique '" + technique.id() + "' (known: " + known + ")");
}

RenderJob::RenderJob(const RenderRequest& request) {
    mTechnique = viz::makeTechnique(request.technique);
    viz::setRunSettings(mInput, viz::completeSettings(*mTechnique, request.settings));
    mInput.stopAfterStage = request.stopAfter.empty() ? -1 : stageIndex(*mTechnique, request.stopAfter);
    mScene = viz::scene::loadScene(request.scene, request.load);
    viz::scene::stampGeometry(mScene);  // a motion path runs many frames of it
    mInput.scene = &mScene;
    mInput.width = request.width;
    mInput.height = request.height;
    mInput.views = viz::onDemandAmong(*mTechnique, request.views, request.allViews);
    if (mTechnique->needsGl()) {
        // Debug builds ask for a debug context and log GL errors through the debug-output callback.
#ifdef NDEBUG
        constexpr bool kDebugContext = false;
#else
        constexpr bool kDebugContext = true;
#endif
        mContext = viz::HeadlessContext::create(kDebugContext);
        if (kDebugContext) viz::gl::installDebugOutput();
    }
}

RenderJob::~RenderJob() {
    // GL objects owned by the technique must die while the context is still current.
    mOutput = {};
    mTechnique.reset();
    mContext.reset();
}

void RenderJob::setSetting(const std::string& name, double value) {
    viz::Settings all = viz::controlSettings(mInput.controls);
    all.insert(mInput.settings.begin(), mInput.settings.end());
    all.at(name) = value;
    viz::setRunSettings(mInput, std::move(all));
}

const viz::FrameOutput& RenderJob::run() {
    mOutput = mTechnique->run(mInput);
    return mOutput;
}

const viz::Intermediate* RenderJob::findIntermediate(const std::string& id) const {
    for (const auto& i : mOutput.intermediates)
        if (i.id == id) return &i;
    return nullptr;
}

std::vector<std::string> RenderJob::badPixelWarnings() const {
    std::vector<std::string> lines;
    const std::string stage = mTechnique->stages().empty()
                                  ? std::string("?")
                                  : mTechnique->stages()[std::size_t(std::max(mOutput.lastStageRun, 0))].id;
    for (const auto& [image, name] : {std::pair{&mOutput.airlight, "L_air"}, std::pair{&mOutput.final, "the final image"}}) {
        const viz::PixelCensus c = viz::census(*image);
        if (!c.clean()) lines.push_back(mTechnique->id() + " (stage " + stage + "): " + name + " has " + c.describe());
    }
    return lines;
}

viz::Image RenderJob::layerImage(const std::string& layer, int arrayLayer) const {
    if (layer == "airlight" || layer == "final") {
        const viz::Image& image = layer == "airlight" ? mOutput.airlight : mOutput.final;
        if (image.empty())
            throw InputError("layer '" + layer + "' is not produced when the run stops after stage '" +
                             mTechnique->stages()[std::size_t(std::max(mOutput.lastStageRun, 0))].id + "'");
        return image;
    }
    const viz::Intermediate* found = findIntermediate(layer);
    if (!found) {
        std::string known = "airlight, final";
        for (const auto& i : mOutput.intermediates) known += ", " + i.id;
        throw InputError("unknown layer '" + layer + "' (this run produced: " + known + ")");
    }
    const int layers = found->glTexture && !found->image ? viz::gl::textureLayerCount(found->glTexture) : 1;
    if (arrayLayer >= layers)
        throw InputError("--layer-index " + std::to_string(arrayLayer) + " is past the last layer of '" + layer +
                         "' (" + (layers == 1 ? std::string("it has one layer, 0") :
                                  "it has " + std::to_string(layers) + " layers, 0 to " + std::to_string(layers - 1)) +
                         ")");
    if (found->image) return *found->image;
    if (found->glTexture) return viz::gl::readTexture(found->glTexture, 0, arrayLayer);
    throw InputError("intermediate '" + layer + "' is a " + viz::viewKindName(found->kind) +
                     " and cannot be written as an image");
}

float autoExposure(const viz::Image& image) {
    std::vector<float> values;
    values.reserve(std::size_t(image.width) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float m = 0.0f;
            for (int c = 0; c < std::min(image.channels, 3); ++c) {
                const float v = image.at(x, y, c);
                if (std::isfinite(v)) m = std::max(m, v);
            }
            values.push_back(m);
        }
    if (values.empty()) return 1.0f;
    const std::size_t k = std::min(values.size() - 1, std::size_t(double(values.size()) * 0.995));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    const float p = values[k];
    return p > 0.0f ? 1.0f / p : 1.0f;
}

}  // namespace airlight
