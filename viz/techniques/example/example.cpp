#include "techniques/example/example.h"

#include <array>
#include <string>
#include <string_view>

#include "core/error.h"
#include "debug/declared_technique.h"
#include "debug/stage_runner.h"
#include "scene/camera.h"
#include "shared/airlight.h"

namespace viz {
namespace {

// ---- ids (stable: tests use them) ----
constexpr const char* kStageLengths = "example.lengths";
constexpr const char* kStageAirlight = "example.airlight";
constexpr const char* kStageCompose = "example.compose";
constexpr const char* kLengths = "example.lengths";
constexpr const char* kAirlight = "example.airlight";
constexpr const char* kFinal = "example.final";

// Stage indices come from the declared order, never from a hand-kept enum.
constexpr std::array<std::string_view, 3> kStageOrder = {kStageLengths, kStageAirlight, kStageCompose};
constexpr int kLengthsIndex = stageIndexOf(kStageOrder, kStageLengths);
constexpr int kAirlightIndex = stageIndexOf(kStageOrder, kStageAirlight);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, kStageCompose);

enum class Integration { Closed = 0, Midpoint = 1 };

// The settings a run reads, each declared once with its parameter.
struct ExampleSettings {
    Integration integration = Integration::Closed;
    int samples = 0;
};

const ParamTable<ExampleSettings>& exampleParams() {
    using S = ExampleSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::integration, {"integration", "closed: the closed form of each sun's segment; midpoint: the "
                                   "midpoint rule with `samples` intervals", 0, 0, 1, true, {"closed", "midpoint"}})
            .add(&S::samples, {"samples", "integration=midpoint: intervals along each ray", 16, 1, 4096, true});
    return table;
}

// The card (id, description, what it needs) and the parameters are data; DeclaredTechnique answers the
// accessors from them and the stages the constructor declares.
class ExampleTechnique final : public DeclaredTechnique<ExampleSettings> {
public:
    ExampleTechnique()
        : DeclaredTechnique({.id = "example",
                             .description = "worked example: unshadowed airlight of suns, no surfaces",
                             .needsGl = false},
                            exampleParams()) {
        mStages = {
            {kStageLengths, "Ray lengths", "every eye ray runs to zfar: the example has no surfaces", {},
             {kLengths}, 1},
            {kStageAirlight, "Airlight", "per pixel and sun: sigma_s p E integral of exp(-sigma_t t) over [0, d]",
             {"integration", "samples"}, {kAirlight}, 1},
            {kStageCompose, "Compose", "final = L_air (nothing lies behind the medium)", {}, {kFinal}, 1},
        };
        mStages[kLengthsIndex].keepsOutputs = true;  // mLengths stays until the next run computes it again
        checkStageOrder(mStages, kStageOrder);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        const ExampleSettings s = read(settings);
        Plan p = planEveryStage(mStages);
        if (scene.medium.sigma_s == 0.0) {
            p.stages[kAirlightIndex].runs = false;
            p.stages[kAirlightIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
        }
        int suns = 0;
        for (const scene::Light& l : scene.lights) suns += l.type == scene::LightType::Directional;
        const int others = int(scene.lights.size()) - suns;
        p.features.push_back({"OTHER_LIGHTS", false,
                              others == 0 ? "the scene has suns only"
                                          : std::to_string(others) + " point, spot or area light(s) left out: the "
                                                                     "example shades suns only"});
        const bool midpoint = s.integration == Integration::Midpoint;
        p.features.push_back({"MIDPOINT", midpoint,
                              midpoint ? std::to_string(s.samples) + " midpoint intervals per ray and sun"
                                       : "integration=closed: one closed form per ray and sun"});
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        VIZ_CHECK(input.scene != nullptr, "FrameInput::scene is null");
        const scene::Scene& scene = *input.scene;
        const ExampleSettings s = read(input.settings);
        const int w = input.width, h = input.height;
        FrameOutput out;
        out.plan = plan(scene, input.settings);
        CpuStageClock clock;
        StageRunner stages(mStages, input, out, mReuse, clock);

        if (!stages.run(
                kLengthsIndex,
                [&] {
                    mLengths = std::make_shared<Image>(w, h, 1);
                    for (float& d : mLengths->pixels) d = float(scene.camera.zfar);
                },
                [&] {
                    out.intermediates.push_back(cpuIntermediate(kLengths, "Ray length d", "zfar: no surfaces",
                                                                ViewKind::Depth, mLengths, 0.0f,
                                                                float(scene.camera.zfar)));
                }))
            return out;

        auto airlight = std::make_shared<Image>(w, h, 3);
        if (!stages.run(
                kAirlightIndex,
                [&] {
                    if (!out.plan.stages[kAirlightIndex].runs) return;
                    for (int y = 0; y < h; ++y)
                        for (int x = 0; x < w; ++x) {
                            const glm::dvec3 L = pixelAirlight(scene, s, scene::pixelRay(scene.camera, w, h, x, y),
                                                               double(mLengths->at(x, y)));
                            for (int c = 0; c < 3; ++c) airlight->at(x, y, c) = float(L[c]);
                        }
                },
                [&] {
                    out.intermediates.push_back(cpuIntermediate(
                        kAirlight, "L_air", "every sun's segment [0, d]", ViewKind::Colour, airlight));
                    out.airlight = *airlight;
                }))
            return out;

        stages.run(kComposeIndex, [&] { out.final = *airlight; },
                   [&] {
                       out.intermediates.push_back(cpuIntermediate(kFinal, "Final", "L_air", ViewKind::Colour, airlight));
                   });
        return out;
    }

private:
    // L_air of one ray of direction w (unit) and length d: every sun's segment [0, d].
    static glm::dvec3 pixelAirlight(const scene::Scene& scene, const ExampleSettings& s, const glm::dvec3& w,
                                    double d) {
        const scene::Medium& m = scene.medium;
        glm::dvec3 L(0.0);
        for (const scene::Light& light : scene.lights) {
            if (light.type != scene::LightType::Directional) continue;
            // cos(phase angle) = dot(travel direction, direction towards the eye) = dot(dir, -w).
            const double cosTheta = glm::dot(light.direction, -w);
            double unit = 0.0;  // the segment for unit irradiance
            if (s.integration == Integration::Closed) {
                unit = airlight::directionalSegment(cosTheta, 0.0, d, m.sigma_s, m.sigma_t(), m.g, 1.0);
            } else {
                const double dt = d / s.samples, scatter = m.sigma_s * airlight::phaseHG(cosTheta, m.g);
                for (int k = 0; k < s.samples; ++k) unit += scatter * std::exp(-m.sigma_t() * (k + 0.5) * dt) * dt;
            }
            L += light.colour * light.intensity * unit;
        }
        return L;
    }

    StageReuse mReuse;
    std::shared_ptr<Image> mLengths;  // the lengths stage's output, kept for a run that resumes after it
};

}  // namespace

std::unique_ptr<Technique> makeExampleTechnique() { return std::make_unique<ExampleTechnique>(); }

}  // namespace viz
