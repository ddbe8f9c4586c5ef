"""Differential core-profile programs in the style of the seed lecture
(seeds/001): GLSL 1.40/1.50/3.30 on OpenGL 3.3 core contexts, with generic
vertex attributes in vertex array objects, `in`/`out` between the stages
(plain and as an interface block), per-fragment Phong lighting from
uniforms and from a std140 uniform block, and instanced sphere impostors
(per-instance attributes with a divisor, `glDrawArraysInstanced`,
`gl_FragDepth`).
"""
import ctypes
import math

from harness import GL, errors, main, program, scene
from OpenGL.raw.GL.VERSION import GL_3_1 as raw31  # noqa: E402

CORE = (3, 3, "core")


def floats(v):
    return (ctypes.c_float * len(v))(*v)


def mat_mul(a, b):
    """4x4 column-major product a * b."""
    return [sum(a[k * 4 + r] * b[c * 4 + k] for k in range(4)) for c in range(4) for r in range(4)]


def perspective(fovy, aspect, near, far):
    f = 1.0 / math.tan(fovy / 2)
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1,
            0, 0, 2 * far * near / (near - far), 0]


def translate(x, y, z):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]


def rotate_x(a):
    c, s = math.cos(a), math.sin(a)
    return [1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1]


def upper3(m):
    """The upper-left 3x3 (the normal matrix of a rotation and translation)."""
    return [m[c * 4 + r] for c in range(3) for r in range(3)]


def sphere_mesh(slices=24, stacks=16):
    """Positions (= normals) of a unit sphere, interleaved with normals, and
    triangle indices."""
    verts, idx = [], []
    for i in range(stacks + 1):
        phi = math.pi * i / stacks
        for j in range(slices + 1):
            th = 2 * math.pi * j / slices
            p = (math.sin(phi) * math.cos(th), math.cos(phi), math.sin(phi) * math.sin(th))
            verts.extend(p + p)
    for i in range(stacks):
        for j in range(slices):
            a = i * (slices + 1) + j
            b = a + slices + 1
            idx.extend((a, b, a + 1, a + 1, b, b + 1))
    return verts, idx


def sphere_vao():
    """A VAO with the sphere at attributes 0 (position) and 1 (normal) and
    its element buffer; returns the index count."""
    verts, idx = sphere_mesh()
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    vb, ib = GL.glGenBuffers(2)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vb)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, 4 * len(verts), floats(verts), GL.GL_STATIC_DRAW)
    GL.glVertexAttribPointer(0, 3, GL.GL_FLOAT, GL.GL_FALSE, 24, ctypes.c_void_p(0))
    GL.glVertexAttribPointer(1, 3, GL.GL_FLOAT, GL.GL_FALSE, 24, ctypes.c_void_p(12))
    GL.glEnableVertexAttribArray(0)
    GL.glEnableVertexAttribArray(1)
    GL.glBindBuffer(GL.GL_ELEMENT_ARRAY_BUFFER, ib)
    data = (ctypes.c_ushort * len(idx))(*idx)
    GL.glBufferData(GL.GL_ELEMENT_ARRAY_BUFFER, ctypes.sizeof(data), data, GL.GL_STATIC_DRAW)
    return len(idx)


def set_mat(p, name, m):
    loc = GL.glGetUniformLocation(p, name)
    if loc < 0:
        raise RuntimeError(f"uniform {name} not active")
    (GL.glUniformMatrix4fv if len(m) == 16 else GL.glUniformMatrix3fv)(loc, 1, GL.GL_FALSE, floats(m))


def set_vec(p, name, *v):
    loc = GL.glGetUniformLocation(p, name)
    if loc < 0:
        raise RuntimeError(f"uniform {name} not active")
    getattr(GL, f"glUniform{len(v)}f")(loc, *v)


def begin(w, h):
    GL.glViewport(0, 0, w, h)
    GL.glClearColor(0.1, 0.1, 0.15, 1.0)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)


MODEL_VIEW = mat_mul(translate(0.0, 0.0, -3.0), rotate_x(0.4))
PROJECTION = perspective(math.radians(50.0), 1.0, 0.5, 10.0)

