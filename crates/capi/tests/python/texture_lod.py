"""Differential scenes: mipmapped textures minified by receding quads, where
the level of detail λ and its fraction change across the image (GL 3.3
§3.8.11). Held to per-scene bounds (texture_lod_bounds.txt): llvmpipe takes
log2 of ρ² piecewise linearly between powers of two (λ up to 0.043 below
log2 ρ, an approximation of ρ by up to 3 % below the least the spec
allows), shaderbox the spec's λ = log2 ρ; docs/CONFORMANCE.md says how much
that moves each scene.

Run by compare.py --bounds (python3 texture_lod.py OUTDIR [SCENE...]); see
harness.py.
"""
import math
import sys

from harness import GL, lib, main, perspective, program, scene, uniform_i


def mipmapped_texture(unit, size, texel):
    """A size x size texture with every level given (texel(level, x, y, n)
    gives each level's RGBA, n its size), LINEAR_MIPMAP_LINEAR, repeat."""
    GL.glActiveTexture(GL.GL_TEXTURE0 + unit)
    t = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, t)
    level = 0
    while size >= 1:
        data = bytearray()
        for y in range(size):
            for x in range(size):
                data += bytes(texel(level, x, y, size))
        GL.glTexImage2D(GL.GL_TEXTURE_2D, level, GL.GL_RGBA, size, size, 0, GL.GL_RGBA,
                        GL.GL_UNSIGNED_BYTE, bytes(data))
        size //= 2
        level += 1
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_REPEAT)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_REPEAT)
    GL.glActiveTexture(GL.GL_TEXTURE0)


def smooth(c0, c1, cells):
    """harness.pattern_texture's smooth pattern, the same at every level."""
    def texel(level, x, y, n):
        k = 0.5 + 0.25 * (math.sin(2 * math.pi * cells * (x + 0.5) / n)
                          + math.cos(2 * math.pi * cells * (y + 0.5) / n))
        return [int(round(a + (b - a) * k)) for a, b in zip(c0, c1)]
    return texel


def receding_quad(scales):
    """A quad tilted away from the viewer, texture coordinate set i spanning
    scales[i] repeats across and down it."""
    perspective(0.5, 0.5, 20.0)
    GL.glTranslatef(0.0, -0.3, -2.5)
    GL.glRotatef(-70.0, 1.0, 0.0, 0.0)
    GL.glBegin(GL.GL_QUADS)
    for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        GL.glColor4f(0.9, 0.9, 0.9, 1.0)
        for unit, (su, sv) in enumerate(scales):
            GL.glMultiTexCoord2f(GL.GL_TEXTURE0 + unit, su * (x + 1), sv * (y + 1))
        GL.glVertex3f(1.5 * x, 3.0 * y, 0.0)
    GL.glEnd()


@scene("lod_level_weights", 96, 96)
def lod_level_weights(log):
    """Flat levels alternately black and white: each pixel is the weight
    of the coarser of the two levels its λ blends, so the image is the
    fraction of λ across the receding quad."""
    p = program([lib("texturing.vert")], [lib("single-texture.frag"), lib("texturing-lib.frag")])
    GL.glClearColor(0.1, 0.1, 0.1, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    mipmapped_texture(0, 64, lambda level, x, y, n: [255 * (level % 2)] * 3 + [255])
    uniform_i(p, "TexUnit0", 0)
    uniform_i(p, "TexturingType", 0)  # replace
    receding_quad([(4.0, 6.0)])


@scene("texture_two_mipmapped", 96, 96)
def texture_two_mipmapped(log):
    """Two mipmapped smooth patterns on the receding quad, combined by the
    multi-texture library shader (modulate, then add)."""
    p = program([lib("texturing.vert")], [lib("multi-texture.frag"), lib("texturing-lib.frag")])
    GL.glClearColor(0.1, 0.1, 0.1, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    mipmapped_texture(0, 64, smooth((250, 40, 20, 255), (30, 200, 240, 90), 4))
    mipmapped_texture(1, 32, smooth((20, 20, 20, 255), (200, 220, 60, 160), 3))
    uniform_i(p, "TexUnit0", 0)
    uniform_i(p, "TexUnit1", 1)
    uniform_i(p, "TexturingType0", 1)  # modulate
    uniform_i(p, "TexturingType1", 4)  # add
    receding_quad([(4.0, 6.0), (3.0, 5.0)])


if __name__ == "__main__":
    sys.exit(main())
