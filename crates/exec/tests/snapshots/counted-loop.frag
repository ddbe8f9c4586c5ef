// A counted loop that lowering unrolls (constant start, bound and step,
// no break): the counter indexes the uniform array statically.
#version 120
uniform float weights[4];
varying vec2 uv;

void main()
{
    float sum = 0.0;
    for (int i = 0; i < 4; i++) {
        sum += weights[i] * (uv.x + float(i));
    }
    gl_FragColor = vec4(sum, uv.y, 0.0, 1.0);
}
