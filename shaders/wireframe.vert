// wireframe.vert: single-pass wireframe over shaded triangles (vertex
// stage, for wireframe.frag).
//
// What it does: every vertex of a triangle carries the whole triangle:
// its three object-space corners in gl_MultiTexCoord0.xyz,
// gl_MultiTexCoord1.xyz and gl_MultiTexCoord2.xyz (the same three values
// on the triangle's three vertices; draw with glDrawArrays, no shared
// vertices). The shader projects the three corners and this vertex to
// window coordinates (with the `viewport` uniform) and writes the
// window-space distances from this vertex to the three edge lines into
// `edge_distance` (two of them are 0: the edges through this vertex).
// Window-space distances must be interpolated linearly in window space,
// which a GLSL 1.10 varying is not (it is perspective-correct): the
// distances are pre-multiplied by clip w here and post-multiplied by
// gl_FragCoord.w (= 1/w, linear in window space) in wireframe.frag.
// Also hands on the eye-space normal (`normal`) and gl_Color for the fill.
//
// State it reads: uniform vec4 viewport (x, y, width, height, as given to
// glViewport); gl_Vertex, gl_Normal, gl_Color, gl_MultiTexCoord0..2,
// gl_ModelViewProjectionMatrix, gl_NormalMatrix.
// Limitation: every corner must be in front of the eye (clip w > 0); a
// triangle crossing the eye plane gets wrong distances.
//
// After the "Shaders" slides (seed 004, "Wireframe Shading", after
// Baerentzen et al., "Single-Pass Wireframe Rendering", SIGGRAPH 2006),
// which give only excerpts. Changes: the slides compute one distance
// (to the opposite edge) per vertex, keyed by which vertex it is; here
// all three distances come from the three corners, so no vertex index is
// needed. The slides post-multiply by a second varying 1/w, which would
// itself be interpolated perspective-correctly; gl_FragCoord.w is the
// screen-linear 1/w the technique needs.

uniform vec4 viewport;

varying vec3 edge_distance;
varying vec3 normal;

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
    vec4 clip = gl_ModelViewProjectionMatrix * gl_Vertex;
    vec2 p = toWindow(clip);
    vec2 p0 = toWindow(gl_ModelViewProjectionMatrix * vec4(gl_MultiTexCoord0.xyz, 1.0));
    vec2 p1 = toWindow(gl_ModelViewProjectionMatrix * vec4(gl_MultiTexCoord1.xyz, 1.0));
    vec2 p2 = toWindow(gl_ModelViewProjectionMatrix * vec4(gl_MultiTexCoord2.xyz, 1.0));

    edge_distance = vec3(lineDistance(p, p1, p2),
                         lineDistance(p, p2, p0),
                         lineDistance(p, p0, p1)) * clip.w;
    normal = normalize(gl_NormalMatrix * gl_Normal);
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
    gl_Position = clip;
}
