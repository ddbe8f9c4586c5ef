// User functions inlined: nested calls without recursion, out and inout
// parameters, an early return.
#version 120
varying vec3 n;
varying vec3 v;

float sq(float a) { return a * a; }

float lensq(vec3 a) { return sq(a.x) + sq(a.y) + sq(a.z); }

void split(in vec3 a, out float len, inout vec3 dir)
{
    len = sqrt(lensq(a));
    if (len == 0.0) {
        dir = vec3(0.0, 0.0, 1.0);
        return;
    }
    dir = a / len;
}

void main()
{
    float len;
    vec3 dir = v;
    split(n, len, dir);
    gl_FragColor = vec4(dir * 0.5 + 0.5, sq(len));
}
