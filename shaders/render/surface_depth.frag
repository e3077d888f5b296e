#version 450 core
// The surface pass's depth prepass (render::SurfacePass): the depth of the nearest surface within uZfar
// at each pixel, so that the shading pass (render/surface.frag) shades one fragment a pixel instead of
// every fragment that covers it. Surfaces beyond uZfar count as misses, as in the shading pass.
uniform float uZfar;

in vec3 vPosition;  // eye-relative: the eye is at the origin

void main() {
    if (length(vPosition) > uZfar) discard;
}
