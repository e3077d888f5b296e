// Pan and zoom of an image view: the point under the cursor stays put and the view stays on the image.
#include <gtest/gtest.h>

#include "ui/image_view.h"

namespace viz::ui {
namespace {

TEST(ImageViewTransform, ZoomKeepsThePointUnderTheCursorAndPanStaysOnTheImage) {
    ImageViewTransform v;
    EXPECT_EQ(v.paneToUv({0.0, 0.0}), glm::dvec2(0.0, 0.0));
    EXPECT_EQ(v.paneToUv({1.0, 1.0}), glm::dvec2(1.0, 1.0));
    const glm::dvec2 cursor{0.8, 0.3};
    const glm::dvec2 before = v.paneToUv(cursor);
    v.zoomAt(cursor, 8.0);
    EXPECT_DOUBLE_EQ(v.zoom, 8.0);
    EXPECT_NEAR(glm::length(v.paneToUv(cursor) - before), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(v.uvToPane(v.paneToUv({0.1, 0.9})) - glm::dvec2(0.1, 0.9)), 0.0, 1e-12);
    // 160 texels shown 640 pixels wide at zoom 8: each texel covers 32 pixels.
    EXPECT_DOUBLE_EQ(v.texelPixels(640.0, 160.0), 32.0);
    // Panning far away stops at the image's edge.
    v.panBy({100.0, -100.0});
    EXPECT_NEAR(v.paneToUv({0.0, 0.0}).x, 0.0, 1e-12);
    EXPECT_NEAR(v.paneToUv({1.0, 1.0}).y, 1.0, 1e-12);
    // Zooming out past 1 fits the image again.
    v.zoomAt(cursor, 1e-6);
    EXPECT_DOUBLE_EQ(v.zoom, 1.0);
    EXPECT_EQ(v.center, glm::dvec2(0.5));
}

}  // namespace
}  // namespace viz::ui
