// Writing a folder of files all or nothing: every file goes into a hidden staging folder beside the
// target, and only a complete set is moved into place, so a failure halfway leaves no partial folder
// (and no half-replaced one). Used by lesson exports and animations written as numbered frames.
#pragma once

#include <filesystem>
#include <string>

namespace viz {

class StagedFolder {
public:
    // Creates (emptied) the staging folder .NAME.partial beside `target`; throws InputError when it cannot.
    explicit StagedFolder(const std::string& target);
    ~StagedFolder();  // removes the staging folder and whatever is left in it
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;

    // Where to write `file` (a name, no folders) before commit().
    std::string path(const std::string& file) const;

    // Moves every staged file into the target folder (created if needed), replacing same-named files.
    // Throws InputError when it cannot.
    void commit();

private:
    std::string mTarget;
    std::filesystem::path mStage;
};

}  // namespace viz
