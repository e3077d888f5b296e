// `airlight animate`: the GIF's frame count, size and rate as OpenImageIO reads them back, numbered
// frames in a folder, video through ffmpeg (a stand-in program when checking the pipe, the real one when
// installed), and bad input as a one-line error with exit code 2 that leaves no file behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_fixture.h"
#include "core/animation_io.h"
#include "core/image_io.h"
#include "core/process_pipe.h"

namespace fs = std::filesystem;
using viz::testing::CliTest;
using viz::testing::readFile;
using viz::testing::RunResult;

namespace {

class AnimateTest : public CliTest {
protected:
    // Everything in the test's folder that a run may have written (not its captured output or the test's
    // own inputs), hidden temporary files and staging folders included.
    std::vector<std::string> written(const std::vector<std::string>& inputs = {}) const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(mDir)) {
            const std::string name = entry.path().filename().string();
            if (name == "stdout.txt" || name == "stderr.txt") continue;
            if (std::find(inputs.begin(), inputs.end(), name) != inputs.end()) continue;
            names.push_back(name);
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    // A program named ffmpeg in its own folder, running `body` under /bin/sh.
    fs::path standInFfmpeg(const std::string& body) const {
        const fs::path folder = mDir / "bin";
        fs::create_directories(folder);
        const fs::path program = writeText("bin/ffmpeg", "#!/bin/sh\n" + body + "\n");
        ::chmod(program.c_str(), 0755);
        return folder;
    }

    // Runs with PATH replaced (the binary is started by its full path, the shell by /bin/sh).
    RunResult runWithPath(const std::string& path, const std::string& args) {
        const char* old = std::getenv("PATH");
        const std::string saved = old ? old : "";
        ::setenv("PATH", path.c_str(), 1);
        RunResult r = run(args);
        ::setenv("PATH", saved.c_str(), 1);
        return r;
    }

    static constexpr const char* kAnimate = "animate --scene grate --technique raymarch --set samples=16 ";
};

TEST_F(AnimateTest, HelpNamesTheOptions) {
    const RunResult r = run("animate --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* word : {"usage: airlight animate", "--path", "--frames", "camera-orbit", "light-sweep", "--fps"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST_F(AnimateTest, WritesAGifWhoseFramesAndSizeReadBack) {
    const fs::path gif = path("orbit.gif");
    const RunResult r = run(std::string(kAnimate) + "--path camera-orbit:20deg,light-sweep:10deg --frames 5 --size 40x30 " +
                            "--fps 20 --out " + gif.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + gif.string() + " (5 frames, 40x30, 20 fps"), std::string::npos) << r.out;
    const viz::AnimationInfo info = viz::readAnimationInfo(gif.string());
    EXPECT_EQ(info.frames, 5);
    EXPECT_EQ(info.width, 40);
    EXPECT_EQ(info.height, 30);
    EXPECT_DOUBLE_EQ(info.fps, 20.0);
    EXPECT_EQ(written(), std::vector<std::string>{"orbit.gif"});  // no temporary file left beside it
}

TEST_F(AnimateTest, BadPathOrFrameCountIsAOneLineErrorAndNoFile) {
    const std::string gif = " --size 32x24 --out " + path("bad.gif").string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--path camera-orbt:30deg --frames 4", "unknown motion 'camera-orbt'"},
        {"--path camera-orbit:30 --frames 4", "camera-orbit takes an angle"},
        {"--path light-sweep --frames 4", "light-sweep needs an angle"},
        {"--path camera-dolly:near --frames 4", "camera-dolly distance 'near' is not a number"},
        {"--path missing.json --frames 4", "keyframe file 'missing.json' cannot be read"},
        {"--path camera-orbit:30deg --frames 0", "--frames must be a whole number from 1 to 10000"},
        {"--path camera-orbit:30deg --frames 10001", "--frames must be a whole number from 1 to 10000"},
        {"--path camera-orbit:30deg --frames 2.5", "--frames must be a whole number"},
        {"--path camera-orbit:30deg --frames many", "'many' is not a finite number"},
        {"--path camera-orbit:30deg", "animate needs --frames"},
        {"--frames 4", "animate needs --path"},
        {"--path camera-orbit:30deg --frames 4 --fps 0", "--fps must be a whole number from 1 to 100"},
        {"--path camera-orbit:30deg --frames 4 --layer depth", "animate writes final or airlight"},
    };
    for (const auto& [args, mentions] : cases) {
        SCOPED_TRACE(args);
        expectUserError(run(std::string(kAnimate) + args + gif), mentions);
        EXPECT_TRUE(written().empty());
    }
    // A bad size, a light path on a scene whose first light cannot move, an output that is no animation.
    expectUserError(run(std::string(kAnimate) + "--path camera-orbit:30deg --frames 4 --size 0x24 --out " + path("bad.gif").string()),
                    "size '0x24' is out of range");
    expectUserError(run("animate --scene tv-room --technique raymarch --path light-orbit --frames 4" + gif), "area light");
    expectUserError(run(std::string(kAnimate) + "--path camera-orbit:30deg --frames 4 --size 32x24 --out " + path("a.png").string()),
                    "must end in .gif or .mp4");
    expectUserError(run(std::string(kAnimate) + "--path camera-orbit:30deg --frames 4 --size 32x24 --out " +
                        (mDir / "none" / "a.gif").string()),
                    "does not exist");
    EXPECT_TRUE(written().empty());
}

