//! The control byte the GLSL targets (`compile`, `preprocess`) start
//! with: bits 0-1 the stage (vertex, fragment, geometry, compute), bit 2 a
//! core-only context (clear: the context offers the compatibility
//! profile), bits 3-5 the version of a shader without `#version` (an index
//! into `Version::ALL`; past its end, the language's default), bit 6 a
//! tessellation stage instead (bit 0: control or evaluation).

use glsl::{Stage, Version};

pub struct Control {
    pub stage: Stage,
    pub compatibility_context: bool,
    pub default_version: Option<Version>,
}

pub fn control(byte: u8) -> Control {
    Control {
        stage: if byte & 0x40 != 0 {
            [Stage::TessControl, Stage::TessEvaluation][usize::from(byte & 1)]
        } else {
            [Stage::Vertex, Stage::Fragment, Stage::Geometry, Stage::Compute][usize::from(byte & 3)]
        },
        compatibility_context: byte & 4 == 0,
        default_version: Version::ALL.get(usize::from(byte >> 3 & 7)).copied(),
    }
}
