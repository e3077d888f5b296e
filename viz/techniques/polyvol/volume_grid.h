// What shaders/polyvol/volume_grid.glsl needs to place a light volume's vertices: one light's shadow map
// and how its texels become points (eye-relative world). Shared by the volume draw and the adaptive
// tessellation.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/program.h"

namespace viz::polyvol {

// Vertex modes of volume_grid.glsl.
inline constexpr int kModeSpot = 0, kModeDirectional = 1, kModeCube = 2;

struct VolumeGrid {
    int lightIndex = 0;
    int mode = kModeSpot;
    int mapSize = 0;     // N
    int layer = 0;       // 2D map layer or cube index
    int faces = 1;       // 1 or 6
    bool vplCube = false;  // the cube of an area light's virtual point light
    int keyStride = 0;   // N (static) or N + 1 (adaptive)
    glm::vec3 planeOrigin{0.0f}, planeX{0.0f}, planeY{0.0f};
    float noHit = 0.0f, capDepth = 0.0f, skirt = 1.0f, cookieMask = 0.0f;
    float range = 1.0f;  // far - near of the stored values
};

inline void setGridUniforms(const gl::Program& p, const VolumeGrid& g) {
    p.set("uMode", g.mode);
    p.set("uMapSize", g.mapSize);
    p.set("uLayer", g.layer);
    p.set("uLightIndex", g.lightIndex);
    p.set("uVplCube", g.vplCube ? 1 : 0);
    p.set("uKeyStride", g.keyStride);
    p.set("uPlaneOrigin", g.planeOrigin);
    p.set("uPlaneX", g.planeX);
    p.set("uPlaneY", g.planeY);
    p.set("uNoHit", g.noHit);
    p.set("uCapDepth", g.capDepth);
    p.set("uSkirt", g.skirt);
    p.set("uCookieMask", g.cookieMask);
}

}  // namespace viz::polyvol
