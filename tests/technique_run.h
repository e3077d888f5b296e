// Running a technique in a test, with no GL of its own (the caller provides a context if it needs one).
#pragma once

#include <string>

#include "techniques/registry.h"

namespace viz::testing {

inline FrameOutput runTechnique(Technique& technique, const scene::Scene& scene, const Settings& given, int w,
                                int h, int stopAfter = -1, int frame = 0, const std::vector<std::string>& views = {}) {
    FrameInput in;
    in.scene = &scene;
    in.width = w;
    in.height = h;
    setRunSettings(in, completeSettings(technique, given));
    in.stopAfterStage = stopAfter;
    in.frame = frame;
    in.views = views;
    return technique.run(in);
}

// A technique's plan for `scene` with `given` completed by its defaults.
inline Plan planOf(const std::string& technique, const scene::Scene& scene, const Settings& given = {}) {
    const auto t = makeTechnique(technique);
    return t->plan(scene, completeSettings(*t, given));
}

}  // namespace viz::testing
