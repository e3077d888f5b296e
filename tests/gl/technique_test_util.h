// Shared by the technique tests: run a technique headless to a stage and compare images.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_test_fixture.h"
#include "gl/readback.h"
#include "technique_run.h"
#include "scene/camera.h"
#include "techniques/registry.h"

namespace viz::testing {

// Every value of `image` is finite (no NaN, no Inf).
inline bool allFinite(const Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(), [](float v) { return std::isfinite(v); });
}

// ||a - b||_2 / ||b||_2 over all pixels and channels.
inline double relativeL2(const Image& a, const Image& b) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < b.pixels.size(); ++i) {
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        num += d * d;
        den += double(b.pixels[i]) * double(b.pixels[i]);
    }
    return std::sqrt(num / den);
}

class TechniqueTest : public gl::GlTest {
protected:
    // Runs a technique; `keep` lists intermediates to read back before the technique (and its textures)
    // goes away. Every other GL name in the result is cleared.
    static FrameOutput render(const scene::Scene& scene, const std::string& technique, const Settings& settings,
                              int w, int h, int stopAfter = -1, const std::vector<std::string>& keep = {}) {
        // What it reads back is what it shows: the on-demand views among them are drawn (StageInfo::onDemand).
        auto t = makeTechnique(technique);
        FrameOutput out = runTechnique(*t, scene, settings, w, h, stopAfter, 0, onDemandAmong(*t, keep));
        for (auto& i : out.intermediates) {
            if (i.glTexture != 0 && std::find(keep.begin(), keep.end(), i.id) != keep.end())
                i.image = std::make_shared<Image>(gl::readTexture(i.glTexture));
            i.glTexture = 0;
        }
        return out;
    }
    // Stops after every stage in turn: the run reports that stage as its last, timed every stage up to it,
    // and published nothing a later stage declares. L_air exists from stage `airlightStage` on and the
    // final image from `finalStage` on.
    static void expectEachStageStopsCleanly(const std::string& technique, const scene::Scene& scene,
                                            const Settings& settings, int airlightStage, int finalStage) {
        const auto stages = makeTechnique(technique)->stages();
        for (int s = 0; s < int(stages.size()); ++s) {
            const FrameOutput out = render(scene, technique, settings, 32, 24, s);
            EXPECT_EQ(out.lastStageRun, s);
            EXPECT_EQ(out.timing.stages.size(), std::size_t(s + 1));
            for (int later = s + 1; later < int(stages.size()); ++later)
                for (const auto& id : stages[std::size_t(later)].intermediates)
                    for (const auto& i : out.intermediates) EXPECT_NE(i.id, id) << "stage " << s;
            EXPECT_EQ(out.airlight.empty(), s < airlightStage) << "stage " << s;
            EXPECT_EQ(out.final.empty(), s < finalStage) << "stage " << s;
        }
    }
    // The plan's entry for feature `name`; a failure, and an empty entry, when the plan does not list it.
    static FeaturePlan feature(const Plan& plan, const std::string& name) {
        const FeaturePlan* f = findFeature(plan, name);
        if (!f) ADD_FAILURE() << "no feature " << name;
        return f ? *f : FeaturePlan{};
    }
    // Renders `technique` and the reference at w x h and expects the technique's L_air finite and within
    // `bound` relative L2 of the reference's; prints "label: relative L2 = e" and returns e.
    static double expectNearReference(const scene::Scene& scene, const std::string& technique,
                                      const Settings& settings, int w, int h, double bound, const std::string& label) {
        const FrameOutput reference = render(scene, "reference", {}, w, h);
        const FrameOutput out = render(scene, technique, settings, w, h);
        EXPECT_TRUE(allFinite(out.airlight)) << label;
        const double e = relativeL2(out.airlight, reference.airlight);
        std::printf("%s: relative L2 = %.4f\n", label.c_str(), e);
        EXPECT_LT(e, bound) << label;
        return e;
    }
    static const Intermediate* find(const FrameOutput& out, const std::string& id) {
        for (const auto& i : out.intermediates)
            if (i.id == id) return &i;
        return nullptr;
    }
};

// The shaders' pixelRay (pixel centre, row 0 at the top) in float, as the GPU computes it, for CPU mirrors
// that must follow the GPU's rounding.
inline glm::vec3 shaderPixelRay(const scene::Camera& cam, int w, int h, int x, int y) {
    const float tanHalf = float(std::tan(cam.yfov * 0.5));
    const float aspect = float(scene::aspectOf(cam, w, h));
    const float ndcX = 2.0f * (float(x) + 0.5f) / float(w) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (float(y) + 0.5f) / float(h);
    return glm::normalize(glm::vec3(cam.forward) + (ndcX * tanHalf * aspect) * glm::vec3(scene::cameraRight(cam)) +
                          (ndcY * tanHalf) * glm::vec3(cam.up));
}

// vsv's and ivsv's picked column (two rows of phi bits: as voxelized, after the scan; 0.5 beyond the
// fragment) against the voxels slice at the pixel's theta (alpha x phi, before the scan): some alpha cell
// must have row 0 as its column and row 1 as the prefix OR of the columns up to it. Returns the number of
// bits read and, in `before` / `after`, the set bits of each row up to there.
// `expectedAlpha`: the pixel's alpha in cell units, computed by the caller from the camera and the frame;
// the column must be the voxels' column at that cell (or a neighbour, for a ray on a cell boundary). NaN:
// any cell (ivsv, whose frame is a VPL's that only the technique knows).
inline int expectColumnIsAVoxelColumnAndItsPrefixOr(const Image& voxels, const Image& column, double expectedAlpha,
                                                    int& before, int& after) {
    EXPECT_EQ(column.height, 2);
    EXPECT_EQ(column.width, voxels.height);
    int read = 0;
    while (read < column.width && column.at(read, 0) != 0.5f) ++read;
    for (int k = read; k < column.width; ++k) EXPECT_EQ(column.at(k, 1), 0.5f);
    int matches = 0;
    bool atExpected = false;
    for (int a = 0; a < voxels.width; ++a) {
        bool same = true, prefix = true;
        for (int k = 0; k < read; ++k) {
            same = same && (voxels.at(a, k) > 0.5f) == (column.at(k, 0) > 0.5f);
            bool any = false;
            for (int b = 0; b <= a; ++b) any = any || voxels.at(b, k) > 0.5f;
            prefix = prefix && any == (column.at(k, 1) > 0.5f);
        }
        matches += same && prefix;
        atExpected = atExpected || (same && prefix && std::abs(a + 0.5 - expectedAlpha) <= 1.0);
    }
    EXPECT_GE(matches, 1) << "no alpha cell explains both rows";
    if (!std::isnan(expectedAlpha)) {
        EXPECT_TRUE(atExpected) << "the rows are not the voxel column at the pixel's alpha cell " << expectedAlpha;
    }
    before = after = 0;
    for (int k = 0; k < read; ++k) before += column.at(k, 0) > 0.5f, after += column.at(k, 1) > 0.5f;
    EXPECT_GE(after, before);
    return read;
}

}  // namespace viz::testing
