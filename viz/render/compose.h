// Full-screen helpers: a vertex-buffer-free triangle for passes, and the final composite
// final = surfaceRadiance * exp(-sigma_t * distance) + airlight.
#pragma once

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/medium_block.h"
#include "scene/scene.h"

namespace viz::render {

// Draws one triangle covering the viewport (vertices from gl_VertexID in shaders/render/fullscreen.vert,
// which also outputs vUv in [0,1]^2 with GL's row 0 at the bottom). The caller binds program and target.
class FullscreenTriangle {
public:
    FullscreenTriangle();
    void draw() const;

private:
    gl::VertexArray mVao;
};

// Writes `out` (RGBA32F, same size as the inputs) = surfaceRadiance * exp(-sigma_t * distance) + airlight,
// sigma_t the medium's extinction.
// distance is R32F; surfaceRadiance and airlight are RGBA32F (airlight may be any RGB(A) float texture).
class Composer {
public:
    Composer();
    void run(const gl::Texture& surfaceRadiance, const gl::Texture& distance, const gl::Texture& airlight,
             const scene::Medium& medium, const gl::Texture& out);

private:
    gl::Program mProgram;
    MediumBlock mMedium;
    FullscreenTriangle mTriangle;
    gl::Framebuffer mFramebuffer;
};

// One-shot convenience (compiles the tiny program on each call; keep a Composer to reuse it).
void composeFinal(const gl::Texture& surfaceRadiance, const gl::Texture& distance, const gl::Texture& airlight,
                  const scene::Medium& medium, const gl::Texture& out);

}  // namespace viz::render
