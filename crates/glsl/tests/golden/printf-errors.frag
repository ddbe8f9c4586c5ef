#version 120
#extension GL_SHADERBOX_debug_printf : enable
// Format mistakes: wrong type, wrong count, unknown conversion, no literal.
uniform vec3 v;
uniform int n;
void main()
{
    debugPrintfEXT("%d\n", v.x);
    debugPrintfEXT("%f %f\n", v.x);
    debugPrintfEXT("%s\n", n);
    debugPrintfEXT(n);
    gl_FragColor = vec4(v, 1.0);
}
