#version 450 core
// Scene geometry (render::GpuScene) to clip space. uModel takes world positions to eye-relative space
// (render::eyeRelativeModel, a pure translation); uViewProj maps eye-relative space to clip space.
// Outputs are eye-relative; normals are world = eye-relative directions (axes are unchanged).

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in uint aMaterial;

uniform mat4 uModel;
uniform mat4 uViewProj;

// The same depth in every program that draws the scene: the surface pass tests its shading pass against
// its depth prepass for equality.
invariant gl_Position;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
flat out uint vMaterial;

void main() {
    vec4 p = uModel * vec4(aPosition, 1.0);
    vPosition = p.xyz;
    vNormal = aNormal;
    vUv = aUv;
    vMaterial = aMaterial;
    gl_Position = uViewProj * p;
}
