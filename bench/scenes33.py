"""The OpenGL 3.3 core-profile benchmark scenes (bench/scene.py runs them
in a 3.3 core context from OSMesaCreateContextAttribs):

    core-spheres:N:WxH      instanced sphere impostors: one quad, N instances
                            (centre and radius, colour: divisor 1), the
                            camera and lights in a std140 uniform block,
                            ray-sphere depth in gl_FragDepth
    core-mesh:TRIANGLES:WxH a lit mesh from a vertex array object, per-
                            fragment Phong lighting from a std140 block
    core-itex:LAYERS:WxH    integer textures: LAYERS full-screen passes
                            reading a 1024² GL_R16UI index map with
                            texelFetch on a usampler2D) into a
                            palette uniform block, blended

The same data as the compatibility scenes (the atoms of `spheres`, the
surface of `mesh`), from the same seeds, so both implementations draw the
same pictures. Matrices are computed here (no fixed-function stack in core).
"""
import array
import ctypes
import math
import random

from OpenGL import GL

from scene import ATOM_VOLUME, ELEMENTS, LIGHTS, program, surface, vbo


def _floats(v):
    return (ctypes.c_float * len(v))(*v)


def _mul(a, b):
    """Column-major 4x4 product a * b."""
    return [sum(a[k * 4 + r] * b[c * 4 + k] for k in range(4)) for c in range(4) for r in range(4)]


def _translate(x, y, z):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]


def _rotate(deg, axis):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    if axis == "x":
        return [1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1]
    return [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1]


def _ortho(l, r, b, t, n, f):
    return [2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, -2 / (f - n), 0,
            -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1]


def _frustum(l, r, b, t, n, f):
    return [2 * n / (r - l), 0, 0, 0, 0, 2 * n / (t - b), 0, 0,
            (r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1,
            0, 0, -2 * f * n / (f - n), 0]


def _uniform_block(prog, name, binding, data):
    """Binds block `name` of `prog` to `binding` and fills a buffer there."""
    index = GL.glGetUniformBlockIndex(prog, name)
    if index == GL.GL_INVALID_INDEX:
        raise RuntimeError(f"uniform block {name} not active")
    GL.glUniformBlockBinding(prog, index, binding)
    buf = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_UNIFORM_BUFFER, buf)
    GL.glBufferData(GL.GL_UNIFORM_BUFFER, 4 * len(data), _floats(data), GL.GL_STATIC_DRAW)
    GL.glBindBufferBase(GL.GL_UNIFORM_BUFFER, binding, buf)


def _lights_std140():
    """The two lights of scene.LIGHTS as std140 (vec4 direction, vec4
    ambient/diffuse/specular/unused) pairs."""
    out = []
    for pos, a, d, s in LIGHTS:
        n = math.sqrt(sum(c * c for c in pos[:3]))
        out += [pos[0] / n, pos[1] / n, pos[2] / n, 0.0, a, d, s, 0.0]
    return out


SPHERE_VS = """#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 atom;      // centre (world), radius
layout(location = 2) in vec3 in_color;
layout(std140) uniform Camera {
    mat4 view;
    mat4 projection;
    vec4 light[4];                      // per light: direction, (a, d, s, -)
};
out vec2 quad;
flat out vec3 centre_eye;
flat out float radius;
flat out vec3 base;
void main() {
    vec4 c = view * vec4(atom.xyz, 1.0);
    quad = corner;
    centre_eye = c.xyz;
    radius = atom.w;
    base = in_color;
    gl_Position = projection * vec4(c.xy + corner * atom.w, c.z + atom.w, 1.0);
}
"""
SPHERE_FS = """#version 330 core
layout(std140) uniform Camera {
    mat4 view;
    mat4 projection;
    vec4 light[4];
};
in vec2 quad;
flat in vec3 centre_eye;
flat in float radius;
flat in vec3 base;
out vec4 color;
void main() {
    float r2 = dot(quad, quad);
    if (r2 > 1.0)
        discard;
    vec3 n = vec3(quad, sqrt(1.0 - r2));
    vec4 clip = projection * vec4(centre_eye + n * radius, 1.0);
    gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
    vec3 c = vec3(0.0);
    for (int i = 0; i < 2; i++) {
        vec3 l = light[2 * i].xyz;
        vec3 k = light[2 * i + 1].xyz;
        float d = max(dot(n, l), 0.0);
        float s = pow(max(dot(reflect(-l, n), vec3(0.0, 0.0, 1.0)), 0.0), 50.0);
        c += base * (k.x + k.y * d) + vec3(k.z * s);
    }
    color = vec4(c, 1.0);
}
"""


