// The spread of timed runs (report/run_spread.h) and where the report's and the bench's files show it:
// the fastest and slowest run beside each median, and a marked time where they lie too far apart.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/bench_table.h"
#include "report/report_table.h"
#include "report/run_spread.h"
#include "temp_dir.h"

namespace viz::report {
namespace {

namespace fs = std::filesystem;
using viz::testing::readText;

TEST(RunSpread, IsTheFastestAndSlowestRunAndTheirDistanceOverTheMedian) {
    const RunSpread s = spreadOf({120.0, 100.0, 180.0, 110.0});
    EXPECT_EQ(s.minMilliseconds, 100.0);
    EXPECT_EQ(s.maxMilliseconds, 180.0);
    EXPECT_DOUBLE_EQ(spreadFraction(115.0, s), 80.0 / 115.0);
    EXPECT_TRUE(std::isnan(spreadOf({}).minMilliseconds));
    EXPECT_TRUE(std::isnan(spreadFraction(100.0, {})));            // not measured
    EXPECT_TRUE(std::isnan(spreadFraction(0.0, {1.0, 2.0})));       // no positive median
    EXPECT_EQ(spreadText(100.0, {}), "");
    EXPECT_EQ(spreadText(100.0, {90.0, 125.0}), "runs 90 to 125 ms, 35 % of the median");
}

TEST(RunSpread, ATimeIsNoisyOnlyWhenItsRunsLieMoreThanAFifthOfItApart) {
    EXPECT_FALSE(isNoisy(100.0, {95.0, 110.0}));   // 15 %
    EXPECT_FALSE(isNoisy(100.0, {100.0, 120.0}));  // 20 %: not more than a fifth
    EXPECT_TRUE(isNoisy(100.0, {99.0, 121.0}));    // 22 %
    EXPECT_FALSE(isNoisy(100.0, {}));              // one copy of nothing is not noise
}

TEST(RunSpread, TheNoteCountsTheNoisyTimesAndNamesTheWidest) {
    EXPECT_EQ(noisyRunsNote({{"a", 100.0, {99.0, 101.0}}}, "settings"), "");
    const std::string note = noisyRunsNote({{"quiet", 100.0, {99.0, 101.0}},
                                            {"wide", 10.0, {8.0, 30.0}},  // 220 %
                                            {"busy", 100.0, {90.0, 150.0}}},
                                           "settings");
    EXPECT_EQ(note.rfind("note: the timed runs of 2 of 3 settings spread by more than 20 % of their median (widest: wide, "
                         "runs 8 to 30 ms, 220 % of the median)",
                         0),
              0u)
        << note;
}

// Two rows of one scene: one whose runs agree, one whose runs lie far apart.
std::vector<ReportRow> reportRows() {
    std::vector<ReportRow> rows(2);
    for (int i = 0; i < 2; ++i) {
        ReportRow& r = rows[std::size_t(i)];
        r.scene = "grate";
        r.technique = "raymarch";
        r.setting = i == 0 ? "N=16" : "N=64";
        r.width = 32, r.height = 24, r.runs = 3, r.clock = "glFinish+steady_clock";
        r.totalMilliseconds = i == 0 ? 10.0 : 40.0;
        r.totalSpread = i == 0 ? RunSpread{9.5, 10.5} : RunSpread{38.0, 82.0};
        r.error.relativeL2 = i == 0 ? 0.2 : 0.05;
    }
    return rows;
}

TEST(RunSpread, TheReportsFilesCarryItAndItsPageMarksTheNoisyTimeAlone) {
    viz::testing::TempDir temp("run_spread_report");
    std::vector<ReportRow> rows = reportRows();
    annotateTradeoffs(rows);

    writeCsv((temp / "results.csv").string(), rows);
    std::istringstream csv(readText(temp / "results.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_NE(header.find(",total_ms_min,total_ms_max"), std::string::npos) << header;
    std::getline(csv, line);
    // The fields under those two names (no field of this row is quoted).
    auto fields = [](const std::string& text) {
        std::vector<std::string> out(1);
        for (char c : text) {
            if (c == ',') out.emplace_back();
            else out.back().push_back(c);
        }
        return out;
    };
    const std::vector<std::string> names = fields(header), values = fields(line);
    ASSERT_EQ(names.size(), values.size()) << line;
    const auto column = [&](const std::string& name) {
        return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    ASSERT_LT(column("total_ms_max"), values.size());
    EXPECT_EQ(values[column("total_ms_min")], "9.5") << line;
    EXPECT_EQ(values[column("total_ms_max")], "10.5") << line;

    writeJson((temp / "results.json").string(), {}, rows);
    const nlohmann::json j = nlohmann::json::parse(readText(temp / "results.json"));
    EXPECT_EQ(j.at("rows")[1].at("total_ms_min").get<double>(), 38.0);
    EXPECT_EQ(j.at("rows")[1].at("total_ms_max").get<double>(), 82.0);

    writeHtml((temp / "index.html").string(), {}, rows, {{"grate", "", ""}});
    const std::string page = readText(temp / "index.html");
    EXPECT_NE(page.find("title=\"runs 38 to 82 ms, 110 % of the median\">40.0&dagger;"), std::string::npos);
    EXPECT_NE(page.find("<td>10.0</td>"), std::string::npos);  // the quiet row: unmarked
    EXPECT_NE(page.find("lay more than 20 % of their median apart"), std::string::npos);

    rows[1].totalSpread = {39.0, 41.0};
    writeHtml((temp / "quiet.html").string(), {}, rows, {{"grate", "", ""}});
    EXPECT_EQ(readText(temp / "quiet.html").find("&dagger;"), std::string::npos);
}

TEST(RunSpread, TheHeadlineSpeedupSaysHowFarTheRunsSpreadCouldMoveIt) {
    // raymarch reaches 10 % at 100 ms (runs 80 to 120), minmax at 20 ms (runs 18 to 30): 5x faster; with
    // raymarch's fastest against minmax's slowest 80 / 30, the reverse 120 / 18.
    std::vector<ReportRow> rows(2);
    for (int i = 0; i < 2; ++i) {
        rows[std::size_t(i)].scene = "grate";
        rows[std::size_t(i)].technique = i == 0 ? "raymarch" : "minmax";
        rows[std::size_t(i)].error.relativeL2 = 0.1;
    }
    rows[0].totalMilliseconds = 100.0, rows[0].totalSpread = {80.0, 120.0};
    rows[1].totalMilliseconds = 20.0, rows[1].totalSpread = {18.0, 30.0};
    const TargetSpeedup s = targetSpeedup(rows, "grate", "minmax", 0.1);
    EXPECT_DOUBLE_EQ(s.ratio, 5.0);
    EXPECT_DOUBLE_EQ(s.ratioLow, 80.0 / 30.0);
    EXPECT_DOUBLE_EQ(s.ratioHigh, 120.0 / 18.0);
    EXPECT_EQ(targetSpeedupPhrase(s), "5.00x faster (20 ms against 100 ms); between 2.67x and 6.67x faster over the "
                                      "runs' spread");
    // Counted work has no spread; a row without one leaves the range out.
    EXPECT_TRUE(std::isnan(targetSpeedup(rows, "grate", "minmax", 0.1, "raymarch", Measure::Work).ratioLow));
    rows[1].totalSpread = {};
    EXPECT_EQ(targetSpeedupPhrase(targetSpeedup(rows, "grate", "minmax", 0.1)), "5.00x faster (20 ms against 100 ms)");
    // One timed run on each side: the range would read "between 5.00x and 5.00x".
    rows[0].totalSpread = {100.0, 100.0};
    rows[1].totalSpread = {20.0, 20.0};
    EXPECT_EQ(targetSpeedupPhrase(targetSpeedup(rows, "grate", "minmax", 0.1)), "5.00x faster (20 ms against 100 ms)");
    rows[0].totalSpread = {80.0, 120.0};
    // minmax below the target at its only setting: its time, and so the speed-up, is a bound, and so is the range.
    rows[1].totalSpread = {18.0, 30.0};
    rows[1].error.relativeL2 = 0.05;
    const TargetSpeedup bound = targetSpeedup(rows, "grate", "minmax", 0.1);
    ASSERT_EQ(bound.bound, TargetSpeedup::Bound::AtLeast);
    EXPECT_EQ(targetSpeedupPhrase(bound), "at least 5.00x faster (20 ms or less against 100 ms); the bound lies between "
                                          "2.67x and 6.67x faster over the runs' spread");
}

TEST(RunSpread, TheBenchsFilesCarryItAndItsPageMarksTheNoisyTimeAlone) {
    viz::testing::TempDir temp("run_spread_bench");
    std::vector<BenchRow> rows;
    for (int i = 0; i < 2; ++i)
        rows.push_back({"grate", "raymarch", "size", i == 0 ? "160x120" : "320x240", i == 0 ? 19200.0 : 76800.0, "total",
                        i == 0 ? 20.0 : 80.0, "glFinish+steady_clock", "llvmpipe", 3, i == 0 ? 21.0 : 81.0,
                        i == 0 ? RunSpread{19.0, 21.0} : RunSpread{70.0, 150.0}});
    writeBenchCsv((temp / "bench.csv").string(), rows);
    std::istringstream csv(readText(temp / "bench.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "scene,technique,axis,value,stage,ms,clock,renderer,work,runs,wall_ms,ms_min,ms_max");
    std::getline(csv, line);
    EXPECT_EQ(line, "grate,raymarch,size,160x120,total,20,glFinish+steady_clock,llvmpipe,19200,3,21,19,21");

    BenchMeta meta;
    meta.runs = 3;
    writeBenchHtml((temp / "bench.html").string(), meta, rows, fitSeries(rows), {});
    const std::string page = readText(temp / "bench.html");
    EXPECT_NE(page.find("title=\"runs 70 to 150 ms, 100 % of the median\">80&dagger;"), std::string::npos);
    EXPECT_NE(page.find("<td>20</td>"), std::string::npos);
    EXPECT_NE(page.find("lay more than 20 % of their median apart"), std::string::npos);
}

}  // namespace
}  // namespace viz::report
