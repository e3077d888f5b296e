#version 450 core
// polyvol/wire.frag: the light volume mesh as a wireframe (polygon mode GL_LINE): faces where rays leave
// the volume (front-facing, +L) green, faces where they enter (-L) red.
layout(location = 0) out vec4 oColour;

void main() {
    oColour = gl_FrontFacing ? vec4(0.1, 0.8, 0.2, 1.0) : vec4(0.9, 0.15, 0.1, 1.0);
}
