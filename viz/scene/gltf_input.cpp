#include "scene/gltf_input.h"

#include <sys/stat.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include "core/error.h"
#include "core/text.h"
#include "core/json_check.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_texture_use.h"

namespace viz::scene::gltf {
namespace {

namespace fs = std::filesystem;
using Limits = LoadLimits;

std::string gib(std::uint64_t bytes) { return std::to_string(bytes >> 30) + " GiB"; }

// What stat says a path is, in words for a message; empty when it is a regular file within the limit.
std::string fileProblem(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return "does not exist";
    if (S_ISDIR(st.st_mode)) return "names a folder, not a file";
    if (!S_ISREG(st.st_mode)) return "is not a regular file (a FIFO, device or socket)";
    if (std::uint64_t(st.st_size) > Limits::kMaxFileBytes) {
        return "is " + std::to_string(st.st_size) + " bytes, over the " + gib(Limits::kMaxFileBytes) + " limit";
    }
    return {};
}

bool readWhole(const std::string& path, std::vector<unsigned char>& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0 || std::uint64_t(size) > Limits::kMaxFileBytes) return false;
    in.seekg(0, std::ios::beg);
    out.resize(std::size_t(size));
    if (size > 0) in.read(reinterpret_cast<char*>(out.data()), size);
    return bool(in) || in.gcount() == size;
}

// ---- external files: resolved in the file's folder, regular files only ----

// %XX escapes decoded (glTF URIs are URI-encoded); a malformed escape stays as written.
std::string percentDecoded(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

struct Folder {
    fs::path base;  // absolute and lexically normal; empty: no external files
};

// The file an URI names, or an error message (without the "glTF 'FILE': " prefix).
std::string resolveUri(const Folder& folder, const std::string& uri, const std::string& who, std::string& resolved) {
    const std::string decoded = percentDecoded(uri);
    if (folder.base.empty()) return who + ": external file " + quoteValue(uri) + " cannot be read here (data: URIs only)";
    if (decoded.empty() || decoded.find('\0') != std::string::npos) return who + ": URI " + quoteValue(uri) + " is not a file name";
    if (decoded.find("://") != std::string::npos) return who + ": URI " + quoteValue(uri) + " is not a relative file name";
    const fs::path rel(decoded);
    if (rel.is_absolute()) return who + ": URI " + quoteValue(uri) + " is an absolute path (glTF URIs are relative to the file)";
    const fs::path full = (folder.base / rel).lexically_normal();
    const fs::path inside = full.lexically_relative(folder.base);
    if (inside.empty() || *inside.begin() == ".." || inside == ".") {
        return who + ": URI " + quoteValue(uri) + (inside == "." ? " names the file's folder" : " leaves the file's folder");
    }
    const std::string problem = fileProblem(full.string());
    if (!problem.empty()) return who + ": file " + quoteValue(uri) + " " + problem;
    resolved = full.string();
    return {};
}

// tinygltf's file callbacks: the same rules again, for whatever path tinygltf builds (it also tries
// the current folder, which must not be reachable).
bool guardedFileExists(const std::string& path, void* user) {
    const Folder& folder = *static_cast<const Folder*>(user);
    if (folder.base.empty()) return false;
    const fs::path full = fs::absolute(fs::path(path)).lexically_normal();
    const fs::path inside = full.lexically_relative(folder.base);
    if (inside.empty() || *inside.begin() == "..") return false;
    return fileProblem(full.string()).empty();
}

std::string unexpandedPath(const std::string& path, void*) { return path; }

bool guardedReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (!guardedFileExists(path, user) || !readWhole(path, *out)) {
        if (err) *err += "cannot read " + quoteValue(path);
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the loader writes no files";
    return false;
}

// What the image callback needs: the model being parsed, and which images are drawn.
struct ImageContext {
    const tinygltf::Model* model = nullptr;
    const std::vector<bool>* used = nullptr;
};

// Decodes an image only when something draws it, its bytes lie inside what was loaded and its header
// states a size within the limits. An image nothing draws stays empty (it may be a DDS or KTX2 file
// reached only through an extension). tinygltf hands over an image in a bufferView as the buffer's
// bytes from the view's offset, `byteLength` long, without checking that the view fits in the buffer.
bool boundedImageLoader(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int reqWidth,
                        int reqHeight, const unsigned char* bytes, int size, void* user) {
    const ImageContext& context = *static_cast<const ImageContext*>(user);
    if (index < 0 || std::size_t(index) >= context.used->size() || !(*context.used)[std::size_t(index)]) return true;
    if (image->bufferView >= 0) {
        const tinygltf::Model& model = *context.model;
        const std::size_t view = std::size_t(image->bufferView);
        const tinygltf::BufferView* v = view < model.bufferViews.size() ? &model.bufferViews[view] : nullptr;
        const std::size_t have = v && std::size_t(v->buffer) < model.buffers.size()
                                     ? model.buffers[std::size_t(v->buffer)].data.size()
                                     : 0;
        if (!v || v->byteOffset > have || v->byteLength > have - v->byteOffset || v->byteLength > std::size_t(INT_MAX)) {
            if (err)
                *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) +
                        (v ? " (offset " + std::to_string(v->byteOffset) + ", " + std::to_string(v->byteLength) +
                                 " bytes) runs past the end of buffer " + std::to_string(v->buffer) + " (" +
                                 std::to_string(have) + " bytes)"
                           : std::string(" does not exist")) +
                        "\n";
            return false;
        }
    }
    int w = 0, h = 0, c = 0;
    if (size <= 0 || !stbi_info_from_memory(bytes, size, &w, &h, &c)) {
        if (err) {
            const char* why = stbi_failure_reason();
            *err += "image " + std::to_string(index) + " is not a PNG, JPEG or other decodable image" +
                    (why ? std::string(" (") + why + ")" : std::string()) + "\n";
        }
        return false;
    }
    if (w <= 0 || h <= 0 || w > 16384 || h > 16384 || std::uint64_t(w) * std::uint64_t(h) > Limits::kMaxImagePixels) {
        if (err) *err += "image " + std::to_string(index) + " is " + std::to_string(w) + "x" + std::to_string(h) +
                         ", over the 16384 x 16384 limit\n";
        return false;
    }
    return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, nullptr);
}

