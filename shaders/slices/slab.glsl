// The view-depth length of plane i's slab, for the physical weight dt = slab length / dot(w, forward).
// Every slab is delta s long, except with plane_grid=world the nearest one when the eye lies inside it:
// only its part in front of the eye (a fraction uNearestWeight of delta s) is on the rays.
#ifndef SLICES_SLAB_GLSL
#define SLICES_SLAB_GLSL

uniform float uSpacing;        // delta s, view depth between planes
uniform int uNearestPlane;     // index of the nearest plane (the last drawn back to front)
uniform float uNearestWeight;  // the part of its slab in front of the eye, 1 unless plane_grid=world cut it

float slabLength(int plane) {
    return plane == uNearestPlane ? uSpacing * uNearestWeight : uSpacing;
}

#endif  // SLICES_SLAB_GLSL