# The lecture's per-fragment Phong program: `#version 140`, generic
# attributes named in_pos/in_normal bound with glBindAttribLocation.
VS_PHONG = """#version 140
in vec3 in_pos;
in vec3 in_normal;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
out vec3 normal;
out vec3 p;
void main() {
    vec4 eye = modelViewMatrix * vec4(in_pos, 1.0);
    p = eye.xyz;
    normal = normalMatrix * in_normal;
    gl_Position = projectionMatrix * eye;
}
"""
FS_PHONG = """#version 140
uniform vec3 lightpos;
uniform vec3 Kd, Ka, Ks;
uniform vec3 Ld, La, Ls;
uniform float alpha;
in vec3 normal;
in vec3 p;
out vec4 color;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(lightpos - p);
    vec3 v = normalize(-p);
    vec3 r = reflect(-l, n);
    vec3 c = Ka * La + Kd * Ld * max(dot(l, n), 0.0)
           + Ks * Ls * pow(max(dot(r, v), 0.0), alpha);
    color = vec4(c, 1.0);
}
"""


@scene("core_phong_generic_attributes", 96, 96, CORE)
def phong(log):
    begin(96, 96)
    count = sphere_vao()
    p = program([VS_PHONG], [FS_PHONG], attribs=((0, "in_pos"), (1, "in_normal")))
    log.append(f"attrib locations: {GL.glGetAttribLocation(p, 'in_pos')} "
               f"{GL.glGetAttribLocation(p, 'in_normal')}")
    set_mat(p, "modelViewMatrix", MODEL_VIEW)
    set_mat(p, "projectionMatrix", PROJECTION)
    set_mat(p, "normalMatrix", upper3(MODEL_VIEW))
    set_vec(p, "lightpos", 2.0, 2.0, 1.0)
    set_vec(p, "Kd", 0.8, 0.3, 0.2)
    set_vec(p, "Ka", 0.2, 0.2, 0.2)
    set_vec(p, "Ks", 0.6, 0.6, 0.6)
    set_vec(p, "Ld", 1.0, 1.0, 1.0)
    set_vec(p, "La", 0.3, 0.3, 0.3)
    set_vec(p, "Ls", 1.0, 1.0, 1.0)
    set_vec(p, "alpha", 20.0)
    GL.glDrawElements(GL.GL_TRIANGLES, count, GL.GL_UNSIGNED_SHORT, None)
    log.append(f"draw: {errors()}")


# The same lighting in GLSL 1.50: the stages joined by an interface block,
# the camera in one std140 block and the light and material in another
# (an instance-named block), the attributes still bound by name.
VS_BLOCK = """#version 150
in vec3 in_pos;
in vec3 in_normal;
layout(std140) uniform Camera {
    mat4 modelView;
    mat4 projection;
};
out Surface {
    vec3 normal;
    vec3 p;
} surface;
void main() {
    vec4 eye = modelView * vec4(in_pos, 1.0);
    surface.p = eye.xyz;
    surface.normal = mat3(modelView) * in_normal;
    gl_Position = projection * eye;
}
"""
FS_BLOCK = """#version 150
layout(std140) uniform Lighting {
    vec4 lightpos;
    vec4 Kd, Ka, Ks;
    vec4 Ld, La, Ls;
    float alpha;
} lighting;
in Surface {
    vec3 normal;
    vec3 p;
} surface;
out vec4 color;
void main() {
    vec3 n = normalize(surface.normal);
    vec3 l = normalize(lighting.lightpos.xyz - surface.p);
    vec3 r = reflect(-l, n);
    vec3 c = lighting.Ka.rgb * lighting.La.rgb
           + lighting.Kd.rgb * lighting.Ld.rgb * max(dot(l, n), 0.0)
           + lighting.Ks.rgb * lighting.Ls.rgb
             * pow(max(dot(r, normalize(-surface.p)), 0.0), lighting.alpha);
    color = vec4(c, 1.0);
}
"""


def ubo(p, block, binding, data):
    i = raw31.glGetUniformBlockIndex(p, block.encode())
    if i == GL.GL_INVALID_INDEX:
        raise RuntimeError(f"block {block} not active")
    raw31.glUniformBlockBinding(p, i, binding)
    b = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_UNIFORM_BUFFER, b)
    GL.glBufferData(GL.GL_UNIFORM_BUFFER, 4 * len(data), floats(data), GL.GL_STATIC_DRAW)
    GL.glBindBufferBase(GL.GL_UNIFORM_BUFFER, binding, b)
    size = ctypes.c_int()
    raw31.glGetActiveUniformBlockiv(p, i, GL.GL_UNIFORM_BLOCK_DATA_SIZE, ctypes.byref(size))
    return size.value


