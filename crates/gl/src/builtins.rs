//! The built-in uniform state of GLSL 1.20 §7.5, derived from the GL
//! state when a draw needs it.
//!
//! [`Context::builtin_uniform`] returns the value of one `gl_*` uniform as
//! the flattened float components of its whole type (structs member by
//! member, arrays element by element, matrices column-major).
//!
//! Derived values:
//! - `*Inverse` of a singular matrix is the identity (undefined in GL);
//! - `gl_NormalMatrix` is the inverse transpose of the model-view's upper
//!   3x3 (GL 2.1 §2.11.3); `gl_NormalScale` is `1 / |row 3 of (M^-1)|` over
//!   its first three columns (§2.11.3, RESCALE_NORMAL);
//! - light positions, spot directions, clip and eye planes are stored in
//!   eye space when specified (§2.12, §2.14.2, §2.11.4);
//! - `halfVector` = normalize(normalize(position.xyz) + (0, 0, 1)), w = 1,
//!   the infinite-viewer half vector Mesa also provides;
//! - `spotCosCutoff` = cos(radians(spotCutoff)) (-1 for 180);
//! - light products multiply material and light colors component-wise in
//!   r, g, b and take alpha from the material (the alpha of a lit color is
//!   the material's, GL 2.1 §2.14.1); `sceneColor` = emission + ambient ×
//!   light-model ambient with the diffuse material alpha;
//! - `gl_Fog.scale` = 1 / (end - start).

use crate::matrix::{self, Mat4};
use crate::state::{Light, Material};
use crate::Context;
use glsl::math;

fn mat_inv(m: &Mat4) -> Mat4 {
    matrix::inverse_or_identity(m)
}

fn light_values(l: &Light, out: &mut Vec<f32>) {
    out.extend_from_slice(&l.ambient);
    out.extend_from_slice(&l.diffuse);
    out.extend_from_slice(&l.specular);
    out.extend_from_slice(&l.position);
    out.extend_from_slice(&half_vector(l.position));
    out.extend_from_slice(&l.spot_direction);
    out.push(l.spot_exponent);
    out.push(l.spot_cutoff);
    out.push(spot_cos_cutoff(l.spot_cutoff));
    out.extend_from_slice(&l.attenuation);
}

/// cos(radians(cutoff)); exactly -1 for the default 180.
pub fn spot_cos_cutoff(cutoff: f32) -> f32 {
    if cutoff == 180.0 {
        -1.0
    } else {
        math::cos(math::radians(cutoff))
    }
}

fn normalize3(v: [f32; 3]) -> [f32; 3] {
    let len = math::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if len == 0.0 {
        v
    } else {
        [v[0] / len, v[1] / len, v[2] / len]
    }
}

/// The infinite-viewer half vector of a light.
pub fn half_vector(position: [f32; 4]) -> [f32; 4] {
    let p = normalize3([position[0], position[1], position[2]]);
    let h = normalize3([p[0], p[1], p[2] + 1.0]);
    [h[0], h[1], h[2], 1.0]
}

fn material_values(m: &Material, out: &mut Vec<f32>) {
    out.extend_from_slice(&m.emission);
    out.extend_from_slice(&m.ambient);
    out.extend_from_slice(&m.diffuse);
    out.extend_from_slice(&m.specular);
    out.push(m.shininess);
}

fn product(light: [f32; 4], material: [f32; 4]) -> [f32; 4] {
    [
        light[0] * material[0],
        light[1] * material[1],
        light[2] * material[2],
        material[3],
    ]
}

