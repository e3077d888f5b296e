// What the GL techniques (raymarch, slices, polyvol, minmax, vsv, ivsv) keep the same way beyond their card
// (debug/declared_technique.h): the current run's settings, read once at its start; the shared stages'
// passes (shadow maps, surface, compose: render/scene_view.h); the medium's uniform block; the stages
// carried over from the last run. It also brings in the headers all their files use, so that a technique's
// own header lists only what is its own.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "debug/declared_technique.h"
#include "debug/permutations.h"
#include "debug/stage_runner.h"
#include "gl/program.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/medium_block.h"
#include "render/scene_view.h"
#include "scene/camera.h"

namespace viz::render {

template <class SettingsT>
class GlTechnique : public DeclaredTechnique<SettingsT> {
protected:
    GlTechnique(TechniqueCard card, const ParamTable<SettingsT>& table)
        : DeclaredTechnique<SettingsT>(std::move(card), table) {}

    // A run's start: its settings read once into mSettings, and its plan into out.plan.
    const SettingsT& startRun(const FrameInput& input, FrameOutput& out) {
        mSettings = this->read(input.settings);
        out.plan = planForRun(input);
        return mSettings;
    }
    // The plan of a run: plan() by default; a technique whose plan depends on the image size (vsv's grid
    // covers what is in view) plans with the run's own.
    virtual Plan planForRun(const FrameInput& input) const { return this->plan(*input.scene, input.settings); }

    SettingsT mSettings{};  // the current run's (startRun)
    SceneViewPasses mView;
    MediumBlock mMedium;  // sigma_s, sigma_t, g for the shaders (common/medium.glsl)
    StageReuse mReuse;    // stages carried over from the last run (FrameInput::resumeAtStage)
};

}  // namespace viz::render
