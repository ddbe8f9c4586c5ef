//! Fixed-function shading parameters, the state the generated stages
//! ([`crate::ffgen`]) read: lights, materials and the light model
//! (GL 2.1 §2.14), glColorMaterial tracking, fog (§3.10), the texture
//! environment (§3.8.13), texture coordinate generation (§2.11.4) and the
//! active texture unit.
//!
//! Contract: light positions and spot directions are transformed to eye
//! coordinates by the modelview matrix when set (Table 6.9); each call
//! family (glLight{f,i,fv,iv}...) is one method over a [`Param`], which
//! maps integer colors linearly to [-1, 1] (Table 2.9); a scalar form of
//! a parameter of several values is GL_INVALID_ENUM for lights,
//! materials, the light model and fog, and GL_INVALID_VALUE (too few
//! values) for the texture environment and coordinate generation.

use crate::enums::*;
use crate::matrix;
use crate::param::Param;
use crate::state::clamp01;
use crate::{Context, MAX_LIGHTS, MAX_TEXTURE_UNITS};

/// The number of values a light/material/fog/light-model parameter takes.
fn light_param_len(pname: u32) -> usize {
    match pname {
        GL_AMBIENT
        | GL_DIFFUSE
        | GL_SPECULAR
        | GL_POSITION
        | GL_EMISSION
        | GL_AMBIENT_AND_DIFFUSE
        | GL_LIGHT_MODEL_AMBIENT
        | GL_FOG_COLOR => 4,
        GL_SPOT_DIRECTION | GL_COLOR_INDEXES => 3,
        _ => 1,
    }
}

