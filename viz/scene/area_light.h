// Area lights are emissive planar rectangles. This derives the Light (centre, half edges, normal,
// radiance) from the emitter's mesh, so that the glTF loader and the built-in scenes compute it the
// same way, bit for bit.
#pragma once

#include "scene/scene.h"

namespace viz::scene {

// The mesh must have 4 distinct vertex positions and 2 triangles forming a planar rectangle, and an
// emissive material; throws viz::InputError naming the mesh otherwise.
//  - direction: unit normal of the side the triangles' counter-clockwise winding faces (world space);
//  - halfU/halfV: when the mesh has uvs that put the corners at (0,0), (1,0), (0,1), (1,1), the edges
//    along which u and v grow (so emission uvs match the mesh's uvs; then cross(halfU, halfV) may point
//    along -direction); otherwise two edges with cross(halfU, halfV) along direction. A textured
//    emitter requires those uvs.
//  - radiance = emissiveFactor * emissiveStrength; emissionTexture = the material's emissive texture.
Light areaLightFromMesh(const Scene& scene, int meshIndex);

}  // namespace viz::scene
