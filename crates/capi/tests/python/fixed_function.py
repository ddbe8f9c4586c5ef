"""Fixed-function PyOpenGL scene on OSMesa: glFrustum, two lights, a material,
a smooth-shaded immediate-mode sphere in a display list, fog, and a client-array quad drawn with
glDrawElements. Writes RGBA pixels (bottom row first) to argv[1] if given."""
import ctypes
import math
import sys

from OpenGL import GL, arrays
from OpenGL import osmesa

W, H = 96, 72


def sphere(r, slices, stacks):
    for i in range(stacks):
        a0, a1 = math.pi * i / stacks, math.pi * (i + 1) / stacks
        GL.glBegin(GL.GL_QUAD_STRIP)
        for j in range(slices + 1):
            b = 2 * math.pi * j / slices
            for a in (a0, a1):
                n = (math.sin(a) * math.cos(b), math.sin(a) * math.sin(b), math.cos(a))
                GL.glNormal3f(*n)
                GL.glVertex3f(r * n[0], r * n[1], r * n[2])
        GL.glEnd()


def main():
    ctx = osmesa.OSMesaCreateContext(osmesa.OSMESA_RGBA, None)
    buf = arrays.GLubyteArray.zeros((H, W, 4))
    assert osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, W, H)
    GL.glClearColor(0.1, 0.1, 0.1, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 10.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glTranslatef(0.0, 0.0, -3.0)
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glEnable(GL.GL_LIGHT1)
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (1.0, 1.0, 2.0, 0.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, (0.8, 0.7, 0.6, 1.0))
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_POSITION, (-2.0, 0.0, 1.0, 1.0))
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_DIFFUSE, (0.0, 0.3, 0.6, 1.0))
    GL.glLightf(GL.GL_LIGHT1, GL.GL_LINEAR_ATTENUATION, 0.2)
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_AMBIENT, (0.2, 0.2, 0.2, 1.0))
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_DIFFUSE, (0.9, 0.9, 0.9, 1.0))
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_SPECULAR, (1.0, 1.0, 1.0, 1.0))
    GL.glMaterialf(GL.GL_FRONT_AND_BACK, GL.GL_SHININESS, 30.0)
    GL.glLightModelfv(GL.GL_LIGHT_MODEL_AMBIENT, (0.1, 0.1, 0.1, 1.0))
    GL.glShadeModel(GL.GL_SMOOTH)
    # The sphere goes through a display list (with its transform and a
    # material change inside), called once.
    lst = GL.glGenLists(1)
    GL.glNewList(lst, GL.GL_COMPILE)
    GL.glPushMatrix()
    GL.glRotatef(30.0, 1.0, 0.0, 0.0)
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_DIFFUSE, (0.9, 0.9, 0.9, 1.0))
    sphere(0.9, 24, 16)
    GL.glPopMatrix()
    GL.glEndList()
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_DIFFUSE, (0.0, 0.0, 0.0, 1.0))
    GL.glCallList(lst)
    mv = GL.glGetFloatv(GL.GL_MODELVIEW_MATRIX)
    assert abs(mv[3][2] + 3.0) < 1e-6, mv

    GL.glDisable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_FOG)
    GL.glFogi(GL.GL_FOG_MODE, GL.GL_LINEAR)
    GL.glFogf(GL.GL_FOG_START, 2.0)
    GL.glFogf(GL.GL_FOG_END, 6.0)
    GL.glFogfv(GL.GL_FOG_COLOR, (0.5, 0.5, 0.5, 1.0))
    verts = (ctypes.c_float * 12)(0.6, -0.9, -1.0, 1.4, -0.9, -2.0, 1.4, -0.1, -2.0, 0.6, -0.1, -1.0)
    cols = (ctypes.c_ubyte * 16)(255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255)
    idx = (ctypes.c_ushort * 6)(0, 1, 2, 0, 2, 3)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_COLOR_ARRAY)
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, verts)
    GL.glColorPointer(4, GL.GL_UNSIGNED_BYTE, 0, cols)
    GL.glDrawElements(GL.GL_TRIANGLES, 6, GL.GL_UNSIGNED_SHORT, idx)
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
