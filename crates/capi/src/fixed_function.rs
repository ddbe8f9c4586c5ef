//! The fixed-function pipeline's parameters and their queries: texture
//! coordinate generation (GL 2.1 §2.11.4), lighting and materials
//! (§2.14), the texture environment (§3.8.13) and fog (§3.10). The vector
//! setters read as many values as their pname takes; while a list is being
//! compiled they record a copy of them (§5.4).

use crate::abi::*;
use crate::context::{record_call, vector_call_n, with_ctx};
use gl::enums::*;
use gl::Param;

/// Integer form of a float query: colours (ranges [0, 1] or [-1, 1]) map
/// linearly to the integer range, the rest round (GL 2.1 §6.1.2).
fn to_int(v: f32, color: bool) -> i32 {
    if color {
        let x = (v as f64 * 2147483647.0).clamp(i32::MIN as f64, i32::MAX as f64);
        if x >= 0.0 {
            (x + 0.5).floor() as i32
        } else {
            (x - 0.5).ceil() as i32
        }
    } else {
        let x = (v as f64).clamp(i32::MIN as f64, i32::MAX as f64);
        (x + 0.5).floor() as i32
    }
}

/// Writes a float query's values at `v` in integer form ([`to_int`]).
unsafe fn wr_ints(v: *mut GLint, r: &[f32], color: bool) {
    let r: Vec<GLint> = r.iter().map(|&x| to_int(x, color)).collect();
    // SAFETY: GL's contract: the query's value count fits at v.
    unsafe { wr(v, &r) };
}

/// How many values glLight*v reads for `pname`.
fn light_len(pname: GLenum) -> i64 {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
        GL_SPOT_DIRECTION => 3,
        _ => 1,
    }
}

/// How many values glMaterial*v reads for `pname`.
fn material_len(pname: GLenum) -> i64 {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
        GL_COLOR_INDEXES => 3,
        _ => 1,
    }
}

/// How many values a vector setter reads: `wide` for the pname that takes
/// a colour, plane or other 4-vector, 1 for the rest.
fn len_if(pname: GLenum, wide: GLenum) -> i64 {
    if pname == wide {
        4
    } else {
        1
    }
}

/// How many values glTexGen*v reads for `pname`: the mode, or a plane's
/// four coefficients (GL 2.1 §2.11.4).
fn tex_gen_len(pname: GLenum) -> i64 {
    if pname == GL_TEXTURE_GEN_MODE {
        1
    } else {
        4
    }
}

/// The float form of glTexGendv/glTexGeniv's values.
fn to_f32<T: Copy + Into<f64>>(v: &[T]) -> Vec<f32> {
    v.iter().map(|&x| x.into() as f32).collect()
}

