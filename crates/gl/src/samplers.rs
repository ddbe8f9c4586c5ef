//! Sampler objects (GL 3.3 §3.8.2, ARB_sampler_objects): glGenSamplers,
//! glDeleteSamplers, glIsSampler, glBindSampler, glSamplerParameter*,
//! glGetSamplerParameter*.
//!
//! Contract: a sampler bound to a texture image unit supplies the sampler
//! state (GL 3.3 Table 6.23) of every texture that unit samples, in place
//! of the texture's own ([`crate::texture_units`] builds raster's textures
//! from both); the texture's parameters stay as they were and queryable.
//! Errors: a name glGenSamplers did not return (or since deleted) is
//! GL_INVALID_OPERATION for glBindSampler and for the parameter calls and
//! queries (the GL 3.3 text says GL_INVALID_VALUE for the latter; GL 4.x
//! and Mesa answer GL_INVALID_OPERATION, which programs are tested
//! against); a unit past
//! GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS is GL_INVALID_VALUE; a pname that is
//! not sampler state is GL_INVALID_ENUM; a bad value gets glTexParameter's
//! error. Deleting a bound sampler unbinds it from every unit.

use crate::enums::*;
use crate::objects::{SamplerObj, TexParams};
use crate::param::Param;
use crate::textures::set_sampler_state;
use crate::Context;

/// The number of values a sampler parameter takes (4 for the border
/// colour, 1 for the others; 0 for a pname that is no sampler state).
pub fn sampler_parameter_count(pname: u32) -> usize {
    match pname {
        GL_TEXTURE_BORDER_COLOR => 4,
        GL_TEXTURE_WRAP_S
        | GL_TEXTURE_WRAP_T
        | GL_TEXTURE_WRAP_R
        | GL_TEXTURE_MIN_FILTER
        | GL_TEXTURE_MAG_FILTER
        | GL_TEXTURE_MIN_LOD
        | GL_TEXTURE_MAX_LOD
        | GL_TEXTURE_LOD_BIAS
        | GL_TEXTURE_COMPARE_MODE
        | GL_TEXTURE_COMPARE_FUNC => 1,
        _ => 0,
    }
}

impl Context {
    /// glGenSamplers.
    pub fn gen_samplers(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.samplers, &mut o.next_sampler),
            SamplerObj::default,
        )
    }

    /// glDeleteSamplers: unknown names and 0 are ignored; a deleted
    /// sampler bound to a unit leaves that unit with none.
    pub fn delete_samplers(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 || self.objects.samplers.remove(&name).is_none() {
                continue;
            }
            for b in self.objects.bound_samplers.iter_mut() {
                if *b == name {
                    *b = 0;
                }
            }
            self.cache.textures.retain(|k, _| k.2 != name);
        }
    }

    /// glIsSampler.
    pub fn is_sampler(&self, name: u32) -> bool {
        name != 0 && self.objects.samplers.contains_key(&name)
    }

    /// glBindSampler: `unit` is an index (0-based), not a GL_TEXTUREi enum.
    pub fn bind_sampler(&mut self, unit: u32, sampler: u32) {
        if unit as usize >= crate::MAX_TEXTURE_IMAGE_UNITS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if sampler != 0 && !self.objects.samplers.contains_key(&sampler) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.objects.bound_samplers[unit as usize] = sampler;
    }

    /// The sampler `sampler`'s object, or GL_INVALID_OPERATION.
    fn sampler_mut(&mut self, sampler: u32) -> Option<&mut SamplerObj> {
        if !self.objects.samplers.contains_key(&sampler) {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        self.objects.samplers.get_mut(&sampler)
    }

    /// glSamplerParameter{i,f,iv,fv} (and, with the border colour's values
    /// already as floats, glSamplerParameterI{i,ui}v). A scalar form of
    /// the four-valued GL_TEXTURE_BORDER_COLOR is GL_INVALID_ENUM (it is
    /// no single-valued parameter).
    pub fn sampler_parameter(&mut self, sampler: u32, pname: u32, v: Param) {
        let (e, vals) = (v.as_enum(), v.floats(pname));
        let Some(s) = self.sampler_mut(sampler) else {
            return;
        };
        let need = sampler_parameter_count(pname);
        let err = if need == 0 || (need > 1 && v.is_scalar()) {
            GL_INVALID_ENUM
        } else if vals.len() < need {
            GL_INVALID_VALUE
        } else {
            let mut p = s.params;
            let err = set_sampler_state(&mut p, pname, e, &vals).unwrap_or(GL_INVALID_ENUM);
            if err == GL_NO_ERROR {
                s.params = p;
                s.generation += 1;
            }
            err
        };
        if err != GL_NO_ERROR {
            self.set_error(err);
        }
    }

    /// glGetSamplerParameter{i,f}v: the parameter's values as floats (the
    /// enums' values exactly); empty after an error.
    pub fn get_sampler_parameter(&mut self, sampler: u32, pname: u32) -> Vec<f32> {
        let Some(s) = self.sampler_mut(sampler) else {
            return Vec::new();
        };
        let p: TexParams = s.params;
        match pname {
            GL_TEXTURE_WRAP_S => vec![p.wrap[0] as f32],
            GL_TEXTURE_WRAP_T => vec![p.wrap[1] as f32],
            GL_TEXTURE_WRAP_R => vec![p.wrap[2] as f32],
            GL_TEXTURE_MIN_FILTER => vec![p.min_filter as f32],
            GL_TEXTURE_MAG_FILTER => vec![p.mag_filter as f32],
            GL_TEXTURE_BORDER_COLOR => p.border_color.to_vec(),
            GL_TEXTURE_MIN_LOD => vec![p.min_lod],
            GL_TEXTURE_MAX_LOD => vec![p.max_lod],
            GL_TEXTURE_LOD_BIAS => vec![p.lod_bias],
            GL_TEXTURE_COMPARE_MODE => vec![p.compare_mode as f32],
            GL_TEXTURE_COMPARE_FUNC => vec![p.compare_func as f32],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }
}

/// `tex` (a texture object's parameters) with the sampler state of `s`
/// (GL 3.3 §3.8.2: a bound sampler's state supersedes the texture's).
pub(crate) fn with_sampler(tex: &TexParams, s: &TexParams) -> TexParams {
    TexParams {
        min_filter: s.min_filter,
        mag_filter: s.mag_filter,
        wrap: s.wrap,
        border_color: s.border_color,
        min_lod: s.min_lod,
        max_lod: s.max_lod,
        lod_bias: s.lod_bias,
        compare_mode: s.compare_mode,
        compare_func: s.compare_func,
        ..*tex
    }
}

/// Whether sampler state `p` would have been refused by glTexParameter on
/// a rectangle texture (mipmap filtering, repeating s or t wraps; r is no
/// axis of a rectangle): such a texture samples as incomplete (GL 3.3
/// §3.8.2).
pub(crate) fn invalid_for_rectangle(p: &TexParams) -> bool {
    !matches!(p.min_filter, GL_NEAREST | GL_LINEAR)
        || p.wrap[..2]
            .iter()
            .any(|&w| matches!(w, GL_REPEAT | GL_MIRRORED_REPEAT))
}