impl Context {
    /// The values of a light, material, light-model or fog call as an enum
    /// and as floats, or `None` with the error recorded. The checks run in
    /// this order: a scalar form of a parameter of several values is
    /// GL_INVALID_ENUM; a call between glBegin and glEnd is
    /// GL_INVALID_OPERATION unless `in_begin_ok` (glMaterial); an unknown
    /// light or face (`object_ok` false) is GL_INVALID_ENUM; too few values
    /// is GL_INVALID_VALUE.
    fn lighting_values(
        &mut self,
        pname: u32,
        v: Param,
        object_ok: bool,
        in_begin_ok: bool,
    ) -> Option<(u32, Vec<f32>)> {
        if v.is_scalar() && light_param_len(pname) != 1 {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        if !in_begin_ok && self.reject_in_begin() {
            return None;
        }
        if !object_ok {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let f = v.floats(pname);
        if f.len() < light_param_len(pname) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some((v.as_enum(), f))
    }

    /// glLight{f,i,fv,iv}. GL_POSITION is transformed by the model-view
    /// matrix, GL_SPOT_DIRECTION by its upper 3x3 (GL 2.1 §2.14.2).
    pub fn light(&mut self, light: u32, pname: u32, v: Param) {
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        let Some((_, v)) = self.lighting_values(pname, v, i < MAX_LIGHTS, false) else {
            return;
        };
        let mv = self.modelview_matrix();
        let l = &mut self.st.lights[i];
        let v4 = || [v[0], v[1], v[2], v[3]];
        match pname {
            GL_AMBIENT => l.ambient = v4(),
            GL_DIFFUSE => l.diffuse = v4(),
            GL_SPECULAR => l.specular = v4(),
            GL_POSITION => l.position = matrix::mul_vec(&mv, v4()),
            GL_SPOT_DIRECTION => {
                let d = matrix::mul_vec(&mv, [v[0], v[1], v[2], 0.0]);
                l.spot_direction = [d[0], d[1], d[2]];
            }
            GL_SPOT_EXPONENT => {
                if !(0.0..=128.0).contains(&v[0]) {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.spot_exponent = v[0];
                }
            }
            GL_SPOT_CUTOFF => {
                if !((0.0..=90.0).contains(&v[0]) || v[0] == 180.0) {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.spot_cutoff = v[0];
                }
            }
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                if v[0].is_nan() || v[0] < 0.0 {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.attenuation[(pname - GL_CONSTANT_ATTENUATION) as usize] = v[0];
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetLightfv (position and direction in eye coordinates).
    pub fn get_lightfv(&mut self, light: u32, pname: u32) -> Vec<f32> {
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        let Some(l) = self.st.lights.get(i) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        match pname {
            GL_AMBIENT => l.ambient.to_vec(),
            GL_DIFFUSE => l.diffuse.to_vec(),
            GL_SPECULAR => l.specular.to_vec(),
            GL_POSITION => l.position.to_vec(),
            GL_SPOT_DIRECTION => l.spot_direction.to_vec(),
            GL_SPOT_EXPONENT => vec![l.spot_exponent],
            GL_SPOT_CUTOFF => vec![l.spot_cutoff],
            GL_CONSTANT_ATTENUATION => vec![l.attenuation[0]],
            GL_LINEAR_ATTENUATION => vec![l.attenuation[1]],
            GL_QUADRATIC_ATTENUATION => vec![l.attenuation[2]],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glMaterial{f,i,fv,iv}.
    pub fn material(&mut self, face: u32, pname: u32, v: Param) {
        let faces = Self::faces(face).unwrap_or(&[]);
        let Some((_, v)) = self.lighting_values(pname, v, !faces.is_empty(), true) else {
            return;
        };
        let v4 = || [v[0], v[1], v[2], v[3]];
        if pname == GL_SHININESS && !(0.0..=128.0).contains(&v[0]) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        for &f in faces {
            let m = &mut self.st.material[f];
            match pname {
                GL_AMBIENT => m.ambient = v4(),
                GL_DIFFUSE => m.diffuse = v4(),
                GL_SPECULAR => m.specular = v4(),
                GL_EMISSION => m.emission = v4(),
                GL_AMBIENT_AND_DIFFUSE => {
                    m.ambient = v4();
                    m.diffuse = v4();
                }
                GL_SHININESS => m.shininess = v[0],
                GL_COLOR_INDEXES => {}
                _ => {
                    self.set_error(GL_INVALID_ENUM);
                    return;
                }
            }
        }
    }

    /// glGetMaterialfv.
    pub fn get_materialfv(&mut self, face: u32, pname: u32) -> Vec<f32> {
        let m = match face {
            GL_FRONT => self.st.material[0],
            GL_BACK => self.st.material[1],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return Vec::new();
            }
        };
        match pname {
            GL_AMBIENT => m.ambient.to_vec(),
            GL_DIFFUSE => m.diffuse.to_vec(),
            GL_SPECULAR => m.specular.to_vec(),
            GL_EMISSION => m.emission.to_vec(),
            GL_SHININESS => vec![m.shininess],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glColorMaterial.
    pub fn color_material(&mut self, face: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if Self::faces(face).is_none()
            || !matches!(
                mode,
                GL_EMISSION | GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_AMBIENT_AND_DIFFUSE
            )
        {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.color_material_face = face;
        self.st.color_material_mode = mode;
        if self.st.is_on(GL_COLOR_MATERIAL) {
            self.track_color_material();
        }
    }

    /// With GL_COLOR_MATERIAL on, the selected material colors follow the
    /// current color (GL 2.1 §2.14.3).
    pub(crate) fn track_color_material(&mut self) {
        if !self.st.is_on(GL_COLOR_MATERIAL) {
            return;
        }
        let c = self.va.current_color();
        let faces = Self::faces(self.st.color_material_face).unwrap_or(&[0, 1]);
        for &f in faces {
            let m = &mut self.st.material[f];
            match self.st.color_material_mode {
                GL_EMISSION => m.emission = c,
                GL_AMBIENT => m.ambient = c,
                GL_DIFFUSE => m.diffuse = c,
                GL_SPECULAR => m.specular = c,
                _ => {
                    m.ambient = c;
                    m.diffuse = c;
                }
            }
        }
    }

    /// glLightModel{f,i,fv,iv}.
    pub fn light_model(&mut self, pname: u32, v: Param) {
        let Some((as_enum, v)) = self.lighting_values(pname, v, true, false) else {
            return;
        };
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.st.light_model_ambient = [v[0], v[1], v[2], v[3]],
            GL_LIGHT_MODEL_LOCAL_VIEWER => self.st.light_model_local_viewer = v[0] != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => self.st.light_model_two_side = v[0] != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                if as_enum == GL_SINGLE_COLOR || as_enum == GL_SEPARATE_SPECULAR_COLOR {
                    self.st.light_model_color_control = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    // ---- fog ----

    /// glFog{f,i,fv,iv}.
    pub fn fog(&mut self, pname: u32, v: Param) {
        let Some((as_enum, v)) = self.lighting_values(pname, v, true, false) else {
            return;
        };
        let fog = &mut self.st.fog;
        match pname {
            GL_FOG_MODE => {
                if matches!(as_enum, GL_LINEAR | GL_EXP | GL_EXP2) {
                    fog.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            GL_FOG_DENSITY => {
                if v[0].is_nan() || v[0] < 0.0 {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    fog.density = v[0];
                }
            }
            GL_FOG_START => fog.start = v[0],
            GL_FOG_END => fog.end = v[0],
            GL_FOG_INDEX => {}
            GL_FOG_COLOR => fog.color = [v[0], v[1], v[2], v[3]].map(clamp01),
            GL_FOG_COORD_SRC => {
                if as_enum == GL_FOG_COORD || as_enum == GL_FRAGMENT_DEPTH {
                    fog.coord_src = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    // ---- texture environment and coordinate generation ----

    /// glTexEnv{f,i,fv,iv}.
    pub fn tex_env(&mut self, target: u32, pname: u32, v: Param) {
        if self.reject_in_begin() {
            return;
        }
        let (as_enum, v) = (v.as_enum(), &v.floats(pname)[..]);
        let unit = self.st.active_texture as usize;
        let need = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let Some(env) = self.st.tex_env.get_mut(unit) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => {
                if matches!(
                    as_enum,
                    GL_MODULATE | GL_DECAL | GL_BLEND | GL_REPLACE | GL_ADD | GL_COMBINE
                ) {
                    env.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => {
                env.color = [v[0], v[1], v[2], v[3]].map(clamp01);
            }
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => env.lod_bias = v[0],
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => env.coord_replace = v[0] != 0.0,
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => env.alpha_scale = v[0],
            (GL_TEXTURE_ENV, _) => {
                // GL_COMBINE's sources and operands are kept for queries
                // but not applied.
                match env
                    .combine
                    .get_mut(pname.wrapping_sub(GL_COMBINE_RGB) as usize)
                {
                    Some(x) => *x = v[0],
                    None => self.set_error(GL_INVALID_ENUM),
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetTexEnvfv (enum values as floats).
    pub fn get_tex_envfv(&mut self, target: u32, pname: u32) -> Vec<f32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        let unit = self.st.active_texture as usize;
        let Some(env) = self.st.tex_env.get(unit).copied() else {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        };
        match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => vec![env.mode as f32],
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => env.color.to_vec(),
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => vec![env.alpha_scale],
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => vec![env.lod_bias],
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => vec![env.coord_replace as i32 as f32],
            (GL_TEXTURE_ENV, _) => {
                match env.combine.get(pname.wrapping_sub(GL_COMBINE_RGB) as usize) {
                    Some(&x) => vec![x],
                    None => {
                        self.set_error(GL_INVALID_ENUM);
                        Vec::new()
                    }
                }
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// The index of a glTexGen coordinate (GL_S..GL_Q); GL_INVALID_ENUM
    /// for another value.
    fn tex_gen_coord(&mut self, coord: u32) -> Option<usize> {
        match coord {
            GL_S => Some(0),
            GL_T => Some(1),
            GL_R => Some(2),
            GL_Q => Some(3),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetTexGenfv (the eye plane as stored: in eye coordinates).
    pub fn get_tex_genfv(&mut self, coord: u32, pname: u32) -> Vec<f32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        let Some(c) = self.tex_gen_coord(coord) else {
            return Vec::new();
        };
        let unit = self.st.active_texture as usize;
        let Some(g) = self.st.tex_gen.get(unit).map(|u| u[c]) else {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        };
        match pname {
            GL_TEXTURE_GEN_MODE => vec![g.mode as f32],
            GL_OBJECT_PLANE => g.object_plane.to_vec(),
            GL_EYE_PLANE => g.eye_plane.to_vec(),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glTexGen{f,i,fv,iv} (glTexGend* convert to floats first).
    /// GL_EYE_PLANE is transformed by the inverse model-view matrix
    /// (GL 2.1 §2.11.4).
    pub fn tex_gen(&mut self, coord: u32, pname: u32, v: Param) {
        if self.reject_in_begin() {
            return;
        }
        let (as_enum, v) = (v.as_enum(), &v.floats(pname)[..]);
        let Some(c) = self.tex_gen_coord(coord) else {
            return;
        };
        let unit = self.st.active_texture as usize;
        if unit >= MAX_TEXTURE_UNITS {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let need = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let inv = matrix::inverse_or_identity(&self.modelview_matrix());
        let g = &mut self.st.tex_gen[unit][c];
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let ok = match as_enum {
                    GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
                    GL_SPHERE_MAP => c < 2,
                    GL_NORMAL_MAP | GL_REFLECTION_MAP => c < 3,
                    _ => false,
                };
                if ok {
                    g.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            GL_OBJECT_PLANE => g.object_plane = [v[0], v[1], v[2], v[3]],
            GL_EYE_PLANE => g.eye_plane = matrix::vec_mul([v[0], v[1], v[2], v[3]], &inv),
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glActiveTexture.
    pub fn active_texture(&mut self, unit: u32) {
        if self.reject_in_begin() {
            return;
        }
        let i = unit.wrapping_sub(GL_TEXTURE0);
        if i as usize >= crate::MAX_TEXTURE_IMAGE_UNITS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.active_texture = i;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn light_position_goes_to_eye_space() {
        let mut ctx = Context::new(4, 4);
        ctx.translatef(0.0, 0.0, -5.0);
        ctx.light(GL_LIGHT1, GL_POSITION, Param::Fv(&[1.0, 2.0, 3.0, 1.0]));
        assert_eq!(
            ctx.get_lightfv(GL_LIGHT1, GL_POSITION),
            vec![1.0, 2.0, -2.0, 1.0]
        );
        // Directions ignore the translation.
        ctx.light(GL_LIGHT1, GL_SPOT_DIRECTION, Param::Fv(&[0.0, 1.0, 0.0]));
        assert_eq!(
            ctx.get_lightfv(GL_LIGHT1, GL_SPOT_DIRECTION),
            vec![0.0, 1.0, 0.0]
        );
        ctx.light(GL_LIGHT1, GL_SPOT_CUTOFF, Param::F(95.0));
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.light(GL_LIGHT1, GL_POSITION, Param::F(1.0));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.light(GL_LIGHT0 + 8, GL_AMBIENT, Param::Fv(&[0.0; 4]));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.light(GL_LIGHT0, GL_AMBIENT, Param::Fv(&[0.0; 2]));
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn every_form_of_a_family_checks_and_converts_alike() {
        let mut ctx = Context::new(4, 4);
        // A scalar form of a color: GL_INVALID_ENUM for lighting and fog,
        // too few values for the texture environment.
        ctx.material(GL_FRONT, GL_DIFFUSE, Param::I(1));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.fog(GL_FOG_COLOR, Param::F(1.0));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, Param::F(1.0));
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        // The scalar check comes before the light number's.
        ctx.light(GL_LIGHT0 + 99, GL_DIFFUSE, Param::F(1.0));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.light(GL_LIGHT0 + 99, GL_DIFFUSE, Param::Fv(&[1.0]));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.light(GL_LIGHT0, GL_DIFFUSE, Param::Fv(&[1.0]));
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        // Integer colors are normalized, other integers convert.
        ctx.fog(GL_FOG_COLOR, Param::Iv(&[i32::MAX, 0, i32::MAX, i32::MAX]));
        assert_eq!(ctx.st.fog.color[0], 1.0);
        ctx.tex_env(
            GL_TEXTURE_ENV,
            GL_TEXTURE_ENV_COLOR,
            Param::Iv(&[i32::MAX; 4]),
        );
        assert_eq!(ctx.st.tex_env[0].color, [1.0; 4]);
        ctx.fog(GL_FOG_END, Param::Iv(&[3]));
        assert_eq!(ctx.st.fog.end, 3.0);
        ctx.light_model(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            Param::Iv(&[GL_SEPARATE_SPECULAR_COLOR as i32]),
        );
        assert_eq!(ctx.st.light_model_color_control, GL_SEPARATE_SPECULAR_COLOR);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn color_material_tracks_current_color() {
        let mut ctx = Context::new(4, 4);
        ctx.color_4f(0.5, 0.25, 1.0, 1.0);
        ctx.enable(GL_COLOR_MATERIAL);
        assert_eq!(ctx.st.material[0].diffuse, [0.5, 0.25, 1.0, 1.0]);
        assert_eq!(ctx.st.material[1].ambient, [0.5, 0.25, 1.0, 1.0]);
        ctx.color_material(GL_FRONT, GL_EMISSION);
        ctx.color_4f(0.0, 1.0, 0.0, 1.0);
        assert_eq!(ctx.st.material[0].emission, [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(ctx.st.material[1].emission, [0.0, 0.0, 0.0, 1.0]);
    }
}
