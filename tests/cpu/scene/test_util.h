// Helpers shared by the scene tests: a fresh temporary folder per test, and file writing.
#pragma once

#include <deque>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene.h"
#include "temp_dir.h"

namespace viz::scene::test {

// A fresh folder for the running test, removed when the test program exits (ctest runs each test in a
// process of its own, so a folder lives as long as its test).
inline std::filesystem::path freshTempDir(const std::string& tag) {
    static std::deque<viz::testing::TempDir> made;  // a deque: its elements never move
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return made.emplace_back("scene_" + tag + "_" + info->test_suite_name() + "_" + info->name()).path();
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