@scene("core_uniform_blocks_interface_block", 96, 96, CORE)
def blocks(log):
    begin(96, 96)
    count = sphere_vao()
    p = program([VS_BLOCK], [FS_BLOCK], attribs=((0, "in_pos"), (1, "in_normal")))
    size = ubo(p, "Camera", 1, MODEL_VIEW + PROJECTION)
    log.append(f"Camera size: {size}")
    lighting = [2.0, 2.0, 1.0, 1.0,
                0.2, 0.5, 0.9, 0.0, 0.15, 0.15, 0.2, 0.0, 0.7, 0.7, 0.7, 0.0,
                1.0, 1.0, 1.0, 0.0, 0.3, 0.3, 0.3, 0.0, 1.0, 0.9, 0.8, 0.0,
                32.0, 0.0, 0.0, 0.0]
    size = ubo(p, "Lighting", 3, lighting)
    log.append(f"Lighting size: {size}")
    GL.glDrawElements(GL.GL_TRIANGLES, count, GL.GL_UNSIGNED_SHORT, None)
    log.append(f"draw: {errors()}")


# Instanced sphere impostors, the molecular-graphics workhorse: one quad,
# per-instance centre/radius and colour (divisor 1), a ray-sphere test per
# fragment, the true depth written to gl_FragDepth.
VS_IMPOSTOR = """#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 sphere;     // centre (eye space), radius
layout(location = 2) in vec3 in_color;
uniform mat4 projection;
out vec3 eye_pos;
flat out vec4 eye_sphere;
flat out vec3 base;
void main() {
    vec3 c = sphere.xyz + vec3(corner * sphere.w * 1.5, 0.0);
    c.z += sphere.w;
    eye_pos = c;
    eye_sphere = sphere;
    base = in_color;
    gl_Position = projection * vec4(c, 1.0);
}
"""
FS_IMPOSTOR = """#version 330 core
uniform mat4 projection;
in vec3 eye_pos;
flat in vec4 eye_sphere;
flat in vec3 base;
layout(location = 0) out vec4 color;
void main() {
    vec3 ray = normalize(eye_pos);
    vec3 c = eye_sphere.xyz;
    float b = dot(ray, c);
    vec3 closest = c - b * ray;
    float d2 = eye_sphere.w * eye_sphere.w - dot(closest, closest);
    if (d2 < 0.0)
        discard;
    vec3 hit = (b - sqrt(d2)) * ray;
    vec3 n = (hit - c) / eye_sphere.w;
    vec4 clip = projection * vec4(hit, 1.0);
    gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
    vec3 l = normalize(vec3(0.5, 0.7, 1.0));
    float diffuse = max(dot(n, l), 0.0);
    float spec = pow(max(dot(reflect(-l, n), -ray), 0.0), 24.0);
    color = vec4(base * (0.2 + 0.8 * diffuse) + vec3(0.4 * spec), 1.0);
}
"""


@scene("core_instanced_sphere_impostors", 128, 128, CORE)
def impostors(log):
    begin(128, 128)
    p = program([VS_IMPOSTOR], [FS_IMPOSTOR])
    set_mat(p, "projection", PROJECTION)
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    quad, inst = GL.glGenBuffers(2)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, quad)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, 32, floats([-1, -1, 1, -1, -1, 1, 1, 1]), GL.GL_STATIC_DRAW)
    GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glEnableVertexAttribArray(0)
    # A small ring-and-chain "molecule": overlapping spheres at varied depth.
    data = []
    n = 14
    for i in range(n):
        a = 2 * math.pi * i / n + 0.13  # no silhouette through a pixel centre
        data.extend((0.9 * math.cos(a), 0.9 * math.sin(a), -3.2 - 0.4 * math.sin(2 * a),
                     0.28 if i % 3 else 0.38,
                     0.4 + 0.6 * (i % 2), 0.3 + 0.05 * i, 1.0 - 0.06 * i))
    data.extend((0.0, 0.0, -3.4, 0.55, 0.9, 0.9, 0.9))
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, inst)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, 4 * len(data), floats(data), GL.GL_STATIC_DRAW)
    GL.glVertexAttribPointer(1, 4, GL.GL_FLOAT, GL.GL_FALSE, 28, ctypes.c_void_p(0))
    GL.glVertexAttribPointer(2, 3, GL.GL_FLOAT, GL.GL_FALSE, 28, ctypes.c_void_p(16))
    GL.glEnableVertexAttribArray(1)
    GL.glEnableVertexAttribArray(2)
    GL.glVertexAttribDivisor(1, 1)
    GL.glVertexAttribDivisor(2, 1)
    GL.glDrawArraysInstanced(GL.GL_TRIANGLE_STRIP, 0, 4, n + 1)
    log.append(f"draw: {errors()}")


if __name__ == "__main__":
    main()
