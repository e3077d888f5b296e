// Shader source loading: #define injection after #version, recursive #include "x.glsl" resolved
// against the shader directory (each file once), and #line markers carrying a file index so that
// compile errors can be mapped back to "shaders/common/x.glsl:42". The main file keeps its own line
// numbers.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace viz::gl {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

// Line numbers in #line markers are fileIndex * kShaderLineStride + line (see shader_source.cpp),
// so a file may have at most kShaderLineStride - 1 lines.
inline constexpr int kShaderLineStride = 100000;

struct ShaderSource {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // display names; index = source-string number used in #line
};

// The shaders/ folder: $AIRLIGHT_SHADER_DIR when set, else the compiled-in VIZ_SHADER_DIR.
std::string shaderDirectory();

// path: relative to shaderDirectory() ("raymarch/march.frag"), or absolute. Each define becomes
// "#define NAME VALUE" right after the #version line. Includes are relative to shaderDirectory().
// Throws ShaderError when a file (the main one or an include) cannot be read.
ShaderSource loadShaderSource(const std::string& path, const ShaderDefines& defines = {});

// Maps a driver log ("0:12(5): error: ...", Mesa; "0(12) : error ...", NVIDIA) to
// "shaders/file.glsl:LINE: error: ..." using files; lines it does not recognise are kept as they
// are. firstFile/firstLine receive the location of the first mapped line (empty / 0 if none).
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files,
                         std::string* firstFile = nullptr, int* firstLine = nullptr);

}  // namespace viz::gl
