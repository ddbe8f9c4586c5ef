//! The texture units of a draw ([`TextureUnits`]) and the lookups the
//! shaders make through them (`exec::Textures`): each request goes to
//! the 2D fast path (`texture_2d`) when it applies, else to the general
//! path (`texture_general`); both give the same bits.

use crate::ex::{FetchRequest, SampleRequest, TexelLevel, Textures, LANES};
use crate::texture::TextureUnit;
use crate::{texture_2d, texture_general};
use glsl::types::SamplerKind;

/// All texture units; samples for the exec crate.
#[derive(Clone, Debug)]
pub struct TextureUnits {
    pub units: Vec<TextureUnit>,
    /// What the fast path of 2D lookups finds out about each unit's 2D
    /// texture that depends on the texture alone (completeness, last
    /// level, storage), at the first lookup through these units; each
    /// entry holds the texture it describes and is used only for that
    /// texture (`units` may change after it is filled).
    pub(crate) checked_2d: texture_2d::CheckedUnits,
    /// The instruction set the fast path of 2D lookups runs in (the
    /// executor's, `texture_2d::current_level`), found once per set of
    /// units rather than per lookup.
    pub(crate) level: texture_2d::Level,
    /// The memory of the draw or dispatch (its shader storage buffers):
    /// what [`Textures::memory`] gives the kernels.
    pub memory: Option<std::sync::Arc<dyn exec::Memory + Send>>,
}

impl TextureUnits {
    /// The units `units` (the texture units of a draw).
    pub fn new(units: Vec<TextureUnit>) -> TextureUnits {
        TextureUnits {
            units,
            checked_2d: texture_2d::CheckedUnits::new(),
            level: texture_2d::current_level(),
            memory: None,
        }
    }
}

impl Default for TextureUnits {
    /// No units.
    fn default() -> TextureUnits {
        TextureUnits::new(Vec::new())
    }
}

impl Textures for TextureUnits {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        if !texture_2d::sample_with(self.level, &self.units, &self.checked_2d, req, out) {
            texture_general::sample_general(&self.units, req, out);
        }
    }

    fn sample_2d_implicit(
        &self,
        unit: u32,
        st: [&[f32; LANES]; 2],
        mask: u32,
        out: &mut [[f32; LANES]; 4],
    ) -> bool {
        use texture_2d::{sample_implicit_with, Sampled};
        let (units, checked) = (&self.units, &self.checked_2d);
        match sample_implicit_with(self.level, units, checked, unit, st, mask, out) {
            Sampled::Unorm8 => true,
            Sampled::Yes => false,
            Sampled::No => {
                self.sample(&exec::implicit_2d_request(unit, st, mask), out);
                false
            }
        }
    }

    fn fetch(&self, req: &FetchRequest, out: &mut [[f32; LANES]; 4]) {
        texture_general::fetch_general(&self.units, req, out);
    }

    fn texel_level(&self, unit: u32, target: SamplerKind, lod: i32) -> Option<TexelLevel<'_>> {
        texture_general::plain_level(&self.units, unit, target, lod).map(|(_, level)| level)
    }

    fn size(&self, unit: u32, target: SamplerKind, lod: i32) -> [i32; 3] {
        texture_general::size_general(&self.units, unit, target, lod)
    }

    fn memory(&self) -> Option<&dyn exec::Memory> {
        self.memory.as_deref().map(|m| m as &dyn exec::Memory)
    }
}

impl TextureUnits {
    /// [`texture_general::sample_general`] through these units: every
    /// lookup the general way (the reference of the fast path's tests).
    #[cfg(test)]
    pub(crate) fn sample_general(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        texture_general::sample_general(&self.units, req, out);
    }
}
