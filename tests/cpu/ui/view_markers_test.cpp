// A technique's marks drawn over a view (app/view_markers.h): labels stay inside the image and off each
// other, many labelled points go into a key instead, marks of another layer are left out (the key names
// their layers), and nothing is drawn outside the image. Checked on the draw list itself.
#include <gtest/gtest.h>

#include "ui/font.h"
#include "cpu/ui/synthetic_panel.h"
#include "view_markers.h"

namespace airlight {
namespace {

using viz::ui::Rect;

using viz::ui::testing::testFont;

ViewState viewAt(const Rect& image) {
    ViewState v;
    v.image = image;
    v.pane.size = {64, 48};
    return v;
}

bool inside(const Rect& r, const Rect& outer) {
    return r.min.x >= outer.min.x - 1e-3f && r.max.x <= outer.max.x + 1e-3f && r.min.y >= outer.min.y - 1e-3f &&
           r.max.y <= outer.max.y + 1e-3f;
}

TEST(ViewMarkers, LabelsOfMarksCloseTogetherStayInsideTheImageAndOffEachOther) {
    const Rect image{{100, 100}, {300, 250}};
    const ViewState v = viewAt(image);
    std::vector<viz::ViewMarker> marks;
    // Five segments from nearly one point to the image's right edge: their labels would pile up there.
    for (int i = 0; i < 5; ++i)
        marks.push_back({{0.6f, 0.3f + 0.01f * float(i)}, {0.99f, 0.32f + 0.01f * float(i)}, "crossing " + std::to_string(i), -1});
    viz::ui::DrawList dl(testFont());
    const std::vector<Rect> placed = drawViewMarkers(dl, testFont(), 1.0f, v, marks);
    ASSERT_EQ(placed.size(), 5u);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        EXPECT_TRUE(inside(placed[i], image)) << i;
        for (std::size_t k = 0; k < i; ++k) {
            const bool apart = placed[i].min.x >= placed[k].max.x || placed[k].min.x >= placed[i].max.x ||
                               placed[i].min.y >= placed[k].max.y || placed[k].min.y >= placed[i].max.y;
            EXPECT_TRUE(apart) << i << " over " << k;
        }
    }
    for (const viz::ui::UiVertex& p : dl.vertices()) {
        EXPECT_GE(p.position.x, image.min.x - 1e-3f);
        EXPECT_LE(p.position.x, image.max.x + 1e-3f);
        EXPECT_GE(p.position.y, image.min.y - 1e-3f);
        EXPECT_LE(p.position.y, image.max.y + 1e-3f);
    }
}

// polyvol's shadow-map view: the eye ray (a line, labelled) and its four crossings close together on it.
// The crossings get numbers clear of each other, and the ray's label goes into the key with theirs: it
// once lay across the numbers.
TEST(ViewMarkers, ARaysLabelAndItsCrossingsNumbersDoNotOverlap) {
    const Rect image{{0, 0}, {360, 360}};
    const ViewState v = viewAt(image);
    std::vector<viz::ViewMarker> marks = {{{0.2f, 0.35f}, {1.0f, 0.37f}, "eye ray t=3.56..5.38: 4 crossings, signed +0", -1}};
    for (int i = 0; i < 4; ++i) {
        const float x = 0.74f + 0.04f * float(i);
        marks.push_back({{x, 0.36f}, {x, 0.36f}, "crossing " + std::to_string(i), -1});
    }
    viz::ui::DrawList dl(testFont());
    const std::vector<Rect> placed = drawViewMarkers(dl, testFont(), 1.0f, v, marks);
    ASSERT_EQ(placed.size(), 4u) << "a number per crossing, the ray's label in the key";
    for (std::size_t i = 0; i < placed.size(); ++i)
        for (std::size_t k = 0; k < i; ++k) {
            const bool apart = placed[i].min.x >= placed[k].max.x || placed[k].min.x >= placed[i].max.x ||
                               placed[i].min.y >= placed[k].max.y || placed[k].min.y >= placed[i].max.y;
            EXPECT_TRUE(apart) << i << " over " << k;
        }
}

TEST(ViewMarkers, ManyLabelledPointsGetNumbersAndAKeyAndOtherLayersAreLeftOut) {
    const ViewState v = viewAt({{0, 0}, {320, 240}});
    std::vector<viz::ViewMarker> points;
    for (int i = 0; i < 4; ++i) points.push_back({{0.2f + 0.1f * float(i), 0.5f}, {0.2f + 0.1f * float(i), 0.5f}, "node " + std::to_string(i), -1});
    viz::ui::DrawList dl(testFont());
    EXPECT_EQ(drawViewMarkers(dl, testFont(), 1.0f, v, points).size(), 4u) << "numbers only: the labels go into the key";
    const std::size_t drawn = dl.vertices().size();
    EXPECT_GT(drawn, 0u);
    // The same with a mark on another layer (a cube map's other face, top right): it is not drawn, and the
    // key (bottom left) gains a line naming its layer.
    std::vector<viz::ViewMarker> more = points;
    more.push_back({{0.8f, 0.1f}, {0.95f, 0.2f}, "on face 3", 3});
    viz::ui::DrawList other(testFont());
    (void)drawViewMarkers(other, testFont(), 1.0f, v, more);
    EXPECT_GT(other.vertices().size(), drawn);
    const Rect farMark{{0.8f * 320.0f - 6.0f, 0.1f * 240.0f - 6.0f}, {0.95f * 320.0f + 6.0f, 0.2f * 240.0f + 6.0f}};
    for (const viz::ui::UiVertex& p : other.vertices()) {
        // (v.pane.glRows is false: data rows are the image's rows.)
        EXPECT_FALSE(farMark.contains(p.position)) << p.position.x << ", " << p.position.y;
        EXPECT_TRUE(p.position.x <= 320.0f && p.position.y <= 240.0f && p.position.x >= 0.0f && p.position.y >= 0.0f);
    }
    // Two labelled points: labels beside them, no key.
    viz::ui::DrawList two(testFont());
    EXPECT_EQ(drawViewMarkers(two, testFont(), 1.0f, v, {points[0], points[1]}).size(), 2u);
}

// The key's note on marks elsewhere counts layers from 1, as the view's title does ("layer 4/6").
TEST(ViewMarkers, TheNoteNamesTheOtherLayersThatHoldMarks) {
    const auto mark = [](int layer) { return viz::ViewMarker{{0.1f, 0.1f}, {0.2f, 0.2f}, "m", layer}; };
    EXPECT_EQ(otherLayersNote({mark(-1), mark(2)}, 2, 6), "");
    EXPECT_EQ(otherLayersNote({mark(4), mark(4), mark(2)}, 2, 6), "marks on layer 5 of 6 (, / . to step)");
    EXPECT_EQ(otherLayersNote({mark(4), mark(1), mark(3), mark(-1)}, 3, 6),
              "marks on layers 2 and 5 of 6 (, / . to step)");
    EXPECT_EQ(otherLayersNote({mark(0), mark(1), mark(5)}, 3, 6), "marks on layers 1, 2 and 6 of 6 (, / . to step)");
    EXPECT_EQ(otherLayersNote({}, 0, 1), "");
}

}  // namespace
}  // namespace airlight
