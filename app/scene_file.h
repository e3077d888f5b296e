// The user's own scene file in the window: completing a typed path (File > Open), and noticing when the
// file changes on disk so the window reloads it.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace airlight {

// Whether `path` names a scene file the loader reads (.gltf or .glb, any case).
bool isSceneFile(const std::string& path);

// Completions of a typed path: the entries of its folder whose names start with what follows the last
// '/', folders (with a trailing '/') and .gltf/.glb files only, sorted, at most `max`. An unreadable or
// missing folder gives none. "~/" at the start stands for $HOME.
std::vector<std::string> completePath(const std::string& typed, std::size_t max = 8);
// The longest text every completion starts with (what Tab completes to); `typed` when there are none.
std::string commonCompletion(const std::string& typed, const std::vector<std::string>& completions);

// Polls a file's modification time (at most every `interval`). changed() is true once per change, after
// the file has kept the same time and size for one more poll (an editor writing it in pieces is not
// read half-written); a file that disappears is not a change until it is back.
class SceneFileWatch {
public:
    explicit SceneFileWatch(std::chrono::milliseconds interval = std::chrono::milliseconds(500)) : mInterval(interval) {}
    // Starts watching `path` (empty, or not a file: watches nothing).
    void watch(const std::string& path);
    const std::string& path() const { return mPath; }
    // Polls when the interval has passed since the last poll.
    bool changed(std::chrono::steady_clock::time_point now);

private:
    struct Stamp {
        std::filesystem::file_time_type time;
        std::uintmax_t size = 0;
        bool operator==(const Stamp& o) const { return time == o.time && size == o.size; }
    };
    static std::optional<Stamp> stampOf(const std::string& path);
    std::chrono::milliseconds mInterval;
    std::string mPath;
    std::optional<Stamp> mLoaded;   // the file as last loaded
    std::optional<Stamp> mPending;  // a new stamp seen once, waiting to be seen again
    std::chrono::steady_clock::time_point mLastPoll{};
};

}  // namespace airlight
