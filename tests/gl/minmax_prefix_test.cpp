// minmax's prefix-sum tables (integrand=svd) scanned in log2 passes (prefix_sums=log2) against the
// sequential scan of each row, on every kind of table: a spot light with a cookie (a table per slice), a sun
// (one row shared by every slice) and a point light (a table per slice over its own gamma range).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "gl/readback.h"
#include "minmax_point_scene.h"
#include "scene/builtin_scenes.h"
#include "technique_test_util.h"
#include "techniques/minmax/minmax_technique.h"
#include "techniques/registry.h"

namespace {

class MinmaxPrefixTest : public viz::testing::TechniqueTest {
protected:
    // Every layer of the prefix-sum table of one run (row 0 of an image is the table's last row).
    static std::vector<viz::Image> prefixTables(const viz::scene::Scene& scene, const viz::Settings& settings) {
        auto technique = viz::makeTechnique("minmax");
        const viz::FrameOutput out = viz::testing::runTechnique(*technique, scene, settings, 64, 48, -1);
        const viz::Intermediate* table = find(out, "minmax.prefix_sums");
        if (!table || table->glTexture == 0) return {};
        GLint layers = 0;
        glGetTextureLevelParameteriv(table->glTexture, 0, GL_TEXTURE_DEPTH, &layers);
        std::vector<viz::Image> images;
        for (int layer = 0; layer < layers; ++layer) images.push_back(viz::gl::readTexture(table->glTexture, 0, layer));
        return images;
    }
};

// The largest difference between two tables over layers [0, layers), every row, channel and texel, relative
// to the row's sum of the terms' magnitudes (from `b`'s increments); fails past the recursive summation
// bound, texels x 2^-24 (the unit roundoff) times that sum, for either order of adding. (The singular vectors
// past the first change sign, so a row's prefixes can be far smaller than its terms.) Returns the largest
// such sum, so the caller can check the tables hold light at all.
double expectWithinRounding(const std::vector<viz::Image>& a, const std::vector<viz::Image>& b, std::size_t layers,
                            const std::string& what) {
    double worst = 0.0, largest = 0.0;
    for (std::size_t layer = 0; layer < layers; ++layer) {
        const viz::Image& x = a[layer];
        const viz::Image& y = b[layer];
        EXPECT_EQ(x.width, y.width) << what;
        EXPECT_EQ(x.height, y.height) << what;
        if (x.width != y.width || x.height != y.height) return 0.0;
        const int texels = x.width - 1;
        for (int row = 0; row < x.height; ++row) {
            for (int ch = 0; ch < x.channels; ++ch) {
                double scale = 0.0;
                for (int k = 0; k < texels; ++k) scale += std::abs(double(y.at(k + 1, row, ch)) - double(y.at(k, row, ch)));
                largest = std::max(largest, scale);
                EXPECT_EQ(x.at(0, row, ch), 0.0f) << what << " row " << row;
                const double bound = texels * std::ldexp(1.0, -24) * scale;
                for (int k = 0; k <= texels; ++k) {
                    const double d = std::abs(double(x.at(k, row, ch)) - double(y.at(k, row, ch)));
                    if (scale > 0.0) worst = std::max(worst, d / scale);
                    if (d > bound) {
                        ADD_FAILURE() << what << ": layer " << layer << " row " << row << " channel " << ch
                                      << " texel " << k << ": " << x.at(k, row, ch) << " against " << y.at(k, row, ch)
                                      << " (bound " << bound << ")";
                        return largest;
                    }
                }
            }
        }
    }
    std::printf("%s: %d rows, at most %.2e of the sum of a row's terms apart\n", what.c_str(), a[0].height, worst);
    return largest;
}

std::vector<std::pair<std::string, viz::scene::Scene>> prefixScenes() {
    return {{"stained-glass (spot, cookie)", viz::scene::makeBuiltinScene("stained-glass")},
            {"colonnade (sun)", viz::scene::makeBuiltinScene("colonnade")},
            {"point grate", viz::testing::pointGrate("on")}};
}

}  // namespace

// log2 passes against the sequential scan where the sequential scan fits llvmpipe's loop limit: table
// widths 100 (not a multiple of the 32-wide work group) and 1000 (lanes left idle at the end), at rank 8
// (24 floats a texel, six layers). Texel 0 of every row is exactly 0 and the tables hold light (a scan
// writing nothing would pass the comparison with itself).
TEST_F(MinmaxPrefixTest, Log2PassesGiveTheSequentialScanWithinRounding) {
    for (const auto& [name, scene] : prefixScenes()) {
        for (int texels : {100, 1000}) {
            ASSERT_TRUE(viz::minmax_detail::sequentialScanFits(texels, 8));
            const viz::Settings base{{"integrand", 1}, {"rank", 8}, {"texture_columns", texels}};
            viz::Settings log2 = base, sequential = base;
            log2["prefix_sums"] = 1;
            sequential["prefix_sums"] = 0;
            const std::vector<viz::Image> a = prefixTables(scene, log2);
            const std::vector<viz::Image> b = prefixTables(scene, sequential);
            ASSERT_EQ(a.size(), 6u) << name;
            ASSERT_EQ(b.size(), a.size()) << name;
            EXPECT_GT(expectWithinRounding(a, b, 6, name + ", " + std::to_string(texels) + " texels"), 0.0);
        }
    }
}

// Rows too long for a sequential scan within llvmpipe's 65,535 loop iterations (rank 8, 4096 texels: it
// stopped at texel 3855, leaving the rest of the row unsummed): prefix_sums=auto takes log2 passes and says
// why. Checked against the sequential scan of the rank-4 run, which fits: the SVD is computed whole and
// truncated, so the first four singular vectors (layers 0 to 2 of the table) are the same at either rank.
TEST_F(MinmaxPrefixTest, AutoTakesLog2PassesWhereASequentialRowWouldPassTheLoopLimit) {
    ASSERT_FALSE(viz::minmax_detail::sequentialScanFits(4096, 8));
    ASSERT_TRUE(viz::minmax_detail::sequentialScanFits(4096, 4));
    for (const auto& [name, scene] : prefixScenes()) {
        const viz::Settings rank8{{"integrand", 1}, {"rank", 8}, {"texture_columns", 4096}};
        const viz::Settings rank4{{"integrand", 1}, {"rank", 4}, {"texture_columns", 4096}, {"prefix_sums", 0}};
        auto technique = viz::makeTechnique("minmax");
        const viz::Plan plan = technique->plan(scene, viz::completeSettings(*technique, rank8));
        const viz::FeaturePlan f = feature(plan, "PREFIX_LOG2_PASSES");
        EXPECT_TRUE(f.enabled) << name;
        EXPECT_NE(f.why.find("loop"), std::string::npos) << f.why;
        const std::vector<viz::Image> a = prefixTables(scene, rank8);
        const std::vector<viz::Image> b = prefixTables(scene, rank4);
        ASSERT_EQ(a.size(), 6u) << name;
        ASSERT_EQ(b.size(), 3u) << name;
        EXPECT_GT(expectWithinRounding(a, b, 3, name + ", 4096 texels, rank 8 auto against rank 4 sequential"), 0.0);
    }
}
