// trivial.frag: writes the interpolated colour (fragment stage).
//
// What it does: gl_FragColor = gl_Color (the front or back colour the
// vertex stage wrote, chosen by facing when GL_VERTEX_PROGRAM_TWO_SIDE is
// on, else the front colour).
//
// State it reads: gl_Color. Pair: trivial.vert (or any vertex shader that
// writes gl_FrontColor).
//
// After the seed talk ("GLSL v1.20", Example 01), which has no slips.

void main(void)
{
    gl_FragColor = gl_Color;
}
