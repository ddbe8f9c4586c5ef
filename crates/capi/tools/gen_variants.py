#!/usr/bin/env python3
"""Generates crates/capi/src/variants.rs: the gl* entry points that differ
only in the type and number of their arguments (glVertex2s ... glColor4ubv),
from the table FAMILIES below.

Usage: python3 tools/gen_variants.py > src/variants.rs
(tests/variants_generated.rs checks that the checked-in file is this
script's output.)

Each family is one GL command taking 1-4 components (GL 2.1 §2.7). A
variant converts its C arguments to float and calls the family's
gl::Context method with the missing components filled in from the
family's defaults ((x, y, 0, 1) for positions and texture coordinates,
alpha 1 for colors). The conversion is GL's:
- "plain": the value as a float (positions, texture coordinates, raster
  positions, unnormalized generic attributes, the color index);
- "norm": integers map to [-1, 1] or [0, 1] (GL 2.1 Table 2.9): signed
  (2c + 1) / (2^b - 1), unsigned c / (2^b - 1); floats stay as they are
  (colors, normals, glVertexAttrib4N*);
- "int", "uint": integers stay integers, widened to 32 bits (signed types
  sign-extended), for the glVertexAttribI* forms (GL 3.3 §2.7), whose
  methods take the four integers.

The scalar forms are compiled into display lists as a re-issue of the
same call ([list]); the vector forms (suffix v) read their components at
the call and, while a list is being compiled, record a re-issue with a
copy of them (GL 2.1 §5.4: a list keeps values, not the caller's
pointer).
"""

# suffix: (C type, Rust type, largest magnitude for "norm", signed)
TYPES = {
    "b": ("GLbyte", "i8", "255.0", True),
    "s": ("GLshort", "i16", "65535.0", True),
    "i": ("GLint", "i32", "4294967295.0", True),
    "f": ("GLfloat", "f32", None, None),
    "d": ("GLdouble", "f64", None, None),
    "ub": ("GLubyte", "u8", "255.0", False),
    "us": ("GLushort", "u16", "65535.0", False),
    "ui": ("GLuint", "u32", "4294967295.0", False),
}

COMPONENTS = ["x", "y", "z", "w"]


class Family:
    """One command's variants.

    base: the name before the size digit; sizes: the component counts
    (None: the name has no digit, one component); types: the type
    suffixes; conv: "plain" or "norm"; call: the gl::Context method and
    its defaults for the components a variant leaves out (its length is
    the method's component count); lead: arguments before the components;
    vector_only / scalar_only: (size, type) pairs with only that form;
    infix: between the size and the type ("N" for glVertexAttrib4N*);
    spec: the section the family's comment cites.
    """

    def __init__(self, base, sizes, types, conv, call, defaults, spec, lead=(),
                 forms=None, infix=""):
        self.base, self.sizes, self.types = base, sizes, types.split()
        self.conv, self.call, self.defaults = conv, call, defaults
        self.spec, self.lead, self.infix = spec, list(lead), infix
        # (size, type) -> "sv": which forms exist (scalar, vector).
        self.forms = forms or {}

    def variants(self):
        for size in self.sizes:
            for t in self.types:
                forms = self.forms.get((size, t), "sv")
                name = f"{self.base}{size or ''}{self.infix}{t}"
                yield name, size or 1, t, forms


DEFAULT_4 = ["0.0", "0.0", "0.0", "1.0"]

