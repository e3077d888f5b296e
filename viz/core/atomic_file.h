// Writing a whole file so that readers see the old file or the complete new one, never a partial
// write: the bytes go to a uniquely named temporary file in the target's folder, renamed over the target.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace viz {

// A unique temporary path in the folder of `target`, keeping its extension (some writers pick the
// format from it).
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Returns an empty string on success, else a one-line reason (the temporary file is removed).
std::string writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

}  // namespace viz
