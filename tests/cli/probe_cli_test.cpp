// `airlight probe` end to end on a tiny image: the table, the ratio line and the CSV's shape; the
// one-line errors for options out of range, and no CSV left behind by a refused run.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

TEST_F(CliTest, ProbePrintsEachPassAndWritesTheCsv) {
    const fs::path csv = path("probe.csv");
    const RunResult r = run("probe --size 40x30 --iterations 8 --layers 3 --cell 4 --runs 1 --out " + csv.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("renderer: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("40x30, 8 arithmetic steps a pixel, 3 layers, 4 px cells"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fragment_alu / compute_alu = "), std::string::npos) << r.out;
    std::istringstream in(readFile(csv));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "pass,ms,min_ms,max_ms,work,unit,rate_per_s,clock,renderer,width,height");
    std::vector<std::string> passes;
    while (std::getline(in, line)) {
        passes.push_back(line.substr(0, line.find(',')));
        EXPECT_NE(line.find("OpenGL"), std::string::npos) << line;
        EXPECT_NE(line.find(",40,30"), std::string::npos) << line;
    }
    EXPECT_EQ(passes, (std::vector<std::string>{"compute_alu", "fragment_alu", "blend_rgba32f", "blend_rgba16f", "triangles"}));
}

TEST_F(CliTest, ProbeHelpListsItsPassesAndOptions) {
    const RunResult r = run("probe --help");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* word : {"compute_alu", "fragment_alu", "blend_rgba32f", "blend_rgba16f", "triangles", "--iterations", "--out"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST_F(CliTest, ProbeRefusesBadOptionsInOneLine) {
    expectUserError(run("probe --iterations 0"), "--iterations must be a whole number from 1 to 4096");
    expectUserError(run("probe --layers 2.5"), "--layers must be a whole number");
    expectUserError(run("probe --cell 100"), "--cell must be a whole number from 1 to 64");
    expectUserError(run("probe --runs -1"), "--runs");
    expectUserError(run("probe --size 0x10"), "size");
    expectUserError(run("probe --out " + path("p.txt").string()), "--out must name a .csv file");
    fs::create_directories(path("d.csv"));
    expectUserError(run("probe --out " + path("d.csv").string()), "is a folder");
    expectUserError(run("probe --fast"), "unknown option '--fast' for 'probe'");
    EXPECT_FALSE(fs::exists(path("p.txt")));
}

}  // namespace
}  // namespace viz::testing
