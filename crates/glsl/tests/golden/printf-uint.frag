#version 130
#extension GL_SHADERBOX_debug_printf : enable
// uints print with %u (and %x, %o); %d and %i take ints, and a uint given
// to them is an error that names %u.
uniform uint u;
uniform uvec2 w;
void main()
{
    debugPrintfEXT("%u %x %o %v2u\n", u, u, u, w);
    debugPrintfEXT("%d\n", u);
    debugPrintfEXT("%v2i\n", w);
    debugPrintfEXT("%u\n", 1.5);
    gl_FragColor = vec4(1.0);
}
