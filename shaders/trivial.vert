// trivial.vert: the smallest useful vertex shader (vertex stage).
//
// What it does: transforms the vertex exactly as the fixed-function
// pipeline would (ftransform) and hands the vertex colour on unchanged to
// both faces, so trivial.frag draws unlit colour.
//
// State it reads: gl_Vertex, gl_Color, gl_ModelViewProjectionMatrix.
// It writes gl_Position, gl_FrontColor, gl_BackColor.
//
// After the seed talk ("GLSL v1.20", Example 01, trivial shader), which
// has no slips.

void main(void)
{
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
}
