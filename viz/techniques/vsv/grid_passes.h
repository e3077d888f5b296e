// The voxel grid's two GL passes that vsv and ivsv share: packing the voxelized 32-bit words into the
// grid texture (shaders/vsv/pack.comp) and the scan along alpha that extrudes each occluder into its
// shadow volume (shaders/vsv/scan.comp: log2 passes, each doubling the reach, between two textures).
#pragma once

#include <glm/glm.hpp>

#include "gl/program.h"
#include "gl/texture.h"

namespace viz::vsv {

// The block of `size` cells at `origin` from `words` into `grid`.
void packGrid(const gl::Program& pack, const gl::Texture& words, const gl::Texture& grid, glm::ivec2 origin,
              glm::ivec3 size);

// `passes` passes over the block of `size` cells at `origin`, from `a` and back and forth with `b`;
// `segment` cells per scan (0: the whole alpha axis). Returns the texture the last pass wrote (`a` after
// an even number of passes, none included).
const gl::Texture* scanGrid(const gl::Program& scan, const gl::Texture* a, const gl::Texture* b, glm::ivec2 origin,
                            glm::ivec3 size, int segment, int passes);

}  // namespace viz::vsv
