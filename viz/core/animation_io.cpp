#include "core/animation_io.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_codec.h"
#include "core/image_io.h"
#include "core/process_pipe.h"
#include "core/staged_folder.h"

namespace viz {

namespace fs = std::filesystem;

// One way of writing frames; the destructor of an uncommitted sink removes what it wrote.
class AnimationWriter::Sink {
public:
    virtual ~Sink() = default;
    virtual void add(const Image& frame, float exposure, int index) = 0;
    virtual void commit() = 0;
};

namespace {

void requireFolderOf(const std::string& out) {
    const fs::path target(out);
    if (target.has_parent_path() && !fs::is_directory(target.parent_path()))
        throw InputError("--out '" + out + "': folder '" + target.parent_path().string() + "' does not exist");
}

// A file written under a temporary name beside the target and renamed onto it.
class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& target) : mTarget(target), mTemporary(temporaryPathFor(target)) {}
    ~TemporaryFile() {
        std::error_code ec;
        if (!mDone) fs::remove(mTemporary, ec);
    }
    std::string path() const { return mTemporary.string(); }
    void commit() {
        std::error_code ec;
        fs::rename(mTemporary, mTarget, ec);
        if (ec) throw InputError("cannot write '" + mTarget + "': " + ec.message());
        mDone = true;
    }

private:
    std::string mTarget;
    fs::path mTemporary;
    bool mDone = false;
};

class GifSink : public AnimationWriter::Sink {
public:
    GifSink(const std::string& out, const AnimationSpec& spec)
        : mOut(out), mFile(out), mWriter(codec::openGif(mFile.path(), spec.width, spec.height, spec.frames, spec.fps)) {}
    void add(const Image& frame, float exposure, int index) override {
        const std::vector<std::uint8_t> bytes = srgb8Pixels(frame, exposure, 3);
        if (const std::string error = mWriter->addFrame(bytes.data(), index); !error.empty())
            throw InputError("cannot write '" + mOut + "': " + error);
    }
    void commit() override {
        const std::string error = mWriter->close();
        mWriter.reset();
        if (!error.empty()) throw InputError("cannot write '" + mOut + "': " + error);
        mFile.commit();
    }

private:
    std::string mOut;
    TemporaryFile mFile;
    std::unique_ptr<codec::GifWriter> mWriter;
};

class VideoSink : public AnimationWriter::Sink {
public:
    VideoSink(const std::string& out, const AnimationSpec& spec) : mOut(out), mFile(out), mLog(mFile.path() + ".log") {
        const std::string ffmpeg = findOnPath("ffmpeg");
        if (ffmpeg.empty())
            throw InputError("writing '" + out + "' needs ffmpeg, which is not on PATH (install it, or write a .gif or "
                             "a folder of frames)");
        const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
        // H.264 in yuv420p (what players expect) needs even sides: pad by one pixel where odd.
        mPipe.emplace(std::vector<std::string>{ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                               "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-r",
                                               std::to_string(spec.fps), "-i", "-", "-vf",
                                               "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-f", "mp4",
                                               mFile.path()},
                      mLog);
    }
    ~VideoSink() override {
        mPipe.reset();
        std::error_code ec;
        fs::remove(mLog, ec);
    }
    void add(const Image& frame, float exposure, int) override {
        const std::vector<std::uint8_t> bytes = srgb8Pixels(frame, exposure, 3);
        if (!mPipe->write(bytes.data(), bytes.size())) fail();
    }
    void commit() override {
        const std::string problem = mPipe->finish();
        if (!problem.empty()) throw InputError("ffmpeg could not write '" + mOut + "' (" + problem + ")");
        mFile.commit();
    }

private:
    [[noreturn]] void fail() {
        const std::string problem = mPipe->finish();
        throw InputError("ffmpeg stopped reading frames for '" + mOut + "' (" + (problem.empty() ? "no reason given" : problem) + ")");
    }
    std::string mOut;
    TemporaryFile mFile;
    fs::path mLog;
    std::optional<ProcessPipe> mPipe;
};

class FramesSink : public AnimationWriter::Sink {
public:
    FramesSink(const std::string& out, const AnimationSpec& spec) : mFolder(out), mSpec(spec) {}
    void add(const Image& frame, float exposure, int index) override {
        writeImage(frame, mFolder.path(frameFileName(index, mSpec.frames, ".png")), exposure);
        if (mSpec.exr) writeImage(frame, mFolder.path(frameFileName(index, mSpec.frames, ".exr")));
    }
    void commit() override { mFolder.commit(); }

private:
    StagedFolder mFolder;
    AnimationSpec mSpec;
};

}  // namespace

AnimationFormat animationFormatOf(const std::string& out) {
    if (!out.empty() && (out.back() == '/' || fs::is_directory(out))) return AnimationFormat::Frames;
    const std::string ext = extensionOf(out);
    if (ext == ".gif") return AnimationFormat::Gif;
    if (ext == ".mp4") return AnimationFormat::Video;
    throw InputError("--out '" + out + "' must end in .gif or .mp4, or be a folder ending in / (numbered frames)");
}

std::string frameFileName(int index, int count, const std::string& extension) {
    const int digits = std::max(4, int(std::to_string(std::max(count - 1, 0)).size()));
    char name[32];
    std::snprintf(name, sizeof name, "frame_%0*d", digits, index);
    return name + extension;
}

AnimationWriter::AnimationWriter(const std::string& out, const AnimationSpec& spec) : mSpec(spec) {
    VIZ_CHECK(spec.width > 0 && spec.height > 0 && spec.frames > 0, "AnimationWriter: empty animation");
    if (spec.fps < 1 || spec.fps > kMaxFramesPerSecond)
        throw InputError("--fps must be a whole number from 1 to " + std::to_string(kMaxFramesPerSecond));
    const AnimationFormat format = animationFormatOf(out);
    if (spec.exr && format != AnimationFormat::Frames)
        throw InputError("--exr writes EXR frames into a folder: give --out DIR/");
    if (format == AnimationFormat::Frames) {
        fs::path folder(out);
        if (!folder.has_filename()) folder = folder.parent_path();  // DIR/ names DIR
        requireFolderOf(folder.string());
        mSink = std::make_unique<FramesSink>(out, spec);
        return;
    }
    requireFolderOf(out);
    if (format == AnimationFormat::Gif) mSink = std::make_unique<GifSink>(out, spec);
    else mSink = std::make_unique<VideoSink>(out, spec);
}

AnimationWriter::~AnimationWriter() = default;

void AnimationWriter::add(const Image& frame, float exposure) {
    VIZ_CHECK(mAdded < mSpec.frames, "AnimationWriter: more frames than announced");
    VIZ_CHECK(frame.width == mSpec.width && frame.height == mSpec.height, "AnimationWriter: frame of another size");
    mSink->add(frame, exposure, mAdded);
    ++mAdded;
}

void AnimationWriter::commit() {
    VIZ_CHECK(mAdded == mSpec.frames, "AnimationWriter: fewer frames than announced");
    mSink->commit();
}

AnimationInfo readAnimationInfo(const std::string& path) {
    return codec::readAnimationFileInfo(path);
}

}  // namespace viz
