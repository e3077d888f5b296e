#include "core/staged_folder.h"

#include "core/error.h"

namespace viz {

namespace fs = std::filesystem;

StagedFolder::StagedFolder(const std::string& target) : mTarget(target) {
    const fs::path t = fs::path(target).lexically_normal();
    const fs::path name = t.filename().empty() ? t.parent_path().filename() : t.filename();
    mStage = (t.has_parent_path() ? t.parent_path() : fs::path(".")) / ("." + name.string() + ".partial");
    std::error_code ec;
    fs::remove_all(mStage, ec);
    fs::create_directories(mStage, ec);
    if (!fs::is_directory(mStage)) throw InputError("cannot create the folder '" + mStage.string() + "'");
}

StagedFolder::~StagedFolder() {
    std::error_code ec;
    fs::remove_all(mStage, ec);
}

std::string StagedFolder::path(const std::string& file) const { return (mStage / file).string(); }

void StagedFolder::commit() {
    std::error_code ec;
    fs::create_directories(mTarget, ec);
    if (!fs::is_directory(mTarget)) throw InputError("cannot create the folder '" + mTarget + "'");
    for (const auto& entry : fs::directory_iterator(mStage)) {
        fs::rename(entry.path(), fs::path(mTarget) / entry.path().filename(), ec);
        if (ec) throw InputError("cannot move '" + entry.path().string() + "' into '" + mTarget + "': " + ec.message());
    }
}

}  // namespace viz