FAMILIES = [
    Family("glVertex", [2, 3, 4], "s i f d", "plain", "c.gl.vertex_4f({})", DEFAULT_4,
           "GL 2.1 §2.7: a vertex; (x, y, 0, 1) for two components"),
    Family("glColor", [3, 4], "b s i f d ub us ui", "norm", "c.gl.color_4f({})",
           DEFAULT_4, "GL 2.1 §2.7: the current color, integers normalized (Table 2.9)"),
    Family("glSecondaryColor", [3], "b s i f d ub us ui", "norm",
           "c.gl.secondary_color_3f({})", ["0.0"] * 3,
           "GL 2.1 §2.7: the current secondary color, integers normalized"),
    Family("glNormal", [3], "b s i f d", "norm", "c.gl.normal_3f({})", ["0.0"] * 3,
           "GL 2.1 §2.7: the current normal, integers normalized"),
    Family("glFogCoord", [None], "f d", "plain", "c.gl.fog_coordf({})", ["0.0"],
           "GL 2.1 §2.7: the current fog coordinate"),
    Family("glTexCoord", [1, 2, 3, 4], "s i f d", "plain", "c.gl.tex_coord_4f({})",
           DEFAULT_4, "GL 2.1 §2.7: texture unit 0's current coordinates"),
    Family("glMultiTexCoord", [1, 2, 3, 4], "s i f d", "plain",
           "c.gl.multi_tex_coord_4f(target, {})", DEFAULT_4,
           "GL 2.1 §2.7: a texture unit's current coordinates",
           lead=[("target", "GLenum")]),
    Family("glVertexAttrib", [1, 2, 3, 4], "s f d", "plain",
           "c.gl.vertex_attrib_4f(index, {})", DEFAULT_4,
           "GL 2.1 §2.7: a generic attribute's current value (index 0: a vertex)",
           lead=[("index", "GLuint")]),
    Family("glVertexAttrib", [4], "b i ub us ui", "plain",
           "c.gl.vertex_attrib_4f(index, {})", DEFAULT_4,
           "GL 2.1 §2.7: the integer forms are not normalized",
           lead=[("index", "GLuint")],
           forms={(4, t): "v" for t in ["b", "i", "ub", "us", "ui"]}),
    Family("glVertexAttrib", [4], "b s i ub us ui", "norm",
           "c.gl.vertex_attrib_4f(index, {})", DEFAULT_4,
           "GL 2.1 §2.7: the N forms normalize (Table 2.9)",
           lead=[("index", "GLuint")], infix="N",
           forms={(4, t): "sv" if t == "ub" else "v" for t in ["b", "s", "i", "ub", "us", "ui"]}),
    Family("glVertexAttribI", [1, 2, 3, 4], "i", "int",
           "c.gl.vertex_attrib_i4i(index, [{}])", ["0", "0", "0", "1"],
           "GL 3.3 §2.7: a generic attribute's current value as signed integers",
           lead=[("index", "GLuint")]),
    Family("glVertexAttribI", [1, 2, 3, 4], "ui", "uint",
           "c.gl.vertex_attrib_i4ui(index, [{}])", ["0", "0", "0", "1"],
           "GL 3.3 §2.7: a generic attribute's current value as unsigned integers",
           lead=[("index", "GLuint")]),
    Family("glVertexAttribI", [4], "b s", "int",
           "c.gl.vertex_attrib_i4i(index, [{}])", ["0", "0", "0", "1"],
           "GL 3.3 §2.7: the narrow signed forms, sign-extended",
           lead=[("index", "GLuint")], forms={(4, t): "v" for t in ["b", "s"]}),
    Family("glVertexAttribI", [4], "ub us", "uint",
           "c.gl.vertex_attrib_i4ui(index, [{}])", ["0", "0", "0", "1"],
           "GL 3.3 §2.7: the narrow unsigned forms",
           lead=[("index", "GLuint")], forms={(4, t): "v" for t in ["ub", "us"]}),
    Family("glRasterPos", [2, 3, 4], "s i f d", "plain", "c.gl.raster_pos_4f({})", DEFAULT_4,
           "GL 2.1 §2.13: the raster position, transformed as a vertex"),
    Family("glWindowPos", [2, 3], "s i f d", "plain", "c.gl.window_pos_3f({})",
           ["0.0"] * 3, "GL 2.1 §2.13: the raster position in window coordinates"),
    Family("glIndex", [None], "s i f d ub", "plain", "c.legacy.current_index = {}",
           ["0.0"], "GL 2.1 §2.7: the color index, kept as state (RGBA contexts)"),
]


def convert(family, t, x):
    ctype, rtype, top, signed = TYPES[t]
    if family.conv == "int":
        return f"{x} as i32"
    if family.conv == "uint":
        return f"{x} as u32"
    if family.conv == "norm" and top is not None:
        return f"snorm({x} as f64, {top})" if signed else f"unorm({x} as f64, {top})"
    return f"{x} as f32"


def call(family, size, t):
    comps = [convert(family, t, COMPONENTS[i]) for i in range(size)]
    return family.call.format(", ".join(comps + family.defaults[size:]))


