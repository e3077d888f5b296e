// The glTF loader's first half: bytes to a tinygltf::Model, with everything checked that tinygltf would
// otherwise trust (internal to viz_scene: only gltf_loader.cpp includes it).
//  - the file: a regular file of at most LoadLimits::kMaxFileBytes;
//  - GLB framing: magic, version, chunk lengths, each stated in the error;
//  - JSON: well formed and nested at most LoadLimits::kMaxJsonDepth deep, checked by an iterative
//    parse before tinygltf's recursive one sees it;
//  - buffers and images: declared sizes bounded before allocation; external URIs resolved against the
//    file's folder and refused when they leave it or name anything but a regular file (a folder, a
//    FIFO, a device); images at most 16384 pixels a side, checked from their header before decoding;
//    only the images Airlight draws are decoded or required to exist (gltf_texture_use.h).
#pragma once

#include <string>
#include <vector>

#include "scene/gltf_texture_use.h"

namespace tinygltf {
class Model;
}

namespace viz::scene::gltf {

// A value as it may appear in a message: at most 120 characters, elided in the middle, in quotes.
std::string quoteValue(const std::string& value);

// The whole file, or InputError ("glTF 'NAME': ...") when it is missing, not a regular file or too big.
std::vector<unsigned char> readFile(const std::string& path, const std::string& fileName);

// Parses bytes (binary: GLB) into model and says which textures and images are drawn (the others'
// images are left empty). baseDir: the folder external URIs are resolved in (empty: external URIs are
// refused). Throws InputError naming fileName and the problem.
TextureUse parseModel(const std::vector<unsigned char>& bytes, const std::string& fileName, const std::string& baseDir,
                      bool binary, tinygltf::Model& model);

}  // namespace viz::scene::gltf
