"""OpenGL 2.1 and 3.3 enum values the package uses (numbers from the specs' tables)."""

# Errors.
NO_ERROR = 0
ERROR_NAMES = {
    0x0500: "GL_INVALID_ENUM",
    0x0501: "GL_INVALID_VALUE",
    0x0502: "GL_INVALID_OPERATION",
    0x0503: "GL_STACK_OVERFLOW",
    0x0504: "GL_STACK_UNDERFLOW",
    0x0505: "GL_OUT_OF_MEMORY",
    0x0506: "GL_INVALID_FRAMEBUFFER_OPERATION",
}

# Primitive modes.
MODES = {
    "points": 0x0000,
    "lines": 0x0001,
    "line_loop": 0x0002,
    "line_strip": 0x0003,
    "triangles": 0x0004,
    "triangle_strip": 0x0005,
    "triangle_fan": 0x0006,
    "quads": 0x0007,
    "quad_strip": 0x0008,
    "polygon": 0x0009,
    "lines_adjacency": 0x000A,
    "line_strip_adjacency": 0x000B,
    "triangles_adjacency": 0x000C,
    "triangle_strip_adjacency": 0x000D,
}

# Data types.
BYTE = 0x1400
UNSIGNED_BYTE = 0x1401
SHORT = 0x1402
UNSIGNED_SHORT = 0x1403
INT = 0x1404
UNSIGNED_INT = 0x1405
FLOAT = 0x1406
DOUBLE = 0x140A

# Clear bits.
COLOR_BUFFER_BIT = 0x4000
DEPTH_BUFFER_BIT = 0x0100
STENCIL_BUFFER_BIT = 0x0400

# Capabilities.
CAPS = {
    "depth_test": 0x0B71,
    "blend": 0x0BE2,
    "cull_face": 0x0B44,
    "lighting": 0x0B50,
    "fog": 0x0B60,
    "texture_2d": 0x0DE1,
    "alpha_test": 0x0BC0,
    "normalize": 0x0BA1,
    "point_sprite": 0x8861,
    "vertex_program_point_size": 0x8642,
    "color_material": 0x0B57,
    "scissor_test": 0x0C11,
    "stencil_test": 0x0B90,
}
LIGHT0 = 0x4000

# Depth functions.
DEPTH_FUNCS = {
    "never": 0x0200,
    "<": 0x0201,
    "less": 0x0201,
    "==": 0x0202,
    "equal": 0x0202,
    "<=": 0x0203,
    "lequal": 0x0203,
    ">": 0x0204,
    "greater": 0x0204,
    "!=": 0x0205,
    "notequal": 0x0205,
    ">=": 0x0206,
    "gequal": 0x0206,
    "always": 0x0207,
}

# Blend factors.
BLEND_FACTORS = {
    "zero": 0,
    "one": 1,
    "src_color": 0x0300,
    "one_minus_src_color": 0x0301,
    "src_alpha": 0x0302,
    "one_minus_src_alpha": 0x0303,
    "dst_alpha": 0x0304,
    "one_minus_dst_alpha": 0x0305,
    "dst_color": 0x0306,
    "one_minus_dst_color": 0x0307,
}

CULL_FACES = {"front": 0x0404, "back": 0x0405, "front_and_back": 0x0408}

# Lights and materials.
FRONT = 0x0404
BACK = 0x0405
FRONT_AND_BACK = 0x0408
AMBIENT = 0x1200
DIFFUSE = 0x1201
SPECULAR = 0x1202
POSITION = 0x1203
SPOT_DIRECTION = 0x1204
SPOT_EXPONENT = 0x1205
SPOT_CUTOFF = 0x1206
CONSTANT_ATTENUATION = 0x1207
LINEAR_ATTENUATION = 0x1208
QUADRATIC_ATTENUATION = 0x1209
EMISSION = 0x1600
SHININESS = 0x1601
LIGHT_MODEL_AMBIENT = 0x0B53

# Fog.
FOG_DENSITY = 0x0B62
FOG_START = 0x0B63
FOG_END = 0x0B64
FOG_MODE = 0x0B65
FOG_COLOR = 0x0B66
FOG_MODES = {"linear": 0x2601, "exp": 0x0800, "exp2": 0x0801}

# Matrices.
MODELVIEW = 0x1700
PROJECTION = 0x1701
MODELVIEW_MATRIX = 0x0BA6
PROJECTION_MATRIX = 0x0BA7
VIEWPORT = 0x0BA2

# Textures.
ALPHA = 0x1906
RGB = 0x1907
RGBA = 0x1908
LUMINANCE = 0x1909
LUMINANCE_ALPHA = 0x190A
RGBA32F = 0x8814
RGB32F = 0x8815
ALPHA32F = 0x8816
LUMINANCE32F = 0x8818
LUMINANCE_ALPHA32F = 0x8819
TEXTURE_MAG_FILTER = 0x2800
TEXTURE_MIN_FILTER = 0x2801
TEXTURE_WRAP_S = 0x2802
TEXTURE_WRAP_T = 0x2803
NEAREST = 0x2600
LINEAR = 0x2601
NEAREST_MIPMAP_NEAREST = 0x2700
LINEAR_MIPMAP_LINEAR = 0x2703
WRAPS = {
    "repeat": 0x2901,
    "clamp": 0x812F,  # GL_CLAMP_TO_EDGE
    "clamp_to_edge": 0x812F,
    "mirrored_repeat": 0x8370,
}

