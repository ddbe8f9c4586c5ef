//! A set-up primitive ([`Prim`]): what set-up (`crate::setup`) gives,
//! binning (`crate::binning`) sorts into tiles and the fragment stage
//! (`crate::shade`) rasterizes and shades. It holds what rasterization
//! reads (its shape, bounds, facing, polygon offset, window z and 1/w
//! planes); its varyings' planes sit in its set-up chunk's array.

use crate::interpolate::{offsets, PrimPlanes};
use crate::rasterize::{PixelRect, Shape};

/// A primitive ready for rasterization (small: see [`Shape`]).
pub(crate) struct Prim {
    pub shape: Shape,
    /// Pixel bounds clipped to the framebuffer and scissor box.
    pub bounds: PixelRect,
    pub back: bool,
    /// Polygon offset added to window z.
    pub z_offset: f64,
    /// Its window z and 1/w planes (`crate::interpolate`).
    pub planes: PrimPlanes,
    /// Its index in its set-up chunk (`chunk`, an index into
    /// `FragmentStage::attrs`), whose planes array holds one plane per
    /// link and primitive: its varyings' start at `index` × links.
    pub index: u32,
    pub chunk: u32,
    /// Index of the assembled primitive this one came from (clipping may
    /// split one into several), for the debugger.
    pub source: u32,
}

impl Prim {
    /// [`offsets`]: the window positions its planes are evaluated at.
    #[inline(always)]
    pub fn offsets<const N: usize>(
        &self,
        at: (i64, i64),
        ox: &[f32; N],
        oy: &[f32; N],
    ) -> ([f32; N], [f32; N]) {
        offsets(at, ox, oy, self.planes.top)
    }
}