def core_spheres(n, w, h):
    """Instanced impostors of scene.spheres' random atoms (orthographic)."""
    rng = random.Random(7)
    big_r = (3.0 * ATOM_VOLUME * n / (4.0 * math.pi)) ** (1.0 / 3.0)
    acc, cum = 0.0, []
    for e in ELEMENTS:
        acc += e[2]
        cum.append(acc)
    inst = array.array("f")
    for _ in range(n):
        while True:
            p = [rng.uniform(-big_r, big_r) for _ in range(3)]
            if p[0] ** 2 + p[1] ** 2 + p[2] ** 2 <= big_r * big_r:
                break
        u = rng.random() * acc
        r, c, _ = next(e for e, k in zip(ELEMENTS, cum) if u <= k)
        inst.extend((p[0], p[1], p[2], r, c[0], c[1], c[2]))
    radius = big_r + 1.8
    fitted, aspect, d = radius * 1.05, w / h, 3.0 * radius
    hw, hh = (fitted * aspect, fitted) if aspect >= 1 else (fitted, fitted / aspect)
    proj = _ortho(-hw, hw, -hh, hh, d - 1.5 * radius, d + 1.5 * radius)
    view = _mul(_translate(0.0, 0.0, -d), _mul(_rotate(20.0, "x"), _rotate(30.0, "y")))
    prog = program(SPHERE_VS, SPHERE_FS)
    GL.glUseProgram(prog)
    _uniform_block(prog, "Camera", 0, view + proj + _lights_std140())
    GL.glBindVertexArray(GL.glGenVertexArrays(1))
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo(array.array("f", [-1, -1, 1, -1, -1, 1, 1, 1])))
    GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo(inst))
    GL.glVertexAttribPointer(1, 4, GL.GL_FLOAT, GL.GL_FALSE, 28, ctypes.c_void_p(0))
    GL.glVertexAttribPointer(2, 3, GL.GL_FLOAT, GL.GL_FALSE, 28, ctypes.c_void_p(16))
    for loc, divisor in ((0, 0), (1, 1), (2, 1)):
        GL.glEnableVertexAttribArray(loc)
        GL.glVertexAttribDivisor(loc, divisor)
    GL.glEnable(GL.GL_DEPTH_TEST)
    return lambda: GL.glDrawArraysInstanced(GL.GL_TRIANGLE_STRIP, 0, 4, n)


MESH_VS = """#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 in_color;
uniform mat4 model_view;
uniform mat4 projection;
out vec3 eye_normal;
out vec3 eye_pos;
out vec4 colour;
void main() {
    vec4 e = model_view * vec4(position, 1.0);
    eye_pos = e.xyz;
    eye_normal = mat3(model_view) * normal;
    colour = in_color;
    gl_Position = projection * e;
}
"""
MESH_FS = """#version 330 core
layout(std140) uniform Lighting {
    vec4 light[4];          // per light: direction, (a, d, s, -)
    vec4 material;          // (specular, shininess, -, -)
};
in vec3 eye_normal;
in vec3 eye_pos;
in vec4 colour;
out vec4 frag;
void main() {
    vec3 n = normalize(eye_normal);
    n = gl_FrontFacing ? n : -n;
    vec3 v = normalize(-eye_pos);
    vec3 c = vec3(0.0);
    for (int i = 0; i < 2; i++) {
        vec3 l = light[2 * i].xyz;
        vec3 k = light[2 * i + 1].xyz;
        float d = max(dot(n, l), 0.0);
        float s = d > 0.0 ? pow(max(dot(reflect(-l, n), v), 0.0), material.y) : 0.0;
        c += colour.rgb * (k.x + k.y * d) + vec3(material.x * k.z * s);
    }
    frag = vec4(c, colour.a);
}
"""


