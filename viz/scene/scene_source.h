// Where the app and the CLI get a scene from: a built-in name or a .gltf/.glb path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace viz::scene {

// A built-in scene name (builtin_scenes.h), a stiff case "stiff/ID" (stiff_scenes.h) or a path ending in
// .gltf or .glb; anything else throws
// viz::InputError. The result has passed validateScene.
// A built-in scene, a stiff case "stiff/ID" or a .gltf/.glb file (options apply to files), validated.
Scene loadScene(const std::string& nameOrPath, const LoadOptions& options = {});

// Stable 64-bit FNV-1a hash, as 16 hex digits, of everything that affects rendering: geometry,
// materials, texture bytes (through geometryKeyOf), lights, camera and medium (not names or notes). Same
// value on every run, stamped or not.
std::string sceneContentHash(const Scene& scene);

// The same hash over meshes, materials and textures only: what a GPU upload of the scene depends on.
std::uint64_t geometryContentHash(const Scene& scene);

// Sets scene.geometryKey to geometryContentHash (never 0): the caller's word that it will not change the
// scene's meshes, materials or textures without stamping it again. Who runs many frames of one scene
// stamps it once after loading: the window, bench, report, a render along a motion path.
void stampGeometry(Scene& scene);

// scene.geometryKey when stamped, else geometryContentHash(scene).
std::uint64_t geometryKeyOf(const Scene& scene);

// 64-bit FNV-1a of size bytes, continuing from 'hash' (the FNV offset basis to start).
constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ULL;
std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash = kFnvOffsetBasis);

}  // namespace viz::scene
