// The shader tree shares its constants and its medium: pi is written out in shaders/common/constants.glsl
// only, and the medium's coefficients are declared in shaders/common/medium.glsl only, so every shader uses
// one copy of each.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

TEST(ShaderTree, PiIsWrittenOutInTheSharedConstantsOnly) {
    const fs::path root = fs::path(VIZ_SOURCE_DIR) / "shaders";
    int files = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file()) continue;
        ++files;
        if (e.path() == root / "common" / "constants.glsl") continue;
        std::ifstream in(e.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            const std::string code = line.substr(0, line.find("//"));
            for (const char* digits : {"3.14159", "6.28318", "1.57079"})
                EXPECT_EQ(code.find(digits), std::string::npos)
                    << e.path().string() << ":" << n << ": use kPi from common/constants.glsl: " << line;
        }
    }
    EXPECT_GT(files, 20) << "the shader tree was not found under " << root;
}

// A uniform named like a medium coefficient (uSigmaS, uSigmaT, uG, whatever its type) outside the block.
TEST(ShaderTree, TheMediumIsDeclaredInTheSharedBlockOnly) {
    const fs::path root = fs::path(VIZ_SOURCE_DIR) / "shaders";
    const std::regex loose(R"(\buniform\s+\w+\s+(uSigmaS|uSigmaT|uG)\s*[;=\[])");
    int files = 0, includers = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file()) continue;
        ++files;
        if (e.path() == root / "common" / "medium.glsl") continue;
        std::ifstream in(e.path());
        std::string line;
        bool includes = false;
        for (int n = 1; std::getline(in, line); ++n) {
            const std::string code = line.substr(0, line.find("//"));
            EXPECT_FALSE(std::regex_search(code, loose))
                << e.path().string() << ":" << n << ": include common/medium.glsl instead: " << line;
            includes = includes || code.find("\"common/medium.glsl\"") != std::string::npos;
        }
        includers += includes ? 1 : 0;
    }
    EXPECT_GT(files, 20) << "the shader tree was not found under " << root;
    EXPECT_GE(includers, 9) << "fewer shaders include the medium block than read the medium";
}

}  // namespace
