// wireframe.geom: single-pass wireframe, geometry stage
// (GL_EXT_geometry_shader4; vertex: wireframe-geom.vert; fragment:
// wireframe.frag).
//
// What it does: the seed slides' technique as the slides draw it, in a
// geometry shader: for each triangle it projects the three corners to
// window coordinates (with the `viewport` uniform) and gives each corner
// its window-space distances to the three edge lines (`edge_distance`:
// the corner's height over the opposite edge, 0 for the two edges through
// it), pre-multiplied by clip w for wireframe.frag, which multiplies by
// gl_FragCoord.w to interpolate them linearly in window space (see
// wireframe.vert). The distances are wireframe.vert's formulas on the
// same window positions, so the two programs draw the same picture; this
// one needs no corner attributes. It passes the triangle through
// unchanged otherwise (positions, colours, `normal`).
//
// Program parameters (glProgramParameteriEXT before linking):
//   GL_GEOMETRY_INPUT_TYPE_EXT = GL_TRIANGLES,
//   GL_GEOMETRY_OUTPUT_TYPE_EXT = GL_TRIANGLE_STRIP,
//   GL_GEOMETRY_VERTICES_OUT_EXT = 3.
//
// State it reads: uniform vec4 viewport (x, y, width, height, as given to
// glViewport); gl_PositionIn[0..2], gl_FrontColorIn[], gl_BackColorIn[],
// vertex_normal[] (wireframe-geom.vert).
// Limitation: every corner must be in front of the eye (clip w > 0), as
// for wireframe.vert.
//
// After the "Shaders" slides (seed 004, "Wireframe Shading", after
// Baerentzen et al., "Single-Pass Wireframe Rendering", SIGGRAPH 2006),
// whose geometry-shader form computes the distances per triangle.

#version 120
#extension GL_EXT_geometry_shader4 : enable

uniform vec4 viewport;

varying in vec3 vertex_normal[];

varying out vec3 edge_distance;
varying out vec3 normal;

vec2 toWindow(in vec4 clip)
{
    vec2 ndc = clip.xy / clip.w;
    return viewport.xy + 0.5 * viewport.zw * (ndc + 1.0);
}

// Distance from p to the line through a and b (0 if a == b).
float lineDistance(in vec2 p, in vec2 a, in vec2 b)
{
    vec2 e = b - a;
    float len = length(e);
    if (len <= 0.0)
        return 0.0;
    vec2 d = p - a;
    return abs(e.x * d.y - e.y * d.x) / len;
}

void main(void)
{
    vec2 p0 = toWindow(gl_PositionIn[0]);
    vec2 p1 = toWindow(gl_PositionIn[1]);
    vec2 p2 = toWindow(gl_PositionIn[2]);
    for (int i = 0; i < 3; i++) {
        vec2 p = toWindow(gl_PositionIn[i]);
        edge_distance = vec3(lineDistance(p, p1, p2),
                             lineDistance(p, p2, p0),
                             lineDistance(p, p0, p1)) * gl_PositionIn[i].w;
        normal = vertex_normal[i];
        gl_FrontColor = gl_FrontColorIn[i];
        gl_BackColor = gl_BackColorIn[i];
        gl_Position = gl_PositionIn[i];
        EmitVertex();
    }
    EndPrimitive();
}
