"""Differential GL 3.0–3.3 buffer objects and uniform blocks: the errors of
glMapBufferRange / glFlushMappedBufferRange / glCopyBufferSubData /
glBindBufferRange, what mapped writes leave in the store, the std140
layout queries of a uniform block (offsets, strides, data sizes: fixed by
the std140 rules, so Mesa must agree), and a draw reading a block from
its buffer. Logs hold only what GL specifies; uniforms are logged by name,
sorted, since active-uniform indices are the implementation's choice.
Left out: an unknown access bit (GL 3.3 §2.9.3 says GL_INVALID_VALUE,
Mesa raises GL_INVALID_OPERATION) and a negative glBindBufferRange offset
(an error in GL 4.x's wording, which shaderbox follows; Mesa accepts it
when the offset is aligned). Blocks with instance names use GLSL 1.50
(1.40 has none).
"""
import ctypes
import sys

from harness import GL, errors, main, program, scene
from OpenGL.raw.GL.VERSION import GL_1_5 as raw15  # noqa: E402
from OpenGL.raw.GL.VERSION import GL_3_0 as raw30, GL_3_1 as raw31, GL_3_2 as raw32  # noqa: E402

U8 = ctypes.POINTER(ctypes.c_ubyte)


def check(log, what, f, *args):
    errors()
    r = f(*args)
    log.append(f"{what}: {errors()}")
    return r


def store(target, n):
    out = (ctypes.c_ubyte * n)()
    raw15.glGetBufferSubData(target, 0, n, out)
    return list(out)


@scene("buf_map_range_and_copy", 8, 8)
def map_range(log):
    R, W = GL.GL_MAP_READ_BIT, GL.GL_MAP_WRITE_BIT
    t = GL.GL_COPY_WRITE_BUFFER
    b = (ctypes.c_uint * 2)()
    raw15.glGenBuffers(2, b)
    check(log, "glMapBufferRange(none bound)", raw30.glMapBufferRange, t, 0, 1, R)
    GL.glBindBuffer(t, b[0])
    init = (ctypes.c_ubyte * 16)(*range(16))
    raw15.glBufferData(t, 16, init, GL.GL_STATIC_DRAW)
    for what, off, length, access in [
        ("offset -1", -1, 1, R),
        ("length -1", 0, -1, R),
        ("past the end", 8, 9, R),
        ("no read or write", 0, 1, GL.GL_MAP_INVALIDATE_RANGE_BIT),
        ("read + invalidate range", 0, 1, R | GL.GL_MAP_INVALIDATE_RANGE_BIT),
        ("read + invalidate buffer", 0, 1, R | GL.GL_MAP_INVALIDATE_BUFFER_BIT),
        ("read + unsynchronized", 0, 1, R | GL.GL_MAP_UNSYNCHRONIZED_BIT),
        ("read + flush explicit", 0, 1, R | GL.GL_MAP_FLUSH_EXPLICIT_BIT),
    ]:
        p = check(log, f"glMapBufferRange({what})", raw30.glMapBufferRange, t, off, length, access)
        log.append(f"  null: {not p}")
    p = check(log, "glMapBufferRange(write 4..8)", raw30.glMapBufferRange, t, 4, 4,
              W | GL.GL_MAP_INVALIDATE_RANGE_BIT)
    ctypes.memmove(p, bytes([100, 101, 102, 103]), 4)
    v = ctypes.c_int()
    for pname in ("GL_BUFFER_MAPPED", "GL_BUFFER_ACCESS", "GL_BUFFER_ACCESS_FLAGS",
                  "GL_BUFFER_MAP_OFFSET", "GL_BUFFER_MAP_LENGTH"):
        raw15.glGetBufferParameteriv(t, getattr(GL, pname), ctypes.byref(v))
        log.append(f"  {pname}: {v.value}")
    check(log, "glMapBufferRange(mapped)", raw30.glMapBufferRange, t, 0, 1, R)
    check(log, "glFlushMappedBufferRange(no flush bit)", raw30.glFlushMappedBufferRange, t, 0, 1)
    check(log, "glBufferSubData(mapped range)", raw15.glBufferSubData, t, 6, 1, init)
    check(log, "glBufferSubData(outside the mapped range)", raw15.glBufferSubData, t, 0, 1, init)
    check(log, "glCopyBufferSubData(mapped)", raw31.glCopyBufferSubData, t, t, 0, 8, 1)
    r = check(log, "glUnmapBuffer", raw15.glUnmapBuffer, t)
    log.append(f"  returned {r}; store {store(t, 16)}")
    check(log, "glFlushMappedBufferRange(not mapped)", raw30.glFlushMappedBufferRange, t, 0, 1)
    p = check(log, "glMapBufferRange(flush explicit)", raw30.glMapBufferRange, t, 8, 8,
              W | GL.GL_MAP_FLUSH_EXPLICIT_BIT)
    ctypes.memset(p, 0xAA, 8)
    check(log, "glFlushMappedBufferRange(2, 1)", raw30.glFlushMappedBufferRange, t, 2, 1)
    check(log, "glFlushMappedBufferRange(past the mapping)", raw30.glFlushMappedBufferRange,
          t, 6, 4)
    check(log, "glFlushMappedBufferRange(offset -1)", raw30.glFlushMappedBufferRange, t, -1, 1)
    raw15.glUnmapBuffer(t)
    # Unflushed bytes are undefined (Mesa's writes land at once): only the
    # flushed one is logged.
    log.append(f"  flushed byte {store(t, 16)[10]}")
    p = check(log, "glMapBufferRange(read)", raw30.glMapBufferRange, t, 2, 3, R)
    log.append(f"  read {list(ctypes.cast(p, U8)[:3])}")
    raw15.glUnmapBuffer(t)

    GL.glBindBuffer(GL.GL_COPY_READ_BUFFER, b[0])
    GL.glBindBuffer(t, b[1])
    raw15.glBufferData(t, 8, None, GL.GL_STATIC_DRAW)
    c = GL.GL_COPY_READ_BUFFER
    check(log, "glCopyBufferSubData", raw31.glCopyBufferSubData, c, t, 3, 1, 5)
    log.append(f"  store {store(t, 8)[1:6]}")
    for what, args in [
        ("bad target", (GL.GL_LESS, t, 0, 0, 1)),
        ("read offset -1", (c, t, -1, 0, 1)),
        ("size -1", (c, t, 0, 0, -1)),
        ("read past", (c, t, 12, 0, 5)),
        ("write past", (c, t, 0, 4, 5)),
        ("overlap", (c, c, 0, 2, 4)),
    ]:
        check(log, f"glCopyBufferSubData({what})", raw31.glCopyBufferSubData, *args)
    check(log, "glCopyBufferSubData(same buffer, apart)", raw31.glCopyBufferSubData,
          c, c, 0, 8, 4)
    log.append(f"  store {store(c, 16)[8:12]}")

    u = GL.GL_UNIFORM_BUFFER
    for what, args in [
        ("bad target", (GL.GL_ARRAY_BUFFER, 0, b[0], 0, 16)),
        ("index max", (u, int(GL.glGetIntegerv(GL.GL_MAX_UNIFORM_BUFFER_BINDINGS)), b[0], 0, 16)),
        ("size 0", (u, 0, b[0], 0, 0)),
        ("range", (u, 1, b[0], 0, 16)),
    ]:
        check(log, f"glBindBufferRange({what})", raw30.glBindBufferRange, *args)
    v = ctypes.c_int()
    raw30.glGetIntegeri_v(GL.GL_UNIFORM_BUFFER_SIZE, 1, ctypes.byref(v))
    log.append(f"  GL_UNIFORM_BUFFER_SIZE[1]: {v.value}")
    raw30.glGetIntegeri_v(GL.GL_UNIFORM_BUFFER_BINDING, 1, ctypes.byref(v))
    log.append(f"  GL_UNIFORM_BUFFER_BINDING[1] is b0: {v.value == b[0]}")
    v64 = ctypes.c_int64()
    raw32.glGetBufferParameteri64v(c, GL.GL_BUFFER_SIZE, ctypes.byref(v64))
    log.append(f"  GL_BUFFER_SIZE (64): {v64.value}")
    return False


