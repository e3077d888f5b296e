// The window's ray inspector (`I`), driven as a user does it: the pixel under the cursor, the reference's
// and the technique's values there, the technique's own view of the ray, and silhouette pixels; each
// checked against what `airlight render` writes for the same pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

class GuiInspector : public WindowCliTest {
protected:
    // Opens the window with `args`, lets it draw, hovers the final view at (fx, fy) of its image, presses
    // I and returns the screenshot sidecar (its "inspector" holds the panel's figures).
    nlohmann::json inspect(const std::string& name, const std::string& args, double fx, double fy) {
        const fs::path script = writeText(name + ".txt", "frames 2\nhover final " + std::to_string(fx) + " " +
                                                             std::to_string(fy) + "\nkey I\nframes 2\n");
        const RunResult r =
            run("gui " + args + " --script " + script.string() + " --screenshot " + path(name + ".png").string());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return nlohmann::json::parse(readFile(path(name + ".json")));
    }
};

TEST_F(GuiInspector, TheRayInspectorShowsTheValuesAirlightRenderGivesAtThatPixel) {
    const nlohmann::json j = inspect("inspect", "--scene grate --technique raymarch --size 40x30 --set samples=128",
                                     20.5 / 40.0, 0.45);  // the centre of a pixel, not the edge at 0.5
    ASSERT_TRUE(j.contains("inspector"));
    const auto& in = j.at("inspector");
    const int x = in.at("pixel")[0].get<int>(), y = in.at("pixel")[1].get<int>();
    EXPECT_EQ(x, 20);  // the middle column of 40
    // The light gizmo would cover the inspected pixel: it is hidden while the inspector is open.
    EXPECT_TRUE(j.at("gizmo").is_null()) << j.at("gizmo");
    // The same pixel from the command line: the reference and the technique, rendered on their own.
    ASSERT_EQ(run("render --scene grate --technique reference --size 40x30 --layer airlight --out " +
                  path("ref.exr").string()).exitCode, 0);
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 40x30 --set samples=128 --layer airlight --out " +
                  path("rm.exr").string()).exitCode, 0);
    const Image ref = readImage(path("ref.exr").string()), rm = readImage(path("rm.exr").string());
    for (int c = 0; c < 3; ++c) {
        const double expectRef = ref.at(x, y, c), expectRm = rm.at(x, y, c);
        EXPECT_NEAR(in.at("reference")[std::size_t(c)].get<double>(), expectRef, 1e-6 * expectRef + 1e-9);
        EXPECT_NEAR(in.at("technique_value")[std::size_t(c)].get<double>(), expectRm, 1e-5 * expectRm + 1e-9);
    }
    ASSERT_EQ(in.at("lights").size(), 1u);
    EXPECT_FALSE(in.at("lights")[0].at("lit").empty());
}

// A silhouette pixel: on forest at 80x60 the ray through pixel (44, 21) meets a trunk's edge at 36.9
// while the rasteriser passes it and sees the sky (zfar 80). The inspector says so, with both
// distances, which are those `render` writes as reference.distance and raymarch.distance.
TEST_F(GuiInspector, TheRayInspectorNamesASilhouettePixel) {
    const nlohmann::json j = inspect("inspect_edge", "--scene forest --technique raymarch --size 80x60 --set samples=16",
                                     (44 + 0.5) / 80.0, (21 + 0.5) / 60.0);
    const auto& in = j.at("inspector");
    const int x = in.at("pixel")[0].get<int>(), y = in.at("pixel")[1].get<int>();
    ASSERT_EQ(x, 44);
    ASSERT_EQ(y, 21);
    ASSERT_TRUE(in.contains("first_hit")) << in.dump();
    ASSERT_EQ(run("render --scene forest --technique reference --size 80x60 --layer reference.distance --quiet --out " +
                  path("traced.exr").string()).exitCode, 0);
    ASSERT_EQ(run("render --scene forest --technique raymarch --size 80x60 --layer raymarch.distance --stop-after "
                  "raymarch.surface --quiet --out " + path("drawn.exr").string()).exitCode, 0);
    const float traced = readImage(path("traced.exr").string()).at(x, y);
    const float drawn = readImage(path("drawn.exr").string()).at(x, y);
    EXPECT_NEAR(in.at("first_hit").at("traced").get<double>(), traced, 1e-4 * traced);
    EXPECT_NEAR(in.at("first_hit").at("drawn").get<double>(), drawn, 1e-4 * drawn);
    EXPECT_GT(std::abs(traced - drawn), 0.01f * traced) << "not a silhouette pixel any more";
    EXPECT_FALSE(in.at("first_hit").at("agree").get<bool>());
}

