// The shader tree shares its constants, its medium and its midpoint sample: pi is written out in
// shaders/common/constants.glsl only, the medium's coefficients are declared in shaders/common/medium.glsl
// only, and the midpoint rule's sample sigma_s p E V exp(-sigma_t t) dt is written out in
// shaders/common/airlight_sample.glsl only (raymarch, minmax twice, slices and ivsv call it), so every
// shader uses one copy of each.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// Calls line(path, number, code) for every line of every file under shaders/ but `except`, with its
// comment cut off; returns the number of files read.
template <class Line>
int forEachShaderLine(const fs::path& except, Line&& line) {
    const fs::path root = fs::path(VIZ_SOURCE_DIR) / "shaders";
    int files = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file()) continue;
        ++files;
        if (e.path() == root / except) continue;
        std::ifstream in(e.path());
        std::string text;
        for (int n = 1; std::getline(in, text); ++n) line(e.path(), n, text.substr(0, text.find("//")));
    }
    EXPECT_GT(files, 20) << "the shader tree was not found under " << root;
    return files;
}

TEST(ShaderTree, PiIsWrittenOutInTheSharedConstantsOnly) {
    forEachShaderLine("common/constants.glsl", [](const fs::path& path, int n, const std::string& code) {
        for (const char* digits : {"3.14159", "6.28318", "1.57079"})
            EXPECT_EQ(code.find(digits), std::string::npos)
                << path.string() << ":" << n << ": use kPi from common/constants.glsl: " << code;
    });
}

// A uniform named like a medium coefficient (uSigmaS, uSigmaT, uG, whatever its type) outside the block.
TEST(ShaderTree, TheMediumIsDeclaredInTheSharedBlockOnly) {
    const std::regex loose(R"(\buniform\s+\w+\s+(uSigmaS|uSigmaT|uG)\s*[;=\[])");
    std::set<std::string> includers;
    forEachShaderLine("common/medium.glsl", [&](const fs::path& path, int n, const std::string& code) {
        EXPECT_FALSE(std::regex_search(code, loose))
            << path.string() << ":" << n << ": include common/medium.glsl instead: " << code;
        if (code.find("\"common/medium.glsl\"") != std::string::npos) includers.insert(path.string());
    });
    EXPECT_GE(includers.size(), 9u) << "fewer shaders include the medium block than read the medium";
}

// The midpoint sample: no line outside the shared sample multiplies sigma_s by the phase function
// (the sums of the per-sample integrand along a ray call airlightSample instead: raymarch's march,
// minmax's two marches, slices' planes, the far tail of slices and vsv, ivsv's gather).
TEST(ShaderTree, TheMidpointSampleIsWrittenOutInTheSharedSampleOnly) {
    const std::regex sample(R"(uSigmaS\s*\*[^;]*phaseHG\(|phaseHG\([^;]*\*\s*uSigmaS\b)");
    std::map<std::string, int> calls;
    forEachShaderLine("common/airlight_sample.glsl", [&](const fs::path& path, int n, const std::string& code) {
        EXPECT_FALSE(std::regex_search(code, sample))
            << path.string() << ":" << n << ": call airlightSample (common/airlight_sample.glsl): " << code;
        if (code.find("airlightSample(") != std::string::npos) ++calls[path.filename().string()];
    });
    EXPECT_EQ(calls, (std::map<std::string, int>{{"march.comp", 1},
                                                 {"traverse.comp", 2},
                                                 {"plane.frag", 1},
                                                 {"march_samples.glsl", 1},
                                                 {"ivsv_gather.comp", 1}}));
}

}  // namespace
