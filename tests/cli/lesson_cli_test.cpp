// Lessons: every lesson in lessons/ parses and exports (one image per view of every step, and a page a
// browser loads with no missing image); malformed lessons are one-line errors naming file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "cli/cli_fixture.h"
#include "core/animation_io.h"
#include "core/image_io.h"
#include "techniques/registry.h"

namespace viz::testing {
namespace {

namespace fs = std::filesystem;

// Every parameter with named values (integrand=svd, accum=rgba8), from the techniques' declarations.
std::set<std::string> namedValueParams() {
    std::set<std::string> names;
    for (const std::string& id : viz::techniqueIds()) {
        const auto technique = viz::makeTechnique(id);  // params() refers into it: keep it alive
        for (const viz::ParamInfo& p : technique->params()) {
            if (!p.choices.empty()) names.insert(p.name);
        }
    }
    return names;
}

// A step animated through its stage's sub-steps: the handout's GIF has one frame per sub-step (slices'
// 12 planes drawn one more each frame), the last the still figure's state.
TEST_F(CliTest, ASubstepAnimationExportsOneGifFramePerSubstep) {
    const fs::path lesson = writeText("substeps.md", "# Planes one by one\n\n## Back to front\n```airlight\nscene: grate\n"
                                                     "technique: slices\nset: planes=12\nstage: slices.planes\n"
                                                     "views: slices.accumulation\nanimate: substeps 1s\n```\nThe planes, farthest "
                                                     "first.\n");
    const fs::path out = path("substeps");
    const RunResult r = run("lesson " + lesson.string() + " --export " + out.string() + " --size 32x24");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const viz::AnimationInfo info = viz::readAnimationInfo((out / "step1-animation.gif").string());
    EXPECT_EQ(info.frames, 12);
    // 12 frames over 1 s: 12 per second, stored as a delay of whole hundredths (8: 12.5 per second).
    EXPECT_DOUBLE_EQ(info.fps, 100.0 / std::floor(100.0 / 12.0));
    EXPECT_GE(info.width, 480) << "drawn as the still figures are";
    EXPECT_NE(readFile(out / "index.html").find("substeps over 1 s"), std::string::npos);
}

TEST_F(CliTest, EveryLessonExportsAPageWithAllItsImages) {
    const std::set<std::string> named = namedValueParams();
    ASSERT_FALSE(named.empty());
    int lessons = 0, namedTotal = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(VIZ_SOURCE_DIR) / "lessons")) {
        if (entry.path().extension() != ".md" || entry.path().filename() == "README.md") continue;
        ++lessons;
        const std::string name = entry.path().stem().string();
        const fs::path out = path(name);
        const RunResult r = run("lesson " + name + " --export " + out.string() + " --size 32x24");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        const std::string page = readFile(out / "index.html");
        // Every image the page names exists, and there is at least one per step.
        const std::regex img("<img src=\"([^\"]+)\" alt=\"([^\"]+)\" width=\"([0-9]+)\" height=\"([0-9]+)\"([^>]*)>");
        int images = 0, animations = 0;
        for (auto it = std::sregex_iterator(page.begin(), page.end(), img); it != std::sregex_iterator(); ++it) {
            ++images;
            const std::string file = (*it)[1].str(), view = (*it)[2].str(), rest = (*it)[5].str();
            ASSERT_TRUE(fs::exists(out / file)) << name << ": " << file;
            // The figure is what the window draws: at least 480 px wide (a very tall map is scaled down
            // to fit the height instead), the size the page says.
            const Image png = readImage((out / file).string());
            EXPECT_EQ(png.width, std::stoi((*it)[3].str())) << name << ": " << file;
            EXPECT_EQ(png.height, std::stoi((*it)[4].str())) << name << ": " << file;
            if (rest.find("data-texel-scale=\"0\"") == std::string::npos) {
                EXPECT_GE(png.width, 480) << name << ": " << file;
            }
            // A step's animation: an animated GIF whose frame count OpenImageIO reads back as the page says.
            if (rest.find("class=\"animation\"") != std::string::npos) {
                ++animations;
                const viz::AnimationInfo info = viz::readAnimationInfo((out / file).string());
                const std::size_t at = rest.find("data-frames=\"");
                ASSERT_NE(at, std::string::npos) << name << ": " << file;
                EXPECT_EQ(info.frames, std::stoi(rest.substr(at + 13))) << name << ": " << file;
                EXPECT_GT(info.frames, 1) << name << ": " << file;
                EXPECT_EQ(info.width, png.width) << name << ": " << file;
            }
            // minmax's singular values and basis functions are plots in the window: plots here too, with
            // the curves the plot writer says it drew.
            if (view == "minmax.singular_values" || view == "minmax.basis") {
                EXPECT_NE(rest.find("class=\"plot\""), std::string::npos) << name << ": " << view;
                const std::size_t at = rest.find("data-series=\"");
                ASSERT_NE(at, std::string::npos) << name << ": " << view;
                EXPECT_GE(std::stoi(rest.substr(at + 13)), 1) << name << ": " << view;
            }
        }
        // Every figure says what its colours mean (range, units, exposure or plot titles).
        const std::regex caption("<span class=\"range\">([^<]*)</span>");
        int captions = 0;
        for (auto it = std::sregex_iterator(page.begin(), page.end(), caption); it != std::sregex_iterator(); ++it) {
            ++captions;
            EXPECT_FALSE((*it)[1].str().empty()) << name;
        }
        EXPECT_EQ(captions, images) << name;
        // A step that compares techniques gets a table measured while the page was written (one row per
        // technique, each with a time and an error), not figures from elsewhere.
        const std::string source = readFile(entry.path());
        int compares = 0, tables = 0, rows = 0;
        for (std::size_t at = source.find("\ncompare:"); at != std::string::npos; at = source.find("\ncompare:", at + 1)) {
            const std::size_t end = source.find('\n', at + 1);
            const std::string list = source.substr(at + 9, end - at - 9);
            compares += 1;
            rows += int(std::count(list.begin(), list.end(), ',')) + 1;
        }
        for (std::size_t at = page.find("<table class=\"compare\">"); at != std::string::npos;
             at = page.find("<table class=\"compare\">", at + 1))
            ++tables;
        EXPECT_EQ(tables, compares) << name;
        // Every animated step has its GIF.
        int animated = 0;
        for (std::size_t at = source.find("\nanimate:"); at != std::string::npos; at = source.find("\nanimate:", at + 1))
            ++animated;
        EXPECT_EQ(animations, animated) << name;
        // (A time whose runs lay far apart carries the range in a title and a dagger.)
        const std::regex row("<tr><td>([a-z]+)</td><td(?: class=\"noisy\" title=\"runs [^\"]+\")?>([0-9.]+)(?:&dagger;)?</td>"
                             "<td>error ([0-9.e+-]+)</td>");
        int measured = 0;
        for (auto it = std::sregex_iterator(page.begin(), page.end(), row); it != std::sregex_iterator(); ++it) {
            ++measured;
            EXPECT_GT(std::stod((*it)[2].str()), 0.0) << name << ": " << (*it)[1].str();
        }
        EXPECT_EQ(measured, rows) << name;
        // Settings are shown as the prose names them: a parameter with named values never as a number.
        // (A plain scan: std::regex recurses per character and overflows the stack on a whole page.)
        int namedShown = 0;
        for (std::size_t eq = page.find('='); eq != std::string::npos; eq = page.find('=', eq + 1)) {
            std::size_t b = eq;
            while (b > 0 && (std::islower(static_cast<unsigned char>(page[b - 1])) || page[b - 1] == '_')) --b;
            const std::string key = page.substr(b, eq - b);
            if (!named.count(key) || eq + 1 >= page.size()) continue;
            ++namedShown;
            const char first = page[eq + 1];
            EXPECT_FALSE(std::isdigit(static_cast<unsigned char>(first)) || first == '-')
                << name << ": " << page.substr(b, 40) << " shows a named value as a number";
        }
        namedTotal += namedShown;
        int steps = 0;
        for (std::size_t at = page.find("<h2>"); at != std::string::npos; at = page.find("<h2>", at + 1)) ++steps;
        EXPECT_GE(images, steps) << name;
        EXPECT_GT(steps, 0) << name;
        EXPECT_EQ(htmlValidatorComplaints(out / "index.html", mDir), "") << name;
        // The page as a reader sees it, in one browser run: every image loads, and the first screenful
        // shows its figures (coloured pixels), not just text on white.
        const fs::path shot = mDir / (name + "-page.png");
        const BrowserView view = viewInBrowser(out / "index.html", mDir, shot, 1000, 1600);
        if (view.images.empty()) {
            if (std::getenv("VIZ_REQUIRE_BROWSER")) FAIL() << "VIZ_REQUIRE_BROWSER is set but /usr/bin/chromium is missing";
            continue;
        }
        EXPECT_EQ(view.images, "images=" + std::to_string(images) + " missing=0") << name;
        ASSERT_TRUE(view.screenshot) << name;
        const Image seen = readImage(shot.string());
        std::size_t coloured = 0;
        for (int y = 0; y < seen.height; ++y)
            for (int x = 0; x < seen.width; ++x) {
                const float red = seen.at(x, y, 0), green = seen.at(x, y, 1), blue = seen.at(x, y, 2);
                const float top = std::max({red, green, blue}), low = std::min({red, green, blue});
                coloured += top - low > 0.1f || top < 0.5f ? 1 : 0;  // a colour, or dark (a figure, not paper)
            }
        EXPECT_GT(double(coloured) / double(seen.width * seen.height), 0.10) << name << ": " << shot;
    }
    EXPECT_GE(lessons, 2);
    EXPECT_GT(namedTotal, 0) << "no lesson sets a parameter with named values: the check above checked nothing";
}