// The inspector shows the technique's own view of the ray: its per-pixel intermediates at the pixel
// (vsv: visibility fraction, L_air) and its per-ray views, which follow the inspected pixel (pick_x/y).
TEST_F(GuiInspector, TheRayInspectorShowsTheTechniquesOwnViewOfThePixel) {
    const nlohmann::json j = inspect("inspect_vsv", "--scene grate --technique vsv --size 40x30", 0.3, 0.6);
    const auto& in = j.at("inspector");
    const int x = in.at("pixel")[0].get<int>(), y = in.at("pixel")[1].get<int>();
    EXPECT_EQ(j.at("settings").at("pick_x").get<int>(), x);
    EXPECT_EQ(j.at("settings").at("pick_y").get<int>(), y);
    ASSERT_TRUE(in.contains("readings"));
    const auto& readings = in.at("readings");
    ASSERT_TRUE(readings.contains("vsv.airlight")) << readings.dump();
    ASSERT_TRUE(readings.contains("vsv.visibility")) << readings.dump();
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(readings.at("vsv.airlight")[std::size_t(c)].get<double>(),
                  in.at("technique_value")[std::size_t(c)].get<double>());
    // A colour reads as its three channels, never an RGBA texture's padding alpha.
    EXPECT_EQ(readings.at("vsv.airlight").size(), 3u) << readings.dump();
    EXPECT_EQ(readings.at("vsv.surface").size(), 3u) << readings.dump();
    // Inside the grate's plate, not at a silhouette: the rasterised and traced first hits agree.
    ASSERT_TRUE(in.contains("first_hit")) << in.dump();
    EXPECT_TRUE(in.at("first_hit").at("agree").get<bool>()) << in.at("first_hit").dump();
    const double visible = readings.at("vsv.visibility")[0].get<double>();
    EXPECT_GE(visible, 0.0);
    EXPECT_LE(visible, 1.0);
    const auto& views = in.at("ray_views");
    EXPECT_NE(std::find(views.begin(), views.end(), "vsv.column"), views.end()) << views.dump();
}

// slices in the ray inspector: its per-ray views (the planes along the ray, a table and a chart) follow the
// inspected pixel, and the plot shows one point per shaded plane, its L_air over its dt, as the table that
// `airlight render --layer slices.ray_planes` writes for the same pixel holds them.
TEST_F(GuiInspector, TheRayInspectorPlotsTheSlicesPlanesAlongTheRay) {
    const nlohmann::json j = inspect("inspect_slices", "--scene grate --technique slices --size 40x30 --set planes=32",
                                     0.52, 0.6);
    const auto& in = j.at("inspector");
    const int x = in.at("pixel")[0].get<int>(), y = in.at("pixel")[1].get<int>();
    const auto& views = in.at("ray_views");
    for (const char* id : {"slices.ray_planes", "slices.ray_planes_chart"})
        EXPECT_NE(std::find(views.begin(), views.end(), id), views.end()) << views.dump();
    const auto& series = in.at("ray_series");
    ASSERT_TRUE(series.contains("slices, stored")) << series.dump();
    const auto& points = series.at("slices, stored");
    ASSERT_EQ(run("render --scene grate --technique slices --size 40x30 --set planes=32 --set pick_x=" +
                  std::to_string(x) + " --set pick_y=" + std::to_string(y) +
                  " --layer slices.ray_planes --out " + path("planes.exr").string()).exitCode, 0);
    const Image table = readImage(path("planes.exr").string());
    ASSERT_EQ(table.channels, 4);
    std::size_t k = 0;
    for (int row = 0; row < table.height; ++row) {
        if (table.at(1, row, 0) != 1.0f) continue;  // status 1: shaded and added
        ASSERT_LT(k, points.size());
        const double t = table.at(0, row, 2), dt = table.at(0, row, 3), lair = table.at(5, row, 2);
        EXPECT_NEAR(points[k][0].get<double>(), t, 1e-6 * t);
        EXPECT_NEAR(points[k][1].get<double>(), lair / dt, 1e-6 * std::abs(lair / dt) + 1e-12);
        ++k;
    }
    EXPECT_GT(k, 0u) << "the inspected pixel lies in the spot's light";
    EXPECT_EQ(k, points.size());
}

}  // namespace
}  // namespace viz::testing
