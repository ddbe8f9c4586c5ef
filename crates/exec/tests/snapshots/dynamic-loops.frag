// Loops that stay loops: one bounded by a uniform (indexing by a
// dynamic counter gathers), one with too many iterations to unroll and
// one with a break.
#version 120
uniform int count;
uniform float values[8];
varying float x;

void main()
{
    float acc = 0.0;
    for (int i = 0; i < count; i++) {
        acc += values[i];
    }
    float y = x;
    for (int k = 0; k < 100; k++) {
        y = y * 0.5 + 0.25;
    }
    int n = 0;
    while (true) {
        if (float(n) > acc)
            break;
        n += 2;
    }
    gl_FragColor = vec4(acc, y, float(n), 1.0);
}
