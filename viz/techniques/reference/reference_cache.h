// On-disk cache of reference frames. A file holds named float images (airlight, final and the scalar
// intermediates) and is found by a key that hashes everything the result depends on.
//
// File layout (little-endian): magic "ALREFCH1", u32 format version, u32 width, u32 height,
// u32 image count, then per image: u32 name length, name bytes, u32 channels, width*height*channels
// f32; finally a u64 FNV-1a checksum of every byte before it. Anything else is treated as a miss.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace viz::reference {

struct CachedImages {
    int width = 0, height = 0;
    std::vector<std::pair<std::string, Image>> images;
    const Image* find(const std::string& name) const;
};

// $AIRLIGHT_CACHE_DIR, else $XDG_CACHE_HOME/airlight, else $HOME/.cache/airlight.
std::filesystem::path cacheDirectory();

// 64-bit FNV-1a, hex-encoded: the file name of a key description.
std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t seed = 14695981039346656037ull);
std::string cacheFileName(const std::string& keyDescription);

// Nothing (a miss) when the file is absent, truncated, corrupt or of another size.
std::optional<CachedImages> readCache(const std::filesystem::path& file, int width, int height);

// Writes to a temporary file in the same folder, then renames it over `file`. Returns false (and
// leaves no partial file) when the folder cannot be written.
bool writeCache(const std::filesystem::path& file, const CachedImages& images);

}  // namespace viz::reference
