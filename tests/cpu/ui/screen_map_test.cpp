// The window's registry of named rectangles (app/screen_map.h): what a script's name finds, in which
// order, and what the error lists when it finds nothing.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "screen_map.h"

namespace {

using airlight::ScreenMap;
using Rect = ScreenMap::Rect;

Rect box(float x) { return Rect{{x, 0.0f}, {x + 1.0f, 1.0f}}; }

TEST(ScreenMap, ANameFindsAWidgetFirstThenAViewThenANamedRectangle) {
    ScreenMap map;
    map.place("same", box(1));
    map.placeView({"same", "a view", box(2), 0});
    const std::map<std::string, Rect> widgets{{"same", box(3)}};
    EXPECT_EQ(map.find("same", widgets)->min.x, 3.0f);
    EXPECT_EQ(map.find("same", {})->min.x, 2.0f);
    map.clear();
    map.place("same", box(1));
    EXPECT_EQ(map.find("same", {})->min.x, 1.0f);
    EXPECT_FALSE(map.find("other", widgets).has_value());
}

TEST(ScreenMap, ALaterPlaceReplacesUnlessTheFirstIsKept) {
    ScreenMap map;
    map.place("timeline", box(1));
    map.place("timeline", box(2));
    EXPECT_EQ(map.find("timeline", {})->min.x, 2.0f);
    map.place("gizmo:position", box(3), true);
    map.place("gizmo:position", box(4), true);  // a second view showing the light: the first keeps the name
    EXPECT_EQ(map.find("gizmo:position", {})->min.x, 3.0f);
    // Views of one name: the first drawn is found, and every one is listed for the sidecar.
    map.placeView({"airlight", "L_air", box(5), 0});
    map.placeView({"airlight", "L_air", box(6), 1});
    EXPECT_EQ(map.find("airlight", {})->min.x, 5.0f);
    EXPECT_EQ(map.views().size(), 2u);
}

TEST(ScreenMap, KnownListsNamedRectanglesViewsAndWidgets) {
    ScreenMap map;
    map.place("window", box(0));
    map.placeView({"final", "Final image", box(1), 0});
    EXPECT_EQ(map.known({{"scene", box(2)}}), "window, final, scene");
    map.clear();
    EXPECT_EQ(map.known({}), "");
    EXPECT_TRUE(map.views().empty());
}

}  // namespace
