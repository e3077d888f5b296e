#version 450 core
// render/mesh_view.frag: flat colour for the mesh view (render::MeshView). With uShade, surfaces are
// shaded by the angle of their normal to a fixed head-on direction so their shapes read.
in vec3 vNormal;
uniform vec4 uColour;
uniform int uShade;
layout(location = 0) out vec4 oColour;

void main() {
    float shade = uShade != 0 ? 0.55 + 0.45 * abs(normalize(vNormal).y) : 1.0;
    oColour = vec4(uColour.rgb * shade, uColour.a);
}