TEST_F(AnimateTest, WritesNumberedFramesIntoAFolder) {
    const fs::path folder = path("frames");
    const RunResult r = run(std::string(kAnimate) + "--path light-orbit:90deg --frames 3 --size 24x16 --exr --out " +
                            folder.string() + "/");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(written(), std::vector<std::string>{"frames"});  // the staging folder is gone
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(folder)) files.push_back(entry.path().filename().string());
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"frame_0000.exr", "frame_0000.png", "frame_0001.exr", "frame_0001.png",
                                               "frame_0002.exr", "frame_0002.png"}));
    const viz::Image png = viz::readImage((folder / "frame_0001.png").string());
    EXPECT_EQ(png.width, 24);
    EXPECT_EQ(png.height, 16);
    const viz::Image first = viz::readImage((folder / "frame_0000.exr").string());
    const viz::Image second = viz::readImage((folder / "frame_0001.exr").string());
    EXPECT_EQ(first.channels, 3);
    EXPECT_NE(first.pixels, second.pixels) << "the light did not move";
}

TEST_F(AnimateTest, VideoWithoutFfmpegIsAnErrorAndNoFile) {
    const fs::path empty = path("empty-bin");
    fs::create_directories(empty);
    const RunResult r = runWithPath(empty.string(), std::string(kAnimate) + "--path camera-orbit:10deg --frames 3 " +
                                                        "--size 32x24 --out " + path("clip.mp4").string());
    expectUserError(r, "needs ffmpeg, which is not on PATH");
    EXPECT_EQ(written(), std::vector<std::string>{"empty-bin"});
}

TEST_F(AnimateTest, VideoFramesArePipedToFfmpeg) {
    // The stand-in keeps what it is sent in its last argument, the output file: raw RGB, frame by frame.
    const fs::path bin = standInFfmpeg("for a; do out=$a; done\ncat > \"$out\"");
    const fs::path clip = path("clip.mp4");
    const RunResult r = runWithPath(bin.string() + ":/usr/bin:/bin", std::string(kAnimate) +
                                                                       "--path camera-orbit:10deg --frames 3 --size 32x24 --out " +
                                                                       clip.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(fs::file_size(clip), std::uintmax_t(3 * 32 * 24 * 3));
    EXPECT_EQ(written({"bin"}), std::vector<std::string>{"clip.mp4"});
}

TEST_F(AnimateTest, AFailingFfmpegIsAOneLineErrorAndNoFile) {
    const fs::path bin = standInFfmpeg("cat > /dev/null\necho \"Unknown encoder 'libx264'\" >&2\nexit 1");
    const RunResult r = runWithPath(bin.string() + ":/usr/bin:/bin", std::string(kAnimate) +
                                                                       "--path camera-orbit:10deg --frames 3 --size 32x24 --out " +
                                                                       path("clip.mp4").string());
    expectUserError(r, "ffmpeg could not write");
    EXPECT_NE(r.err.find("Unknown encoder 'libx264'"), std::string::npos) << r.err;
    EXPECT_TRUE(written({"bin"}).empty());
}

TEST_F(AnimateTest, WritesAnMp4WhenFfmpegIsInstalled) {
    if (viz::findOnPath("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
    const fs::path clip = path("clip.mp4");
    const RunResult r = run(std::string(kAnimate) + "--path light-sweep:15deg --frames 4 --size 33x25 --out " + clip.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string bytes = readFile(clip);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(4, 4), "ftyp");  // an ISO media file
    EXPECT_EQ(written(), std::vector<std::string>{"clip.mp4"});
}

}  // namespace
