// The shader tree shares its constants: pi is written out in shaders/common/constants.glsl only, so every
// shader uses one copy of it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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

}  // namespace