TEST_F(CliTest, MalformedLessonsNameTheFileAndLine) {
    const std::string good = "# T\n\nintro\n\n## one\n```airlight\nscene: grate\ntechnique: raymarch\n```\ntext\n";
    const auto lesson = [&](const std::string& name, const std::string& text) { return writeText(name, text).string(); };
    expectUserError(run("lesson " + lesson("unknown.md", good + "## two\n```airlight\ncolour: red\n```\n") +
                        " --export " + path("o1").string()),
                    "unknown.md:13");
    expectUserError(run("lesson " + lesson("badsize.md", good + "## two\n```airlight\nsize: 0x10\n```\n") +
                        " --export " + path("o2").string()),
                    "badsize.md:13");
    expectUserError(run("lesson " + lesson("noscene.md", "# T\n## one\n```airlight\ntechnique: raymarch\n```\n") +
                        " --export " + path("o3").string()),
                    "noscene.md:2");
    expectUserError(run("lesson " + lesson("open.md", "# T\n## one\n```airlight\nscene: grate\n") + " --export " +
                        path("o4").string()),
                    "open.md:3");
    expectUserError(run("lesson " + lesson("noview.md", good + "## two\n```airlight\nviews: no.such.view\n```\n") +
                        " --export " + path("o5").string() + " --size 16x12"),
                    "noview.md:11");
    // The unknown view is found only while exporting step two: nothing of the export is left behind.
    EXPECT_FALSE(fs::exists(path("o5")));
    EXPECT_FALSE(fs::exists(path(".o5.partial")));
    expectUserError(run("lesson no-such-lesson --export " + path("o6").string()), "no-such-lesson");
    // lessons/README.md describes the format and is not a lesson; a name that fits several lists them.
    expectUserError(run("lesson README --export " + path("o10").string()), "unknown lesson 'README' (known: 01-");
    expectUserError(run("lesson volumes --export " + path("o11").string()),
                    "could be any of 04-polygonal-light-volumes, 06-voxelized-shadow-volumes");
    EXPECT_FALSE(fs::exists(path("o10")));
    expectUserError(run("lesson " + lesson("cmp.md", "# T\n## one\n```airlight\nscene: grate\ntechnique: raymarch\n"
                                                      "compare: raymarch, reference\n```\n") +
                        " --export " + path("o9").string()),
                    "compare: 'reference'");
    expectUserError(run("lesson " + lesson("inspect3.md", good + "## two\n```airlight\ninspect: 5 5 5\n```\n") +
                        " --export " + path("o7").string()),
                    "inspect3.md:13: inspect takes one pixel 'x y', got '5 5 5'");
    expectUserError(run("lesson " + lesson("twice.md", good + "## two\n```airlight\nset: samples=8\nset: samples=16\n```\n") +
                        " --export " + path("o8").string()),
                    "twice.md:14: 'samples' is set twice in this step");
}

