#include "gl/shader_source.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "gl/gl_error.h"

#ifndef VIZ_SHADER_DIR
#error "VIZ_SHADER_DIR must be defined by the build (the absolute shaders/ folder)"
#endif

namespace viz::gl {

namespace fs = std::filesystem;

namespace {

// One expansion in progress: the text being built, the file table and the files already included.
struct Expander {
    fs::path root;         // the shader directory
    std::string rootName;  // "shaders": prefix of display names
    std::string text;
    std::vector<std::string> files;
    std::set<fs::path> seen;  // canonical paths: each file is expanded once (include guard)
};

std::string displayName(const Expander& e, const fs::path& file) {
    const fs::path rel = file.lexically_relative(e.root);
    if (!rel.empty() && *rel.begin() != "..")
        return e.rootName + "/" + rel.generic_string();
    return file.generic_string();
}

bool readLines(const fs::path& file, std::vector<std::string>& lines) {
    std::ifstream in(file);
    if (!in)
        return false;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        lines.push_back(std::move(line));
    }
    return true;
}

bool isVersionLine(const std::string& line) {
    static const std::regex kVersion(R"(^\s*#\s*version\b.*)");
    return std::regex_match(line, kVersion);
}

// "#line L S" sets the next line's number and source-string number. Mesa 22.3 keeps S only for
// syntax errors (semantic errors print source 0), so the file index is also encoded in the line
// number itself: L = fileIndex * kLineStride + line. mapShaderLog decodes either form.
void appendLineMarker(Expander& e, int line, int fileIndex) {
    e.text += "#line " + std::to_string(fileIndex * kShaderLineStride + line) + " " +
              std::to_string(fileIndex) + "\n";
}

// Emits the #define lines under their own entry of the file table, so an error in a value is
// reported as "<defines of shaders/x.comp>:K" (K = the K-th define) rather than as a line of the
// shader file.
void appendDefines(Expander& e, const ShaderDefines& defines) {
    if (defines.empty())
        return;
    const int index = static_cast<int>(e.files.size());
    e.files.push_back("<defines of " + e.files.front() + ">");
    appendLineMarker(e, 1, index);
    for (const auto& [name, value] : defines)
        e.text += "#define " + name + " " + value + "\n";
}

// Appends `file` (already registered as files[fileIndex]) with its includes expanded. `defines` is
// non-null only for the main file: they go right after its #version line.
void expand(Expander& e, const fs::path& file, int fileIndex, const ShaderDefines* defines) {
    static const std::regex kInclude(R"(^\s*#\s*include\s*[\"<]([^\">]+)[\">].*)");
    std::vector<std::string> lines;
    if (!readLines(file, lines)) {
        throw ShaderError(
            e.files[static_cast<size_t>(fileIndex)] + ":1: error: cannot read the file",
            e.files[static_cast<size_t>(fileIndex)], 1);
    }
    bool definesDone = defines == nullptr;
    // A file without #version (an include, or a malformed main file) gets its defines first.
    if (!definesDone && std::none_of(lines.begin(), lines.end(), isVersionLine)) {
        appendDefines(e, *defines);
        definesDone = true;
        appendLineMarker(e, 1, fileIndex);
    } else if (fileIndex != 0) {
        // The main file starts at line 1 of source string 0 by itself; #version must stay its first
        // line.
        appendLineMarker(e, 1, fileIndex);
    }
    for (size_t i = 0; i < lines.size(); ++i) {
        const int lineNo = static_cast<int>(i) + 1;
        const std::string& line = lines[i];
        std::smatch m;
        if (std::regex_match(line, m, kInclude)) {
            const std::string name = m[1].str();
            // Includes are relative to the shader directory; a sibling of the including file also
            // works.
            fs::path target = e.root / name;
            if (!fs::exists(target))
                target = file.parent_path() / name;
            if (!fs::exists(target)) {
                const std::string& here = e.files[static_cast<size_t>(fileIndex)];
                throw ShaderError(here + ":" + std::to_string(lineNo) +
                                      ": error: cannot find include \"" + name + "\"",
                                  here, lineNo);
            }
            const fs::path canonical = fs::weakly_canonical(target);
            if (e.seen.insert(canonical).second) {
                const int childIndex = static_cast<int>(e.files.size());
                e.files.push_back(displayName(e, canonical));
                expand(e, canonical, childIndex, nullptr);
                appendLineMarker(e, lineNo + 1, fileIndex);
            } else {
                // Already expanded earlier: keep the line count with an empty line.
                e.text += "\n";
            }
            continue;
        }
        e.text += line;
        e.text += "\n";
        if (!definesDone && isVersionLine(line)) {
            appendDefines(e, *defines);
            if (!defines->empty())
                appendLineMarker(e, lineNo + 1, fileIndex);
            definesDone = true;
        }
    }
}

}  // namespace

