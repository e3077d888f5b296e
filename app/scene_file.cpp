#include "scene_file.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace airlight {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string expandHome(const std::string& typed) {
    if (typed.rfind("~/", 0) != 0) return typed;
    const char* home = std::getenv("HOME");
    return home ? std::string(home) + typed.substr(1) : typed;
}

}  // namespace

bool isSceneFile(const std::string& path) {
    const std::string ext = lower(fs::path(path).extension().string());
    return ext == ".gltf" || ext == ".glb";
}

std::vector<std::string> completePath(const std::string& typed, std::size_t max) {
    const std::string expanded = expandHome(typed);
    const auto slash = typed.find_last_of('/');
    const std::string shownFolder = slash == std::string::npos ? std::string() : typed.substr(0, slash + 1);
    const auto expandedSlash = expanded.find_last_of('/');
    const std::string folder = expandedSlash == std::string::npos ? "." : expanded.substr(0, expandedSlash + 1);
    const std::string prefix = expandedSlash == std::string::npos ? expanded : expanded.substr(expandedSlash + 1);
    std::vector<std::string> out;
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) return out;
    for (const fs::directory_entry& e : it) {
        const std::string name = e.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || (prefix.empty() && !name.empty() && name[0] == '.')) continue;
        std::error_code typeError;
        if (e.is_directory(typeError)) out.push_back(shownFolder + name + "/");
        else if (isSceneFile(name)) out.push_back(shownFolder + name);
    }
    std::sort(out.begin(), out.end());
    if (out.size() > max) out.resize(max);
    return out;
}

std::string commonCompletion(const std::string& typed, const std::vector<std::string>& completions) {
    if (completions.empty()) return typed;
    std::string common = completions.front();
    for (const std::string& c : completions) {
        std::size_t n = 0;
        while (n < common.size() && n < c.size() && common[n] == c[n]) ++n;
        common.resize(n);
    }
    return common.size() > typed.size() ? common : typed;
}

std::optional<SceneFileWatch::Stamp> SceneFileWatch::stampOf(const std::string& path) {
    std::error_code ec;
    if (path.empty() || !fs::is_regular_file(path, ec)) return std::nullopt;
    Stamp s;
    s.time = fs::last_write_time(path, ec);
    if (ec) return std::nullopt;
    s.size = fs::file_size(path, ec);
    if (ec) return std::nullopt;
    return s;
}

void SceneFileWatch::watch(const std::string& path) {
    mPath = isSceneFile(path) ? path : std::string();
    mLoaded = stampOf(mPath);
    mPending.reset();
}

bool SceneFileWatch::changed(std::chrono::steady_clock::time_point now) {
    if (mPath.empty() || now - mLastPoll < mInterval) return false;
    mLastPoll = now;
    const std::optional<Stamp> s = stampOf(mPath);
    if (!s || (mLoaded && *s == *mLoaded)) {
        mPending.reset();
        return false;
    }
    if (!mPending || !(*mPending == *s)) {  // first sight of this version: wait one poll
        mPending = s;
        return false;
    }
    mLoaded = s;
    mPending.reset();
    return true;
}

}  // namespace airlight
