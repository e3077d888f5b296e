// `airlight bench` end to end on a tiny subset: the CSV's shape and its figures against each other (with
// one run, a point's total is the sum of its stages), the page and its plots, and the one-line errors.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_fixture.h"
#include "core/image_io.h"

namespace viz::testing {
namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
            else if (c == '"') quoted = false;
            else field += c;
        } else if (c == '"') quoted = true;
        else if (c == ',') fields.push_back(field), field.clear();
        else field += c;
    }
    fields.push_back(field);
    return fields;
}

TEST_F(CliTest, BenchWritesPerStageTimesFitsAndPlotsForEachAxis) {
    const fs::path out = path("bench");
    const RunResult r = run("bench --scenes grate --techniques raymarch,slices --axes size,shadow_map,triangles "
                            "--sizes 48x36,96x72 --size 48x36 --quick --runs 1 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;

    std::istringstream csv(readFile(out / "bench.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "scene,technique,axis,value,stage,ms,clock,renderer,work,runs,wall_ms,ms_min,ms_max");
    // (technique, axis, value) -> stage -> ms
    std::map<std::tuple<std::string, std::string, std::string>, std::map<std::string, double>> points;
    std::map<std::tuple<std::string, std::string, std::string>, double> work;
    while (std::getline(csv, line)) {
        const auto f = splitCsvLine(line);
        ASSERT_EQ(f.size(), 13u) << line;
        // One timed run: it is the median, the fastest and the slowest.
        EXPECT_EQ(f[11], f[5]) << line;
        EXPECT_EQ(f[12], f[5]) << line;
        // A stage's wall time covers its GPU time (glFinish+steady_clock here: the same interval).
        EXPECT_GE(std::stod(f[10]), 0.99 * std::stod(f[5]) - 1e-3) << line;
        EXPECT_EQ(f[0], "grate");
        EXPECT_EQ(f[9], "1");
        EXPECT_NE(f[7].find("OpenGL"), std::string::npos) << f[7];
        const double ms = std::stod(f[5]);
        EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << line;
        points[{f[1], f[2], f[3]}][f[4]] = ms;
        work[{f[1], f[2], f[3]}] = std::stod(f[8]);
    }
    // Each technique on each axis at each of its values; shadow_map has 3 quick points, triangles 2.
    for (const std::string t : {"raymarch", "slices"}) {
        EXPECT_EQ(work.at({t, "size", "48x36"}), 48.0 * 36.0);
        EXPECT_EQ(work.at({t, "size", "96x72"}), 96.0 * 72.0);
        EXPECT_EQ(work.at({t, "shadow_map", "1024"}), 1024.0 * 1024.0);
        EXPECT_TRUE(points.count({t, "shadow_map", "256"}) && points.count({t, "shadow_map", "512"}));
        // Ten times the grate's bars: the triangles counted grow about ninefold (the floor and cube stay).
        const double ratio = work.at({t, "triangles", "10"}) / work.at({t, "triangles", "1"});
        EXPECT_GT(ratio, 7.0);
        EXPECT_LT(ratio, 10.0);
    }
    EXPECT_EQ(points.size(), 2u * (2 + 3 + 2));
    for (const auto& [key, stages] : points) {
        ASSERT_TRUE(stages.count("total") && stages.count("wall")) << std::get<0>(key);
        double sum = 0.0;
        for (const auto& [stage, ms] : stages)
            if (stage != "total" && stage != "wall") sum += ms;
        EXPECT_GE(stages.size(), 3u);  // at least one stage of its own
        EXPECT_NEAR(stages.at("total"), sum, 1e-4 * sum + 1e-5) << std::get<0>(key) << " " << std::get<1>(key);
        EXPECT_GE(stages.at("wall"), 0.5 * stages.at("total"));
    }

    // The page: a section per axis, an exponent per technique and stage, every plot present and loading.
    const std::string html = readFile(out / "bench.html");
    // slices is timed without the inspector's recording (Technique::measurementSettings), and the page says so.
    for (const std::string s : {"grate: size", "grate: shadow_map", "grate: triangles", "exponent k",
                                "The debugger's recordings off: slices ray_planes=0.",
                                "as long in a fragment shader as in a compute shader here"})
        EXPECT_NE(html.find(s), std::string::npos) << s;
    int plots = 0;
    for (const auto& entry : fs::directory_iterator(out))
        if (entry.path().extension() == ".png") {
            ++plots;
            EXPECT_NE(html.find(entry.path().filename().string()), std::string::npos) << entry.path();
            EXPECT_GT(viz::readImage(entry.path().string()).width, 200);
        }
    EXPECT_EQ(plots, 3 * (1 + 2));  // per axis: the totals and one per technique
    EXPECT_EQ(htmlValidatorComplaints(out / "bench.html", mDir), "");
    const std::string loaded = imagesLoadedInBrowser(out / "bench.html", mDir);
    if (!loaded.empty()) {
        EXPECT_EQ(loaded, "images=9 missing=0");
    }
    EXPECT_NE(r.out.find("total ~ work^"), std::string::npos) << r.out;
}

// --set reaches the techniques that have the parameter and only them: minmax's integrand beside raymarch
// (which would refuse an unknown name), an out-of-range value refused by the technique it reaches, a name no
// measured technique has refused outright; the page names what was set.
TEST_F(CliTest, BenchSetsAParameterForTheTechniquesThatHaveIt) {
    const fs::path out = path("bench");
    const RunResult r = run("bench --scenes grate --techniques raymarch,minmax --axes size --sizes 32x24 --runs 1 "
                            "--set integrand=svd --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFile(out / "bench.html").find("default settings with integrand=svd"), std::string::npos);
    const fs::path other = path("bench2");
    expectUserError(run("bench --scenes grate --techniques raymarch --axes size --sizes 32x24 --runs 1 "
                        "--set samples=0 --out " + other.string()),
                    "'samples' = 0 is out of range");
    expectUserError(run("bench --techniques raymarch --set integrand=svd --out " + other.string()),
                    "none of the techniques measured has that parameter");
    EXPECT_FALSE(fs::exists(other));
}

TEST_F(CliTest, BenchRejectsWhatItCannotMeasureBeforeWritingAnything) {
    const fs::path out = path("bench");
    expectUserError(run("bench --axes sizes --out " + out.string()), "unknown axis 'sizes'");
    expectUserError(run("bench --scenes grate --techniques raymarch --axes vpls --out " + out.string()),
                    "nothing to measure");
    expectUserError(run("bench --scenes nowhere --out " + out.string()), "nowhere");
    expectUserError(run("bench --techniques raymarch --runs 0 --out " + out.string()), "--runs");
    expectUserError(run("bench --techniques raymarch"), "--out");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace viz::testing
