#version 450 core
// vsv/bilateral.comp: depth-aware reconstruction of ivsv's reduced gathers, at full resolution.
//   uMode 0 (3x3 interleaved): mean of the 3x3 neighbourhood (each pixel gathered one ninth of the VPLs,
//            scaled by 9), each neighbour weighted by exp(-(relative distance difference / uSigma)^2).
//   uMode 1 (quarter): low-res sample (X, Y) was gathered at pixel (2X, 2Y); a pixel blends its four
//            nearest samples with bilinear weights times the same distance weight.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 8) uniform sampler2D uDistance;
layout(rgba32f, binding = 0) uniform readonly image2D uSource;
layout(rgba32f, binding = 1) uniform writeonly image2D uTarget;
uniform ivec2 uSize;      // full image
uniform ivec2 uSourceSize;
uniform int uMode;
uniform float uSigma;

float depthWeight(float d, float dn) { float r = (dn - d) / (uSigma * max(d, 1e-6)); return exp(-r * r); }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    float d = texelFetch(uDistance, p, 0).r;
    vec3 sum = vec3(0.0);
    float wsum = 0.0;
    if (uMode == 0) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), uSize - 1);
                float wq = depthWeight(d, texelFetch(uDistance, q, 0).r);
                sum += wq * imageLoad(uSource, q).rgb;
                wsum += wq;
            }
    } else {
        ivec2 base = p / 2;
        vec2 f = vec2(p - 2 * base) * 0.5;
        for (int c = 0; c < 4; ++c) {
            ivec2 o = ivec2(c & 1, c >> 1);
            ivec2 s = min(base + o, uSourceSize - 1);
            float wb = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
            if (wb <= 0.0) continue;
            float wq = wb * depthWeight(d, texelFetch(uDistance, min(2 * s, uSize - 1), 0).r);
            sum += wq * imageLoad(uSource, s).rgb;
            wsum += wq;
        }
        if (wsum <= 1e-8) {  // every neighbour across an edge: nearest sample
            sum = imageLoad(uSource, min(base, uSourceSize - 1)).rgb;
            wsum = 1.0;
        }
    }
    imageStore(uTarget, p, vec4(sum / max(wsum, 1e-8), 1.0));
}
