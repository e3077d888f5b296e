// Path completion for File > Open and the scene file watch (app/scene_file.h), on a temporary folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "scene_file.h"
#include "temp_dir.h"

namespace airlight {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

class SceneFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(mDir / "halls");
        for (const char* f : {"hall_a.gltf", "hall_b.GLB", "hall_notes.txt", ".hidden.gltf", "other.gltf"})
            std::ofstream(mDir / f) << "x";
    }
    std::string at(const std::string& name) const { return (mDir / name).string(); }
    viz::testing::TempDir mTemp{"scene_file"};
    fs::path mDir = mTemp.path();
};

TEST_F(SceneFileTest, CompletionListsSceneFilesAndFoldersStartingWithTheTypedName) {
    EXPECT_EQ(completePath(at("hall")), (std::vector<std::string>{at("hall_a.gltf"), at("hall_b.GLB"), at("halls/")}));
    EXPECT_EQ(completePath(at("o")), (std::vector<std::string>{at("other.gltf")}));
    EXPECT_TRUE(completePath(at("zzz")).empty());
    EXPECT_TRUE(completePath(at("missing/folder/x")).empty());
    const auto all = completePath(mDir.string() + "/");
    EXPECT_EQ(std::count(all.begin(), all.end(), at(".hidden.gltf")), 0) << "hidden files only when asked for";
    EXPECT_EQ(completePath(mDir.string() + "/", 2).size(), 2u);
}

TEST_F(SceneFileTest, TabCompletesToTheCommonStart) {
    EXPECT_EQ(commonCompletion(at("h"), completePath(at("h"))), at("hall"));
    EXPECT_EQ(commonCompletion(at("o"), completePath(at("o"))), at("other.gltf"));
    EXPECT_EQ(commonCompletion(at("zzz"), completePath(at("zzz"))), at("zzz"));
    EXPECT_TRUE(isSceneFile("a/B.GlTf"));
    EXPECT_FALSE(isSceneFile("a/gltf"));
}

// A change is reported once, after the file kept its new time and size for one more poll.
TEST_F(SceneFileTest, AChangeIsReportedOnceAfterTheFileSettles) {
    SceneFileWatch watch(milliseconds(0));
    watch.watch(at("hall_a.gltf"));
    auto now = std::chrono::steady_clock::now();
    const auto tick = [&] { return now += milliseconds(10); };
    EXPECT_FALSE(watch.changed(tick()));
    std::this_thread::sleep_for(milliseconds(20));
    std::ofstream(mDir / "hall_a.gltf") << "changed";
    EXPECT_FALSE(watch.changed(tick())) << "first sight: wait for it to settle";
    EXPECT_TRUE(watch.changed(tick()));
    EXPECT_FALSE(watch.changed(tick())) << "reported once";
    fs::remove(mDir / "hall_a.gltf");
    EXPECT_FALSE(watch.changed(tick()));
    EXPECT_FALSE(watch.changed(tick())) << "a file that disappears is not a change";
    SceneFileWatch none;
    none.watch("grate");
    EXPECT_FALSE(none.changed(tick())) << "a built-in scene is not watched";
}

}  // namespace
}  // namespace airlight
