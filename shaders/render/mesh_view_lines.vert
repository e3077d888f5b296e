#version 450 core
// render/mesh_view_lines.vert: line segments already in the main camera's eye-relative space, through
// the mesh view's orbit view-projection.
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProj;
out vec3 vNormal;

void main() {
    vNormal = vec3(0.0, 1.0, 0.0);
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