impl Context {
    /// The value of built-in uniform `name` (a whole `gl_*` global), or
    /// `None` if it is not one.
    pub fn builtin_uniform(&self, name: &str) -> Option<Vec<f32>> {
        let mv = self.modelview_matrix();
        let p = self.projection_matrix();
        let mvp = || matrix::mul(&p, &mv);
        let tex = |f: &dyn Fn(&Mat4) -> Mat4| -> Vec<f32> {
            (0..crate::MAX_TEXTURE_UNITS)
                .flat_map(|i| f(&self.texture_matrix(i)))
                .collect()
        };
        let st = &self.st;
        let v: Vec<f32> = match name {
            "gl_ModelViewMatrix" => mv.to_vec(),
            "gl_ProjectionMatrix" => p.to_vec(),
            "gl_ModelViewProjectionMatrix" => mvp().to_vec(),
            "gl_TextureMatrix" => tex(&|m| *m),
            "gl_NormalMatrix" => matrix::normal_matrix(&mv).to_vec(),
            "gl_ModelViewMatrixInverse" => mat_inv(&mv).to_vec(),
            "gl_ProjectionMatrixInverse" => mat_inv(&p).to_vec(),
            "gl_ModelViewProjectionMatrixInverse" => mat_inv(&mvp()).to_vec(),
            "gl_TextureMatrixInverse" => tex(&mat_inv),
            "gl_ModelViewMatrixTranspose" => matrix::transpose(&mv).to_vec(),
            "gl_ProjectionMatrixTranspose" => matrix::transpose(&p).to_vec(),
            "gl_ModelViewProjectionMatrixTranspose" => matrix::transpose(&mvp()).to_vec(),
            "gl_TextureMatrixTranspose" => tex(&matrix::transpose),
            "gl_ModelViewMatrixInverseTranspose" => matrix::transpose(&mat_inv(&mv)).to_vec(),
            "gl_ProjectionMatrixInverseTranspose" => matrix::transpose(&mat_inv(&p)).to_vec(),
            "gl_ModelViewProjectionMatrixInverseTranspose" => {
                matrix::transpose(&mat_inv(&mvp())).to_vec()
            }
            "gl_TextureMatrixInverseTranspose" => tex(&|m| matrix::transpose(&mat_inv(m))),
            "gl_NormalScale" => {
                let inv = mat_inv(&mv);
                // Row 3 (index 2) of M^-1, first three columns.
                let (a, b, c) = (inv[2], inv[6], inv[10]);
                let len = math::sqrt(a * a + b * b + c * c);
                vec![if len == 0.0 { 1.0 } else { 1.0 / len }]
            }
            "gl_DepthRange" => {
                let [n, f] = self.depth_range;
                vec![n, f, f - n]
            }
            "gl_ClipPlane" => self.clip_planes.iter().flatten().copied().collect(),
            "gl_Point" => {
                let pt = &st.point;
                vec![
                    pt.size,
                    pt.size_min,
                    pt.size_max,
                    pt.fade_threshold,
                    pt.attenuation[0],
                    pt.attenuation[1],
                    pt.attenuation[2],
                ]
            }
            "gl_FrontMaterial" | "gl_BackMaterial" => {
                let mut out = Vec::new();
                material_values(
                    &st.material[usize::from(name == "gl_BackMaterial")],
                    &mut out,
                );
                out
            }
            "gl_LightSource" => {
                let mut out = Vec::new();
                for l in &st.lights {
                    light_values(l, &mut out);
                }
                out
            }
            "gl_LightModel" => st.light_model_ambient.to_vec(),
            "gl_FrontLightModelProduct" | "gl_BackLightModelProduct" => {
                let m = &st.material[usize::from(name == "gl_BackLightModelProduct")];
                let a = st.light_model_ambient;
                vec![
                    m.emission[0] + m.ambient[0] * a[0],
                    m.emission[1] + m.ambient[1] * a[1],
                    m.emission[2] + m.ambient[2] * a[2],
                    m.diffuse[3],
                ]
            }
            "gl_FrontLightProduct" | "gl_BackLightProduct" => {
                let m = &st.material[usize::from(name == "gl_BackLightProduct")];
                st.lights
                    .iter()
                    .flat_map(|l| {
                        let mut v = product(l.ambient, m.ambient).to_vec();
                        v.extend_from_slice(&product(l.diffuse, m.diffuse));
                        v.extend_from_slice(&product(l.specular, m.specular));
                        v
                    })
                    .collect()
            }
            "gl_TextureEnvColor" => {
                // Sized by image units in 1.10: units past the fixed-function
                // ones have the default (0, 0, 0, 0).
                let mut v: Vec<f32> = st.tex_env.iter().flat_map(|e| e.color).collect();
                v.resize(crate::MAX_TEXTURE_IMAGE_UNITS * 4, 0.0);
                v
            }
            "gl_Fog" => {
                let f = &st.fog;
                let mut v = f.color.to_vec();
                let range = f.end - f.start;
                v.extend_from_slice(&[f.density, f.start, f.end, 1.0 / range]);
                v
            }
            _ => {
                let rest = name.strip_prefix("gl_")?;
                let (eye, coord) = if let Some(c) = rest.strip_prefix("EyePlane") {
                    (true, c)
                } else {
                    (false, rest.strip_prefix("ObjectPlane")?)
                };
                let c = match coord {
                    "S" => 0,
                    "T" => 1,
                    "R" => 2,
                    "Q" => 3,
                    _ => return None,
                };
                st.tex_gen
                    .iter()
                    .flat_map(|g| {
                        if eye {
                            g[c].eye_plane
                        } else {
                            g[c].object_plane
                        }
                    })
                    .collect()
            }
        };
        Some(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::enums::*;
    use crate::param::Param;

    fn close(a: &[f32], b: &[f32]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-5)
    }

    #[test]
    fn matrices_and_inverses() {
        let mut ctx = Context::new(4, 4);
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.scalef(2.0, 2.0, 2.0);
        let mvp = ctx.builtin_uniform("gl_ModelViewProjectionMatrix").unwrap();
        // x' = 2x * 0.5 - 1.
        assert!(close(&mvp[..1], &[1.0]));
        assert!(close(&mvp[12..13], &[-1.0]));
        let inv = ctx.builtin_uniform("gl_ModelViewMatrixInverse").unwrap();
        assert!(close(&inv[..1], &[0.5]));
        let nm = ctx.builtin_uniform("gl_NormalMatrix").unwrap();
        assert!(close(&nm, &[0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5]));
        // Normals shrink by 0.5 under M^-1; the rescale factor undoes it.
        assert!(close(
            &ctx.builtin_uniform("gl_NormalScale").unwrap(),
            &[2.0]
        ));
        let t = ctx.builtin_uniform("gl_ProjectionMatrixTranspose").unwrap();
        assert!(close(&t[3..4], &[-1.0]));
        assert_eq!(
            ctx.builtin_uniform("gl_TextureMatrix").unwrap().len(),
            8 * 16
        );
        assert_eq!(ctx.builtin_uniform("gl_NotAThing"), None);
    }

    #[test]
    fn light_source_layout_and_products() {
        let mut ctx = Context::new(4, 4);
        let ls = ctx.builtin_uniform("gl_LightSource").unwrap();
        assert_eq!(ls.len(), 8 * 29);
        // Light 0 defaults: diffuse white, position (0,0,1,0): half vector
        // normalize((0,0,2)) = (0,0,1).
        assert!(close(&ls[4..8], &[1.0; 4]));
        assert!(close(&ls[16..20], &[0.0, 0.0, 1.0, 1.0]));
        assert!(close(&ls[23..29], &[0.0, 180.0, -1.0, 1.0, 0.0, 0.0]));
        ctx.light(GL_LIGHT0, GL_POSITION, Param::Fv(&[1.0, 0.0, 0.0, 0.0]));
        let h = ctx.builtin_uniform("gl_LightSource").unwrap();
        let s = 1.0 / 2.0f32.sqrt();
        assert!(close(&h[16..20], &[s, 0.0, s, 1.0]));
        ctx.light(GL_LIGHT0, GL_SPOT_CUTOFF, Param::F(60.0));
        let h = ctx.builtin_uniform("gl_LightSource").unwrap();
        assert!(close(&h[25..26], &[0.5]));
        ctx.material(GL_FRONT, GL_DIFFUSE, Param::Fv(&[0.5, 0.5, 0.5, 0.25]));
        ctx.light(GL_LIGHT1, GL_DIFFUSE, Param::Fv(&[0.2, 0.4, 0.6, 1.0]));
        let p = ctx.builtin_uniform("gl_FrontLightProduct").unwrap();
        assert_eq!(p.len(), 8 * 12);
        assert!(close(&p[12 + 4..12 + 8], &[0.1, 0.2, 0.3, 0.25]));
        // Back material untouched: default diffuse 0.8.
        let b = ctx.builtin_uniform("gl_BackLightProduct").unwrap();
        assert!(close(&b[12 + 4..12 + 8], &[0.16, 0.32, 0.48, 1.0]));
        let sc = ctx.builtin_uniform("gl_FrontLightModelProduct").unwrap();
        // emission 0 + ambient 0.2 * model ambient 0.2; alpha = diffuse alpha.
        assert!(close(&sc, &[0.04, 0.04, 0.04, 0.25]));
    }

    #[test]
    fn fog_depth_range_planes() {
        let mut ctx = Context::new(4, 4);
        ctx.fog(GL_FOG_START, Param::F(2.0));
        ctx.fog(GL_FOG_END, Param::F(6.0));
        let f = ctx.builtin_uniform("gl_Fog").unwrap();
        assert!(close(&f, &[0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 6.0, 0.25]));
        ctx.depth_range(0.25, 0.75);
        assert!(close(
            &ctx.builtin_uniform("gl_DepthRange").unwrap(),
            &[0.25, 0.75, 0.5]
        ));
        ctx.translatef(1.0, 0.0, 0.0);
        ctx.active_texture(GL_TEXTURE1);
        ctx.tex_gen(GL_S, GL_EYE_PLANE, Param::Fv(&[1.0, 0.0, 0.0, 0.0]));
        let e = ctx.builtin_uniform("gl_EyePlaneS").unwrap();
        // Plane x = 0 in object space is x = 1 in eye space: (1, 0, 0, -1).
        assert!(close(&e[4..8], &[1.0, 0.0, 0.0, -1.0]));
        let o = ctx.builtin_uniform("gl_ObjectPlaneT").unwrap();
        assert!(close(&o[0..4], &[0.0, 1.0, 0.0, 0.0]));
    }
}