// The window's own arguments fail before it opens, with or without a display: the lesson's name, an
// export folder that is a file.
TEST_F(CliTest, TheWindowsArgumentsAreCheckedBeforeItOpens) {
    expectUserError(run("lesson volumes --screenshot " + path("a.png").string()), "could be any of");
    expectUserError(run("lesson '' --screenshot " + path("b.png").string()), "lesson needs a NAME");
    const fs::path file = writeText("exports", "a file\n");
    expectUserError(run("gui --export-dir " + file.string() + " --screenshot " + path("c.png").string()),
                    "--export-dir '" + file.string() + "' is a file, not a folder");
    EXPECT_EQ(readFile(file), "a file\n");
    for (const char* shot : {"a.png", "b.png", "c.png"}) EXPECT_FALSE(fs::exists(path(shot))) << shot;
}

TEST_F(CliTest, ALessonWithAByteOrderMarkExports) {
    const std::string text = "\xEF\xBB\xBF# Title after a BOM\n\n## one\n```airlight\nscene: grate\ntechnique: raymarch\n```\ntext\n";
    const RunResult r = run("lesson " + writeText("bom.md", text).string() + " --export " + path("bom").string() +
                            " --size 16x12");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFile(path("bom") / "index.html").find("<h1>Title after a BOM</h1>"), std::string::npos);
    EXPECT_FALSE(fs::exists(path(".bom.partial")));
}

}  // namespace
}  // namespace viz::testing
