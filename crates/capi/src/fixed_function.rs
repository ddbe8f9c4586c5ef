//! The fixed-function pipeline's parameters and their queries: texture
//! coordinate generation (GL 2.1 §2.11.4), lighting and materials
//! (§2.14), the texture environment (§3.8.13) and fog (§3.10). The vector
//! setters read as many values as their pname takes; while a list is being
//! compiled they record a copy of them (§5.4).

use crate::abi::*;
use crate::context::{record_call, with_ctx};
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

gl_entry_points! {
    // ---- lighting ----
    [list] fn glShadeModel(mode: GLenum) => |c| { c.gl.shade_model(mode) }
    [list] fn glLightf(light: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.light(light, pname, Param::F(v)) }
    [list] fn glLighti(light: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.light(light, pname, Param::I(v)) }
    fn glLightfv(light: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
            GL_SPOT_DIRECTION => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightfv(light, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light(light, pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glLightiv(light: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
            GL_SPOT_DIRECTION => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightiv(light, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light(light, pname, Param::Iv(&rd_vec(v, n))) }
    }
    [list] fn glMaterialf(face: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.material(face, pname, Param::F(v)) }
    [list] fn glMateriali(face: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.material(face, pname, Param::I(v)) }
    fn glMaterialfv(face: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
            GL_COLOR_INDEXES => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glMaterialfv(face, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.material(face, pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glMaterialiv(face: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
            GL_COLOR_INDEXES => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glMaterialiv(face, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.material(face, pname, Param::Iv(&rd_vec(v, n))) }
    }
    [list] fn glColorMaterial(face: GLenum, mode: GLenum) => |c| { c.gl.color_material(face, mode) }
    [list] fn glLightModelf(pname: GLenum, v: GLfloat) => |c| { c.gl.light_model(pname, Param::F(v)) }
    [list] fn glLightModeli(pname: GLenum, v: GLint) => |c| { c.gl.light_model(pname, Param::I(v)) }
    fn glLightModelfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_LIGHT_MODEL_AMBIENT { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightModelfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light_model(pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glLightModeliv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_LIGHT_MODEL_AMBIENT { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightModeliv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light_model(pname, Param::Iv(&rd_vec(v, n))) }
    }
    fn glGetLightfv(light: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_lightfv(light, pname);
        wr(v, &r);
    }
    fn glGetLightiv(light: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR);
        let r: Vec<GLint> = c.gl.get_lightfv(light, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }
    fn glGetMaterialfv(face: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_materialfv(face, pname);
        wr(v, &r);
    }
    fn glGetMaterialiv(face: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION);
        let r: Vec<GLint> = c.gl.get_materialfv(face, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }

    // ---- texture coordinate generation ----
    [list] fn glTexGeni(coord: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_gen(coord, pname, Param::I(v)) }
    [list] fn glTexGenf(coord: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_gen(coord, pname, Param::F(v)) }
    [list] fn glTexGend(coord: GLenum, pname: GLenum, v: GLdouble) => |c| { c.gl.tex_gen(coord, pname, Param::F(v as f32)) }
    fn glTexGenfv(coord: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGenfv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_gen(coord, pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glTexGendv(coord: GLenum, pname: GLenum, v: *const GLdouble) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGendv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() {
            let f: Vec<f32> = rd_vec(v, n).iter().map(|&x| x as f32).collect();
            c.gl.tex_gen(coord, pname, Param::Fv(&f))
        }
    }
    fn glTexGeniv(coord: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGeniv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() {
            let f: Vec<f32> = rd_vec(v, n).iter().map(|&x| x as f32).collect();
            c.gl.tex_gen(coord, pname, Param::Fv(&f))
        }
    }
    fn glGetTexGenfv(coord: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_genfv(coord, pname);
        wr(v, &r);
    }
    fn glGetTexGendv(coord: GLenum, pname: GLenum, v: *mut GLdouble) => |c| {
        let r: Vec<f64> = c.gl.get_tex_genfv(coord, pname).iter().map(|&x| x as f64).collect();
        wr(v, &r);
    }
    fn glGetTexGeniv(coord: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = c.gl.get_tex_genfv(coord, pname).iter().map(|&x| to_int(x, false)).collect();
        wr(v, &r);
    }

    // ---- texture environment ----
    [list] fn glTexEnvi(target: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_env(target, pname, Param::I(v)) }
    [list] fn glTexEnvf(target: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_env(target, pname, Param::F(v)) }
    fn glTexEnvfv(target: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexEnvfv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_env(target, pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glTexEnviv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexEnviv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_env(target, pname, Param::Iv(&rd_vec(v, n))) }
    }
    fn glGetTexEnvfv(target: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_envfv(target, pname);
        wr(v, &r);
    }
    fn glGetTexEnviv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = pname == GL_TEXTURE_ENV_COLOR;
        let r: Vec<GLint> = c.gl.get_tex_envfv(target, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }

    // ---- fog ----
    [list] fn glFogf(pname: GLenum, v: GLfloat) => |c| { c.gl.fog(pname, Param::F(v)) }
    [list] fn glFogi(pname: GLenum, v: GLint) => |c| { c.gl.fog(pname, Param::I(v)) }
    fn glFogfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_FOG_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glFogfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.fog(pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glFogiv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_FOG_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glFogiv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.fog(pname, Param::Iv(&rd_vec(v, n))) }
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
