// An included file with a deliberate type error; the test finds the marked line by its text.
float brokenHelper(float x) {
    float y = x * 2.0;
    vec3 wrong = y;  // DELIBERATE ERROR: float assigned to vec3
    return y;
}
