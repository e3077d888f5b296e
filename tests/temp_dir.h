// A temporary folder of the test's own: made with mkdtemp, so its name is unique even when the same test
// binary runs twice at once (the suite, and the ASan build beside it in CI), and removed with everything
// in it when it goes out of scope.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace viz::testing {

class TempDir {
public:
    // 'tag' goes into the name, to tell the folders apart when one is left behind by a killed test.
    explicit TempDir(const std::string& tag) {
        std::string name = "airlight_" + tag + "_XXXXXX";
        for (char& c : name)
            if (c == '/') c = '_';  // a parameterised test's name
        std::string pattern = (std::filesystem::temp_directory_path() / name).string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
        mPath = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& name) const { return mPath / name; }

private:
    std::filesystem::path mPath;
};

// The whole of a file the test wrote ("" when it cannot be read).
inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace viz::testing
