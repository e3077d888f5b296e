// The values a zoomed-in view writes into its texels (app/texel_labels.h), no window: which texels are
// labelled at which zoom (worked out by hand), and that every label sits in its own texel and says that
// texel's value, channel by channel.
#include <gtest/gtest.h>

#include <cstdio>

#include "texel_labels.h"
#include "cpu/ui/synthetic_panel.h"

namespace airlight {
namespace {

using viz::ui::ImageViewTransform;
using viz::ui::Rect;

using viz::ui::testing::testFont;

TEST(TexelLabels, OnlyAZoomThatGivesATexelRoomForItsValueLabelsTheTexelsInView) {
    const Rect image{{100.0f, 50.0f}, {500.0f, 350.0f}};  // 400 x 300 pixels
    const glm::ivec2 pane{8, 6};                           // 50 pixels a texel at zoom 1
    const float line = testFont().lineHeight();
    ASSERT_GT(4.2f * line, 50.0f) << "the test assumes a 50-pixel texel is too small for a label";
    ASSERT_LT(4.2f * line, 100.0f);
    ImageViewTransform view;
    EXPECT_FALSE(labelledTexels(pane, image, view, line)) << "zoom 1: texels too small";
    view.zoom = 2.0;  // 100 pixels a texel; the middle half of the image is in view: u 0.25 .. 0.75
    const auto block = labelledTexels(pane, image, view, line);
    ASSERT_TRUE(block);
    EXPECT_EQ(block->lo, glm::ivec2(2, 1));  // x 8 * 0.25 = 2, y 6 * 0.25 = 1.5
    EXPECT_EQ(block->hi, glm::ivec2(5, 4));  // x just under 8 * 0.75 = 6, y just under 4.5
    // Panned to the top-left corner: the block starts at texel 0.
    view.center = {0.25, 0.25};
    const auto corner = labelledTexels(pane, image, view, line);
    ASSERT_TRUE(corner);
    EXPECT_EQ(corner->lo, glm::ivec2(0, 0));
    EXPECT_EQ(corner->hi, glm::ivec2(3, 2));
    // Texels large enough but too many in view (100 x 100 of them): none.
    EXPECT_FALSE(labelledTexels({100, 100}, {{0.0f, 0.0f}, {7200.0f, 7200.0f}}, ImageViewTransform{}, line));
}

TEST(TexelLabels, EachLabelSitsInItsTexelAndSaysItsValueChannelByChannel) {
    const Rect image{{0.0f, 0.0f}, {400.0f, 300.0f}};
    const glm::ivec2 pane{8, 6};
    ImageViewTransform view;
    view.zoom = 2.0;
    const auto block = labelledTexels(pane, image, view, testFont().lineHeight());
    ASSERT_TRUE(block);
    const auto value = [](int x, int y) { return glm::vec4(float(x + 10 * y), -0.5f * float(x), 1e-4f * float(y), 7.0f); };
    for (int channels : {1, 3}) {
        SCOPED_TRACE(channels);
        const std::vector<TexelLabel> labels = texelLabels(*block, pane, image, view, channels, value, testFont(), 1.0f);
        // 4 x 4 texels in view, each whole (100 pixels, 50 of the first and last shown): every one labelled.
        std::map<std::pair<int, int>, std::vector<std::string>> byTexel;
        for (const TexelLabel& l : labels) {
            EXPECT_TRUE(image.contains(l.at));
            const glm::ivec2 t = texelUnder(pane, image, view, l.at);
            byTexel[{t.x, t.y}].push_back(l.text);
            EXPECT_GT(l.clipX, l.at.x);
        }
        EXPECT_EQ(byTexel.size(), 16u);
        for (const auto& [t, texts] : byTexel) {
            ASSERT_EQ(int(texts.size()), channels) << t.first << "," << t.second;
            char expected[32];
            std::snprintf(expected, sizeof expected, "%.3g", double(t.first + 10 * t.second));
            EXPECT_EQ(texts[0], expected);
            if (channels == 3) {
                std::snprintf(expected, sizeof expected, "%.3g", -0.5 * double(t.first));
                EXPECT_EQ(texts[1], expected);
                std::snprintf(expected, sizeof expected, "%.3g", double(1e-4f * float(t.second)));
                EXPECT_EQ(texts[2], expected);
            }
        }
    }
    // Panned right by a sixth of a texel (16.7 pixels): column 6 comes into view by that much, too little
    // for a label; the others keep theirs.
    view.center.x += (1.0 / 6.0) / 8.0;
    const auto cut = labelledTexels(pane, image, view, testFont().lineHeight());
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->hi.x, 6);
    const std::vector<TexelLabel> labels = texelLabels(*cut, pane, image, view, 1, value, testFont(), 1.0f);
    for (const TexelLabel& l : labels) {
        const glm::ivec2 t = texelUnder(pane, image, view, l.at);
        const double left = (view.uvToPane(glm::dvec2(double(t.x) / 8.0, 0.0)).x) * 400.0;
        const double right = (view.uvToPane(glm::dvec2(double(t.x + 1) / 8.0, 0.0)).x) * 400.0;
        EXPECT_GE(std::min(right, 400.0) - std::max(left, 0.0), 3.0 * testFont().lineHeight()) << t.x;
        EXPECT_NE(t.x, 6);
    }
    EXPECT_EQ(labels.size(), 16u);  // columns 2 to 5, rows 1 to 4
}

}  // namespace
}  // namespace airlight
