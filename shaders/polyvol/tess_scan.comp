#version 450 core
// polyvol/tess_scan.comp: between tess_refine.comp's two passes over one level, one work group turns the
// refine groups' totals (children, triangles) into their offsets: an exclusive prefix sum in group order,
// the triangles' starting from those the light's earlier levels and faces emitted. It then sets the
// counters as the refine step's appends did: outCount the level's children, triangles the running total.
// Each invocation sums a run of consecutive groups, the runs' totals are scanned in shared memory
// (Hillis-Steele), and each invocation writes its run's offsets: at most 4 M quads per list make 64 K
// groups, 256 per invocation.
layout(local_size_x = 256) in;

uniform int uFromGrid;     // 1: the step read every quad of the coarse grid, uGridQuads of them
uniform uint uGridQuads;

layout(std430, binding = 4) buffer Counters {
    uint inCount;
    uint outCount;
    uint triangles;
    uint overflow;
    uint dispatchArgs[3];
    uint drawArgs[4];
};
layout(std430, binding = 8) buffer Groups { uvec2 groups[]; };

shared uvec2 sRuns[256];

void main() {
    uint local = gl_LocalInvocationIndex;
    uint emitted = triangles;  // read by all before invocation 255 writes it (the barriers below)
    uint items = uFromGrid != 0 ? uGridQuads : inCount;
    uint groupCount = (items + 63u) / 64u;
    uint per = (groupCount + 255u) / 256u;
    uint begin = min(local * per, groupCount), end = min(begin + per, groupCount);
    uvec2 run = uvec2(0u);
    for (uint g = begin; g < end; ++g) run += groups[g];
    sRuns[local] = run;
    barrier();
    for (uint step = 1u; step < 256u; step <<= 1u) {
        uvec2 before = local >= step ? sRuns[local - step] : uvec2(0u);
        barrier();
        sRuns[local] += before;
        barrier();
    }
    uvec2 at = sRuns[local] - run + uvec2(0u, emitted);
    for (uint g = begin; g < end; ++g) {
        uvec2 total = groups[g];
        groups[g] = at;
        at += total;
    }
    if (local == 255u) {
        outCount = sRuns[255].x;
        triangles = emitted + sRuns[255].y;
    }
}
