// A view's image rectangle (app/image_fit.h): pictures keep their aspect and fill the area's width or
// height; a data strip (a few rows much wider than tall, or a few columns much taller than wide) is
// stretched to at most 8:1 (1:8).
#include <gtest/gtest.h>

#include "image_fit.h"

namespace airlight {
namespace {

const viz::ui::Rect kArea{{100.0f, 50.0f}, {1100.0f, 450.0f}};  // 1000 x 400

TEST(ImageFit, PicturesKeepTheirAspectAndFillTheArea) {
    const viz::ui::Rect wide = fitImageRect(kArea, {320, 240});  // height-limited
    EXPECT_FLOAT_EQ(wide.size().y, 400.0f);
    EXPECT_FLOAT_EQ(wide.size().x, 400.0f * 320.0f / 240.0f);
    EXPECT_FLOAT_EQ(wide.min.x + wide.max.x, kArea.min.x + kArea.max.x) << "centred across";
    EXPECT_FLOAT_EQ(wide.min.y, kArea.min.y) << "top-aligned";
    const viz::ui::Rect pyramid = fitImageRect(kArea, {1024, 336});  // width-limited, tall enough: as is
    EXPECT_FLOAT_EQ(pyramid.size().x, 1000.0f);
    EXPECT_FLOAT_EQ(pyramid.size().y, 1000.0f * 336.0f / 1024.0f);
    const viz::ui::Rect line = fitImageRect(kArea, {2048, 17});  // more than 16 rows: a picture
    EXPECT_FLOAT_EQ(line.size().y, 1000.0f * 17.0f / 2048.0f);
}

TEST(ImageFit, AStripOfAFewRowsOrColumnsIsStretchedToEightToOne) {
    const viz::ui::Rect column = fitImageRect(kArea, {128, 2});  // a picked ray's bits before and after
    EXPECT_FLOAT_EQ(column.size().x, 1000.0f);
    EXPECT_FLOAT_EQ(column.size().y, 125.0f);
    const viz::ui::Rect perVpl = fitImageRect(kArea, {4096, 1});
    EXPECT_FLOAT_EQ(perVpl.size().x / perVpl.size().y, 8.0f);
    const viz::ui::Rect narrow = fitImageRect(kArea, {12, 2});  // 6:1 already: as is
    EXPECT_FLOAT_EQ(narrow.size().x / narrow.size().y, 6.0f);
    EXPECT_FLOAT_EQ(displayAspect({0, 0}), 1.0f) << "an empty image does not divide by zero";
    // A few columns, many rows (slices' planes along the picked ray: 6 x 128): 1:8, height-limited.
    const viz::ui::Rect table = fitImageRect(kArea, {6, 128});
    EXPECT_FLOAT_EQ(table.size().y, 400.0f);
    EXPECT_FLOAT_EQ(table.size().x, 50.0f);
    EXPECT_FLOAT_EQ(displayAspect({17, 400}), 17.0f / 400.0f) << "more than 16 columns: a picture";
}

}  // namespace
}  // namespace airlight
