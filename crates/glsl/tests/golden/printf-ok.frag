#version 120
#extension GL_SHADERBOX_debug_printf : enable
// debugPrintfEXT with ints, floats and vectors compiles.
uniform vec3 v;
void main()
{
    for (int i = 0; i < 2; i++)
        debugPrintfEXT("i=%d v=%v3f len=%.3f\n", i, v, length(v));
    gl_FragColor = vec4(v, 1.0);
}
