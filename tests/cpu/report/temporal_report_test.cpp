// The report's temporal part on constructed rows: the ranking by error, time and stability, and the
// temporal figures in results.csv, results.json and index.html.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "report/report_table.h"
#include "report/temporal_report.h"
#include "temp_dir.h"

namespace viz::report {
namespace {

namespace fs = std::filesystem;

constexpr double kNaNFigure = std::numeric_limits<double>::quiet_NaN();

ReportRow row(const std::string& technique, const std::string& setting, double ms, double error,
              std::optional<double> temporalRms) {
    ReportRow r;
    r.scene = "grate";
    r.technique = technique;
    r.setting = setting;
    r.totalMilliseconds = ms;
    r.error.relativeL2 = error;
    if (temporalRms) {
        TemporalFigures t;
        t.path = "camera-orbit:10deg";
        t.frames = 6;
        t.meanFrameError = error;
        t.temporalRms = *temporalRms;
        t.worstFlicker = 3.0 * *temporalRms;
        t.msPerFrame = ms;
        t.flickerImage = "grate-" + technique + "-flicker.png";
        r.temporal = t;
    }
    return r;
}

class TemporalReport : public ::testing::Test {
protected:
    void SetUp() override {
        // raymarch: accurate and slow, and the steadiest; slices: fast, wrong and jumping; vsv: wrong but
        // stable; minmax: never measured along the path.
        mRows = {row("raymarch", "N=16", 40.0, 0.2, 0.02), row("raymarch", "N=64", 90.0, 0.05, 0.004),
                 row("slices", "planes=32", 5.0, 0.3, 0.2), row("vsv", "voxels=64", 8.0, 0.4, 0.01),
                 row("minmax", "map=512", 12.0, kNaNFigure, std::nullopt)};
    }
    std::string read(const std::string& name) const {
        std::ifstream in(mDir / name);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    viz::testing::TempDir mTemp{"temporal_report"};
    fs::path mDir = mTemp.path();
    std::vector<ReportRow> mRows;
};

TEST_F(TemporalReport, RanksByErrorTimeAndStabilityLeavingUnmeasuredUnranked) {
    const std::vector<TechniqueRank> ranks = rankTechniques(mRows, "grate");
    ASSERT_EQ(ranks.size(), 4u);
    EXPECT_EQ(ranks[0].technique, "raymarch");  // in order of appearance
    EXPECT_EQ(ranks[3].technique, "minmax");
    // raymarch: best error (0.05) and most stable (0.004) at N=64, slowest at 40 ms.
    EXPECT_EQ(ranks[0].errorRank, 1);
    EXPECT_EQ(ranks[0].bestErrorSetting, "N=64");
    EXPECT_EQ(ranks[0].stabilityRank, 1);
    EXPECT_DOUBLE_EQ(ranks[0].mostStable, 0.004);
    EXPECT_EQ(ranks[0].timeRank, 4);
    // slices: fastest, but the least stable of those measured; vsv wrong but stable ranks second.
    EXPECT_EQ(ranks[1].timeRank, 1);
    EXPECT_EQ(ranks[1].stabilityRank, 3);
    EXPECT_EQ(ranks[2].stabilityRank, 2);
    EXPECT_DOUBLE_EQ(ranks[2].mostStableFlicker, 0.03);
    // minmax: no finite error (last) and no temporal figures (no stability rank).
    EXPECT_EQ(ranks[3].errorRank, 4);
    EXPECT_EQ(ranks[3].stabilityRank, 0);
    EXPECT_TRUE(std::isnan(ranks[3].mostStable));
}

TEST_F(TemporalReport, WithoutTemporalFiguresNoStabilityRank) {
    for (ReportRow& r : mRows) r.temporal.reset();
    for (const TechniqueRank& t : rankTechniques(mRows, "grate")) EXPECT_EQ(t.stabilityRank, 0) << t.technique;
}

TEST_F(TemporalReport, CsvAndJsonCarryTheFiguresAndLeaveUnmeasuredRowsEmpty) {
    writeCsv((mDir / "results.csv").string(), mRows);
    std::istringstream csv(read("results.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_NE(header.find(",temporal_path,temporal_frames,mean_frame_error,temporal_rms,worst_flicker,ms_per_frame,"
                          "flicker_image"),
              std::string::npos);
    std::vector<std::string> lines;
    while (std::getline(csv, line)) lines.push_back(line);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_NE(lines[2].find(",camera-orbit:10deg,6,0.3,0.2,0.6,5,grate-slices-flicker.png"), std::string::npos)
        << lines[2];
    EXPECT_NE(lines[4].find(",,,,,,"), std::string::npos) << lines[4];  // minmax: not measured

    ReportMeta meta;
    meta.temporal = true;
    writeJson((mDir / "results.json").string(), meta, mRows);
    const nlohmann::json j = nlohmann::json::parse(read("results.json"));
    EXPECT_TRUE(j.at("meta").at("temporal").get<bool>());
    EXPECT_TRUE(j.at("meta").contains("temporal_of"));
    const auto& t = j.at("rows")[3].at("temporal");
    EXPECT_DOUBLE_EQ(t.at("temporal_rms").get<double>(), 0.01);
    EXPECT_EQ(t.at("frames"), 6);
    EXPECT_EQ(t.at("flicker_image"), "grate-vsv-flicker.png");
    EXPECT_TRUE(j.at("rows")[4].at("temporal").is_null());
}

TEST_F(TemporalReport, PageShowsTheTemporalTableFlickerMapsPlotAndRanking) {
    ScenePage page{"grate", "grate-plot.png", "grate-reference.png"};
    page.motionPath = "camera-orbit:10deg";
    page.frames = 6;
    page.temporalPlot = "grate-temporal-plot.png";
    writeHtml((mDir / "index.html").string(), {}, mRows, {page});
    const std::string html = read("index.html");
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_NE(html.find("Temporal error along camera-orbit:10deg (6 frames)"), std::string::npos);
    for (const char* image : {"grate-temporal-plot.png", "grate-raymarch-flicker.png", "grate-slices-flicker.png",
                              "grate-vsv-flicker.png"})
        EXPECT_NE(html.find(std::string("src=\"") + image + "\""), std::string::npos) << image;
    // The temporal plot sits beside the error plot, before the tables.
    EXPECT_LT(html.find("grate-plot.png"), html.find("grate-temporal-plot.png"));
    EXPECT_LT(html.find("grate-temporal-plot.png"), html.find("<th>mean frame error</th>"));
    EXPECT_NE(html.find("<th>stability</th>"), std::string::npos);

    // Without temporal figures: no temporal section, no stability column.
    for (ReportRow& r : mRows) r.temporal.reset();
    writeHtml((mDir / "still.html").string(), {}, mRows, {{"grate", "grate-plot.png", "grate-reference.png"}});
    const std::string still = read("still.html");
    EXPECT_EQ(still.find("Temporal error along"), std::string::npos);
    EXPECT_EQ(still.find("<th>stability</th>"), std::string::npos);
    EXPECT_NE(still.find("Ranking"), std::string::npos);
}

}  // namespace
}  // namespace viz::report
