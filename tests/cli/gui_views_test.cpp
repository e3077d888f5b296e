// The window's view grid under a (virtual) display: splitting, swapping and maximising views, linked
// cursors across screen-space views and into minmax's rectified map, difference views with the
// report's error figures, and the negative-pixel count. Checked through the screenshot's sidecar JSON
// and, where another path computes the same number, against it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class GuiViews : public WindowCliTest {
protected:
    json sidecar(const std::string& png) { return json::parse(readFile(path(png).replace_extension(".json"))); }
};

const json* viewWithCell(const json& j, int cell) {
    for (const auto& v : j.at("views"))
        if (v.value("cell", -1) == cell) return &v;
    return nullptr;
}

// ||a - b|| / ||b|| over RGB, and max |a - b|: the report's figures, computed here on their own.
double relativeL2Of(const Image& a, const Image& b, double& maxAbs) {
    double diff2 = 0.0, ref2 = 0.0;
    maxAbs = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double e = double(a.at(x, y, c)) - double(b.at(x, y, c));
                diff2 += e * e;
                ref2 += double(b.at(x, y, c)) * b.at(x, y, c);
                maxAbs = std::max(maxAbs, std::abs(e));
            }
    return std::sqrt(diff2 / ref2);
}

bool overlap(const json& a, const json& b) {
    return a[0].get<double>() < b[2].get<double>() && b[0].get<double>() < a[2].get<double>() &&
           a[1].get<double>() < b[3].get<double>() && b[1].get<double>() < a[3].get<double>();
}

TEST_F(GuiViews, TheGridSplitsSwapsAndMaximisesAndCursorsLinkAcrossScreenSpaceViews) {
    // View 1 (L_air, focused) gets a view beside it (2: the next entry, the shadow map) and view 2 one
    // below it (3: the next again, the distance d); then 3 swaps with the next in reading order (0, the
    // final frame); the cursor hovers L_air's centre; finally 3 is maximised.
    const fs::path script = writeText("grid.txt", "key H\nframes 1\nkey J\nframes 1\nscreenshot " +
                                                      path("four.png").string() +
                                                      "\nkey O\nframes 1\nhover cell:1 0.5 0.5\nframes 1\nscreenshot " +
                                                      path("linked.png").string() + "\nkey M\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 64x48 --set samples=32 --script " +
                            script.string() + " --screenshot " + path("max.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const json four = sidecar("four.png");
    EXPECT_EQ(four.at("view_grid").at("layout"), "x(0.5,0,x(0.5,1,y(0.5,2,3)))");
    EXPECT_EQ(four.at("view_grid").at("focused"), 3);
    ASSERT_EQ(four.at("views").size(), 4u);
    EXPECT_EQ(four.at("views")[0].at("name"), "final");
    EXPECT_EQ(four.at("views")[1].at("name"), "airlight");
    EXPECT_EQ(four.at("views")[2].at("name"), "raymarch.shadow_map");
    EXPECT_EQ(four.at("views")[3].at("name"), "raymarch.distance");
    for (std::size_t i = 0; i < 4; ++i) {
        const json& rect = four.at("views")[i].at("cell_rect");
        EXPECT_GE(rect[0].get<double>(), 0.0);
        EXPECT_LE(rect[2].get<double>(), four.at("window")[0].get<double>());
        for (std::size_t k = i + 1; k < 4; ++k) EXPECT_FALSE(overlap(rect, four.at("views")[k].at("cell_rect"))) << i << k;
    }
    // 2 sits above 3 in the right quarter.
    EXPECT_LT(four.at("views")[2].at("cell_rect")[3].get<double>(), four.at("views")[3].at("cell_rect")[1].get<double>());

    const json linked = sidecar("linked.png");
    EXPECT_EQ(linked.at("view_grid").at("layout"), "x(0.5,3,x(0.5,1,y(0.5,2,0)))");
    ASSERT_EQ(linked.at("view_grid").at("linked_pixel"), json::array({32, 24}));
    const json* final = viewWithCell(linked, 0);
    const json* airlight = viewWithCell(linked, 1);
    const json* shadow = viewWithCell(linked, 2);
    const json* distance = viewWithCell(linked, 3);
    ASSERT_TRUE(final && airlight && shadow && distance);
    // Swapped: the distance view now has the final frame's old place.
    EXPECT_EQ((*distance).at("cell_rect"), four.at("views")[0].at("cell_rect"));
    for (const json* v : {final, airlight, distance}) {
        EXPECT_TRUE(v->at("screen_space").get<bool>()) << v->at("name");
        EXPECT_EQ(v->at("cursor"), json::array({32, 24})) << v->at("name");
    }
    EXPECT_FALSE(shadow->at("screen_space").get<bool>());
    EXPECT_TRUE(shadow->at("cursor").is_null());
    // The value each view shows there is what `airlight render` gives at that pixel.
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 64x48 --set samples=32 --layer airlight --out " +
                  path("airlight.exr").string()).exitCode, 0);
    const Image expected = readImage(path("airlight.exr").string());
    for (int c = 0; c < 3; ++c) {
        const double want = expected.at(32, 24, c);
        EXPECT_NEAR(airlight->at("cursor_value")[std::size_t(c)].get<double>(), want, 1e-5 * want + 1e-9);
    }
    // Also through a GL texture (row 0 at the bottom in GL): the distance view's value at the pixel.
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 64x48 --set samples=32 --layer raymarch.distance "
                  "--out " + path("distance.exr").string()).exitCode, 0);
    const Image d = readImage(path("distance.exr").string());
    ASSERT_EQ(d.width, 64);
    EXPECT_NEAR(distance->at("cursor_value")[0].get<double>(), d.at(32, 24, 0), 1e-5 * std::abs(d.at(32, 24, 0)));
    // The linked view draws a cyan crosshair around the pixel (its arm 5 px right of the centre).
    const Image shot = readImage(path("linked.png").string());
    const json& rect = final->at("rect");
    const double cx = rect[0].get<double>() + (32.5 / 64.0) * (rect[2].get<double>() - rect[0].get<double>());
    const double cy = rect[1].get<double>() + (24.5 / 48.0) * (rect[3].get<double>() - rect[1].get<double>());
    const int px = int(cx) + 5, py = int(cy);
    EXPECT_GT(shot.at(px, py, 1), 0.8f);
    EXPECT_GT(shot.at(px, py, 2), 0.8f);
    EXPECT_LT(shot.at(px, py, 0), 0.3f);

    const json max = sidecar("max.png");
    EXPECT_EQ(max.at("view_grid").at("maximised"), 3);
    ASSERT_EQ(max.at("views").size(), 1u);
    EXPECT_EQ(max.at("views")[0].at("cell"), 3);
    // The maximised view spans the grid: as wide as the four views together.
    EXPECT_EQ(max.at("views")[0].at("cell_rect")[0], four.at("views")[0].at("cell_rect")[0]);
    EXPECT_EQ(max.at("views")[0].at("cell_rect")[2], four.at("views")[3].at("cell_rect")[2]);
}

