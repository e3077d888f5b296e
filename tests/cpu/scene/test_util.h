// Helpers shared by the scene tests: a fresh temporary folder per test, and file writing.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene.h"

namespace viz::scene::test {

// The folders freshTempDir made, removed when the test program exits (ctest runs each test in a process
// of its own, so a folder lives as long as its test).
struct TempDirs {
    std::vector<std::filesystem::path> dirs;
    ~TempDirs() {
        for (const auto& d : dirs) {
            std::error_code ec;
            std::filesystem::remove_all(d, ec);
        }
    }
};

inline std::filesystem::path freshTempDir(const std::string& tag) {
    static TempDirs made;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "airlight_scene_" + tag + "_" + info->test_suite_name() + "_" + info->name() + "_" +
                       std::to_string(::getpid());
    for (char& c : name)
        if (c == '/') c = '_';  // parameterised tests' names
    std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    made.dirs.push_back(dir);
    return dir;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string dataPath(const std::string& name) { return std::string(VIZ_TEST_DATA_DIR) + "/scene/" + name; }

inline bool hasNote(const Scene& scene, const std::string& part) {
    for (const std::string& n : scene.notes) {
        if (n.find(part) != std::string::npos) return true;
    }
    return false;
}

// Runs f, expects an InputError whose message contains 'part', and returns the message.
template <typename F>
std::string expectInputError(F&& f, const std::string& part) {
    try {
        f();
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
        return msg;
    }
    ADD_FAILURE() << "no InputError (expected one mentioning '" << part << "')";
    return {};
}

}  // namespace viz::scene::test
