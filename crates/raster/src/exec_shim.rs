//! TEMPORARY: a private copy of the `exec` API declared in PIPELINE.md, used
//! until the real `exec` crate lands on main. Delete this module at merge
//! time and point `crate::ex` at `::exec`.
#![allow(dead_code, clippy::large_enum_variant)]

use glsl::types::{SamplerKind, Type};

pub const LANES: usize = 16;
pub type LaneMask = u32;

#[derive(Clone, Debug)]
pub struct Slot {
    pub name: String,
    pub ty: Type,
    pub offset: usize,
    pub components: usize,
    pub written: bool,
}

#[derive(Clone, Debug, Default)]
pub struct Interface {
    pub inputs: Vec<Slot>,
    pub outputs: Vec<Slot>,
    pub uniforms: Vec<Slot>,
    pub uniform_words: usize,
    pub input_components: usize,
    pub output_components: usize,
}

#[derive(Clone, Debug)]
pub struct Batch {
    pub inputs: Vec<[f32; LANES]>,
    pub outputs: Vec<[f32; LANES]>,
    pub active: LaneMask,
    pub discarded: LaneMask,
    pub helper: LaneMask,
}

pub trait Textures {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]);
}

#[derive(Clone, Debug)]
pub struct SampleRequest {
    pub unit: [u32; LANES],
    pub target: SamplerKind,
    pub coord: [[f32; LANES]; 4],
    pub compare: Option<[f32; LANES]>,
    pub lod: Lod,
    pub mask: LaneMask,
}

#[derive(Clone, Debug)]
pub enum Lod {
    Derivatives {
        ddx: [[f32; LANES]; 3],
        ddy: [[f32; LANES]; 3],
        bias: [f32; LANES],
    },
    Explicit([f32; LANES]),
}

#[derive(Debug, thiserror::Error)]
pub enum ExecError {
    #[error("shader exceeded {iterations} loop iterations in one invocation")]
    LoopBudget { iterations: u64 },
    #[error("unsupported IR: {0}")]
    Unsupported(String),
}

/// Stand-in for the lowered program; runs nothing.
pub struct Kernel {
    interface: Interface,
}

impl Kernel {
    pub fn interface(&self) -> &Interface {
        &self.interface
    }
    pub fn run(
        &self,
        _batch: &mut Batch,
        _uniforms: &[u32],
        _textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        Err(ExecError::Unsupported("exec not merged yet".into()))
    }
}
