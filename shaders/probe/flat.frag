#version 450 core
// probe/flat.frag: one colour, for the probe's blending and triangle passes (the fixed-function cost).
uniform vec4 uColour;
layout(location = 0) out vec4 oColour;

void main() {
    oColour = uColour;
}
