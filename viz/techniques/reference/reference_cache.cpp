#include "techniques/reference/reference_cache.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/atomic_file.h"

namespace viz::reference {

namespace {

constexpr char kMagic[8] = {'A', 'L', 'R', 'E', 'F', 'C', 'H', '1'};
constexpr std::uint32_t kFormatVersion = 1;

void putU32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFFu));
}
void putU64(std::string& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out.push_back(char((v >> (8 * i)) & 0xFFu));
}

// Sequential reader over a byte buffer; every read checks the remaining size.
class Reader {
public:
    explicit Reader(const std::string& bytes, std::size_t end) : mBytes(bytes), mEnd(end) {}
    bool u32(std::uint32_t& v) {
        if (mPos + 4 > mEnd) return false;
        v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(std::uint8_t(mBytes[mPos + std::size_t(i)])) << (8 * i);
        mPos += 4;
        return true;
    }
    bool bytes(void* dst, std::size_t n) {
        if (n > mEnd - mPos) return false;
        std::memcpy(dst, mBytes.data() + mPos, n);
        mPos += n;
        return true;
    }
    bool atEnd() const { return mPos == mEnd; }

private:
    const std::string& mBytes;
    std::size_t mEnd;
    std::size_t mPos = 0;
};

}  // namespace

const Image* CachedImages::find(const std::string& name) const {
    for (const auto& [n, img] : images)
        if (n == name) return &img;
    return nullptr;
}

std::filesystem::path cacheDirectory() {
    if (const char* dir = std::getenv("AIRLIGHT_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "airlight";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "airlight";
    return std::filesystem::temp_directory_path() / "airlight";
}

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t seed) {
    std::uint64_t h = seed;
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

std::string cacheFileName(const std::string& keyDescription) {
    char name[64];
    std::snprintf(name, sizeof(name), "reference-%016llx.bin",
                  static_cast<unsigned long long>(fnv1a64(keyDescription.data(), keyDescription.size())));
    return name;
}

std::optional<CachedImages> readCache(const std::filesystem::path& file, int width, int height) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < sizeof(kMagic) + 8) return std::nullopt;
    // The checksum covers everything before it: a flipped or missing byte is a miss.
    const std::size_t payload = bytes.size() - 8;
    std::uint64_t stored = 0;
    for (int i = 0; i < 8; ++i) stored |= std::uint64_t(std::uint8_t(bytes[payload + std::size_t(i)])) << (8 * i);
    if (fnv1a64(bytes.data(), payload) != stored) return std::nullopt;

    Reader r(bytes, payload);
    char magic[8];
    std::uint32_t version = 0, w = 0, h = 0, count = 0;
    if (!r.bytes(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) return std::nullopt;
    if (!r.u32(version) || version != kFormatVersion) return std::nullopt;
    if (!r.u32(w) || !r.u32(h) || int(w) != width || int(h) != height) return std::nullopt;
    if (!r.u32(count) || count > 64) return std::nullopt;
    CachedImages out;
    out.width = width;
    out.height = height;
    for (std::uint32_t k = 0; k < count; ++k) {
        std::uint32_t nameLength = 0, channels = 0;
        if (!r.u32(nameLength) || nameLength > 256) return std::nullopt;
        std::string name(nameLength, '\0');
        if (!r.bytes(name.data(), nameLength)) return std::nullopt;
        if (!r.u32(channels) || channels < 1 || channels > 4) return std::nullopt;
        Image img(width, height, int(channels));
        if (!r.bytes(img.pixels.data(), img.pixels.size() * sizeof(float))) return std::nullopt;
        out.images.emplace_back(std::move(name), std::move(img));
    }
    if (!r.atEnd()) return std::nullopt;
    return out;
}

bool writeCache(const std::filesystem::path& file, const CachedImages& images) {
    std::string bytes(kMagic, kMagic + 8);
    putU32(bytes, kFormatVersion);
    putU32(bytes, std::uint32_t(images.width));
    putU32(bytes, std::uint32_t(images.height));
    putU32(bytes, std::uint32_t(images.images.size()));
    for (const auto& [name, img] : images.images) {
        putU32(bytes, std::uint32_t(name.size()));
        bytes += name;
        putU32(bytes, std::uint32_t(img.channels));
        bytes.append(reinterpret_cast<const char*>(img.pixels.data()), img.pixels.size() * sizeof(float));
    }
    putU64(bytes, fnv1a64(bytes.data(), bytes.size()));

    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    // Readers see the old file or the whole new one; concurrent writers never share a temporary.
    return writeFileAtomically(file, std::string_view(bytes.data(), bytes.size())).empty();
}

}  // namespace viz::reference