def lead_params(family):
    return [f"{a}: {ty}" for a, ty in family.lead]


def scalar(family, name, size, t):
    params = lead_params(family) + [f"{x}: {TYPES[t][0]}" for x in COMPONENTS[:size]]
    return f"    [list] fn {name}({', '.join(params)}) => |c| {{ {call(family, size, t)} }}\n"


def vector(family, name, size, t):
    ctype, rtype = TYPES[t][:2]
    params = lead_params(family) + [f"v: *const {ctype}"]
    lead = "".join(f"{a}, " for a, _ in family.lead)
    comps = ", ".join(COMPONENTS[:size])
    return (
        f"    fn {name}v({', '.join(params)}) => |c| {{ vector_call::<{size}, {rtype}>(c, v, "
        f"move |p| unsafe {{ {name}v({lead}p) }}, |c, [{comps}]| {call(family, size, t)}) }}\n"
    )


def rects():
    """glRect{s,i,f,d}[v] (GL 2.1 §2.10): the vector forms take two
    corners; while compiling they record glRectf with the converted
    corners (`rect_vector`, in RECT_HELPERS)."""
    out = "    // GL 2.1 §2.10: a rectangle as a polygon; the vector forms take two corners.\n"
    for t in "s i f d".split():
        ctype, rtype = TYPES[t][:2]
        corners = ["x1", "y1", "x2", "y2"]
        params = ", ".join(f"{x}: {ctype}" for x in corners)
        conv = ", ".join(f"{x} as f32" for x in corners)
        out += (
            f"    [list] fn glRect{t}({params}) => |c| {{ rect(c, [{conv}]) }}\n"
            f"    fn glRect{t}v(v1: *const {ctype}, v2: *const {ctype}) => |c| {{\n"
            f"        if let (Some([x1, y1]), Some([x2, y2])) = (rd::<2, {rtype}>(v1), rd::<2, {rtype}>(v2)) {{\n"
            f"            rect_vector(c, [{conv}]);\n"
            f"        }}\n"
            f"    }}\n"
        )
    return out


RECT_HELPERS = '''
/// glRect's body: the rectangle drawn as a polygon (GL 2.1 §2.10).
fn rect(c: &mut OsContext, [x1, y1, x2, y2]: [f32; 4]) {
    c.gl.rectf(x1, y1, x2, y2);
    c.dirty = true;
}

/// glRect*v's body: inside glNewList the corners read now are recorded as
/// glRectf (a list keeps values, not the caller's pointers); else drawn.
fn rect_vector(c: &mut OsContext, corners: [f32; 4]) {
    let [x1, y1, x2, y2] = corners;
    // SAFETY: glRectf reads only its arguments.
    if c.record(move || unsafe { glRectf(x1, y1, x2, y2) }) {
        return;
    }
    rect(c, corners);
}
'''


HEADER = '''\
//! The gl* entry points that differ only in the type and number of their
//! arguments: glVertex*, glColor*, glSecondaryColor*, glNormal*,
//! glFogCoord*, glTexCoord*, glMultiTexCoord*, glVertexAttrib*,
//! glVertexAttribI*, glRasterPos*, glWindowPos*, glIndex* and glRect*.
//!
//! Generated by `tools/gen_variants.py` from its table of families (the
//! conversion rules are described there); do not edit —
//! `tests/variants_generated.rs` fails when this file and the script
//! disagree. A script rather than a `macro_rules!` table because each
//! variant needs its own name (glColor3ubv), which `macro_rules!` cannot
//! build from parts, and because the output stays plain, greppable code.

use crate::abi::*;
use crate::context::{record_call, vector_call, with_ctx, OsContext};
'''


def main():
    out = [HEADER, "\ngl_entry_points! {\n"]
    first = True
    for family in FAMILIES:
        if not first:
            out.append("\n")
        first = False
        out.append(f"    // {family.spec}.\n")
        for name, size, t, forms in family.variants():
            if "s" in forms:
                out.append(scalar(family, name, size, t))
            if "v" in forms:
                out.append(vector(family, name, size, t))
    out.append("\n")
    out.append(rects())
    out.append("}\n")
    out.append(RECT_HELPERS)
    print("".join(out), end="")


if __name__ == "__main__":
    main()
