"""PyOpenGL on OSMesa: a GLSL program sampling a checkerboard texture, a
per-pixel Phong-lit sphere-ish quad rendered into an FBO texture, then drawn
to the window with a VBO; error paths (bad shader, failing link) checked.
Writes RGBA pixels (bottom row first) to argv[1] if given."""
import ctypes
import sys

from OpenGL import GL, arrays
from OpenGL import osmesa

W, H = 80, 60

VS = """
varying vec2 uv;
void main() { uv = gl_MultiTexCoord0.xy; gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
"""
FS_SCENE = """
uniform sampler2D tex;
uniform vec3 light;
varying vec2 uv;
void main() {
    vec2 p = uv * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    vec3 n = vec3(p, sqrt(1.0 - r2));
    float d = max(dot(n, normalize(light)), 0.0);
    float s = pow(max(dot(reflect(-normalize(light), n), vec3(0.0, 0.0, 1.0)), 0.0), 16.0);
    gl_FragColor = vec4(texture2D(tex, uv * 4.0).rgb * d + vec3(s), 1.0);
}
"""
FS_SHOW = """
uniform sampler2D tex;
varying vec2 uv;
void main() { gl_FragColor = texture2D(tex, uv).bgra; }
"""


def shader(kind, src):
    s = GL.glCreateShader(kind)
    GL.glShaderSource(s, src)
    GL.glCompileShader(s)
    return s


def program(vs, fs):
    p = GL.glCreateProgram()
    GL.glAttachShader(p, shader(GL.GL_VERTEX_SHADER, vs))
    GL.glAttachShader(p, shader(GL.GL_FRAGMENT_SHADER, fs))
    GL.glLinkProgram(p)
    assert GL.glGetProgramiv(p, GL.GL_LINK_STATUS), GL.glGetProgramInfoLog(p)
    return p


def main():
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    buf = arrays.GLubyteArray.zeros((H, W, 4))
    assert osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, W, H)

    # Error paths.
    bad = shader(GL.GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(1.0) + ; }")
    assert not GL.glGetShaderiv(bad, GL.GL_COMPILE_STATUS)
    assert GL.glGetShaderInfoLog(bad)
    p = GL.glCreateProgram()
    GL.glAttachShader(p, shader(GL.GL_FRAGMENT_SHADER, "void f(); void main() { f(); }"))
    GL.glLinkProgram(p)
    assert not GL.glGetProgramiv(p, GL.GL_LINK_STATUS)
    assert GL.glGetProgramInfoLog(p)
    assert GL.glGetError() == 0

    checker = (ctypes.c_ubyte * (8 * 8 * 4))()
    for y in range(8):
        for x in range(8):
            v = 255 if (x + y) % 2 else 60
            checker[(y * 8 + x) * 4:(y * 8 + x) * 4 + 4] = [v, v // 2 + 60, 255 - v, 255]
    tex = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, tex)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA, 8, 8, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, checker)

    target = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, target)
    # Linear: a rotated nearest lookup has texel-boundary ties where an ulp
    # of interpolation error picks the other checker cell (spec-allowed).
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA, 64, 64, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, None)
    fbo = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo)
    GL.glFramebufferTexture2D(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_TEXTURE_2D, target, 0)
    assert GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE
    GL.glViewport(0, 0, 64, 64)
    GL.glClearColor(0.2, 0.0, 0.2, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)

    scene = program(VS, FS_SCENE)
    GL.glUseProgram(scene)
    GL.glBindTexture(GL.GL_TEXTURE_2D, tex)
    GL.glUniform1i(GL.glGetUniformLocation(scene, "tex"), 0)
    GL.glUniform3f(GL.glGetUniformLocation(scene, "light"), 0.5, 0.7, 1.0)
    quad = (ctypes.c_float * 16)(-1, -1, 0, 0, 1, -1, 1, 0, 1, 1, 1, 1, -1, 1, 0, 1)
    vbo = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, ctypes.sizeof(quad), quad, GL.GL_STATIC_DRAW)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_TEXTURE_COORD_ARRAY)
    GL.glVertexPointer(2, GL.GL_FLOAT, 16, ctypes.c_void_p(0))
    GL.glTexCoordPointer(2, GL.GL_FLOAT, 16, ctypes.c_void_p(8))
    GL.glDrawArrays(GL.GL_TRIANGLE_FAN, 0, 4)

    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, 0)
    GL.glViewport(0, 0, W, H)
    GL.glClearColor(0.0, 0.0, 0.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    show = program(VS, FS_SHOW)
    GL.glUseProgram(show)
    GL.glBindTexture(GL.GL_TEXTURE_2D, target)
    GL.glUniform1i(GL.glGetUniformLocation(show, "tex"), 0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glRotatef(20.0, 0.0, 0.0, 1.0)
    GL.glScalef(0.8, 0.8, 1.0)
    GL.glDrawArrays(GL.GL_TRIANGLE_FAN, 0, 4)
    GL.glFinish()
    px = bytes(GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
    assert px == bytes(buf)
    if len(sys.argv) > 1:
        with open(sys.argv[1], "wb") as f:
            f.write(px)
    err = GL.glGetError()
    osmesa.OSMesaDestroyContext(ctx)
    print("glGetError:", err)
    return 0 if err == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