gl_entry_points! {
    // ---- lighting ----
    [list] fn glShadeModel(mode: GLenum) => |c| { c.gl.shade_model(mode) }
    [list] fn glProvokingVertex(mode: GLenum) => |c| { c.gl.provoking_vertex(mode) }
    [list] fn glProvokingVertexEXT(mode: GLenum) => |c| { c.gl.provoking_vertex(mode) }
    [list] fn glLightf(light: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.light(light, pname, Param::F(v)) }
    [list] fn glLighti(light: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.light(light, pname, Param::I(v)) }
    fn glLightfv(light: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, light_len(pname), move |p| unsafe { glLightfv(light, pname, p) }, |c, a| c.gl.light(light, pname, Param::Fv(a)))
    }
    fn glLightiv(light: GLenum, pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, light_len(pname), move |p| unsafe { glLightiv(light, pname, p) }, |c, a| c.gl.light(light, pname, Param::Iv(a)))
    }
    [list] fn glMaterialf(face: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.material(face, pname, Param::F(v)) }
    [list] fn glMateriali(face: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.material(face, pname, Param::I(v)) }
    fn glMaterialfv(face: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, material_len(pname), move |p| unsafe { glMaterialfv(face, pname, p) }, |c, a| c.gl.material(face, pname, Param::Fv(a)))
    }
    fn glMaterialiv(face: GLenum, pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, material_len(pname), move |p| unsafe { glMaterialiv(face, pname, p) }, |c, a| c.gl.material(face, pname, Param::Iv(a)))
    }
    [list] fn glColorMaterial(face: GLenum, mode: GLenum) => |c| { c.gl.color_material(face, mode) }
    [list] fn glLightModelf(pname: GLenum, v: GLfloat) => |c| { c.gl.light_model(pname, Param::F(v)) }
    [list] fn glLightModeli(pname: GLenum, v: GLint) => |c| { c.gl.light_model(pname, Param::I(v)) }
    fn glLightModelfv(pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, len_if(pname, GL_LIGHT_MODEL_AMBIENT), move |p| unsafe { glLightModelfv(pname, p) }, |c, a| c.gl.light_model(pname, Param::Fv(a)))
    }
    fn glLightModeliv(pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, len_if(pname, GL_LIGHT_MODEL_AMBIENT), move |p| unsafe { glLightModeliv(pname, p) }, |c, a| c.gl.light_model(pname, Param::Iv(a)))
    }
    fn glGetLightfv(light: GLenum, pname: GLenum, v: *mut GLfloat) => |c| { wr(v, &c.gl.get_lightfv(light, pname)) }
    fn glGetLightiv(light: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        wr_ints(v, &c.gl.get_lightfv(light, pname), matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR))
    }
    fn glGetMaterialfv(face: GLenum, pname: GLenum, v: *mut GLfloat) => |c| { wr(v, &c.gl.get_materialfv(face, pname)) }
    fn glGetMaterialiv(face: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        wr_ints(v, &c.gl.get_materialfv(face, pname), matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION))
    }

    // ---- texture coordinate generation ----
    [list] fn glTexGeni(coord: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_gen(coord, pname, Param::I(v)) }
    [list] fn glTexGenf(coord: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_gen(coord, pname, Param::F(v)) }
    [list] fn glTexGend(coord: GLenum, pname: GLenum, v: GLdouble) => |c| { c.gl.tex_gen(coord, pname, Param::F(v as f32)) }
    fn glTexGenfv(coord: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, tex_gen_len(pname), move |p| unsafe { glTexGenfv(coord, pname, p) }, |c, a| c.gl.tex_gen(coord, pname, Param::Fv(a)))
    }
    fn glTexGendv(coord: GLenum, pname: GLenum, v: *const GLdouble) => |c| {
        vector_call_n(c, v, tex_gen_len(pname), move |p| unsafe { glTexGendv(coord, pname, p) }, |c, a| c.gl.tex_gen(coord, pname, Param::Fv(&to_f32(a))))
    }
    fn glTexGeniv(coord: GLenum, pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, tex_gen_len(pname), move |p| unsafe { glTexGeniv(coord, pname, p) }, |c, a| c.gl.tex_gen(coord, pname, Param::Fv(&to_f32(a))))
    }
    fn glGetTexGenfv(coord: GLenum, pname: GLenum, v: *mut GLfloat) => |c| { wr(v, &c.gl.get_tex_genfv(coord, pname)) }
    fn glGetTexGendv(coord: GLenum, pname: GLenum, v: *mut GLdouble) => |c| {
        let r: Vec<f64> = c.gl.get_tex_genfv(coord, pname).iter().map(|&x| x as f64).collect();
        wr(v, &r);
    }
    fn glGetTexGeniv(coord: GLenum, pname: GLenum, v: *mut GLint) => |c| { wr_ints(v, &c.gl.get_tex_genfv(coord, pname), false) }

    // ---- texture environment ----
    [list] fn glTexEnvi(target: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_env(target, pname, Param::I(v)) }
    [list] fn glTexEnvf(target: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_env(target, pname, Param::F(v)) }
    fn glTexEnvfv(target: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, len_if(pname, GL_TEXTURE_ENV_COLOR), move |p| unsafe { glTexEnvfv(target, pname, p) }, |c, a| c.gl.tex_env(target, pname, Param::Fv(a)))
    }
    fn glTexEnviv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, len_if(pname, GL_TEXTURE_ENV_COLOR), move |p| unsafe { glTexEnviv(target, pname, p) }, |c, a| c.gl.tex_env(target, pname, Param::Iv(a)))
    }
    fn glGetTexEnvfv(target: GLenum, pname: GLenum, v: *mut GLfloat) => |c| { wr(v, &c.gl.get_tex_envfv(target, pname)) }
    fn glGetTexEnviv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        wr_ints(v, &c.gl.get_tex_envfv(target, pname), pname == GL_TEXTURE_ENV_COLOR)
    }

    // ---- fog ----
    [list] fn glFogf(pname: GLenum, v: GLfloat) => |c| { c.gl.fog(pname, Param::F(v)) }
    [list] fn glFogi(pname: GLenum, v: GLint) => |c| { c.gl.fog(pname, Param::I(v)) }
    fn glFogfv(pname: GLenum, v: *const GLfloat) => |c| {
        vector_call_n(c, v, len_if(pname, GL_FOG_COLOR), move |p| unsafe { glFogfv(pname, p) }, |c, a| c.gl.fog(pname, Param::Fv(a)))
    }
    fn glFogiv(pname: GLenum, v: *const GLint) => |c| {
        vector_call_n(c, v, len_if(pname, GL_FOG_COLOR), move |p| unsafe { glFogiv(pname, p) }, |c, a| c.gl.fog(pname, Param::Iv(a)))
    }
}

#[cfg(test)]
mod tests {
    use super::to_int;

    #[test]
    fn colors_map_to_the_full_integer_range() {
        assert_eq!(to_int(1.0, true), i32::MAX);
        assert_eq!(to_int(-1.0, true), -i32::MAX);
        assert_eq!(to_int(0.0, true), 0);
        assert_eq!(to_int(2.6, false), 3);
        assert_eq!(to_int(f32::NAN, false), 0);
    }
}
