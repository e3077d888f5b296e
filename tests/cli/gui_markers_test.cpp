// Linked cursors into shadow maps, end to end: a pixel hovered in the final frame puts its eye ray and
// the light-space points along it into the shadow-map view (the screenshot's sidecar JSON lists them).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "cli/sidecar_views.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class GuiMarkers : public WindowCliTest {
protected:
    json sidecar(const std::string& png) { return json::parse(readFile(path(png).replace_extension(".json"))); }
};

TEST_F(GuiMarkers, PolyvolShadowMapShowsTheRaysSignedCrossings) {
    const fs::path script =
        writeText("poly.txt", "click \"view:Spot shadow map\"\nframes 1\nhover final 0.62 0.84\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique polyvol --size 64x48 --set shadow_map=128 --script " +
                            script.string() + " --screenshot " + path("poly.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("poly.png");
    const json* map = sidecarView(j, "polyvol.shadow_map");
    ASSERT_NE(map, nullptr);
    ASSERT_TRUE(map->contains("markers"));
    const json& marks = map->at("markers");
    ASSERT_GE(marks.size(), 2u);
    // The segment says how many crossings and their signed sum; the points are those crossings.
    int count = -1, sum = 0;
    const std::string label = marks[0].at("label");
    const std::size_t at = label.find(": ");
    ASSERT_NE(at, std::string::npos) << label;
    ASSERT_EQ(std::sscanf(label.c_str() + at, ": %d crossings, signed %d", &count, &sum), 2) << label;
    int points = 0, signedPoints = 0;
    for (std::size_t i = 1; i < marks.size(); ++i) {
        EXPECT_EQ(marks[i].at("from"), marks[i].at("to"));
        const std::string l = marks[i].at("label");
        ASSERT_TRUE(l.rfind("+1 leaves lit", 0) == 0 || l.rfind("-1 enters lit", 0) == 0) << l;
        ++points;
        signedPoints += l[0] == '+' ? 1 : -1;
        EXPECT_EQ(marks[i].at("layer"), -1);
    }
    EXPECT_EQ(points, count);
    EXPECT_EQ(signedPoints, sum);
    EXPECT_GE(count, 2);  // the pixel looks at the floor through the cone
}

TEST_F(GuiMarkers, CubeMapMarksNameTheirFaceAndTheViewShowsThatFace) {
    // tv-room's area light as one VPL: its cube map. Hover a floor pixel, then step the view's layer to
    // the face the marks name (", ." step layers).
    const fs::path first = writeText("cube0.txt", "click \"view:VPL shadow cube\"\nframes 1\nhover final 0.35 0.75\n"
                                                  "frames 1\n");
    const std::string args = "gui --scene tv-room --technique raymarch --size 64x48 --set area_samples=1 "
                             "--set shadow_map=64 --set samples=8 --script ";
    ASSERT_EQ(run(args + first.string() + " --screenshot " + path("cube0.png").string()).exitCode, 0);
    const json before = sidecar("cube0.png");
    const json* cube = sidecarView(before, "raymarch.shadow_map");
    ASSERT_NE(cube, nullptr);
    ASSERT_GE(cube->at("markers").size(), 1u);
    const int face = cube->at("markers")[0].at("layer");
    ASSERT_GE(face, 0);
    ASSERT_LT(face, 6);
    std::string steps;
    for (int k = 0; k < face; ++k) steps += "key .\n";
    const fs::path second = writeText("cube1.txt", "click \"view:VPL shadow cube\"\nframes 1\nhover final 0.35 0.75\n"
                                                   "frames 1\n" + steps + "frames 1\n");
    ASSERT_EQ(run(args + second.string() + " --screenshot " + path("cube1.png").string()).exitCode, 0);
    const json j = sidecar("cube1.png");
    const json* shown = sidecarView(j, "raymarch.shadow_map");
    ASSERT_NE(shown, nullptr);
    EXPECT_EQ(shown->at("layer"), face);
    EXPECT_EQ(shown->at("markers").size(), cube->at("markers").size());
}

}  // namespace
}  // namespace viz::testing
