// Stepping inside a stage (Technique::substepValues, substepPosition, setSubstep): every stage that
// declares a sub-step parameter steps through values its parameter accepts, one position per value, and
// its last step runs the stage whole; the counts follow the settings they depend on.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "techniques/registry.h"

namespace viz {
namespace {

int stageIndex(const Technique& t, const std::string& id) {
    for (std::size_t i = 0; i < t.stages().size(); ++i)
        if (t.stages()[i].id == id) return int(i);
    ADD_FAILURE() << t.id() << " has no stage " << id;
    return -1;
}

const ParamInfo& param(const Technique& t, const std::string& name) {
    for (const ParamInfo& p : t.params())
        if (p.name == name) return p;
    ADD_FAILURE() << t.id() << " has no parameter " << name;
    static const ParamInfo kNone;
    return kNone;
}

std::vector<double> values(const std::string& technique, const std::string& stage, const Settings& given = {}) {
    const auto t = makeTechnique(technique);
    return t->substepValues(stageIndex(*t, stage), completeSettings(*t, given));
}

// Every declared sub-step parameter: values in range, distinct, each reachable with setSubstep and
// reported back by substepPosition, and the last one is "run it all" (the parameter's default).
TEST(Substeps, EveryDeclaredStageStepsThroughValidDistinctValues) {
    int declared = 0;
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        for (int stage = 0; stage < int(t->stages().size()); ++stage) {
            const StageInfo& st = t->stages()[std::size_t(stage)];
            if (st.substepParam.empty()) {
                EXPECT_TRUE(t->substepValues(stage, completeSettings(*t, {})).empty()) << id << " " << st.id;
                continue;
            }
            const ParamInfo& p = param(*t, st.substepParam);
            Settings settings = completeSettings(*t, {});
            // polyvol steps only adaptive refinement: ask for it on a map where the plan keeps it.
            if (id == "polyvol") settings = completeSettings(*t, {{"tessellation", 1}});
            const std::vector<double> v = t->substepValues(stage, settings);
            ASSERT_FALSE(v.empty()) << id << " " << st.id;
            ++declared;
            EXPECT_EQ(v.back(), p.defaultValue) << id << " " << st.id << ": the last step runs the stage whole";
            EXPECT_EQ(std::set<double>(v.begin(), v.end()).size(), v.size()) << id << " " << st.id;
            for (double value : v) {
                EXPECT_GE(value, p.minValue) << id << " " << st.id;
                EXPECT_LE(value, p.maxValue) << id << " " << st.id;
            }
            EXPECT_EQ(substepPosition(*t, stage, settings).at, int(v.size())) << id << " " << st.id;
            for (int k = 1; k <= int(v.size()); ++k) {
                ASSERT_TRUE(setSubstep(*t, stage, settings, k));
                const SubstepPosition pos = substepPosition(*t, stage, settings);
                EXPECT_EQ(pos.at, k) << id << " " << st.id;
                EXPECT_EQ(pos.count, int(v.size())) << id << " " << st.id;
            }
            ASSERT_TRUE(setSubstep(*t, stage, settings, 0));  // clamped to the first
            EXPECT_EQ(substepPosition(*t, stage, settings).at, 1) << id << " " << st.id;
        }
    }
    EXPECT_GE(declared, 7) << "slices, polyvol, minmax (2), vsv and ivsv (2) declare sub-steps";
}

// The counts follow the settings: planes, refinement levels of the map, tree levels of the rows, scan
// passes of the alpha cells, VPLs.
TEST(Substeps, CountsFollowTheSettings) {
    EXPECT_EQ(values("slices", "slices.planes", {{"planes", 40}}).size(), 40u);
    // polyvol 1024^2: the coarse quads are 64 texels, six levels above single texels; the coarse grid,
    // then 1 .. 5 levels below it, then fully refined.
    const std::vector<double> refine = values("polyvol", "polyvol.volume", {{"tessellation", 1}, {"shadow_map", 1024}});
    EXPECT_EQ(refine, (std::vector<double>{0, 1, 2, 3, 4, 5, -1}));
    EXPECT_EQ(values("polyvol", "polyvol.volume"), refine) << "adaptive at 1024^2 by default";
    EXPECT_TRUE(values("polyvol", "polyvol.volume", {{"tessellation", 0}}).empty())
        << "static tessellation has no refinement steps";
    EXPECT_TRUE(values("polyvol", "polyvol.volume", {{"tessellation", 1}, {"shadow_map", 256}}).empty())
        << "below 512^2 the plan leaves adaptive out";
    EXPECT_EQ(values("polyvol", "polyvol.volume", {{"tessellation", 1}, {"shadow_map", 256}, {"force_features", 1}}).size(),
              5u);
    // minmax: 512 columns are a 9-level tree: passes 1 .. 8, then all.
    EXPECT_EQ(values("minmax", "minmax.mipmap", {{"columns", 512}}).size(), 9u);
    EXPECT_EQ(values("minmax", "minmax.mipmap", {{"shadow_map", 256}}).size(), 8u);
    // vsv: 128 alpha cells take 7 passes: before any, after 1 .. 6, then all.
    EXPECT_EQ(values("vsv", "vsv.scan", {{"voxels", 128}}), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, -1}));
    EXPECT_EQ(values("vsv", "vsv.scan", {{"voxels", 128}, {"voxels_alpha", 32}}).size(), 6u);
    EXPECT_EQ(values("ivsv", "ivsv.gather", {{"vpls", 16}}).size(), 16u);
    EXPECT_EQ(values("ivsv", "ivsv.gather", {{"vpls", 16}}).front(), 0.0) << "VPL 0 alone first";
}

}  // namespace
}  // namespace viz