FS_LAYOUT = """#version 150
struct S { vec3 a; float b; mat2 c[2]; };
layout(std140) uniform Block {
    float f;
    vec2 v2;
    vec3 v3;
    int i;
    bool flag;
    vec3 arr[3];
    mat3 m3;
    layout(row_major) mat2x3 rm;
    S s;
    float tail[2];
} blk;
layout(std140) uniform Second { vec4 colour; };
out vec4 o;
void main() {
    o = vec4(blk.f + blk.v2.x + blk.v3.x + float(blk.i) + float(blk.flag) + blk.arr[2].x
        + blk.m3[1].x + blk.rm[1].x + blk.s.a.x + blk.s.b + blk.s.c[1][0].x + blk.tail[1])
        + colour;
}
"""
VS = "#version 150\nin vec4 pos;\nvoid main() { gl_Position = pos; }\n"


def block_index(p, name):
    return raw31.glGetUniformBlockIndex(p, name.encode())


@scene("ubo_std140_layout", 8, 8)
def layout(log):
    p = program([VS], [FS_LAYOUT])
    log.append(f"GL_ACTIVE_UNIFORM_BLOCKS: {GL.glGetProgramiv(p, GL.GL_ACTIVE_UNIFORM_BLOCKS)}")
    v = ctypes.c_int()
    for name in ("Block", "Second"):
        i = block_index(p, name)
        for pname in ("GL_UNIFORM_BLOCK_DATA_SIZE", "GL_UNIFORM_BLOCK_NAME_LENGTH",
                      "GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS", "GL_UNIFORM_BLOCK_BINDING",
                      "GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER"):
            raw31.glGetActiveUniformBlockiv(p, i, getattr(GL, pname), ctypes.byref(v))
            log.append(f"{name} {pname}: {v.value}")
    log.append(f"index of blk: {block_index(p, 'blk') == GL.GL_INVALID_INDEX}")
    names = ["Block.f", "Block.v2", "Block.v3", "Block.i", "Block.flag", "Block.arr",
             "Block.arr[0]", "Block.m3", "Block.rm", "Block.s.a", "Block.s.b", "Block.s.c",
             "Block.tail", "colour", "blk.f", "f"]
    arr = (ctypes.c_char_p * len(names))(*[n.encode() for n in names])
    idx = (ctypes.c_uint * len(names))()
    raw31.glGetUniformIndices(p, len(names),
                              ctypes.cast(arr, ctypes.POINTER(ctypes.POINTER(ctypes.c_char))),
                              idx)
    found = [(n, i) for n, i in zip(names, idx) if i != GL.GL_INVALID_INDEX]
    log.append(f"not found: {[n for n, i in zip(names, idx) if i == GL.GL_INVALID_INDEX]}")
    log.append(f"Block.arr == Block.arr[0]: {idx[5] == idx[6]}")
    for n, i in sorted(found):
        one = (ctypes.c_uint * 1)(i)
        vals = []
        for pname in ("GL_UNIFORM_TYPE", "GL_UNIFORM_SIZE", "GL_UNIFORM_NAME_LENGTH",
                      "GL_UNIFORM_OFFSET", "GL_UNIFORM_ARRAY_STRIDE", "GL_UNIFORM_MATRIX_STRIDE",
                      "GL_UNIFORM_IS_ROW_MAJOR"):
            raw31.glGetActiveUniformsiv(p, 1, one, getattr(GL, pname), ctypes.byref(v))
            vals.append(v.value)
        raw31.glGetActiveUniformsiv(p, 1, one, GL.GL_UNIFORM_BLOCK_INDEX, ctypes.byref(v))
        blk = "Block" if v.value == block_index(p, "Block") else "Second"
        log.append(f"{n}: type/size/namelen/offset/astride/mstride/rowmajor {vals} in {blk}")
    log.append(f"location of colour: {GL.glGetUniformLocation(p, 'colour')}")
    check(log, "glUniformBlockBinding(binding max)", raw31.glUniformBlockBinding, p, 0,
          int(GL.glGetIntegerv(GL.GL_MAX_UNIFORM_BUFFER_BINDINGS)))
    check(log, "glUniformBlockBinding(index 2)", raw31.glUniformBlockBinding, p, 2, 0)
    check(log, "glGetActiveUniformBlockiv(index 2)", raw31.glGetActiveUniformBlockiv, p, 2,
          GL.GL_UNIFORM_BLOCK_DATA_SIZE, ctypes.byref(v))
    check(log, "glGetActiveUniformBlockiv(bad pname)", raw31.glGetActiveUniformBlockiv, p, 0,
          GL.GL_UNIFORM_SIZE, ctypes.byref(v))
    return False