TEST_F(GuiViews, ADifferenceViewCarriesTheReportsErrorAgainstTheReference) {
    // F: the focused view (L_air) shows |raymarch - reference|; its relative L2 is the one computed here
    // from the two images `airlight render` writes.
    // Then the chooser sets the other side to slices.
    const fs::path script = writeText("diff.txt", "key F\nframes 1\nclick strip:1\nframes 1\nclick \"log scale##v1\"\n"
                                                  "frames 1\nscreenshot " + path("diff.png").string() +
                                                  "\nclick \"against##v1\"\nframes 1\nclick \"against##v1/slices\"\n"
                                                  "frames 1\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 40x30 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("slices.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("diff.png");
    const json* v = viewWithCell(j, 1);
    ASSERT_TRUE(v);
    ASSERT_TRUE(v->contains("difference"));
    const json& d = v->at("difference");
    EXPECT_EQ(d.at("against"), "reference");
    EXPECT_EQ(d.at("mode"), "|a - b|");
    EXPECT_TRUE(v->at("display").at("log").get<bool>());
    EXPECT_TRUE(v->at("display").at("strip_open").get<bool>());
    EXPECT_EQ(v->at("display").at("mode"), 8);  // the heat map
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 40x30 --set samples=16 --layer airlight --out " +
                  path("rm.exr").string()).exitCode, 0);
    ASSERT_EQ(run("render --scene grate --technique reference --size 40x30 --layer airlight --out " +
                  path("ref.exr").string()).exitCode, 0);
    const Image a = readImage(path("rm.exr").string()), b = readImage(path("ref.exr").string());
    double maxAbs = 0.0;
    const double relativeL2 = relativeL2Of(a, b, maxAbs);
    ASSERT_TRUE(d.at("relative_l2").is_number());
    EXPECT_GT(relativeL2, 0.0);
    EXPECT_NEAR(d.at("relative_l2").get<double>(), relativeL2, 1e-6 * relativeL2);
    EXPECT_NEAR(d.at("max_abs").get<double>(), maxAbs, 1e-6 * maxAbs);
    // The difference of an image with no negative values has none either.
    EXPECT_EQ(v->at("negative_pixels"), 0);

    const json second = sidecar("slices.png");
    const json* toSlices = viewWithCell(second, 1);
    ASSERT_TRUE(toSlices);
    EXPECT_EQ(toSlices->at("difference").at("against"), "slices");
    ASSERT_EQ(run("render --scene grate --technique slices --size 40x30 --layer airlight --out " +
                  path("slices.exr").string()).exitCode, 0);
    double ignored = 0.0;
    const double toSlicesL2 = relativeL2Of(a, readImage(path("slices.exr").string()), ignored);
    ASSERT_TRUE(toSlices->at("difference").at("relative_l2").is_number());
    EXPECT_NEAR(toSlices->at("difference").at("relative_l2").get<double>(), toSlicesL2, 1e-6 * toSlicesL2);
}

