// Replays the fuzzer's files through loadGltfFromMemory in the normal suite: every input that once
// crashed or hung the loader (tests/fuzz/regressions/) and every seed (tests/fuzz/corpus/). As in the
// fuzz target, a file is a GLB when it starts with "glTF" and there is no folder to read from. Each one
// must give a finite scene that passes validateScene, or a one-line InputError of at most 600
// characters; another exception, or a load that runs past a minute, is a failure.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "fuzz/load_contract.h"
#include "scene/gltf_loader.h"
#include "scene/validate.h"

namespace viz::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(VIZ_SOURCE_DIR) / "tests" / "fuzz";

std::vector<fs::path> filesIn(const char* folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(kFuzzDir / folder, ec)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<fs::path> allFiles() {
    std::vector<fs::path> files = filesIn("regressions");
    const std::vector<fs::path> seeds = filesIn("corpus");
    files.insert(files.end(), seeds.begin(), seeds.end());
    return files;
}

// "regressions/index_value_int32_max.gltf" -> "regressions_index_value_int32_max_gltf".
std::string testName(const ::testing::TestParamInfo<fs::path>& info) {
    std::string name = info.param.parent_path().filename().string() + "_" + info.param.filename().string();
    std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

// A hang would otherwise hold the suite until CTest's timeout: past the limit, say which file and stop.
class Watchdog {
public:
    Watchdog(std::string what, std::chrono::seconds limit) : mThread(&Watchdog::watch, this, std::move(what), limit) {}
    ~Watchdog() {
        {
            std::lock_guard lock(mMutex);
            mFinished = true;
        }
        mDone.notify_one();
        mThread.join();
    }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    void watch(const std::string& what, std::chrono::seconds limit) {
        std::unique_lock lock(mMutex);
        if (!mDone.wait_for(lock, limit, [this] { return mFinished; })) {
            std::fprintf(stderr, "%s: still loading after %lld s, a hang\n", what.c_str(),
                         static_cast<long long>(limit.count()));
            std::_Exit(1);
        }
    }

    std::mutex mMutex;
    std::condition_variable mDone;
    bool mFinished = false;
    std::thread mThread;  // last: starts once the members it waits on exist
};

class FuzzFileTest : public ::testing::TestWithParam<fs::path> {};

TEST_P(FuzzFileTest, LoadsFiniteOrRefusesInOneLine) {
    const fs::path& path = GetParam();
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << path;
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    // The exported built-in scenes are valid: they must load, not merely fail politely.
    const bool mustLoad = path.filename().string().rfind("builtin_", 0) == 0;

    Watchdog watchdog(path.string(), std::chrono::seconds(60));
    try {
        const Scene scene = loadGltfFromMemory(bytes, path.filename().string(), /*baseDir=*/"", binary);
        EXPECT_EQ(contract::sceneProblem(scene), "") << "a non-finite or out-of-range value";
        EXPECT_NO_THROW(validateScene(scene));
    } catch (const InputError& e) {
        EXPECT_FALSE(mustLoad) << "refused: " << e.what();
        EXPECT_EQ(contract::errorMessageProblem(e.what()), "") << "message: " << e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "an exception other than InputError: " << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Fuzz, FuzzFileTest, ::testing::ValuesIn(allFiles()), testName);

TEST(FuzzFiles, BothFoldersHaveFiles) {
    EXPECT_FALSE(filesIn("regressions").empty()) << kFuzzDir / "regressions";
    EXPECT_FALSE(filesIn("corpus").empty()) << kFuzzDir / "corpus";
}

}  // namespace
}  // namespace viz::scene