// An item's "uri", when it names an external file: that file must be one the loader may read.
// Returns false when the item has no uri (a GLB's own chunk, an image in a bufferView).
bool checkItemUri(const nlohmann::json& item, const std::string& who, const Folder& folder, const std::string& prefix) {
    const auto uri = item.find("uri");
    if (uri == item.end()) return false;
    if (!uri->is_string()) throw InputError(prefix + who + ": uri must be a string");
    const std::string u = uri->get<std::string>();
    if (u.rfind("data:", 0) == 0) return true;
    std::string resolved;
    const std::string problem = resolveUri(folder, u, who, resolved);
    if (!problem.empty()) throw InputError(prefix + problem);
    return true;
}

// Checks the document's required extensions, its buffers and the images it draws before tinygltf
// allocates or opens anything for them, and says which textures and images are drawn. Extensions come
// first: a Draco-compressed mesh's accessors have no bufferView, which tinygltf would report instead.
TextureUse checkResources(const std::string& json, const Folder& folder, bool binary, std::uint64_t fileSize,
                          const std::string& prefix) {
    const nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) throw InputError(prefix + "the JSON document is not an object");
    auto items = [&](const char* key) -> const nlohmann::json* {
        const auto it = doc.find(key);
        return it != doc.end() && it->is_array() ? &*it : nullptr;
    };
    if (const nlohmann::json* required = items("extensionsRequired")) {
        static const std::vector<std::string> kSupported = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
        for (const nlohmann::json& ext : *required) {
            if (!ext.is_string()) throw InputError(prefix + "extensionsRequired holds a " + ext.type_name() + ", not a name");
            const std::string name = ext.get<std::string>();
            if (std::find(kSupported.begin(), kSupported.end(), name) == kSupported.end()) {
                std::string reads;
                for (std::size_t k = 0; k < kSupported.size(); ++k)
                    reads += (k == 0 ? "" : k + 1 == kSupported.size() ? " and " : ", ") + kSupported[k];
                throw InputError(prefix + "requires unsupported extension " + quoteValue(name) + " (Airlight reads " +
                                 reads + ")");
            }
        }
    }
    if (const nlohmann::json* buffers = items("buffers")) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const nlohmann::json& b = (*buffers)[i];
            const std::string who = "buffer " + std::to_string(i);
            if (!b.is_object()) throw InputError(prefix + who + " is not an object");
            const auto len = b.find("byteLength");
            if (len == b.end() || !len->is_number_unsigned()) {
                throw InputError(prefix + who + ": byteLength must be a non-negative integer");
            }
            const std::uint64_t bytes = len->get<std::uint64_t>();
            if (bytes > Limits::kMaxFileBytes) {
                throw InputError(prefix + who + ": byteLength " + std::to_string(bytes) + " is over the " +
                                 gib(Limits::kMaxFileBytes) + " limit");
            }
            if (!checkItemUri(b, who, folder, prefix) && binary && i == 0 && bytes > fileSize) {
                throw InputError(prefix + who + ": byteLength " + std::to_string(bytes) + " is more than the whole file (" +
                                 std::to_string(fileSize) + " bytes)");
            }
        }
    }
    TextureUse use = textureUse(doc);
    if (const nlohmann::json* images = items("images")) {
        for (std::size_t i = 0; i < images->size(); ++i) {
            const nlohmann::json& im = (*images)[i];
            const std::string who = "image " + std::to_string(i);
            if (!im.is_object()) throw InputError(prefix + who + " is not an object");
            // An image nothing draws may be missing; tinygltf's reads still go through the guarded
            // callbacks below, so it cannot reach outside the folder or block on a FIFO either.
            if (use.images[i]) checkItemUri(im, who, folder, prefix);
        }
    }
    return use;
}

