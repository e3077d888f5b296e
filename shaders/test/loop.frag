#version 450 core
// Benchmark load: a loop of uSteps iterations per fragment (a stand-in for a 256-step ray march).
uniform int uSteps;
layout(location = 0) out vec4 outColour;
void main() {
    vec2 p = gl_FragCoord.xy * 0.001;
    float acc = 0.0;
    for (int i = 0; i < uSteps; ++i) {
        p = vec2(p.x * 0.99 + sin(p.y + float(i) * 0.01), p.y * 0.99 + cos(p.x));
        acc += exp(-0.01 * float(i)) * fract(p.x * p.y);
    }
    outColour = vec4(acc, p, 1.0);
}