FS_DRAW = """#version 150
layout(std140) uniform Colors {
    vec4 colour;
    mat4 m;
    float weights[3];
    layout(row_major) mat2 r;
};
uniform Extra { vec4 add; } extra;
out vec4 result;
void main() {
    vec4 c = m * colour;
    result = vec4(c.x, c.y * weights[2], (r * vec2(1.0, 0.0)).y, 1.0) + extra.add;
}
"""


def floats(v):
    return (ctypes.c_float * len(v))(*v)


@scene("ubo_draw", 32, 32)
def draw(log):
    p = program([VS], [FS_DRAW])
    w = [0.0] * 68
    w[0:4] = [0.25, 0.5, 0.75, 1.0]
    w[4:20] = [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1]
    w[28] = 0.5
    w[32:34] = [0.9, 0.1]
    w[36:38] = [0.6, 0.3]
    w[64:68] = [0.1, 0.1, 0.1, 0.0]
    b = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_UNIFORM_BUFFER, b)
    raw15.glBufferData(GL.GL_UNIFORM_BUFFER, 272, floats(w), GL.GL_DYNAMIC_DRAW)
    raw31.glUniformBlockBinding(p, block_index(p, "Colors"), 2)
    raw31.glUniformBlockBinding(p, block_index(p, "Extra"), 5)
    raw30.glBindBufferBase(GL.GL_UNIFORM_BUFFER, 2, b)
    raw30.glBindBufferRange(GL.GL_UNIFORM_BUFFER, 5, b, 256, 16)
    pos = GL.glGetAttribLocation(p, "pos")
    GL.glEnableVertexAttribArray(pos)
    GL.glViewport(0, 0, 16, 32)
    quad = floats([-1, -1, 1, -1, -1, 1, 1, 1])
    GL.glVertexAttribPointer(pos, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, quad)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    # New data through a mapping, drawn on the right half.
    m = raw30.glMapBufferRange(GL.GL_UNIFORM_BUFFER, 0, 16, GL.GL_MAP_WRITE_BIT)
    ctypes.memmove(m, floats([0.0, 1.0, 0.0, 1.0]), 16)
    raw15.glUnmapBuffer(GL.GL_UNIFORM_BUFFER)
    GL.glViewport(16, 0, 16, 32)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    log.append(f"draws: {errors()}")


if __name__ == "__main__":
    sys.exit(main())