std::uint32_t le32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

// The JSON chunk of a GLB, after checking the header and the chunk's bounds.
std::string glbJson(const std::vector<unsigned char>& bytes, const std::string& prefix) {
    if (bytes.size() < 20) throw InputError(prefix + "not a binary glTF: " + std::to_string(bytes.size()) + " bytes, shorter than a GLB header");
    if (std::memcmp(bytes.data(), "glTF", 4) != 0) {
        throw InputError(prefix + "not a binary glTF: the file does not start with 'glTF' (a .glb must; a JSON glTF is .gltf)");
    }
    const std::uint32_t version = le32(&bytes[4]);
    if (version != 2) throw InputError(prefix + "GLB version " + std::to_string(version) + " is not supported (only 2)");
    const std::uint32_t total = le32(&bytes[8]);
    if (total > bytes.size()) {
        throw InputError(prefix + "GLB header states " + std::to_string(total) + " bytes, the file has " +
                         std::to_string(bytes.size()) + " (truncated?)");
    }
    const std::uint32_t jsonLength = le32(&bytes[12]);
    if (le32(&bytes[16]) != 0x4E4F534Au) throw InputError(prefix + "GLB's first chunk is not JSON");
    if (jsonLength == 0 || std::uint64_t(jsonLength) + 20 > total) {
        throw InputError(prefix + "GLB's JSON chunk length " + std::to_string(jsonLength) + " does not fit in the file");
    }
    return std::string(reinterpret_cast<const char*>(&bytes[20]), jsonLength);
}

// tinygltf's messages, one line each, shortened; data URIs and long values never echoed whole.
std::string messageLine(const std::string& s) {
    const std::string line = firstLine(s);
    return line.size() > 200 ? line.substr(0, 120) + "..." : line;
}

}  // namespace