std::string shaderDirectory() {
    if (const char* env = std::getenv("AIRLIGHT_SHADER_DIR"); env != nullptr && env[0] != '\0') {
        return env;
    }
    return VIZ_SHADER_DIR;
}

ShaderSource loadShaderSource(const std::string& path, const ShaderDefines& defines) {
    Expander e;
    e.root = fs::weakly_canonical(fs::path(shaderDirectory()));
    e.rootName = e.root.filename().string();
    if (e.rootName.empty())
        e.rootName = "shaders";
    const fs::path given(path);
    const fs::path file = fs::weakly_canonical(given.is_absolute() ? given : e.root / given);
    e.files.push_back(displayName(e, file));
    // A define name must be a GLSL identifier; the preprocessor's own message would point nowhere
    // useful.
    static const std::regex kIdentifier(R"([A-Za-z_][A-Za-z0-9_]*)");
    for (const auto& define : defines) {
        if (!std::regex_match(define.first, kIdentifier)) {
            throw ShaderError(e.files.front() + ":0: error: define name '" + define.first +
                                  "' is not a GLSL identifier",
                              e.files.front(), 0);
        }
    }
    e.seen.insert(file);
    expand(e, file, 0, &defines);
    return ShaderSource{std::move(e.text), std::move(e.files)};
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files,
                         std::string* firstFile, int* firstLine) {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error C1008: ...". Group 1 = source string, 2 =
    // line.
    static const std::regex kMesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex kNvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::string line;
    std::string errors, others;
    std::string fileOfError;
    int lineOfError = 0;
    std::string fileOfAny;
    int lineOfAny = 0;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        std::smatch m;
        std::string mapped = line;
        bool isError = line.find("error") != std::string::npos;
        if (std::regex_match(line, m, kMesa) || std::regex_match(line, m, kNvidia)) {
            const long reported = std::stol(m[2].str());
            const size_t index = reported >= kShaderLineStride
                                     ? static_cast<size_t>(reported / kShaderLineStride)
                                     : std::stoul(m[1].str());
            const int lineNo = static_cast<int>(reported % kShaderLineStride);
            const std::string name = index < files.size() ? files[index] : "source " + m[1].str();
            mapped = name + ":" + std::to_string(lineNo) + ": " + m[3].str();
            if (isError && fileOfError.empty()) {
                fileOfError = name;
                lineOfError = lineNo;
            }
            if (fileOfAny.empty()) {
                fileOfAny = name;
                lineOfAny = lineNo;
            }
        }
        (isError ? errors : others) += mapped + "\n";
    }
    if (fileOfError.empty()) {
        fileOfError = fileOfAny;
        lineOfError = lineOfAny;
    }
    if (firstFile)
        *firstFile = fileOfError;
    if (firstLine)
        *firstLine = lineOfError;
    std::string out = errors + others;
    while (!out.empty() && out.back() == '\n')
        out.pop_back();
    return out;
}

}  // namespace viz::gl
