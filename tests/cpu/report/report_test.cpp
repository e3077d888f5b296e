// The report's figures and files: error metrics, the Pareto front and speed-up at equal error, and the
// CSV / JSON / HTML writers, all on constructed inputs whose answers are known independently.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "report/error_metrics.h"
#include "report/report_table.h"
#include "report/text_output.h"
#include "report/tradeoff.h"
#include "temp_dir.h"

namespace viz::report {
namespace {

namespace fs = std::filesystem;

Image constant(int w, int h, float v) {
    Image image(w, h, 3);
    for (float& p : image.pixels) p = v;
    return image;
}

using viz::testing::readText;

TEST(ErrorMetrics, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
    const Image a = constant(8, 4, 0.5f);
    const ErrorMetrics m = compareImages(a, a);
    EXPECT_EQ(m.relativeL2, 0.0);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_EQ(m.maxAbsolute, 0.0);
    EXPECT_EQ(m.relativeP999, 0.0);
    EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0);
    EXPECT_EQ(m.pixels, 32u);
}

TEST(ErrorMetrics, ScaledImageGivesTheScaleAsRelativeError) {
    Image ref(16, 8, 3);
    for (std::size_t i = 0; i < ref.pixels.size(); ++i) ref.pixels[i] = 0.1f + float(i % 7);
    Image test = ref;
    for (float& v : test.pixels) v *= 1.25f;
    const ErrorMetrics m = compareImages(test, ref);
    EXPECT_NEAR(m.relativeL2, 0.25, 1e-6);
    // Every pixel's relative error is 0.25 (no pixel is below the floor), so is its 99.9th percentile.
    EXPECT_NEAR(m.relativeP999, 0.25, 1e-6);
    double maxRef = 0.0, sum2 = 0.0;
    for (float v : ref.pixels) maxRef = std::max(maxRef, double(v)), sum2 += 0.0625 * double(v) * double(v);
    EXPECT_NEAR(m.maxAbsolute, 0.25 * maxRef, 1e-5);
    EXPECT_NEAR(m.rmse, std::sqrt(sum2 / double(ref.pixels.size())), 1e-5);
    EXPECT_GT(m.psnr, 0.0);
    EXPECT_TRUE(std::isfinite(m.psnr));
}

TEST(ErrorMetrics, PercentileIgnoresTheWorstTenthOfAPercent) {
    // 2000 pixels: one is far off, the rest exact: the 99.9th percentile (rank 1998 of 2000) is 0.
    const Image ref = constant(100, 20, 1.0f);
    Image test = ref;
    test.at(3, 4, 0) = 50.0f;
    EXPECT_EQ(compareImages(test, ref).relativeP999, 0.0);
    test.at(5, 6, 1) = 50.0f;
    test.at(7, 8, 2) = 50.0f;  // 3 bad pixels > 0.1 %: now the percentile sees one
    EXPECT_GT(compareImages(test, ref).relativeP999, 10.0);
}

TEST(ErrorMetrics, NonFinitePixelsAreCountedAndMakeFiguresUndefined) {
    const Image ref = constant(4, 4, 1.0f);
    Image test = ref;
    test.at(0, 0, 1) = std::numeric_limits<float>::quiet_NaN();
    test.at(1, 0, 0) = std::numeric_limits<float>::infinity();
    test.at(1, 0, 2) = std::numeric_limits<float>::quiet_NaN();  // same pixel: counted once per kind
    test.at(2, 0, 0) = -0.5f;
    const ErrorMetrics m = compareImages(test, ref);
    EXPECT_EQ(m.nanPixels, 2u);
    EXPECT_EQ(m.infPixels, 1u);
    EXPECT_EQ(m.negativePixels, 1u);
    EXPECT_FALSE(m.finite());
    EXPECT_TRUE(std::isnan(m.relativeL2));
    EXPECT_TRUE(std::isnan(m.psnr));
}

TEST(ErrorMetrics, PsnrUsesTheStatedToneMap) {
    const Image ref = constant(4, 4, 2.0f);
    const Image test = constant(4, 4, 3.0f);
    const double k = kToneKey / 2.0;
    const double d = toneMap(3.0, k) - toneMap(2.0, k);
    EXPECT_NEAR(compareImages(test, ref).psnr, -10.0 * std::log10(d * d), 1e-9);
}

TEST(Tradeoff, ParetoFrontKeepsOnlyUndominatedPoints) {
    const std::vector<TradeoffPoint> p = {{10, 0.5}, {20, 0.2}, {15, 0.6}, {40, 0.05}, {30, 0.3}, {5, 0.9},
                                          {0, 0.1}, {50, std::numeric_limits<double>::quiet_NaN()}};
    EXPECT_EQ(paretoFront(p), (std::vector<int>{5, 0, 1, 3}));
}

TEST(Tradeoff, SpeedupInterpolatesOnALogLogLine) {
    // Baseline time = 100 * error^-0.5 exactly, so interpolation on log-log axes is exact in between.
    std::vector<TradeoffPoint> base;
    for (double e : {0.8, 0.2, 0.05, 0.0125}) base.push_back({100.0 * std::pow(e, -0.5), e});
    const double e = 0.1;
    const auto t = baselineTimeAtError(base, e);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(*t, 100.0 * std::pow(e, -0.5), 1e-9);
    const auto s = speedupAtEqualError(base, {*t / 4.0, e});
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(*s, 4.0, 1e-9);
    // Outside the baseline's error range there is no extrapolation.
    EXPECT_FALSE(baselineTimeAtError(base, 0.9).has_value());
    EXPECT_FALSE(baselineTimeAtError(base, 0.01).has_value());
    EXPECT_TRUE(baselineTimeAtError(base, 0.0125).has_value());
}

TEST(Tradeoff, TimeToReachATargetFollowsTheSeriesOwnFront) {
    // Time = 100 * error^-0.5 exactly on the front, plus a dominated point that must not be used.
    std::vector<TradeoffPoint> series;
    for (double e : {0.4, 0.1, 0.025}) series.push_back({100.0 * std::pow(e, -0.5), e});
    series.push_back({170.0, 0.5});  // slower than the 0.4 point (158 ms) and worse: off the front
    const TimeToTarget at5 = timeToReach(series, 0.05);
    EXPECT_EQ(at5.kind, TimeToTarget::Kind::Interpolated);
    EXPECT_NEAR(at5.milliseconds, 100.0 * std::pow(0.05, -0.5), 1e-9);
    // Exactly on a front point.
    EXPECT_NEAR(timeToReach(series, 0.1).milliseconds, 100.0 * std::pow(0.1, -0.5), 1e-9);
    // Below the best error: not reached, and it says how close it came.
    const TimeToTarget at1 = timeToReach(series, 0.01);
    EXPECT_EQ(at1.kind, TimeToTarget::Kind::NotReached);
    EXPECT_DOUBLE_EQ(at1.bestError, 0.025);
    // Above the cheapest point's error: that point's time is an upper bound.
    const TimeToTarget loose = timeToReach(series, 0.6);
    EXPECT_EQ(loose.kind, TimeToTarget::Kind::AtMost);
    EXPECT_DOUBLE_EQ(loose.milliseconds, 100.0 * std::pow(0.4, -0.5));
    EXPECT_EQ(timeToReach({}, 0.05).kind, TimeToTarget::Kind::NotReached);
    // Which points each figure comes from: the front's neighbours around the target, never the dominated one.
    EXPECT_EQ(at5.above, 1);
    EXPECT_EQ(at5.below, 2);
    const TimeToTarget on = timeToReach(series, 0.1);
    EXPECT_EQ(on.above, 1);
    EXPECT_EQ(on.below, 1);
    EXPECT_EQ(loose.above, 0);
    EXPECT_EQ(loose.below, 0);
    EXPECT_EQ(at1.above, -1);
    EXPECT_EQ(at1.below, -1);
}

TEST(Tradeoff, SpeedupAtATargetIsARatioOfTimesOrABoundOrNothing) {
    std::vector<TradeoffPoint> base, fast, coarse;
    for (double e : {0.4, 0.1, 0.025}) base.push_back({100.0 * std::pow(e, -0.5), e});
    for (double e : {0.2, 0.05, 0.02}) fast.push_back({10.0 * std::pow(e, -0.5), e});  // 10x cheaper everywhere
    coarse.push_back({50.0, 0.3});
    const TargetSpeedup exact = speedupAtTarget(base, fast, 0.05);
    EXPECT_EQ(exact.bound, TargetSpeedup::Bound::Exact);
    EXPECT_NEAR(exact.ratio, 10.0, 1e-9);
    EXPECT_EQ(speedupPhrase(exact.ratio), "10x faster");
    // The technique's cheapest point is already below 30 %: its time bounds, so the ratio is a lower bound.
    const TargetSpeedup lower = speedupAtTarget(base, fast, 0.3);
    EXPECT_EQ(lower.bound, TargetSpeedup::Bound::AtLeast);
    EXPECT_NEAR(lower.ratio, 100.0 * std::pow(0.3, -0.5) / (10.0 * std::pow(0.2, -0.5)), 1e-9);
    EXPECT_EQ(targetSpeedupPhrase(lower).rfind("at least ", 0), 0u) << targetSpeedupPhrase(lower);
    // Never reaching the target is said, for either side.
    const TargetSpeedup missed = speedupAtTarget(base, coarse, 0.05);
    EXPECT_EQ(missed.bound, TargetSpeedup::Bound::Unknown);
    EXPECT_EQ(targetSpeedupPhrase(missed), "does not reach 5 % (best 30 %)");
    const TargetSpeedup baseMissed = speedupAtTarget(base, fast, 0.021);
    EXPECT_EQ(targetSpeedupPhrase(baseMissed), "raymarch does not reach 2.1 % (best 2.5 %)");
}

TEST(Tradeoff, APlanSavingIsSignificantOnlyWhenTheRunsDoNotOverlap) {
    PlanSaving p;
    p.plannedRuns = {9.0, 9.5, 10.0};
    p.forcedRuns = {10.5, 11.0, 12.0};
    EXPECT_TRUE(savingIsSignificant(p));
    p.forcedRuns = {9.8, 11.0, 12.0};
    EXPECT_FALSE(savingIsSignificant(p));
    p.forcedRuns = {7.0, 8.0, 8.9};  // the plan costs more, beyond the noise
    EXPECT_TRUE(savingIsSignificant(p));
    p.forcedRuns.clear();
    EXPECT_FALSE(savingIsSignificant(p));
}

class ReportFiles : public ::testing::Test {
protected:
    void SetUp() override {
        for (int i = 0; i < 3; ++i) {
            ReportRow r;
            r.scene = "grate";
            r.technique = i < 2 ? "raymarch" : "slices";
            r.setting = i < 2 ? "N=" + std::to_string(16 << (2 * i)) : "planes=64, \"odd\"";
            r.settings = "samples=16";
            r.width = 32, r.height = 24, r.runs = 5, r.clock = "glFinish+steady_clock";
            r.stages = {{"a.shadow_maps", 1.5}, {"a.march", 2.0 + i}};
            r.totalMilliseconds = 10.0 * (i + 1);
            r.wallMilliseconds = r.totalMilliseconds + 1.0;
            r.error.relativeL2 = i == 0 ? 0.5 : i == 1 ? 0.1 : 0.2;
            r.error.psnr = std::numeric_limits<double>::infinity();
            r.image = i == 2 ? "grate-slices.png" : "";
            mRows.push_back(r);
        }
        annotateTradeoffs(mRows);
    }
    viz::testing::TempDir mTemp{"report"};
    fs::path mDir = mTemp.path();
    std::vector<ReportRow> mRows;
};

TEST_F(ReportFiles, SpeedupAndFrontAreAnnotatedPerScene) {
    ASSERT_TRUE(mRows[2].speedup.has_value());
    // raymarch: 10 ms at 0.5, 20 ms at 0.1; at 0.2 it would take 10 * 2^(log(0.4)/log(0.2)) ms.
    const double expected = 10.0 * std::pow(2.0, std::log(0.2 / 0.5) / std::log(0.1 / 0.5)) / 30.0;
    EXPECT_NEAR(*mRows[2].speedup, expected, 1e-9);
    EXPECT_TRUE(mRows[0].pareto);
    EXPECT_TRUE(mRows[1].pareto);
    EXPECT_FALSE(mRows[2].pareto);  // slower and worse than raymarch N=64
}

TEST_F(ReportFiles, CsvHasTheDocumentedColumnsAndOneLinePerRow) {
    const fs::path csv = mDir / "results.csv";
    writeCsv(csv.string(), mRows);
    std::istringstream in(readText(csv));
    std::string header;
    std::getline(in, header);
    std::string expected;
    for (const std::string& c : csvColumns()) expected += (expected.empty() ? "" : ",") + c;
    EXPECT_EQ(header, expected);
    int lines = 0;
    for (std::string line; std::getline(in, line);) {
        ++lines;
        // Count fields outside quotes: the quoted setting holds a comma and doubled quotes.
        int fields = 1;
        bool quoted = false;
        for (char c : line) {
            if (c == '"') quoted = !quoted;
            if (c == ',' && !quoted) ++fields;
        }
        EXPECT_EQ(fields, int(csvColumns().size())) << line;
    }
    EXPECT_EQ(lines, 3);
    EXPECT_NE(readText(csv).find("\"planes=64, \"\"odd\"\"\""), std::string::npos);
}

TEST_F(ReportFiles, JsonParsesAndPrintsUndefinedFiguresAsNull) {
    const fs::path json = mDir / "results.json";
    ReportMeta meta;
    meta.width = 32, meta.height = 24, meta.runs = 5;
    writeJson(json.string(), meta, mRows);
    const nlohmann::json j = nlohmann::json::parse(readText(json));
    ASSERT_EQ(j.at("rows").size(), 3u);
    const auto& row = j.at("rows")[2];
    for (const char* key : {"scene", "technique", "setting", "total_ms", "wall_ms", "stage_ms", "error", "clock",
                            "speedup_vs_raymarch", "pareto"})
        EXPECT_TRUE(row.contains(key)) << key;
    EXPECT_TRUE(row.at("error").at("psnr_db").is_null());
    EXPECT_DOUBLE_EQ(row.at("stage_ms").at("a.march").get<double>(), 4.0);
    EXPECT_EQ(j.at("meta").at("runs").get<int>(), 5);
}

TEST_F(ReportFiles, HtmlIsStaticAndReferencesItsImages) {
    const fs::path html = mDir / "index.html";
    writeHtml(html.string(), {}, mRows, {{"grate", "grate-plot.png", "grate-reference.png"}});
    const std::string page = readText(html);
    EXPECT_EQ(page.find("<script"), std::string::npos);
    for (const char* image : {"grate-plot.png", "grate-reference.png", "grate-slices.png"})
        EXPECT_NE(page.find(std::string("src=\"") + image + "\""), std::string::npos) << image;
    EXPECT_NE(page.find("&quot;odd&quot;"), std::string::npos);  // escaped
}

// The headline names the settings each side's time at a target lies between, in the page and in
// results.json: here raymarch's 5 % lies between N=4 (20 %) and N=16 (3 %), its 1 % between N=16 and N=64
// (0.5 %); the technique's cheapest setting is below 5 % already (a bound, its own row), and its 1 % lies
// between its two settings. Rows of another scene and a dominated row are never named.
TEST(ReportTargets, EachFigureNamesTheSettingsItLiesBetween) {
    std::vector<ReportRow> rows;
    auto add = [&](const std::string& scene, const std::string& technique, const std::string& setting, double ms,
                   double error) {
        ReportRow r;
        r.scene = scene, r.technique = technique, r.setting = setting;
        r.totalMilliseconds = ms;
        r.error.relativeL2 = error;
        rows.push_back(r);
    };
    add("other", "raymarch", "N=2", 1.0, 0.01);
    add("grate", "raymarch", "N=4", 10.0, 0.2);
    add("grate", "raymarch", "N=8", 30.0, 0.25);  // dominated: slower and worse than N=4
    add("grate", "raymarch", "N=16", 40.0, 0.03);
    add("grate", "raymarch", "N=64", 160.0, 0.005);
    add("grate", "slices", "planes=8 \"odd\"", 5.0, 0.04);
    add("grate", "slices", "planes=64", 20.0, 0.008);
    const TargetSpeedup at5 = targetSpeedup(rows, "grate", "slices", 0.05), at1 = targetSpeedup(rows, "grate", "slices", 0.01);
    using List = std::vector<std::string>;
    EXPECT_EQ(targetSettings(rows, "grate", "raymarch", at5.baseline), (List{"N=4", "N=16"}));
    EXPECT_EQ(targetSettings(rows, "grate", "slices", at5.technique), (List{"planes=8 \"odd\""}));
    EXPECT_EQ(targetSettings(rows, "grate", "raymarch", at1.baseline), (List{"N=16", "N=64"}));
    EXPECT_EQ(targetSettings(rows, "grate", "slices", at1.technique), (List{"planes=8 \"odd\"", "planes=64"}));
    EXPECT_EQ(targetSettingsPhrase(targetSettings(rows, "grate", "raymarch", at1.baseline)), "between N=16 and N=64");
    EXPECT_EQ(targetSettingsPhrase({"N=16"}), "at N=16");
    EXPECT_EQ(targetSettingsPhrase({}), "");
    const TargetSpeedup missed = targetSpeedup(rows, "grate", "slices", 0.001);
    EXPECT_TRUE(targetSettings(rows, "grate", "slices", missed.technique).empty());

    viz::testing::TempDir temp{"report-targets"};
    const fs::path json = temp.path() / "results.json", html = temp.path() / "index.html";
    writeJson(json.string(), {}, rows);
    const nlohmann::json j = nlohmann::json::parse(readText(json));
    int checked = 0;
    for (const auto& t : j.at("speedups_at_targets")) {
        if (t.at("scene") != "grate") continue;
        const bool five = t.at("target_relative_l2").get<double>() == 0.05;
        EXPECT_EQ(t.at("raymarch_settings").get<List>(), five ? (List{"N=4", "N=16"}) : (List{"N=16", "N=64"}));
        EXPECT_EQ(t.at("technique_settings").get<List>(),
                  five ? (List{"planes=8 \"odd\""}) : (List{"planes=8 \"odd\"", "planes=64"}));
        ++checked;
    }
    EXPECT_EQ(checked, 2);
    writeHtml(html.string(), {}, rows, {{"grate", "grate-plot.png", "grate-reference.png"}});
    const std::string page = readText(html);
    // raymarch's under each target (once per row), the technique's under its figure.
    const std::string note = "<br><span class=\"note\">";
    EXPECT_NE(page.find("5 %" + note + "raymarch between N=4 and N=16</span>"), std::string::npos);
    EXPECT_NE(page.find("1 %" + note + "raymarch between N=16 and N=64</span>"), std::string::npos);
    EXPECT_NE(page.find(note + "at planes=8 &quot;odd&quot;</span>"), std::string::npos);
    EXPECT_NE(page.find(note + "between planes=8 &quot;odd&quot; and planes=64</span>"), std::string::npos);
}

TEST_F(ReportFiles, UnwritableFolderIsAnInputError) {
    EXPECT_THROW(writeCsv((mDir / "missing" / "results.csv").string(), mRows), InputError);
    EXPECT_FALSE(fs::exists(mDir / "missing"));
}

}  // namespace
}  // namespace viz::report
