#include "core/atomic_file.h"

#include <fstream>
#include <random>
#include <sstream>
#include <thread>

namespace viz {

std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
    // Unique per writer (thread id and a random number), so concurrent writers never share a file.
    std::ostringstream name;
    name << "." << target.filename().string() << ".tmp" << std::this_thread::get_id() << "-"
         << std::random_device{}() << target.extension().string();
    const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
    return folder / name.str();
}

std::string writeFileAtomically(const std::filesystem::path& target, std::string_view bytes) {
    const std::filesystem::path tmp = temporaryPathFor(target);
    std::error_code ec;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return "cannot create a file in folder '" + tmp.parent_path().string() + "'";
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out) {
            std::filesystem::remove(tmp, ec);
            return "writing failed (disk full?)";
        }
    }
    std::filesystem::rename(tmp, target, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        return "cannot replace the file (" + ec.message() + ")";
    }
    return {};
}

}  // namespace viz
