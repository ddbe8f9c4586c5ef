"""The seed lecture's vertex -> geometry -> fragment programs (seeds/001,
"Simple Program"), differential: on a context with GL_EXT_geometry_shader4
(shaderbox's OpenGL 2.1) the program is built as the lecture builds it:
glCreateShader(GL_GEOMETRY_SHADER_EXT), a GLSL 1.20 geometry shader with
`#extension GL_EXT_geometry_shader4`, the program parameters
GL_GEOMETRY_INPUT_TYPE / GL_GEOMETRY_OUTPUT_TYPE (the lecture's names) and
GL_GEOMETRY_VERTICES_OUT_EXT from GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT, set
with the extension's glProgramParameteriEXT (PyOpenGL offers the
lecture's glProgramParameteri, a GL 4.1 name, only on 4.1 contexts). Mesa never had the extension:
there the same geometry shader is written in GLSL 1.50's compatibility
profile (layouts in the shader), in Mesa's compatibility context. The
images must agree.

Scenes: the lecture's pass-through with its "Simple Coloring Faces"
shaders (front faces coloured, back faces black) on a turning cube; each
triangle shrunk towards its centroid (a geometry shader that moves
vertices); every vertex of a point list expanded into a coloured square
(a shader that makes more primitives than it takes); a triangle strip cut
into separate triangles with EndPrimitive and a per-primitive ID.
"""
import math

from harness import GL, errors, main, scene, shader

from OpenGL.GL.EXT.geometry_shader4 import (
    GL_GEOMETRY_SHADER_EXT,
    GL_GEOMETRY_VERTICES_OUT_EXT,
    GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT,
    glProgramParameteriEXT,
)

GL_GEOMETRY_INPUT_TYPE = 0x8917
GL_GEOMETRY_OUTPUT_TYPE = 0x8918

# The lecture's "Simple Coloring Faces" pair.
SEED_VS = """// vertex shader
void main(void)
{
 gl_Position = gl_ModelViewProjectionMatrix*gl_Vertex;
 gl_FrontColor = gl_Color;
 gl_BackColor = vec4(0,0,0,0); // black for backface
}
"""
SEED_FS = """// fragment shader
void main(void)
{
 gl_FragColor = gl_Color;
}
"""

EXT_HEADER = "#version 120\n#extension GL_EXT_geometry_shader4 : enable\n"


def has_extension():
    ext = GL.glGetString(GL.GL_EXTENSIONS) or b""
    return b"GL_EXT_geometry_shader4" in ext.split()


def geometry_program(body_ext, body_150, input_type, output_type, layout_in, layout_out,
                     vs=SEED_VS, fs=SEED_FS):
    """The program of `vs`, a geometry shader and `fs`: in the lecture's
    form (EXT, program parameters) where the extension exists, else in
    GLSL 1.50 compatibility with `layout_in`/`layout_out`."""
    ext = has_extension()
    p = GL.glCreateProgram()
    stages = [(GL.GL_FRAGMENT_SHADER, fs), (GL.GL_VERTEX_SHADER, vs)]
    if ext:
        stages.append((GL_GEOMETRY_SHADER_EXT, EXT_HEADER + body_ext))
    else:
        gs = "#version 150 compatibility\n" + layout_in + "\n" + layout_out + "\n" + body_150
        stages.append((GL.GL_GEOMETRY_SHADER, gs))
    # Attached in the lecture's order: fragment, vertex, geometry.
    for kind, src in stages:
        s, ok, log = shader(kind, src)
        if not ok:
            raise RuntimeError(f"compile failed: {log}")
        GL.glAttachShader(p, s)
    if ext:
        glProgramParameteriEXT(p, GL_GEOMETRY_INPUT_TYPE, input_type)
        glProgramParameteriEXT(p, GL_GEOMETRY_OUTPUT_TYPE, output_type)
        temp = GL.glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT)
        glProgramParameteriEXT(p, GL_GEOMETRY_VERTICES_OUT_EXT, int(temp))
    GL.glLinkProgram(p)
    if not GL.glGetProgramiv(p, GL.GL_LINK_STATUS):
        raise RuntimeError(f"link failed: {GL.glGetProgramInfoLog(p)}")
    GL.glUseProgram(p)
    return p


