// `airlight report --temporal` end to end at a tiny size: the temporal figures of every technique in
// results.json, results.csv and index.html, flicker maps and the temporal plot that OpenImageIO reads,
// reference frames cached per pose, and one-line errors for bad combinations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

bool finiteNumber(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

int filesIn(const fs::path& dir) {
    int n = 0;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
    return n;
}

// Points the reference's disk cache at the test's own folder for the test's duration.
class ReportTemporalTest : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        mCache = std::make_unique<ScopedCacheDir>(path("cache"));
    }
    void TearDown() override {
        mCache.reset();
        CliTest::TearDown();
    }
    std::unique_ptr<ScopedCacheDir> mCache;
};

TEST_F(ReportTemporalTest, QuickWritesFiniteTemporalFiguresForEveryTechniqueWithFlickerMaps) {
    const fs::path out = path("report");
    const RunResult r = run("report --scenes grate --size 32x24 --quick --runs 1 --temporal --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const nlohmann::json j = nlohmann::json::parse(readFile(out / "results.json"));
    EXPECT_TRUE(j.at("meta").at("temporal").get<bool>());
    std::set<std::string> techniques, measured;
    int temporalRows = 0, stabiliserRows = 0;
    // Stabilising options (Technique::stabilisingOptions): (technique, option) -> temporal RMS off, on.
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> options;
    for (const auto& row : j.at("rows")) {
        const std::string series = row.at("technique").get<std::string>();
        techniques.insert(series);
        const auto& t = row.at("temporal");
        if (!row.at("stabiliser").is_null()) {
            // Every row of an option's pair is measured along the path, with --quick too.
            ++stabiliserRows;
            ASSERT_FALSE(t.is_null()) << row.dump();
            const auto key = std::make_pair(series, row.at("stabiliser").at("option").get<std::string>());
            auto& [off, on] = options.try_emplace(key, -1.0, -1.0).first->second;
            (row.at("stabiliser").at("on").get<bool>() ? on : off) = t.at("temporal_rms").get<double>();
        }
        if (t.is_null()) continue;
        ++temporalRows;
        measured.insert(series);
        EXPECT_EQ(t.at("path"), "camera-orbit:10deg") << series;
        EXPECT_EQ(t.at("frames"), 6) << series;  // --quick
        for (const char* key : {"mean_frame_error", "temporal_rms", "worst_flicker", "ms_per_frame"})
            EXPECT_TRUE(finiteNumber(t.at(key))) << series << " " << key << " " << t.dump();
        EXPECT_GE(t.at("temporal_rms").get<double>(), 0.0) << series;
        EXPECT_GT(t.at("mean_frame_error").get<double>(), 0.0) << series;
        EXPECT_GT(t.at("ms_per_frame").get<double>(), 0.0) << series;
        // The flicker map: a PNG of the report's size that OpenImageIO reads back.
        const fs::path flicker = out / t.at("flicker_image").get<std::string>();
        ASSERT_TRUE(fs::exists(flicker)) << flicker;
        const Image image = readImage(flicker.string());
        EXPECT_EQ(image.width, 32);
        EXPECT_EQ(image.height, 24);
    }
    // Every technique has a row measured along the path (with --quick its cheapest setting, one row each;
    // the paper presets are measured by the full report).
    EXPECT_EQ(temporalRows - stabiliserRows, 6);
    // grate has a spot light and no area light: raymarch's three jitter pairs, slices' plane grid,
    // minmax's slice frame; no ivsv subsets (no VPLs).
    const std::set<std::pair<std::string, std::string>> expected = {
        {"raymarch", "jitter_time=constant (white)"}, {"raymarch", "jitter_time=constant (blue)"},
        {"raymarch", "jitter=blue"}, {"slices", "plane_grid=world"}, {"minmax", "slice_frame=fixed"}};
    std::set<std::pair<std::string, std::string>> found;
    for (const auto& [key, rms] : options) {
        found.insert(key);
        EXPECT_GE(rms.first, 0.0) << key.second << ": no row without it";
        EXPECT_GE(rms.second, 0.0) << key.second << ": no row with it";
    }
    EXPECT_EQ(found, expected);
    EXPECT_EQ(stabiliserRows, 2 * int(expected.size()));
    for (const char* id : {"raymarch", "slices", "polyvol", "minmax", "vsv", "ivsv"})
        EXPECT_TRUE(measured.count(id)) << id;
    for (const std::string& series : techniques)
        if (series.find("(paper)") != std::string::npos) {
            EXPECT_FALSE(measured.count(series)) << series;
        }

    // results.csv carries the same figures in its temporal columns.
    std::istringstream csv(readFile(out / "results.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_NE(header.find("temporal_rms,worst_flicker,ms_per_frame,flicker_image"), std::string::npos) << header;
    int csvTemporal = 0;
    while (std::getline(csv, line)) csvTemporal += line.find("camera-orbit:10deg") != std::string::npos ? 1 : 0;
    EXPECT_EQ(csvTemporal, temporalRows);

    // The page: the temporal table, the ranking by stability and the plot beside the error plot.
    const std::string page = readFile(out / "index.html");
    EXPECT_NE(page.find("Temporal error along camera-orbit:10deg (6 frames)"), std::string::npos);
    EXPECT_EQ(htmlValidatorComplaints(out / "index.html", mDir), "");
    EXPECT_NE(page.find("<th>stability</th>"), std::string::npos);
    EXPECT_NE(page.find("src=\"grate-temporal-plot.png\""), std::string::npos);
    const Image plot = readImage((out / "grate-temporal-plot.png").string());
    EXPECT_GT(plot.width, 0);
    EXPECT_NE(r.out.find("most stable along camera-orbit:10deg"), std::string::npos) << r.out;
    // Each option on the page's table and on the terminal, with the rows' own figures.
    EXPECT_NE(page.find("<h4>Stabilising options</h4>"), std::string::npos);
    for (const auto& [key, rms] : options) {
        char figures[96];
        std::snprintf(figures, sizeof figures, "temporal RMS %.3g -> %.3g", rms.first, rms.second);
        EXPECT_NE(r.out.find("grate          " + key.first + " " + key.second + ": " + figures), std::string::npos)
            << key.second << "\n" << r.out;
        EXPECT_NE(page.find("<td class=\"l\">" + key.second + "</td>"), std::string::npos) << key.second;
    }
}

TEST_F(ReportTemporalTest, ReferenceFramesAreCachedPerPoseAndReused) {
    const std::string args = "report --scenes colonnade --techniques raymarch --size 24x16 --quick --runs 1 "
                             "--temporal --frames 3 --out ";
    const RunResult first = run(args + path("a").string());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    // One file per frame: frame 0 is the scene as it is, the still sweep's reference.
    EXPECT_EQ(filesIn(path("cache")), 3);
    const RunResult second = run(args + path("b").string());
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(filesIn(path("cache")), 3);
    const nlohmann::json a = nlohmann::json::parse(readFile(path("a") / "results.json"));
    const nlohmann::json b = nlohmann::json::parse(readFile(path("b") / "results.json"));
    ASSERT_EQ(a.at("rows").size(), b.at("rows").size());
    for (std::size_t i = 0; i < a.at("rows").size(); ++i) {
        const auto& ta = a.at("rows")[i].at("temporal");
        if (ta.is_null()) continue;
        EXPECT_EQ(ta.at("path"), "light-sweep:10deg");
        // The same frames of the same reference, read back from the cache: the same figures.
        EXPECT_EQ(ta.at("mean_frame_error"), b.at("rows")[i].at("temporal").at("mean_frame_error"));
        EXPECT_EQ(ta.at("temporal_rms"), b.at("rows")[i].at("temporal").at("temporal_rms"));
    }
}

// tv-room's area light: the techniques on the shared VPLs add more of them to their sweeps (each count
// also with a shorter march of each VPL's ray), and with them reach a lower error against the reference
// than at their defaults; the added points are not measured along the path, and vsv (whose air does not
// take the shared VPLs) adds none.
TEST_F(ReportTemporalTest, AnAreaLightAddsVplsToTheSweepsOffThePath) {
    const fs::path out = path("report");
    const RunResult r = run("report --scenes tv-room --techniques raymarch,minmax,vsv --size 32x24 --quick --runs 1 "
                            "--temporal --frames 2 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(readFile(out / "results.json"));
    std::map<std::string, double> defaultError;
    std::map<std::string, std::map<std::string, double>> areaError;  // series -> setting -> error
    for (const auto& row : j.at("rows")) {
        if (!row.at("stabiliser").is_null()) continue;
        const std::string series = row.at("technique").get<std::string>();
        const std::string setting = row.at("setting").get<std::string>();
        const double error = row.at("error").at("relative_l2").get<double>();
        if (setting.rfind("area_samples=", 0) == 0) {
            EXPECT_EQ(row.at("settings"), setting) << series;
            EXPECT_TRUE(row.at("temporal").is_null()) << series << ": measured along the path";
            areaError[series][setting] = error;
        }
        if ((series == "raymarch" && setting == "N=64") || (series == "minmax" && setting == "map=1024 slices=auto"))
            defaultError[series] = error;
    }
    EXPECT_EQ(areaError.size(), 2u);  // raymarch and minmax, not vsv
    for (const auto& [id, march] : std::map<std::string, std::string>{{"raymarch", "samples"}, {"minmax", "vpl_samples"}}) {
        ASSERT_TRUE(defaultError.count(id)) << id;
        std::map<std::string, double>& e = areaError[id];
        ASSERT_EQ(e.size(), 4u) << id;
        const std::string at8 = "area_samples=8", at16 = "area_samples=16";
        for (const std::string& s : {at8, at16, at8 + " " + march + "=16", at16 + " " + march + "=16"})
            ASSERT_TRUE(e.count(s)) << id << ": no " << s;
        // 8^2 and 16^2 VPLs against the default 4^2 (0.039 and 0.015 against 0.084 at 160x120), and with 16
        // samples per VPL ray (0.043 and 0.035).
        EXPECT_LT(e[at8], defaultError[id]) << id;
        EXPECT_LT(e[at16], e[at8]) << id;
        EXPECT_LT(e[at16], 0.4 * defaultError[id]) << id;
        EXPECT_LT(e[at8 + " " + march + "=16"], defaultError[id]) << id;
        EXPECT_LT(e[at16 + " " + march + "=16"], defaultError[id]) << id;
    }
}

TEST_F(ReportTemporalTest, BadCombinationsAreOneLineErrorsBeforeWritingAnything) {
    const fs::path out = path("never");
    const std::string o = " --out " + out.string();
    expectUserError(run("report --scenes grate --frames 6" + o), "--frames needs --temporal");
    expectUserError(run("report --scenes grate --path camera-orbit:5deg" + o), "--path needs --temporal");
    expectUserError(run("report --suite stiff --temporal" + o), "--temporal does not apply");
    expectUserError(run("report --scenes grate --temporal --frames 1" + o), "--frames");
    expectUserError(run("report --scenes grate --temporal --frames 2.5" + o), "--frames");
    expectUserError(run("report --scenes grate --temporal --frames 100000" + o), "--frames");
    expectUserError(run("report --scenes grate --temporal --path camera-orbt:5deg" + o), "camera-orbt");
    // tv-room's first light is an area light: a light path cannot move it.
    expectUserError(run("report --scenes tv-room --temporal --path light-sweep:10deg" + o), "light");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace viz::testing