std::string quoteValue(const std::string& value) {
    std::string v;
    v.reserve(std::min<std::size_t>(value.size(), 130));
    const std::size_t keep = 58;
    auto append = [&](std::size_t from, std::size_t to) {
        for (std::size_t i = from; i < to; ++i) {
            const unsigned char c = static_cast<unsigned char>(value[i]);
            v += c < 0x20 || c == 0x7f ? '?' : char(c);
        }
    };
    if (value.size() <= 120) {
        append(0, value.size());
    } else {
        // Cut at character boundaries (not inside a UTF-8 sequence).
        std::size_t head = keep, tail = value.size() - keep;
        while (head > 0 && (static_cast<unsigned char>(value[head]) & 0xC0) == 0x80) --head;
        while (tail < value.size() && (static_cast<unsigned char>(value[tail]) & 0xC0) == 0x80) ++tail;
        append(0, head);
        v += "...";
        append(tail, value.size());
    }
    return "'" + v + "'";
}

std::vector<unsigned char> readFile(const std::string& path, const std::string& fileName) {
    const std::string prefix = "glTF " + quoteValue(fileName) + ": ";
    const std::string problem = fileProblem(path);
    if (problem == "does not exist") throw InputError("glTF " + quoteValue(path) + ": no such file");
    if (!problem.empty()) throw InputError(prefix + "the path " + problem);
    std::vector<unsigned char> bytes;
    if (!readWhole(path, bytes)) throw InputError(prefix + "could not be read");
    return bytes;
}

TextureUse parseModel(const std::vector<unsigned char>& bytes, const std::string& fileName, const std::string& baseDir,
                      bool binary, tinygltf::Model& model) {
    const std::string prefix = "glTF " + quoteValue(fileName) + ": ";
    if (bytes.size() > Limits::kMaxFileBytes) throw InputError(prefix + "over the " + gib(Limits::kMaxFileBytes) + " limit");
    const std::string json = binary ? glbJson(bytes, prefix) : std::string(bytes.begin(), bytes.end());

    // Depth first: tinygltf's parse and its walk of extras recurse once per level.
    const std::string jsonError = jsonProblem(json, Limits::kMaxJsonDepth);
    if (!jsonError.empty()) throw InputError(prefix + jsonError);

    Folder folder;
    if (!baseDir.empty()) folder.base = fs::absolute(fs::path(baseDir)).lexically_normal();
    TextureUse use = checkResources(json, folder, binary, bytes.size(), prefix);

    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = guardedFileExists;
    callbacks.ExpandFilePath = unexpandedPath;
    callbacks.ReadWholeFile = guardedReadWholeFile;
    callbacks.WriteWholeFile = refuseWrite;
    callbacks.user_data = &folder;
    loader.SetFsCallbacks(callbacks);
    ImageContext images{&model, &use.images};
    loader.SetImageLoader(boundedImageLoader, &images);

    // tinygltf wants a folder it can join paths to; a name that cannot exist keeps it from the
    // current folder when external files are refused.
    const std::string base = folder.base.empty() ? std::string("/nonexistent-airlight-base") : folder.base.string();
    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                    : loader.LoadASCIIFromString(&model, &err, &warn, json.data(), unsigned(json.size()), base);
    } catch (const std::bad_alloc&) {
        throw InputError(prefix + "too large to load (out of memory while parsing)");
    } catch (const std::length_error&) {
        throw InputError(prefix + "too large to load (a count or size beyond what memory can hold)");
    } catch (const std::exception& e) {
        throw InputError(prefix + "could not be parsed (" + messageLine(e.what()) + ")");
    }
    if (!ok) {
        std::string why = messageLine(err.empty() ? warn : err);
        if (why.empty()) why = "tinygltf refused the document";
        if (why.find("size mismatch") != std::string::npos || why.find("Failed to load external") != std::string::npos ||
            why.find("File not found") != std::string::npos || why.find("decode") != std::string::npos ||
            why.find("buffer") != std::string::npos) {
            why = "missing or short buffer/image (" + why + ")";
        }
        throw InputError(prefix + why);
    }
    return use;
}

}  // namespace viz::scene::gltf
