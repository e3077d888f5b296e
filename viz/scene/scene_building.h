// Building scenes in code (the built-in scenes and the stiff-case suite): meshes from quads and boxes,
// and a camera aimed at a point.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

// Camera at eye looking at target, up orthogonalised from world +Y (from -Z when looking straight up
// or down).
Camera lookAt(const std::string& name, glm::dvec3 eye, glm::dvec3 target, double yfov, double znear, double zfar);

// Appends triangles to one Mesh (world space, flat normals per face, uvs per quad).
class MeshBuilder {
public:
    MeshBuilder(std::string name, int material);

    // Quad a, b, c, d counter-clockwise seen from the side it faces; uv (0,0) at a, (1,0) at b,
    // (1,1) at c, (0,1) at d.
    void quad(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d);
    // Box with half extents 'half', rotated by 'yaw' radians about +Y around its centre. Faces point
    // outwards, or inwards for a room seen from inside.
    void box(glm::dvec3 centre, glm::dvec3 half, double yaw = 0.0, bool inward = false);
    // One triangle as given (its normal from the winding; a degenerate one gets +Y).
    void triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);

    Mesh take() { return std::move(mMesh); }
    Mesh& mesh() { return mMesh; }

private:
    Mesh mMesh;
};

}  // namespace viz::scene