# Uniform and attribute types: GL enum -> (GLSL name, scalar kind, shape).
# Shapes are numpy's: a matCxR (C columns, R rows) is (R, C).
TYPES = {
    0x1406: ("float", "float", ()),
    0x8B50: ("vec2", "float", (2,)),
    0x8B51: ("vec3", "float", (3,)),
    0x8B52: ("vec4", "float", (4,)),
    0x1404: ("int", "int", ()),
    0x8B53: ("ivec2", "int", (2,)),
    0x8B54: ("ivec3", "int", (3,)),
    0x8B55: ("ivec4", "int", (4,)),
    0x8B56: ("bool", "bool", ()),
    0x8B57: ("bvec2", "bool", (2,)),
    0x8B58: ("bvec3", "bool", (3,)),
    0x8B59: ("bvec4", "bool", (4,)),
    0x8B5A: ("mat2", "float", (2, 2)),
    0x8B5B: ("mat3", "float", (3, 3)),
    0x8B5C: ("mat4", "float", (4, 4)),
    0x8B65: ("mat2x3", "float", (3, 2)),
    0x8B66: ("mat2x4", "float", (4, 2)),
    0x8B67: ("mat3x2", "float", (2, 3)),
    0x8B68: ("mat3x4", "float", (4, 3)),
    0x8B69: ("mat4x2", "float", (2, 4)),
    0x8B6A: ("mat4x3", "float", (3, 4)),
    0x8B5D: ("sampler1D", "sampler", ()),
    0x8B5E: ("sampler2D", "sampler", ()),
    0x8B5F: ("sampler3D", "sampler", ()),
    0x8B60: ("samplerCube", "sampler", ()),
    0x8B61: ("sampler1DShadow", "sampler", ()),
    0x8B62: ("sampler2DShadow", "sampler", ()),
    # GL 3.0-3.3.
    0x1405: ("uint", "uint", ()),
    0x8DC6: ("uvec2", "uint", (2,)),
    0x8DC7: ("uvec3", "uint", (3,)),
    0x8DC8: ("uvec4", "uint", (4,)),
    0x8B63: ("sampler2DRect", "sampler", ()),
    0x8B64: ("sampler2DRectShadow", "sampler", ()),
    0x8DC0: ("sampler1DArray", "sampler", ()),
    0x8DC1: ("sampler2DArray", "sampler", ()),
    0x8DC2: ("samplerBuffer", "sampler", ()),
    0x8DC3: ("sampler1DArrayShadow", "sampler", ()),
    0x8DC4: ("sampler2DArrayShadow", "sampler", ()),
    0x8DC5: ("samplerCubeShadow", "sampler", ()),
    0x8DC9: ("isampler1D", "sampler", ()),
    0x8DCA: ("isampler2D", "sampler", ()),
    0x8DCB: ("isampler3D", "sampler", ()),
    0x8DCC: ("isamplerCube", "sampler", ()),
    0x8DCD: ("isampler2DRect", "sampler", ()),
    0x8DCE: ("isampler1DArray", "sampler", ()),
    0x8DCF: ("isampler2DArray", "sampler", ()),
    0x8DD0: ("isamplerBuffer", "sampler", ()),
    0x8DD1: ("usampler1D", "sampler", ()),
    0x8DD2: ("usampler2D", "sampler", ()),
    0x8DD3: ("usampler3D", "sampler", ()),
    0x8DD4: ("usamplerCube", "sampler", ()),
    0x8DD5: ("usampler2DRect", "sampler", ()),
    0x8DD6: ("usampler1DArray", "sampler", ()),
    0x8DD7: ("usampler2DArray", "sampler", ()),
    0x8DD8: ("usamplerBuffer", "sampler", ()),
    0x9108: ("sampler2DMS", "sampler", ()),
    0x9109: ("isampler2DMS", "sampler", ()),
    0x910A: ("usampler2DMS", "sampler", ()),
    0x910B: ("sampler2DMSArray", "sampler", ()),
    0x910C: ("isampler2DMSArray", "sampler", ()),
    0x910D: ("usampler2DMSArray", "sampler", ()),
}

# Uniform buffers (GL 3.1).
MAX_UNIFORM_BUFFER_BINDINGS = 0x8A2F
UNIFORM_BUFFER_OFFSET_ALIGNMENT = 0x8A34
# Per-render divisor of a "/r" vertex format: every instance reads element 0.
PER_RENDER_DIVISOR = 0x7FFFFFFF


def error_name(code: int) -> str:
    return ERROR_NAMES.get(code, f"GL error 0x{code:04x}")