TEST_F(GuiViews, ADifferenceViewAgainstTheReferenceIsHeldWhilePlayingAndFollowsWhenPlayStops) {
    // While P plays the light turns every frame; the reference (seconds a pass) is not asked again per
    // frame: its last image stands, titled so. When play stops it renders the frame as play left it.
    const fs::path script = writeText("play.txt", "key F\nframes 1\nscreenshot " + path("still.png").string() +
                                                      "\nkey P\nframes 12\nscreenshot " + path("play.png").string() +
                                                      "\nkey P\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique raymarch --size 40x30 --set samples=16 --script " +
                            script.string() + " --screenshot " + path("stopped.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto view = [&](const std::string& png) {
        const json j = sidecar(png);
        const json* v = viewWithCell(j, 1);
        EXPECT_TRUE(v && v->contains("difference")) << png;
        return v ? *v : json::object();
    };
    const json still = view("still.png"), playing = view("play.png"), stopped = view("stopped.png");
    const auto l2 = [](const json& v) { return v.at("difference").at("relative_l2").get<double>(); };
    EXPECT_EQ(still.at("title").get<std::string>().find("held"), std::string::npos);
    EXPECT_NE(playing.at("title").get<std::string>().find("(held while playing)"), std::string::npos)
        << playing.at("title");
    EXPECT_EQ(stopped.at("title").get<std::string>().find("held"), std::string::npos) << stopped.at("title");
    // Held, the reference is of the still light: raymarch's moved shafts are far from it. Once play stops
    // the two are of the same frame again, as close as on the still frame.
    EXPECT_GT(l2(playing), 5.0 * l2(still));
    EXPECT_LT(l2(stopped), 2.0 * l2(still));
}

TEST_F(GuiViews, SentinelTexelsAreCountedApartAndMinmaxMarksThePixelsEpipolarRow) {
    // minmax's rectified map stores -1 for light rays outside the spot's cone: a sentinel the view
    // counts apart; hovering the final frame marks the pixel's slice as a row there. (0.5104, 0.5139) is
    // the centre of pixel (24, 18), not the edge between two pixels at 0.5.
    const fs::path script =
        writeText("neg.txt", "click \"view:Rectified shadow map S\"\nframes 1\nhover final 0.5104 0.5139\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique minmax --size 48x36 --script " + script.string() +
                            " --screenshot " + path("neg.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("neg.png");
    const json* final = viewWithCell(j, 0);
    const json* rect = viewWithCell(j, 1);
    ASSERT_TRUE(final && rect);
    EXPECT_EQ(rect->at("name"), "minmax.rectified");
    EXPECT_EQ(final->at("negative_pixels"), 0);
    // Its -1 is a declared sentinel: counted in the colour bar's legend under its meaning, not as negative
    // pixels in red in the title.
    EXPECT_EQ(rect->at("negative_pixels").get<int>(), 0);
    EXPECT_EQ(rect->at("title").get<std::string>().find("negative"), std::string::npos) << rect->at("title");
    long outside = -1;
    for (const auto& l : rect->at("colour_bar").at("legend"))
        if (l.at("sentinel") && l.at("value") == -1.0) outside = l.at("pixels");
    EXPECT_GT(outside, 0);
    EXPECT_LT(outside, rect->at("size")[0].get<long>() * rect->at("size")[1].get<long>());
    EXPECT_EQ(j.at("view_grid").at("linked_pixel"), json::array({24, 18}));
    ASSERT_TRUE(rect->contains("markers"));
    const json& marks = rect->at("markers");
    ASSERT_GE(marks.size(), 1u);
    // A full-width row (the slice), inside the map.
    EXPECT_EQ(marks[0].at("from")[0], 0.0);
    EXPECT_EQ(marks[0].at("to")[0], 1.0);
    const double row = marks[0].at("from")[1].get<double>();
    EXPECT_GT(row, 0.0);
    EXPECT_LT(row, 1.0);
    EXPECT_EQ(marks[0].at("to")[1].get<double>(), row);
    EXPECT_NE(marks[0].at("label").get<std::string>().find("slice"), std::string::npos);
}

TEST_F(GuiViews, VsvMarksThePixelsThetaRowAndItsEyeRayInTheVoxelSlice) {
    // The voxel slice shown is the one of the picked pixel (default: the image centre): hovering that
    // pixel puts its eye ray in the slice as a column; the occluder map (y = theta cell) gets a row.
    // (0.5104, 0.5139) is the centre of pixel (24, 18), not the edge between two pixels at 0.5.
    const fs::path script = writeText("vsv.txt", "click \"view:Occluder alpha\"\nframes 1\nkey H\nframes 1\n"
                                                 "hover final 0.5104 0.5139\nframes 1\n");
    const RunResult r = run("gui --scene grate --technique vsv --size 48x36 --script " + script.string() +
                            " --screenshot " + path("vsv.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("vsv.png");
    EXPECT_EQ(j.at("view_grid").at("linked_pixel"), json::array({24, 18}));
    const json* occluder = viewWithCell(j, 1);
    const json* voxels = viewWithCell(j, 2);
    ASSERT_TRUE(occluder && voxels);
    EXPECT_EQ(occluder->at("name"), "vsv.occluder_alpha");
    EXPECT_EQ(voxels->at("name"), "vsv.voxels");
    ASSERT_EQ(occluder->at("markers").size(), 1u);
    const json& row = occluder->at("markers")[0];
    EXPECT_EQ(row.at("from")[1], row.at("to")[1]);
    EXPECT_NE(row.at("label").get<std::string>().find("theta cell"), std::string::npos);
    ASSERT_EQ(voxels->at("markers").size(), 1u);
    const json& column = voxels->at("markers")[0];
    EXPECT_EQ(column.at("from")[0], column.at("to")[0]);
    EXPECT_GT(column.at("from")[0].get<double>(), 0.0);
    EXPECT_LT(column.at("from")[0].get<double>(), 1.0);
}

TEST_F(GuiViews, TheGridComesBackFromTheSessionFile) {
    // F5 saves the session (here after a split and a maximise); a second window started with --state
    // shows the same grid, focus, contents and display settings.
    const fs::path state = path("session.json");
    const fs::path script = writeText("save.txt", "key J\nframes 1\nclick strip:2\nframes 1\nkey M\nkey F5\nframes 1\n");
    ASSERT_EQ(run("gui --scene grate --technique raymarch --size 40x30 --set samples=16 --state " + state.string() +
                  " --script " + script.string() + " --screenshot " + path("first.png").string()).exitCode, 0);
    const json first = sidecar("first.png");
    const RunResult r = run("gui --state " + state.string() + " --screenshot " + path("second.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json second = sidecar("second.png");
    EXPECT_EQ(first.at("view_grid").at("layout"), "x(0.5,0,y(0.5,1,2))");
    EXPECT_EQ(second.at("view_grid").at("layout"), first.at("view_grid").at("layout"));
    EXPECT_EQ(second.at("view_grid").at("focused"), 2);
    EXPECT_EQ(second.at("view_grid").at("maximised"), 2);
    ASSERT_EQ(second.at("views").size(), 1u);
    EXPECT_EQ(second.at("views")[0].at("name"), first.at("views")[0].at("name"));
    EXPECT_TRUE(second.at("views")[0].at("display").at("strip_open").get<bool>());
}

// A view whose chosen content the run does not make shows L_air in its stead and says, in its title,
// which content it was and why: an intermediate of another technique, or one a setting leaves out
// (minmax's SVD tables under its default analytic integrand). The choice is kept.
TEST_F(GuiViews, AViewWhoseContentTheRunDoesNotMakeSaysWhichAndWhy) {
    json views = json::array();
    const std::vector<std::string> contents = {"final", "slices.accumulation", "minmax.singular_values"};
    for (int i = 0; i < int(contents.size()); ++i)
        views.push_back({{"id", i}, {"content", contents[std::size_t(i)]}, {"against", "reference"},
                         {"center", {0.5, 0.5}}, {"channel", 0}, {"colour_map", 0}, {"difference", 0}, {"layer", 0},
                         {"log", false}, {"manual", {0.0, 1.0}}, {"mark_negative", -1}, {"range", 0},
                         {"strip_open", false}, {"zoom", 1.0}});
    // minmax with the analytic integrand: its run makes no SVD tables, so nothing is a singular-values view.
    const json session = {{"version", 1}, {"scene", "grate"}, {"technique", "minmax"},
                          {"settings", {{"minmax", {{"integrand", 0.0}}}}},
                          {"size", {32, 24}}, {"exposure", 0.0}, {"exposure_set", false}, {"view", "final"},
                          {"view_grid", {{"focused", 0}, {"layout", "x(0.3333,0,x(0.5,1,2))"}, {"maximised", -1},
                                         {"views", views}}}};
    const fs::path state = writeText("state.json", session.dump());
    const RunResult r = run("gui --state " + state.string() + " --screenshot " + path("a.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = sidecar("a.png");
    ASSERT_EQ(j.at("views").size(), 3u);
    std::map<std::string, std::string> titleOf;  // by what each view shows
    int standIns = 0;
    for (const json& v : j.at("views")) {
        const std::string title = v.at("title").get<std::string>();
        if (title.find("[chosen: ") == std::string::npos) continue;
        ++standIns;
        EXPECT_EQ(v.at("name"), "airlight") << title;
        titleOf[title.substr(title.find("[chosen: "))] = title;
    }
    EXPECT_EQ(standIns, 2);
    EXPECT_EQ(titleOf.count("[chosen: slices.accumulation, not a view of minmax]"), 1u) << j.at("views").dump();
    EXPECT_EQ(titleOf.count("[chosen: minmax.singular_values, not made with these settings]"), 1u) << j.at("views").dump();
    // The same grid with the SVD integrand: the view shows what was chosen, without a warning.
    const RunResult svd =
        run("gui --state " + state.string() + " --set integrand=svd --screenshot " + path("b.png").string());
    ASSERT_EQ(svd.exitCode, 0) << svd.err;
    bool shown = false;
    const json b = sidecar("b.png");
    for (const json& v : b.at("views")) {
        if (v.at("name") != "minmax.singular_values") continue;
        shown = true;
        EXPECT_EQ(v.at("title").get<std::string>().find("[chosen:"), std::string::npos) << v.at("title");
    }
    EXPECT_TRUE(shown) << b.at("views").dump();
}

// Benchmark (not a test): the CPU cost of the window's UI with seven views, three display strips open
// and the cursor linked into minmax's algorithm-space views, as the sidecar reports it.
// The light gizmo over the final frame: dragging the direction handle turns the spot so that the handle
// lands under the cursor; dragging the position handle (off the view at the top, grabbed at the view's
// edge) moves it by the drag; the technique runs again with the moved light; and the light comes back
// from the session file. Then the divider between the two views is dragged to a third of the width.
TEST_F(GuiViews, TheLightGizmoTurnsAndMovesTheLightAndADividerMovesItsSplit) {
    const fs::path state = path("session.json");
    const fs::path script = writeText(
        "gizmo.txt", "key F\nframes 1\nclick strip:1\nframes 1\nclick \"against##v1\"\nframes 1\n"
                     "click \"against##v1/minmax\"\nframes 2\nscreenshot " + path("before.png").string() +
                         "\ndrag gizmo:direction 0.5 0.5 0.45 0.125 cell:0\nframes 2\nscreenshot " + path("turned.png").string() +
                         "\ndrag gizmo:position 0.5 0.5 0.3 0.25 cell:0\nframes 2\nscreenshot " + path("moved.png").string() +
                         "\ndrag divider:root 0.5 0.5 0.333 0.5 cell:0\nframes 1\nkey F5\nframes 1\n");
    // polyvol and minmax agree closely (0.9 % on this scene, size and map); raymarch's few samples would not.
    const std::string common =
        "gui --scene grate --technique polyvol --size 64x48 --set shadow_map=256 --state " + state.string();
    const RunResult r = run(common + " --script " + script.string() + " --screenshot " + path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const json before = sidecar("before.png"), turned = sidecar("turned.png"), moved = sidecar("moved.png");
    ASSERT_TRUE(before.at("gizmo").is_object());
    const json* final = viewWithCell(before, before.at("gizmo").at("cell").get<int>());
    ASSERT_TRUE(final);
    EXPECT_EQ(final->at("name"), "final");
    const json& rect = final->at("rect");
    const double x0 = rect[0].get<double>(), y0 = rect[1].get<double>();
    const double sx = 64.0 / (rect[2].get<double>() - x0), sy = 48.0 / (rect[3].get<double>() - y0);
    const auto toFrame = [&](double wx, double wy) { return std::pair<double, double>((wx - x0) * sx, (wy - y0) * sy); };

    // Turned: the tip is where the cursor was released, the spot's position stayed.
    const auto [tx, ty] = toFrame(x0 + 0.45 / sx * 64.0, y0 + 0.125 / sy * 48.0);  // within the arm's sphere
    const json& tip = turned.at("gizmo").at("tip");
    EXPECT_NEAR(tip[0].get<double>(), tx, 0.05);
    EXPECT_NEAR(tip[1].get<double>(), ty, 0.05);
    EXPECT_EQ(turned.at("lights")[0].at("position"), before.at("lights")[0].at("position"));
    EXPECT_NE(turned.at("lights")[0].at("direction"), before.at("lights")[0].at("direction"));

    // Moved: the spot starts above the view; its handle is grabbed at the view's edge and moves by the drag.
    ASSERT_TRUE(turned.at("gizmo").at("position").is_array());
    EXPECT_LT(turned.at("gizmo").at("position")[1].get<double>(), 0.0) << "the spot is above the frame";
    const json& grab = turned.at("gizmo").at("position_grab");
    const auto [gx, gy] = toFrame(grab[0].get<double>(), grab[1].get<double>());
    const auto [rx, ry] = toFrame(x0 + 0.3 / sx * 64.0, y0 + 0.25 / sy * 48.0);
    const json& was = turned.at("gizmo").at("position");
    const json& now = moved.at("gizmo").at("position");
    EXPECT_NEAR(now[0].get<double>() - was[0].get<double>(), rx - gx, 0.05);
    EXPECT_NEAR(now[1].get<double>() - was[1].get<double>(), ry - gy, 0.05);
    EXPECT_EQ(moved.at("lights")[0].at("direction"), turned.at("lights")[0].at("direction"));
    // The difference view (polyvol's L_air against minmax) follows the light: minmax ran again with it, so the two
    // techniques still agree as closely as before the drags (against minmax's old image they would not).
    const auto differenceL2 = [](const json& j) {
        const json* v = viewWithCell(j, 1);
        return v && v->contains("difference") && v->at("difference").contains("relative_l2")
                   ? v->at("difference").at("relative_l2").get<double>()
                   : -1.0;
    };
    const double agreeBefore = differenceL2(before), agreeMoved = differenceL2(moved);
    std::printf("polyvol vs minmax, relative L2 of L_air: %.4f before, %.4f after the drags\n", agreeBefore, agreeMoved);
    EXPECT_GT(agreeBefore, 0.0);
    EXPECT_LT(agreeBefore, 0.02);
    EXPECT_GT(agreeMoved, 0.0);
    EXPECT_LT(agreeMoved, 0.05);

    // The technique ran with the moved light: the frame differs from before the drags.
    const Image a = readImage(path("before.png").string()), b = readImage(path("moved.png").string());
    double changed = 0.0;
    for (int y = int(y0) + 2; y < int(rect[3].get<double>()) - 2; ++y)
        for (int x = int(x0) + 2; x < int(rect[2].get<double>()) - 2; ++x) changed += std::abs(a.at(x, y, 0) - b.at(x, y, 0));
    EXPECT_GT(changed, 50.0);

    // The divider: released at a third of the final frame's image, its gap is centred there.
    const json end = sidecar("end.png");
    const json& left = viewWithCell(moved, 0)->at("cell_rect");
    const json& right = viewWithCell(moved, 1)->at("cell_rect");
    const double gap = right[0].get<double>() - left[2].get<double>();
    const double areaMin = left[0].get<double>(), areaWidth = right[2].get<double>() - areaMin;
    const double released = x0 + 0.333 * 64.0 / sx;
    const std::string layout = end.at("view_grid").at("layout");
    ASSERT_EQ(layout.rfind("x(", 0), 0u) << layout;
    EXPECT_NEAR(std::stod(layout.substr(2)), (released - areaMin - 0.5 * gap) / (areaWidth - gap), 2e-3) << layout;
    const json& endLeft = viewWithCell(end, 0)->at("cell_rect");
    const json& endRight = viewWithCell(end, 1)->at("cell_rect");
    EXPECT_NEAR(0.5 * (endLeft[2].get<double>() + endRight[0].get<double>()), released, 1.0);

    // The session file keeps the moved light: a new window starts with it.
    const fs::path look = writeText("look.txt", "frames 1\n");
    ASSERT_EQ(run(common + " --script " + look.string() + " --screenshot " + path("again.png").string()).exitCode, 0);
    const json again = sidecar("again.png");
    EXPECT_EQ(again.at("lights")[0].at("position"), moved.at("lights")[0].at("position"));
    EXPECT_EQ(again.at("lights")[0].at("direction"), moved.at("lights")[0].at("direction"));
}

TEST_F(GuiViews, DISABLED_UiCostWithSevenViews) {
    const fs::path script = writeText("cost.txt",
                                      "click \"view:Rectified shadow map S\"\nkey H\nframes 1\nkey J\nframes 1\nkey H\n"
                                      "frames 1\nkey J\nframes 1\nkey N\nkey H\nframes 1\nclick strip:1\nframes 1\n"
                                      "click strip:2\nframes 1\nclick strip:0\nframes 1\nhover final 0.5 0.5\nframes 3\n");
    ASSERT_EQ(run("gui --scene grate --technique minmax --size 160x120 --script " + script.string() + " --screenshot " +
                  path("cost.png").string()).exitCode, 0);
    const json j = sidecar("cost.png");
    std::printf("%zu views: view grid %.3f ms, whole UI %.3f ms CPU in the last frame\n", j.at("views").size(),
                j.at("view_grid").at("cpu_ms_last_frame").get<double>(),
                j.at("view_grid").at("ui_cpu_ms_last_frame").get<double>());
}

}  // namespace
// The parameter panel's plan section shows what `airlight plan` prints: every feature on or off with its
// reason (the sidecar carries what the section lists), so minmax's integrand=auto choice is visible in the
// window: analytic on forest, svd on grate.
TEST_F(GuiViews, ThePlanSectionSaysWhatAirlightPlanSays) {
    const fs::path script = writeText("plan.txt", "frames 1\nclick \"plan: what runs and why\"\nframes 1\n");
    for (const char* scene : {"forest", "grate"}) {
        const std::string png = std::string(scene) + ".png";
        const RunResult r = run(std::string("gui --scene ") + scene + " --technique minmax --size 32x24 --script " +
                                script.string() + " --screenshot " + path(png).string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const RunResult cli = run(std::string("plan --scene ") + scene + " --technique minmax");
        ASSERT_EQ(cli.exitCode, 0) << cli.err;
        const json features = sidecar(png).at("plan").at("features");
        ASSERT_GT(features.size(), 5u);
        for (const json& f : features) {
            const std::string line = "feature " + f.at("feature").get<std::string>();
            const std::size_t at = cli.out.find(line + " ");
            ASSERT_NE(at, std::string::npos) << line;
            const std::string printed = cli.out.substr(at, cli.out.find('\n', at) - at);
            EXPECT_NE(printed.find(f.at("on").get<bool>() ? " on " : " off "), std::string::npos) << printed;
            EXPECT_NE(printed.find(f.at("why").get<std::string>()), std::string::npos) << printed;
        }
        bool integrand = false;
        for (const json& f : features)
            if (f.at("feature") == "INTEGRAND_SVD") {
                integrand = true;
                EXPECT_EQ(f.at("on").get<bool>(), std::string(scene) == "grate") << f.dump();
                EXPECT_EQ(f.at("why").get<std::string>().rfind("integrand=auto: ", 0), 0u) << f.dump();
            }
        EXPECT_TRUE(integrand) << scene;
    }
}

}  // namespace viz::testing