def core_mesh(triangles, w, h):
    """scene.mesh's surface through a VAO, lit per fragment from a block."""
    pos, nrm, col, idx = surface(triangles)
    prog = program(MESH_VS, MESH_FS)
    GL.glUseProgram(prog)
    mv = _mul(_translate(0.0, 0.0, -3.0), _rotate(-35.0, "x"))
    c, s = math.cos(math.radians(15.0)), math.sin(math.radians(15.0))
    mv = _mul(mv, [c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    proj = _frustum(-0.5 * w / h, 0.5 * w / h, -0.5, 0.5, 1.5, 6.0)
    GL.glUniformMatrix4fv(GL.glGetUniformLocation(prog, "model_view"), 1, GL.GL_FALSE, _floats(mv))
    GL.glUniformMatrix4fv(GL.glGetUniformLocation(prog, "projection"), 1, GL.GL_FALSE, _floats(proj))
    _uniform_block(prog, "Lighting", 1, _lights_std140() + [1.0, 50.0, 0.0, 0.0])
    GL.glBindVertexArray(GL.glGenVertexArrays(1))
    for loc, (data, size) in enumerate(((pos, 3), (nrm, 3), (col, 4))):
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo(data))
        GL.glVertexAttribPointer(loc, size, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
        GL.glEnableVertexAttribArray(loc)
    vbo(idx)  # the element buffer, recorded in the VAO
    GL.glEnable(GL.GL_DEPTH_TEST)
    count = len(idx)
    return lambda: GL.glDrawElements(GL.GL_TRIANGLES, count, GL.GL_UNSIGNED_INT, None)


ITEX_VS = """#version 330 core
layout(location = 0) in vec2 corner;
void main() { gl_Position = vec4(corner, 0.0, 1.0); }
"""
ITEX_FS = """#version 330 core
uniform usampler2D indices;
uniform int layer;
layout(std140) uniform Palette { vec4 colours[64]; };
out vec4 frag;
void main() {
    ivec2 size = textureSize(indices, 0);
    ivec2 at = (ivec2(gl_FragCoord.xy) + ivec2(37, 11) * layer) % size;
    uint i = texelFetch(indices, at, 0).r;
    uint mixed = (i ^ uint(layer * 7)) & 63u;
    frag = vec4(colours[mixed].rgb, 0.25);
}
"""


def core_itex(layers, w, h):
    """`layers` blended full-screen passes of integer texel fetches."""
    size = 1024
    rng = random.Random(11)
    cells = [rng.randrange(1 << 16) for _ in range(64 * 64)]
    texels = array.array("H", (cells[(y // 16) * 64 + x // 16] ^ ((x * 3 + y * 5) & 0xFF)
                               for y in range(size) for x in range(size)))
    tex = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, tex)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
    data = (ctypes.c_char * (len(texels) * 2)).from_buffer(texels)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_R16UI, size, size, 0, GL.GL_RED_INTEGER,
                    GL.GL_UNSIGNED_SHORT, data)
    prog = program(ITEX_VS, ITEX_FS)
    GL.glUseProgram(prog)
    GL.glUniform1i(GL.glGetUniformLocation(prog, "indices"), 0)
    layer = GL.glGetUniformLocation(prog, "layer")
    palette = []
    for i in range(64):
        palette += [0.5 + 0.5 * math.sin(0.3 * i), 0.5 + 0.5 * math.sin(0.5 * i + 1.0),
                    0.5 + 0.5 * math.sin(0.7 * i + 2.0), 1.0]
    _uniform_block(prog, "Palette", 2, palette)
    GL.glBindVertexArray(GL.glGenVertexArrays(1))
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo(array.array("f", [-1, -1, 1, -1, -1, 1, 1, 1])))
    GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glEnableVertexAttribArray(0)
    GL.glEnable(GL.GL_BLEND)
    GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)

    def draw():
        for k in range(layers):
            GL.glUniform1i(layer, k)
            GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    return draw


def build(kind, args, parse_size):
    """(width, height, set-up) for a core-* spec, None for another kind."""
    scenes = {"core-spheres": core_spheres, "core-mesh": core_mesh, "core-itex": core_itex}
    if kind not in scenes:
        return None
    w, h = parse_size(args[1])
    return w, h, lambda: scenes[kind](int(args[0]), w, h)