def view(angle_y, angle_x=25.0):
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glFrustum(-0.6, 0.6, -0.6, 0.6, 1.5, 10.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glTranslatef(0.0, 0.0, -4.0)
    GL.glRotatef(angle_x, 1.0, 0.0, 0.0)
    GL.glRotatef(angle_y, 0.0, 1.0, 0.0)


# A unit cube's faces as triangles, each face its own colour; the faces
# wound counter-clockwise seen from outside. The front faces are culled
# away half the time below to show the back faces' black.
CUBE_FACES = [
    ((0, 0, 1), (1, 0.2, 0.2)), ((0, 0, -1), (0.2, 1, 0.2)), ((1, 0, 0), (0.2, 0.2, 1)),
    ((-1, 0, 0), (1, 1, 0.2)), ((0, 1, 0), (0.2, 1, 1)), ((0, -1, 0), (1, 0.2, 1)),
]


def cube_triangles():
    verts = []
    for n, color in CUBE_FACES:
        n = list(n)
        # Two axes spanning the face, ordered so that u x v = n.
        u = [n[1], n[2], n[0]] if n[0] == 0 else [0, 1, 0]
        u = [abs(c) for c in u]
        v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
        corners = []
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            corners.append([0.7 * (n[k] + a * u[k] + b * v[k]) for k in range(3)])
        for i in (0, 1, 2, 0, 2, 3):
            verts.append((corners[i], color))
    return verts


def draw_triangles(verts):
    GL.glBegin(GL.GL_TRIANGLES)
    for p, c in verts:
        GL.glColor3f(*c)
        GL.glVertex3f(*p)
    GL.glEnd()


PASS_EXT = """void main()
{
    for (int i = 0; i < gl_VerticesIn; i++) {
        gl_Position = gl_PositionIn[i];
        gl_FrontColor = gl_FrontColorIn[i];
        gl_BackColor = gl_BackColorIn[i];
        EmitVertex();
    }
    EndPrimitive();
}
"""
PASS_150 = """void main()
{
    for (int i = 0; i < gl_in.length(); i++) {
        gl_Position = gl_in[i].gl_Position;
        gl_FrontColor = gl_in[i].gl_FrontColor;
        gl_BackColor = gl_in[i].gl_BackColor;
        EmitVertex();
    }
    EndPrimitive();
}
"""


@scene("seed_simple_program_cube", 96, 96)
def seed_cube(log):
    """The lecture's program as written: vertex -> pass-through geometry
    -> fragment, two-sided colours."""
    geometry_program(PASS_EXT, PASS_150, GL.GL_TRIANGLES, GL.GL_TRIANGLE_STRIP,
                     "layout(triangles) in;", "layout(triangle_strip, max_vertices = 3) out;")
    log.append(f"program: {errors()}")
    GL.glEnable(GL.GL_VERTEX_PROGRAM_TWO_SIDE)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClearColor(0.3, 0.3, 0.35, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    view(33.0)
    # Front faces of the near half culled: the inside (back faces, black)
    # shows through.
    GL.glEnable(GL.GL_CLIP_PLANE0)
    GL.glClipPlane(GL.GL_CLIP_PLANE0, (0.0, 0.0, -1.0, 0.25))
    draw_triangles(cube_triangles())
    GL.glDisable(GL.GL_CLIP_PLANE0)
    log.append(f"draw: {errors()}")


SHRINK_EXT = """uniform float shrink;
void main()
{
    vec4 c = (gl_PositionIn[0] + gl_PositionIn[1] + gl_PositionIn[2]) / 3.0;
    for (int i = 0; i < gl_VerticesIn; i++) {
        gl_Position = mix(c, gl_PositionIn[i], shrink);
        gl_FrontColor = gl_FrontColorIn[i];
        gl_BackColor = gl_BackColorIn[i];
        EmitVertex();
    }
    EndPrimitive();
}
"""
SHRINK_150 = """uniform float shrink;
void main()
{
    vec4 c = (gl_in[0].gl_Position + gl_in[1].gl_Position + gl_in[2].gl_Position) / 3.0;
    for (int i = 0; i < 3; i++) {
        gl_Position = mix(c, gl_in[i].gl_Position, shrink);
        gl_FrontColor = gl_in[i].gl_FrontColor;
        gl_BackColor = gl_in[i].gl_BackColor;
        EmitVertex();
    }
    EndPrimitive();
}
"""


@scene("seed_shrunk_triangles", 96, 96)
def shrunk(log):
    """Every triangle of the cube shrunk to 70% about its centroid."""
    p = geometry_program(SHRINK_EXT, SHRINK_150, GL.GL_TRIANGLES, GL.GL_TRIANGLE_STRIP,
                         "layout(triangles) in;", "layout(triangle_strip, max_vertices = 3) out;")
    GL.glUniform1f(GL.glGetUniformLocation(p, "shrink"), 0.7)
    log.append(f"program: {errors()}")
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    view(-21.0, 40.0)
    draw_triangles(cube_triangles())
    log.append(f"draw: {errors()}")


SQUARES_EXT = """uniform float half_size;
void main()
{
    vec4 c = gl_PositionIn[0];
    for (int i = 0; i < 4; i++) {
        vec2 corner = vec2(float(i - 2 * (i / 2)), float(i / 2)) * 2.0 - 1.0;
        gl_Position = c + vec4(corner * half_size * c.w, 0.0, 0.0);
        gl_FrontColor = vec4(gl_FrontColorIn[0].rgb * (0.6 + 0.2 * corner.y), 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
"""
SQUARES_150 = """uniform float half_size;
void main()
{
    vec4 c = gl_in[0].gl_Position;
    for (int i = 0; i < 4; i++) {
        vec2 corner = vec2(float(i - 2 * (i / 2)), float(i / 2)) * 2.0 - 1.0;
        gl_Position = c + vec4(corner * half_size * c.w, 0.0, 0.0);
        gl_FrontColor = vec4(gl_in[0].gl_FrontColor.rgb * (0.6 + 0.2 * corner.y), 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
"""


@scene("seed_points_to_squares", 96, 96)
def squares(log):
    """A spiral of points, each made a square by the geometry shader
    (more primitives out than in), depth-tested."""
    p = geometry_program(SQUARES_EXT, SQUARES_150, GL.GL_POINTS, GL.GL_TRIANGLE_STRIP,
                         "layout(points) in;", "layout(triangle_strip, max_vertices = 4) out;")
    GL.glUniform1f(GL.glGetUniformLocation(p, "half_size"), 0.07)
    log.append(f"program: {errors()}")
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClearColor(0.0, 0.0, 0.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    view(10.0, 60.0)
    GL.glBegin(GL.GL_POINTS)
    for i in range(40):
        a = 0.45 * i + 0.1
        r = 0.2 + 0.02 * i
        GL.glColor3f(0.3 + 0.7 * (i % 3 == 0), 0.3 + 0.7 * (i % 3 == 1), 0.3 + 0.7 * (i % 3 == 2))
        GL.glVertex3f(r * math.cos(a), 0.03 * i - 0.6, r * math.sin(a))
    GL.glEnd()
    log.append(f"draw: {errors()}")


CUT_EXT = """void main()
{
    // Each triangle of the strip drawn alone, coloured by its ID.
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_PositionIn[i];
        float k = float(gl_PrimitiveIDIn);
        gl_FrontColor = vec4(fract(k * 0.37), fract(k * 0.61), fract(k * 0.13), 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
"""
CUT_150 = """void main()
{
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        float k = float(gl_PrimitiveIDIn);
        gl_FrontColor = vec4(fract(k * 0.37), fract(k * 0.61), fract(k * 0.13), 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
"""


@scene("seed_strip_primitive_ids", 96, 96)
def strip_ids(log):
    """A triangle strip whose triangles the geometry shader colours by
    gl_PrimitiveIDIn, flat-shaded."""
    geometry_program(CUT_EXT, CUT_150, GL.GL_TRIANGLES, GL.GL_TRIANGLE_STRIP,
                     "layout(triangles) in;", "layout(triangle_strip, max_vertices = 3) out;")
    log.append(f"program: {errors()}")
    GL.glShadeModel(GL.GL_FLAT)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glBegin(GL.GL_TRIANGLE_STRIP)
    for i in range(14):
        x = -0.9 + 1.8 * (i // 2) / 6.0
        y = -0.5 + 0.9 * (i % 2) + 0.07 * math.sin(i)
        GL.glVertex2f(x, y)
    GL.glEnd()
    log.append(f"draw: {errors()}")


if __name__ == "__main__":
    main()
