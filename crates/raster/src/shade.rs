//! The fragment stage: covered quads of a set-up primitive are shaded four
//! at a time (one [`Batch`] of 16 lanes), then sent through the
//! per-fragment operations in order.

use crate::ex::{Batch, ExecError, Textures, LANES};
use crate::fragment_ops::{self, Fragment, QuickOps, QuickTarget};
use crate::framebuffer::{depth_to_fixed, Framebuffer, MAX_DRAW_BUFFERS};
use crate::interpolate::{Kind, Plane, QUAD_X, QUAD_Y, STRIP_X, STRIP_Y};
use crate::linkage::{new_batch, FsLayout};
use crate::prim::Prim;
use crate::probe::Probe;
use crate::rasterize::{PixelRect, Shape, STRIP};
use crate::simd::Isa;
use crate::state::PipelineState;
use crate::ShaderStage;

/// The final window z of four pixels from their interpolated z and the
/// primitive's polygon offset (offset, clamped), and its fixed point.
#[inline(always)]
fn window_depths(iz: &[f64; 4], offset: f64) -> ([f64; 4], [u32; 4]) {
    let z = iz.map(|iz| clamp01(iz + offset));
    (z, fragment_ops::depth_to_fixed4(z))
}

fn clamp01(z: f64) -> f64 {
    if z > 0.0 {
        z.min(1.0)
    } else {
        0.0
    }
}

#[derive(Default)]
pub(crate) struct Quad {
    x: i64,
    y: i64,
    live: u8,
    /// Final window z per pixel (offset and clamped).
    z: [f64; 4],
    /// Those depths in fixed point (`depth_to_fixed(z as f32)`).
    zf: [u32; 4],
}

impl Quad {
    /// Window coordinates of pixel `k` (0–3: lane `4q + k`'s pixel, see
    /// `exec`'s lane order) of the quad.
    fn pixel(&self, k: usize) -> (i64, i64) {
        (self.x + (k as i64 & 1), self.y + (k as i64 >> 1))
    }

    /// Makes this the quad at (qx, qy) of `prim` with coverage `mask`,
    /// its window z computed with `window_z` (else `z` and `zf` keep
    /// what they held: see [`FragmentStage::window_z`]).
    #[inline(always)]
    fn set(&mut self, prim: &Prim, qx: i64, qy: i64, mask: u8, window_z: bool) {
        (self.x, self.y, self.live) = (qx, qy, mask);
        if window_z {
            (self.z, self.zf) = quad_depths(prim, (qx, qy));
        }
    }
}

/// The final window z of the quad at `(qx, qy)` of `prim` (its z plane,
/// the polygon offset, clamped) and its fixed point.
#[inline(always)]
fn quad_depths(prim: &Prim, (qx, qy): (i64, i64)) -> ([f64; 4], [u32; 4]) {
    let (x, y) = prim.offsets((qx, qy), &QUAD_X, &QUAD_Y);
    window_depths(&prim.planes.z_at(&x, &y), prim.z_offset)
}

/// A quad waiting for its batch: its primitive (and that primitive's
/// index), and for the colour pass of a deferred tile the pixels to write.
#[derive(Default)]
pub(crate) struct Entry<'p> {
    prim: Option<&'p Prim>,
    index: u32,
    quad: Quad,
    write: u8,
}

impl<'p> Entry<'p> {
    /// Makes this the quad at (qx, qy) of primitive `index`, `prim`
    /// ([`Quad::set`]).
    #[inline(always)]
    fn set(
        &mut self,
        prim: &'p Prim,
        index: u32,
        (qx, qy, mask): (i64, i64, u8),
        write: u8,
        window_z: bool,
    ) {
        self.prim = Some(prim);
        self.index = index;
        self.write = write;
        self.quad.set(prim, qx, qy, mask, window_z);
    }
}

/// Per-tile buffers reused by every primitive and batch of the tile: the
/// batch, its quads (built in place, `n` of them so far) and a
/// primitive's covered quads.
pub(crate) struct Scratch<'p> {
    pub batch: Batch,
    slots: [Entry<'p>; LANES / 4],
    n: usize,
    quads: Vec<(i64, i64, u8)>,
    /// The quads of a packed batch ([`FragmentStage::fill_packed_with`]): up
    /// to one per lane.
    packed: Box<[Entry<'p>; LANES]>,
}

/// Where [`FragmentStage::write_inputs`] puts the pixels a quad runs.
pub(crate) struct Place {
    /// The pixels, in increasing order (`order[..count]`).
    order: [u8; 4],
    count: usize,
    /// The lane of the first.
    first: usize,
}

/// What a strip leaves in the batch's inputs for the next one
/// ([`FragmentStage::shade_strip`]): after a strip of `prim`, its
/// constant varyings, so that its next strip fills only the fills listed
/// in `varying[..count]` (indices into `FragmentStage::fills`). `None`
/// after anything else filled the batch.
#[derive(Default)]
struct InPlace {
    prim: Option<*const Prim>,
    varying: [u16; 32],
    count: usize,
}

/// Bit set in a lane mask for the `LANES / 4` quads of a batch.
fn quads_mask(quads: usize) -> u32 {
    lanes_mask(quads.saturating_mul(4))
}

/// For each 4-bit pixel set, its pixels in increasing order (then
/// zeros): where [`FragmentStage::fill_packed_with`] takes a quad's lanes from.
const COMPRESS: [[u8; 4]; 16] = {
    let mut t = [[0u8; 4]; 16];
    let mut m = 0;
    while m < 16 {
        let (mut k, mut j) = (0, 0);
        while k < 4 {
            if m & (1 << k) != 0 {
                t[m][j] = k as u8;
                j += 1;
            }
            k += 1;
        }
        m += 1;
    }
    t
};

/// Writes a quad's four values from lane `first` on (those past the last
/// lane are dropped).
#[inline(always)]
fn put_quad(lanes: &mut [f32; LANES], first: usize, values: [f32; 4]) {
    match lanes.get_mut(first..first + 4) {
        Some(out) => out.copy_from_slice(&values),
        None => {
            for (x, v) in lanes.iter_mut().skip(first).zip(values) {
                *x = v;
            }
        }
    }
}

/// The lane of pixel `k` of `e`, the `q`-th quad of a batch: `4q + k`,
/// or in a packed batch the next lane (`*next`, then counted) when the
/// quad runs that pixel (`e.write`), else none. Called for the quads in
/// order, each one's pixels in order.
#[inline(always)]
fn lane_of(packed: bool, q: usize, e: &Entry, k: usize, next: &mut usize) -> Option<usize> {
    match packed {
        true if e.write & (1 << k) != 0 => {
            *next += 1;
            Some(*next - 1)
        }
        true => None,
        false => Some(4 * q + k),
    }
}

/// Bit set in a lane mask for the first `lanes` lanes of a batch.
fn lanes_mask(lanes: usize) -> u32 {
    if lanes >= LANES {
        u32::MAX >> (32 - LANES)
    } else {
        (1u32 << lanes) - 1
    }
}

/// What the passes of [`FragmentStage::shade_deferred`] share in a tile.
struct DeferredPass<'d> {
    /// The depth-only slice.
    depth: &'d dyn ShaderStage,
    /// The tile's origin in the window.
    origin: (u32, u32),
    quick: Option<QuickOps>,
    /// Whether the slice runs (else the pass only depth-tests).
    run_slice: bool,
    /// Whether the slice and the full shader run packed batches
    /// ([`FragmentStage::fill_packed_with`]).
    pack_depth: bool,
    pack_colors: bool,
}

/// Takes the quad just set at `pending[*n]` (running the pixels
/// `write`) into a batch being gathered, `*lanes` lanes of it used so
/// far: a quad per 4 lanes, or with `packed` its pixels of `write` only
/// ([`FragmentStage::fill_packed_with`]). Returns `Some((count, spill))` when
/// `pending[..count]` is to run now: with `spill` the new quad did not
/// fit and is to be moved to `pending[0]`, where the next batch starts.
fn admit(packed: bool, n: &mut usize, lanes: &mut usize, write: u8) -> Option<(usize, bool)> {
    let c = match packed {
        true => (write & 0xf).count_ones() as usize,
        false => 4,
    };
    if *lanes + c > LANES {
        let count = *n;
        *n = 1;
        *lanes = c;
        return Some((count, true));
    }
    *n += 1;
    *lanes += c;
    if *lanes == LANES || *n == LANES {
        let count = *n;
        *n = 0;
        *lanes = 0;
        return Some((count, false));
    }
    None
}

/// How [`FragmentStage::fill`] writes one varying component.
#[derive(Clone, Copy, Debug, PartialEq)]
enum FillKind {
    /// Interpolated (its plane: constant for points and flat-shaded
    /// colours).
    Interp,
    /// Replaced by component `c` of (gl_PointCoord, 0, 1) on point
    /// sprites (GL_COORD_REPLACE).
    Replace(usize),
}

/// One varying component [`FragmentStage::fill`] writes: link `li` to
/// input component `offset`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FillLink {
    li: usize,
    offset: usize,
    kind: FillKind,
}

/// Where [`FragmentStage::shade_batched`] sends a tile's fragments: quick
/// operations with a qualifying colour write over the tile's buffers
/// (and that colour's fragment output), or the tile itself.
enum Sink<'f> {
    Quick(QuickTarget<'f>, usize),
    General(&'f mut Framebuffer, Option<QuickOps>),
}

/// How many primitives of a bin ahead [`FragmentStage::prefetch_ahead`]
/// fetches varyings and set-up.
const ATTRS_AHEAD: usize = 6;
const PRIM_AHEAD: usize = 16;
const SLOT_AHEAD: usize = 2 * PRIM_AHEAD;

/// No primitive (in the per-pixel winner table of a deferred tile).
const NO_PRIM: u32 = u32::MAX;

pub(crate) struct FragmentStage<'a> {
    pub shader: &'a dyn ShaderStage,
    pub uniforms: &'a [u32],
    pub textures: &'a (dyn Textures + Sync),
    pub layout: &'a FsLayout,
    pub state: &'a PipelineState,
    /// The planes of the fragment varyings of every primitive, per
    /// set-up chunk (see [`Prim::index`]).
    pub attrs: Vec<&'a [Plane]>,
    /// The varying components the shader reads (unread inputs stay zero;
    /// every link counts as read under the debugger's probe, which shows
    /// inputs), in link order.
    fills: Vec<FillLink>,
    /// Those the depth-only slice reads (its interface's inputs).
    depth_fills: Vec<FillLink>,
    /// The instruction set of the hot loops.
    isa: Isa,
    /// (draw buffer, output offset) of each colour the fragment carries.
    pub colors_out: Vec<(usize, usize)>,
    /// Depth/stencil-test before shading (no gl_FragDepth write).
    pub early: bool,
    /// The depth-only slice of `shader`, when colors may be computed for
    /// the visible fragments only (see [`FragmentStage::shade_deferred`]).
    pub deferred: Option<Box<dyn ShaderStage>>,
    /// The debugger's pixel probe (`None` in normal draws).
    pub probe: Option<&'a Probe>,
    /// `shader`'s and `deferred`'s uniform-only values, once per draw.
    prepared: Option<crate::ex::Prepared>,
    deferred_prepared: Option<crate::ex::Prepared>,
    /// Whether `shader`'s and `deferred`'s lanes are independent
    /// ([`ShaderStage::lanes_independent`]), asked once per draw.
    lanes_independent: bool,
    deferred_lanes_independent: bool,
    /// Whether anything reads a quad's window z (`Quad::z`, `Quad::zf`):
    /// the depth test of interpolated depths, gl_FragCoord.z or the
    /// debugger's probe. Without them the batched and deferred loops
    /// leave it out.
    window_z: bool,
    /// Whether [`FragmentStage::shade_batched`] may run rows of four
    /// whole quads of a triangle as strips ([`FragmentStage::shade_strip`]):
    /// nothing reads a quad's 1/w or pixel position (no gl_FragCoord,
    /// gl_FrontFacing or gl_PointCoord, no probe), and every input is
    /// interpolated or flat.
    strips: bool,
    /// Whether a batch's outputs are cleared before the shader runs (see
    /// [`ShaderStage::writes_every_output`]; always under the probe,
    /// whose traced runs take another path).
    clear_outputs: bool,
}

impl<'a> FragmentStage<'a> {
    /// The fragment stage of a draw: `shader` with `layout`'s linkage
    /// under `state`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        shader: &'a dyn ShaderStage,
        uniforms: &'a [u32],
        textures: &'a (dyn Textures + Sync),
        layout: &'a FsLayout,
        state: &'a PipelineState,
        attrs: Vec<&'a [Plane]>,
        deferred: Option<Box<dyn ShaderStage>>,
        probe: Option<&'a Probe>,
    ) -> FragmentStage<'a> {
        let read_by = |stage: &dyn ShaderStage, offset: usize| {
            probe.is_some()
                || stage
                    .interface()
                    .inputs
                    .iter()
                    .any(|s| s.written && (s.offset..s.offset + s.components).contains(&offset))
        };
        let plan = |stage: &dyn ShaderStage| -> Vec<FillLink> {
            layout
                .links
                .iter()
                .enumerate()
                .filter(|&(_, l)| l.fs_offset < layout.inputs && read_by(stage, l.fs_offset))
                .map(|(li, l)| FillLink {
                    li,
                    offset: l.fs_offset,
                    kind: match l.texcoord {
                        Some((set, c)) if set < 32 && state.coord_replace & (1 << set) != 0 => {
                            FillKind::Replace(c.min(3))
                        }
                        _ => FillKind::Interp,
                    },
                })
                .collect()
        };
        let fills = plan(shader);
        let window_z = probe.is_some()
            || layout.frag_coord.is_some()
            || (layout.frag_depth.is_none() && state.depth_test.is_some());
        let strips = strips_allowed()
            && probe.is_none()
            && layout.frag_coord.is_none()
            && layout.front_facing.is_none()
            && layout.point_coord.is_none()
            && fills.iter().all(|f| matches!(f.kind, FillKind::Interp));
        let depth_fills = match &deferred {
            // Only what both read (the slice reads a subset of the inputs).
            Some(d) => plan(d.as_ref())
                .into_iter()
                .filter(|f| fills.iter().any(|g| g.offset == f.offset))
                .collect(),
            None => Vec::new(),
        };
        FragmentStage {
            shader,
            uniforms,
            textures,
            layout,
            state,
            attrs,
            fills,
            depth_fills,
            isa: crate::simd::detect(),
            colors_out: (0..MAX_DRAW_BUFFERS)
                .filter_map(|i| match (layout.color_out[i], state.draw_buffers[i]) {
                    (Some(o), Some(_)) => Some((i, o)),
                    _ => None,
                })
                .collect(),
            early: layout.frag_depth.is_none(),
            window_z,
            strips,
            clear_outputs: probe.is_some() || !shader.writes_every_output(),
            prepared: shader.prepare(uniforms),
            deferred_prepared: deferred.as_ref().and_then(|d| d.prepare(uniforms)),
            lanes_independent: shader.lanes_independent(),
            deferred_lanes_independent: deferred.as_ref().is_some_and(|d| d.lanes_independent()),
            deferred,
            probe,
        }
    }

    /// Asks the CPU to fetch what the primitives after `bin[i]` will
    /// need: the varyings of the one [`ATTRS_AHEAD`] later (when `attrs`:
    /// finding them reads that primitive, so not for a pass that does
    /// not interpolate), the set-up of
    /// the one [`PRIM_AHEAD`] later (far enough for a memory access when
    /// primitives cover a pixel or two: a tile's primitives lie all over
    /// the draw's), and the `prims` entry (the pointer to the set-up) of
    /// the one [`SLOT_AHEAD`] later, which is read to find that set-up
    /// (with many small primitives the pointer array does not stay in the
    /// cache either). Only a hint: no effect on results.
    #[inline(always)]
    fn prefetch_ahead(&self, prims: &[&Prim], bin: &[u32], i: usize, attrs: bool) {
        if let Some(slot) = bin
            .get(i + SLOT_AHEAD)
            .and_then(|&p| prims.get(p as usize..p as usize + 1))
        {
            prefetch(slot);
        }
        let at = |k: usize| bin.get(i + k).and_then(|&p| prims.get(p as usize));
        if let Some(&next) = at(ATTRS_AHEAD).filter(|_| attrs) {
            self.prefetch_attrs(next);
        }
        if let Some(&after) = at(PRIM_AHEAD) {
            prefetch(std::slice::from_ref(after));
        }
    }

    /// [`prefetch`] of `prim`'s varyings.
    #[inline(always)]
    fn prefetch_attrs(&self, prim: &Prim) {
        let a = self.prim_attrs(prim);
        prefetch(a.get(..self.layout.links.len()).unwrap_or(a));
    }

    /// The planes of `prim`'s varyings (and those after it in its chunk).
    #[inline(always)]
    fn prim_attrs(&self, prim: &Prim) -> &'a [Plane] {
        self.attrs
            .get(prim.chunk as usize)
            .and_then(|a| a.get(prim.index as usize * self.layout.links.len()..))
            .unwrap_or(&[])
    }

    /// Runs the shader on `batch` (with the per-draw prepared values).
    fn run_shader(&self, batch: &mut Batch) -> Result<(), ExecError> {
        match &self.prepared {
            Some(p) => self
                .shader
                .run_prepared(batch, p, self.uniforms, self.textures),
            None => self.shader.run(batch, self.uniforms, self.textures),
        }
    }

    /// Runs the depth-only slice `depth` (this stage's
    /// [`FragmentStage::deferred`]) on `batch`.
    fn run_depth(&self, depth: &dyn ShaderStage, batch: &mut Batch) -> Result<(), ExecError> {
        match &self.deferred_prepared {
            Some(p) => depth.run_prepared(batch, p, self.uniforms, self.textures),
            None => depth.run(batch, self.uniforms, self.textures),
        }
    }

    /// Zeroes `batch`'s outputs before a run, unless the stage writes
    /// them all ([`FragmentStage::clear_outputs`]).
    #[inline(always)]
    fn zero_outputs(&self, batch: &mut Batch) {
        if self.clear_outputs {
            for c in batch.outputs.iter_mut() {
                *c = [0.0; LANES];
            }
        }
    }

    /// Buffers sized for the stage, reused by one tile's primitives and
    /// batches.
    pub fn scratch<'p>(&self) -> Scratch<'p> {
        Scratch {
            batch: new_batch(self.layout.inputs, self.layout.outputs),
            slots: Default::default(),
            n: 0,
            quads: Vec::new(),
            packed: Default::default(),
        }
    }

    /// Shades and writes the part of `prim` inside `tile`. `fb` holds the
    /// pixels of `tile` only (its origin is `(tile.0, tile.1)`).
    pub fn shade<'p>(
        &self,
        fb: &mut Framebuffer,
        prim: &'p Prim,
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let Scratch {
            batch,
            slots,
            n,
            quads,
            ..
        } = scratch;
        *n = 0;
        prim.shape.quads_into(clip_to(prim, tile), quads);
        for &quad in quads.iter() {
            let Some(e) = slots.get_mut(*n) else { break };
            e.set(prim, 0, quad, 0, true);
            if self.early {
                self.early_rejects(fb, origin, prim, &mut e.quad);
            }
            if e.quad.live == 0 {
                continue;
            }
            *n += 1;
            if *n == LANES / 4 {
                self.flush(fb, origin, prim, slots, batch)?;
                *n = 0;
            }
        }
        if *n > 0 {
            self.flush(fb, origin, prim, &slots[..*n], batch)?;
            *n = 0;
        }
        Ok(())
    }

    /// Sends the shaded fragments of `pending` through the per-fragment
    /// operations, in order.
    #[inline(always)]
    fn write_batch(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        batch: &Batch,
        pending: &[Entry],
        quick: Option<&QuickOps>,
    ) {
        if let Some((quick, o)) = quick.and_then(|q| Some((q, q.color_output()?))) {
            let mut target = quick.target(fb, origin);
            self.write_quick(&mut target, o, batch, pending);
            return;
        }
        let mut frag = Fragment {
            x: 0,
            y: 0,
            z: 0.0,
            back_facing: false,
            colors: [[0.0; 4]; MAX_DRAW_BUFFERS],
        };
        for (q, e) in pending.iter().enumerate() {
            let back = e.prim.is_some_and(|p| p.back);
            for k in 0..4 {
                if self.fragment_into(batch, &e.quad, q, k, back, &mut frag) {
                    fragment_ops::process(fb, origin, self.state, &frag);
                }
            }
        }
    }

    /// [`FragmentStage::write_batch`] through quick operations whose
    /// colour write qualifies (to fragment output `o`).
    #[inline(always)]
    fn write_quick(&self, target: &mut QuickTarget, o: usize, batch: &Batch, pending: &[Entry]) {
        {
            // The common states: the same operations per fragment, in the
            // same order, without the general checks; a quad's four
            // pixels (distinct) tested together, and without blending the
            // batch's colours converted together.
            let rgba = match batch.outputs.get(o..o + 4) {
                Some([r, g, b, a]) if target.opaque() => {
                    Some(fragment_ops::unorm8_batch(self.isa, [r, g, b, a]))
                }
                _ => None,
            };
            for (q, e) in pending.iter().enumerate() {
                let quad = &e.quad;
                let lanes = quad.live & !(batch.discarded >> (4 * q)) as u8 & 0xf;
                if lanes == 0 {
                    continue;
                }
                let z = || std::array::from_fn(|k| self.frag_z(batch, 4 * q + k, quad, k));
                // Without gl_FragDepth, z is the quad's (in [0, 1]), its
                // fixed-point depths known (and z needed only when the
                // quad's lanes are tested one by one).
                let zf = match self.layout.frag_depth {
                    Some(_) => z().map(depth_to_fixed),
                    None => quad.zf,
                };
                let (pass, index, inside) = target.test_quad_with((quad.x, quad.y), lanes, z, zf);
                match rgba.as_ref().and_then(|c| c.get(4 * q..4 * q + 4)) {
                    Some(&[c0, c1, c2, c3]) => {
                        target.write_rgba8_quad(pass, index, inside, [c0, c1, c2, c3])
                    }
                    _ => {
                        for (k, &index) in index.iter().enumerate() {
                            if pass & (1 << k) != 0 {
                                let lane = 4 * q + k;
                                target.write(index, [0, 1, 2, 3].map(|j| get(batch, o + j, lane)));
                            }
                        }
                    }
                }
            }
        }
    }

    /// The primitives `bin` (indices into `prims`, in draw order) inside
    /// `tile`, quads of consecutive primitives sharing batches (a
    /// primitive covering a pixel or two no longer costs a whole batch).
    /// Fragments still go through the per-fragment operations in draw
    /// order after their batch ran, so the bytes are those of
    /// [`FragmentStage::shade`] per primitive, provided early rejection
    /// against a depth buffer that misses the batch's pending fragments is
    /// still right: [`FragmentStage::batches_primitives`] says when. On an
    /// error the caller redraws the tile with [`FragmentStage::shade`].
    pub fn shade_batched<'p>(
        &self,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        match self.isa {
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `isa` is only Avx512 when the CPU has the features
            // (`simd::detect`).
            Isa::Avx512 => unsafe { self.shade_batched_avx512(fb, prims, bin, tile, scratch) },
            #[cfg(target_arch = "x86_64")]
            // SAFETY: likewise for AVX2.
            Isa::Avx2 => unsafe { self.shade_batched_avx2(fb, prims, bin, tile, scratch) },
            _ => self.shade_batched_with(fb, prims, bin, tile, scratch),
        }
    }

    /// [`FragmentStage::shade_batched`] compiled for AVX2 (the quad loop,
    /// early depth test and writes inlined: the same operations).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt")]
    unsafe fn shade_batched_avx2<'p>(
        &self,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        self.shade_batched_with(fb, prims, bin, tile, scratch)
    }

    /// [`FragmentStage::shade_batched`] compiled for AVX-512.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt,avx512f,avx512dq,avx512vl")]
    unsafe fn shade_batched_avx512<'p>(
        &self,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        self.shade_batched_with(fb, prims, bin, tile, scratch)
    }

    /// Fills and runs one batch of [`FragmentStage::shade_batched`] and
    /// writes its fragments.
    #[inline(always)]
    fn flush_batched(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        batch: &mut Batch,
        pending: &[Entry],
        quick: Option<&QuickOps>,
    ) -> Result<(), ExecError> {
        self.fill(batch, pending, &self.fills, false);
        self.run_shader(batch)?;
        self.write_batch(fb, origin, batch, pending, quick);
        Ok(())
    }

    #[inline(always)]
    fn shade_batched_with<'p>(
        &self,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let Scratch {
            batch,
            slots,
            n,
            quads,
            ..
        } = scratch;
        *n = 0;
        let quick = QuickOps::new(fb, self.state, &self.colors_out);
        // With quick operations whose colour write qualifies, the tile's
        // buffers are borrowed once for the whole bin (early depth
        // rejection reads them there); else through `fb` per batch.
        let mut sink = match quick.and_then(|q| Some((q, q.color_output()?))) {
            Some((q, o)) => Sink::Quick(q.target(fb, origin), o),
            None => Sink::General(fb, quick),
        };
        // Four whole quads side by side make one entry (`STRIP`) when
        // they may run as a strip.
        let strips = self.strips && matches!(sink, Sink::Quick(..));
        let mut in_place = InPlace::default();
        for (i, &p) in bin.iter().enumerate() {
            let Some(&prim) = prims.get(p as usize) else {
                continue;
            };
            self.prefetch_ahead(prims, bin, i, true);
            prim.shape
                .quads_into_strips(clip_to(prim, tile), quads, strips);
            for &(qx, qy, mask) in quads.iter() {
                if mask & STRIP == 0 {
                    let waiting = *n;
                    self.batch_quad(
                        &mut sink,
                        origin,
                        batch,
                        slots,
                        n,
                        (prim, p),
                        (qx, qy, mask),
                    )?;
                    // Fewer waiting: the batch was filled and run.
                    if *n < waiting {
                        in_place.prim = None;
                    }
                    continue;
                }
                // A batch of its own: the quads waiting go first (a strip
                // comes after a row's first quads, so they would wait for
                // the whole row otherwise).
                if *n > 0 {
                    self.flush_sink(&mut sink, origin, batch, &slots[..*n])?;
                    *n = 0;
                    in_place.prim = None;
                }
                if let Sink::Quick(target, o) = &mut sink {
                    let strip = (prim, p, (qx, qy));
                    self.shade_strip(target, *o, batch, slots, strip, &mut in_place)?;
                }
            }
        }
        if *n > 0 {
            self.flush_sink(&mut sink, origin, batch, &slots[..*n])?;
            *n = 0;
        }
        Ok(())
    }

    /// One covered quad of [`FragmentStage::shade_batched`]: set up in
    /// the next slot, early depth-tested, and kept unless no pixel is
    /// left; a full batch is shaded and written.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn batch_quad<'p>(
        &self,
        sink: &mut Sink,
        origin: (u32, u32),
        batch: &mut Batch,
        slots: &mut [Entry<'p>; LANES / 4],
        n: &mut usize,
        (prim, p): (&'p Prim, u32),
        quad: (i64, i64, u8),
    ) -> Result<(), ExecError> {
        let Some(e) = slots.get_mut(*n) else {
            return Ok(());
        };
        // Inlined: this loop is compiled per instruction set.
        e.set(prim, p, quad, 0, self.window_z);
        if self.early {
            match &*sink {
                // No stencil test (else no quick operations): the
                // depth test alone (`early_rejects`).
                Sink::Quick(t, _) => {
                    let q = &mut e.quad;
                    q.live = t.depth_live((q.x, q.y), q.live, q.zf);
                }
                Sink::General(fb, _) => self.early_rejects(fb, origin, prim, &mut e.quad),
            }
        }
        if e.quad.live == 0 {
            return Ok(());
        }
        *n += 1;
        if *n == LANES / 4 {
            self.flush_sink(sink, origin, batch, slots)?;
            *n = 0;
        }
        Ok(())
    }

    /// A strip of [`FragmentStage::shade_batched`]: the four whole quads
    /// (qx + 2i, qy) of primitive `prim` (index `index`) as one batch, the
    /// inputs evaluated from their planes over the 16 lanes at once (the
    /// operations [`FragmentStage::fill`] performs per quad, so the same
    /// bits), then the stage and the quick write: the bytes of the
    /// quad-at-a-time path, without its entries (only position, coverage
    /// and window z are set, for the early depth test and the write; see
    /// [`FragmentStage::strips`]). The early depth test drops the pixels
    /// of each quad as that path does; a dropped pixel's lane runs as a
    /// helper (its neighbours' results do not depend on it) and a quad
    /// without pixels is not written.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn shade_strip<'p>(
        &self,
        target: &mut QuickTarget,
        o: usize,
        batch: &mut Batch,
        slots: &mut [Entry<'p>; LANES / 4],
        (prim, index, (qx, qy)): (&'p Prim, u32, (i64, i64)),
        in_place: &mut InPlace,
    ) -> Result<(), ExecError> {
        let planes = &prim.planes;
        let (x, y) = prim.offsets((qx, qy), &STRIP_X, &STRIP_Y);
        // Without window z every pixel is live and the entries are only
        // needed by the quad-at-a-time write (set just before it).
        let live_mask = match self.window_z {
            true => self.strip_slots(target, slots, prim, index, (qx, qy), &x, &y),
            false => 0xffff,
        };
        if live_mask == 0 {
            return Ok(());
        }
        self.zero_outputs(batch);
        batch.active = quads_mask(LANES / 4);
        batch.helper = batch.active & !live_mask;
        batch.discarded = 0;
        let rw = planes.reciprocal_w(&x, &y);
        let varyings = self.prim_attrs(prim);
        let me = prim as *const Prim;
        if in_place.prim == Some(me) {
            // After a strip of this primitive (stages only read their
            // inputs): its constant varyings are in place.
            let list = in_place.varying.get(..in_place.count).unwrap_or(&[]);
            for l in list.iter().filter_map(|&i| self.fills.get(i as usize)) {
                if let (Some(lanes), Some(p)) = (batch.inputs.get_mut(l.offset), varyings.get(l.li))
                {
                    *lanes = p.values(&x, &y, &rw);
                }
            }
        } else {
            let mut count = 0;
            for (i, l) in self.fills.iter().enumerate() {
                if let (Some(lanes), Some(p)) = (batch.inputs.get_mut(l.offset), varyings.get(l.li))
                {
                    *lanes = p.values(&x, &y, &rw);
                    if p.kind != Kind::Constant {
                        if let Some(v) = in_place.varying.get_mut(count) {
                            *v = i as u16;
                        }
                        count += 1;
                    }
                }
            }
            // (Too many varying inputs to list: filled in full each time.)
            let fits = count <= in_place.varying.len() && self.fills.len() <= u16::MAX as usize;
            in_place.count = count;
            in_place.prim = fits.then_some(me);
        }
        self.run_shader(batch)?;
        // Every pixel passing (no depth test: the write does not test
        // one), none discarded: the strip's two rows at once.
        if live_mask == 0xffff && batch.discarded == 0 && self.layout.frag_depth.is_none() {
            if let Some([r, g, b, a]) = batch.outputs.get(o..o + 4) {
                if target.write_strip(self.isa, (qx, qy), [r, g, b, a]) {
                    return Ok(());
                }
            }
        }
        if !self.window_z {
            self.strip_slots(target, slots, prim, index, (qx, qy), &x, &y);
        }
        self.write_quick(target, o, batch, &slots[..]);
        Ok(())
    }

    /// The entries of a strip's four quads (see
    /// [`FragmentStage::shade_strip`]): position, coverage and, with
    /// window z, the quads' depths and the early depth test; returns the
    /// live pixels (bit 4k + j: pixel j of quad k).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn strip_slots<'p>(
        &self,
        target: &QuickTarget,
        slots: &mut [Entry<'p>; LANES / 4],
        prim: &'p Prim,
        index: u32,
        (qx, qy): (i64, i64),
        x: &[f32; LANES],
        y: &[f32; LANES],
    ) -> u32 {
        let z = match self.window_z {
            true => prim.planes.z_at(x, y),
            false => [0.0; LANES],
        };
        let mut live_mask = 0u32;
        for (k, e) in slots.iter_mut().enumerate() {
            e.prim = Some(prim);
            e.index = index;
            e.write = 0;
            let q = &mut e.quad;
            (q.x, q.y, q.live) = (qx + 2 * k as i64, qy, 0xf);
            if self.window_z {
                let iz = [z[4 * k], z[4 * k + 1], z[4 * k + 2], z[4 * k + 3]];
                (q.z, q.zf) = window_depths(&iz, prim.z_offset);
                if self.early {
                    q.live = target.depth_live((q.x, q.y), q.live, q.zf);
                }
            }
            live_mask |= (q.live as u32) << (4 * k);
        }
        live_mask
    }

    /// [`FragmentStage::flush_batched`] into `sink`.
    #[inline(always)]
    fn flush_sink(
        &self,
        sink: &mut Sink,
        origin: (u32, u32),
        batch: &mut Batch,
        pending: &[Entry],
    ) -> Result<(), ExecError> {
        match sink {
            Sink::Quick(target, o) => {
                self.fill(batch, pending, &self.fills, false);
                self.run_shader(batch)?;
                self.write_quick(target, *o, batch, pending);
                Ok(())
            }
            Sink::General(fb, quick) => {
                self.flush_batched(fb, origin, batch, pending, quick.as_ref())
            }
        }
    }

    /// Whether [`FragmentStage::shade_batched`] gives the bytes of
    /// [`FragmentStage::shade`]: no early rejection at all, or one that
    /// stays right against an older depth buffer: no stencil test, and a
    /// depth function for which stored depths only move one way
    /// (LESS/LEQUAL: down, GREATER/GEQUAL: up; NEVER/ALWAYS do not look),
    /// or no depth writes. Never with the debugger's probe.
    pub fn batches_primitives(&self, fb: &Framebuffer) -> bool {
        use crate::state::CompareFunc::*;
        if self.probe.is_some() {
            return false;
        }
        if !self.early {
            return true;
        }
        let stencil = self.state.stencil.is_some() && fb.stencil.is_some();
        let monotone = match self.state.depth_test {
            None => true,
            Some(_) if !self.state.depth_mask => true,
            Some(f) => matches!(
                f,
                Less | LessEqual | Greater | GreaterEqual | Never | Always
            ),
        };
        !stencil && monotone
    }

    /// Drops the lanes of `quad` that the stencil or depth test will
    /// certainly reject without side effects (no gl_FragDepth write).
    #[inline(always)]
    fn early_rejects(&self, fb: &Framebuffer, origin: (u32, u32), prim: &Prim, quad: &mut Quad) {
        if self.probe.is_none() && (self.state.stencil.is_none() || fb.stencil.is_none()) {
            // No stencil test: a lane is rejected exactly when it fails
            // the depth test (`fragment_ops::early_reject` without a
            // stencil face), and never without one.
            let (Some(func), Some(depth)) = (self.state.depth_test, fb.depth.as_deref()) else {
                return;
            };
            let at = (quad.x - origin.0 as i64, quad.y - origin.1 as i64);
            let size = (fb.width, fb.height);
            quad.live = fragment_ops::depth_live_in(func, depth, size, at, quad.live, quad.zf);
            return;
        }
        for k in 0..4usize {
            if quad.live & (1 << k) == 0 {
                continue;
            }
            let (x, y) = quad.pixel(k);
            let (lx, ly) = (x - origin.0 as i64, y - origin.1 as i64);
            if lx < 0 || ly < 0 || lx >= fb.width as i64 || ly >= fb.height as i64 {
                continue;
            }
            let index = ly as usize * fb.width as usize + lx as usize;
            let zf = quad.zf[k];
            if fragment_ops::early_reject(fb, self.state, index, zf, prim.back) {
                quad.live &= !(1 << k);
                if let Some(p) = self.probe.filter(|p| p.at(x, y)) {
                    p.early_rejected(fb, self.state, index, prim, quad.z[k]);
                }
            }
        }
    }

    /// Writes the fragment inputs of `pending` (quad `q` in lanes
    /// `4q..4q + 4`; at most `LANES / 4` quads) that `plan` lists, zeroes
    /// the outputs, and sets the active and helper lanes. Varyings are
    /// interpolated with each quad's per-pixel weights, in f64:
    /// `0 + w0·v0 + w1·v1 + w2·v2` for triangles, `0 + w0·v0 + w1·v1` for
    /// lines; vertex 0's value for points and flat-shaded colours.
    ///
    /// Inputs the plan leaves out are not touched: they are zero from
    /// [`new_batch`] when no plan of the draw lists them, and only read by
    /// a stage that does not read them otherwise (stages never write their
    /// inputs). With fewer than `LANES / 4` quads every input is cleared
    /// first, so the lanes of absent quads read zeros.
    ///
    /// With `packed`, [`FragmentStage::fill_packed_with`]'s batch instead.
    fn fill(&self, batch: &mut Batch, pending: &[Entry], plan: &[FillLink], packed: bool) {
        match self.isa {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 | Isa::Avx512 => {
                // SAFETY: `isa` is only Avx2 or Avx512 when the CPU has
                // AVX2 and the bit-count instructions (`simd::detect`).
                unsafe { self.fill_avx2(batch, pending, plan, packed) }
            }
            _ => self.fill_with(batch, pending, plan, packed),
        }
    }

    /// [`FragmentStage::fill`] compiled for AVX2 (the same operations:
    /// four pixels' f64 arithmetic in one register instead of two).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt")]
    unsafe fn fill_avx2(
        &self,
        batch: &mut Batch,
        pending: &[Entry],
        plan: &[FillLink],
        packed: bool,
    ) {
        self.fill_with(batch, pending, plan, packed)
    }

    #[inline(always)]
    fn fill_with(&self, batch: &mut Batch, pending: &[Entry], plan: &[FillLink], packed: bool) {
        if packed {
            return self.fill_packed_with(batch, pending, plan);
        }
        let pending = pending.get(..LANES / 4).unwrap_or(pending);
        if pending.len() < LANES / 4 {
            for c in batch.inputs.iter_mut() {
                *c = [0.0; LANES];
            }
        }
        self.zero_outputs(batch);
        let mut live_mask = 0u32;
        for (q, e) in pending.iter().enumerate() {
            live_mask |= (e.quad.live as u32) << (4 * q);
        }
        let active = quads_mask(pending.len());
        batch.active = active;
        batch.helper = active & !live_mask;
        batch.discarded = 0;

        // Quad q in lanes 4q..4q + 4, its pixels in order.
        self.write_inputs(batch, pending, plan, |q, _| Place {
            order: [0, 1, 2, 3],
            count: 4,
            first: 4 * q,
        });
    }

    /// The lanes of `pending`'s quads in `e.write` (each quad's in pixel
    /// order, the quads one after another: at most [`LANES`] in all) as
    /// one batch without helper lanes, for a stage whose lanes are
    /// independent ([`ShaderStage::lanes_independent`]). Every lane gets
    /// the inputs [`FragmentStage::fill`] gives its pixel (the same f64
    /// arithmetic), so its outputs are those of the quad-at-once path.
    /// Lanes past the last are zero.
    #[inline(always)]
    fn fill_packed_with(&self, batch: &mut Batch, pending: &[Entry], plan: &[FillLink]) {
        let mut total = 0;
        for e in pending {
            total += (e.write & 0xf).count_ones() as usize;
        }
        let total = total.min(LANES);
        self.zero_outputs(batch);
        batch.active = lanes_mask(total);
        batch.helper = 0;
        batch.discarded = 0;
        // Each quad's pixels to run from the lane after the previous
        // quad's.
        let mut firsts = [0usize; LANES];
        let mut first = 0;
        for (f, e) in firsts.iter_mut().zip(pending) {
            *f = first;
            first += (e.write & 0xf).count_ones() as usize;
        }
        self.write_inputs(batch, pending, plan, |q, e| {
            let run = e.write & 0xf;
            Place {
                order: COMPRESS[run as usize],
                count: run.count_ones() as usize,
                first: firsts.get(q).copied().unwrap_or(LANES),
            }
        });
        // Lanes past the last read zeros (as absent quads' do in `fill`),
        // also where the last quad's unused values landed.
        if total < LANES {
            for l in plan {
                if let Some(lanes) = batch.inputs.get_mut(l.offset) {
                    for x in lanes.iter_mut().skip(total) {
                        *x = 0.0;
                    }
                }
            }
        }
    }

    /// Writes the inputs `plan` lists, and gl_FragCoord, gl_FrontFacing
    /// and gl_PointCoord where the stage reads them, for the pixels of
    /// each quad of `pending` that `place` puts in lanes: each varying
    /// evaluated from its plane at those pixels (`crate::interpolate`),
    /// gl_PointCoord on point sprites for the coordinates it replaces. A
    /// quad's four values are stored from its first lane on: those of
    /// pixels it does not run land where the next quad's go (quads are
    /// placed in increasing lane order) or past the last lane, for the
    /// caller to clear.
    #[inline(always)]
    fn write_inputs(
        &self,
        batch: &mut Batch,
        pending: &[Entry],
        plan: &[FillLink],
        place: impl Fn(usize, &Entry) -> Place,
    ) {
        let layout = self.layout;
        let sprite = self.state.point_sprite;
        let lower_left = self.state.point_sprite_origin_lower_left;
        let point_coords = |quad: &Quad, prim: &Prim, order: [u8; 4]| -> [(f32, f32); 4] {
            order.map(|k| {
                let (x, y) = quad.pixel(k as usize & 3);
                prim.shape.point_coord(x, y, lower_left)
            })
        };
        let pixel_inputs = layout.frag_coord.is_some()
            || layout.front_facing.is_some()
            || layout.point_coord.is_some();
        for (q, e) in pending.iter().enumerate() {
            let (Some(prim), quad) = (e.prim, &e.quad) else {
                continue;
            };
            let Place {
                order,
                count,
                first,
            } = place(q, e);
            // The pixels of `order`, in that order.
            let planes = &prim.planes;
            let ox = order.map(|k| QUAD_X[k as usize & 3]);
            let oy = order.map(|k| QUAD_Y[k as usize & 3]);
            let (x, y) = prim.offsets((quad.x, quad.y), &ox, &oy);
            let rw = planes.reciprocal_w(&x, &y);
            let varyings = self.prim_attrs(prim);
            let sprite = sprite && matches!(prim.shape, Shape::Point { .. });
            let inputs = &mut batch.inputs[..];
            for l in plan {
                let Some(lanes) = inputs.get_mut(l.offset) else {
                    continue;
                };
                let values: [f32; 4] = match l.kind {
                    FillKind::Replace(c) if sprite => {
                        point_coords(quad, prim, order).map(|pc| [pc.0, pc.1, 0.0, 1.0][c])
                    }
                    _ => match varyings.get(l.li) {
                        Some(p) => p.values(&x, &y, &rw),
                        None => [0.0; 4],
                    },
                };
                put_quad(lanes, first, values);
            }
            if !pixel_inputs {
                continue;
            }
            let pc = match prim.shape {
                Shape::Point { .. } => point_coords(quad, prim, order),
                _ => [(0.0, 0.0); 4],
            };
            let inv_w = planes.inv_w_at(&x, &y);
            for (i, (lane, k)) in (first..LANES).zip(order).enumerate().take(count) {
                let k = k as usize & 3;
                let (px, py) = quad.pixel(k);
                if let Some(o) = layout.frag_coord {
                    set(batch, o, lane, px as f32 + 0.5);
                    set(batch, o + 1, lane, py as f32 + 0.5);
                    set(batch, o + 2, lane, quad.z[k] as f32);
                    set(batch, o + 3, lane, inv_w[i]);
                }
                if let Some(o) = layout.front_facing {
                    set(batch, o, lane, if prim.back { 0.0 } else { 1.0 });
                }
                if let Some(o) = layout.point_coord {
                    set(batch, o, lane, pc[i].0);
                    set(batch, o + 1, lane, pc[i].1);
                }
            }
        }
    }

    /// Sets `frag` to the fragment of lane `4q + k` after shading; false
    /// when the lane is not covered, was discarded or lies left of /
    /// below the window. Only the colours of `colors_out` are written
    /// (the others stay as they were: zero).
    fn fragment_into(
        &self,
        batch: &Batch,
        quad: &Quad,
        q: usize,
        k: usize,
        back: bool,
        frag: &mut Fragment,
    ) -> bool {
        let lane = 4 * q + k;
        if quad.live & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
            return false;
        }
        let (x, y) = quad.pixel(k);
        if x < 0 || y < 0 {
            return false;
        }
        frag.x = x as u32;
        frag.y = y as u32;
        frag.z = self.frag_z(batch, lane, quad, k);
        frag.back_facing = back;
        self.colors_into(batch, lane, &mut frag.colors);
        true
    }

    /// The fragment's window z after the shader: gl_FragDepth when the
    /// shader writes it (GL 2.1 §3.11.2, clamped to [0, 1] on conversion),
    /// else the interpolated z.
    fn frag_z(&self, batch: &Batch, lane: usize, quad: &Quad, k: usize) -> f32 {
        let z = match self.layout.frag_depth {
            Some(o) => get(batch, o, lane),
            None => quad.z[k] as f32,
        };
        clamp01(z as f64) as f32
    }

    /// Writes lane `lane`'s colours of `colors_out` into `colors`.
    fn colors_into(&self, batch: &Batch, lane: usize, colors: &mut [[f32; 4]; MAX_DRAW_BUFFERS]) {
        for &(i, o) in &self.colors_out {
            if let Some(c) = colors.get_mut(i) {
                for (j, v) in c.iter_mut().enumerate() {
                    *v = get(batch, o + j, lane);
                }
            }
        }
    }

    fn flush(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        prim: &Prim,
        pending: &[Entry],
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        self.fill(batch, pending, &self.fills, false);
        let live_mask = batch.active & !batch.helper;
        let probed = self.probe.and_then(|p| {
            let lane = pending.iter().enumerate().find_map(|(q, e)| {
                (0..4).find_map(|k| {
                    let (x, y) = e.quad.pixel(k);
                    (p.at(x, y) && live_mask & (1 << (4 * q + k)) != 0).then_some(4 * q + k)
                })
            })?;
            Some((p, lane))
        });
        let pixel_of = |l: usize| Some(pending.get(l / 4)?.quad.pixel(l % 4));
        let mut record = None;
        let mut watched = Vec::new();
        match probed {
            Some((p, lane)) => {
                if p.prints_others() {
                    // The other lanes' prints: the same batch run once
                    // more (runs are deterministic).
                    let mut copy = batch.clone();
                    p.print_batch(
                        (self.shader, self.uniforms, self.textures),
                        &mut copy,
                        prim.source,
                        |l| pixel_of(l).filter(|_| l != lane),
                    )?;
                }
                let z = pending.get(lane / 4).map_or(0.0, |e| e.quad.z[lane % 4]);
                let mut r = p.begin(prim, batch, lane, z);
                let result =
                    self.shader
                        .run_probed(batch, self.uniforms, self.textures, lane, &mut r);
                r.finish(batch, lane, result.as_ref().err());
                result?;
                record = Some((p, lane, r));
            }
            None => {
                if let Some((p, view)) = self.probe.and_then(|p| Some((p, p.view()?))) {
                    watched =
                        p.run_view((self.shader, self.uniforms, self.textures), batch, view)?;
                } else if let Some(p) = self.probe {
                    p.print_batch(
                        (self.shader, self.uniforms, self.textures),
                        batch,
                        prim.source,
                        pixel_of,
                    )?;
                } else {
                    self.run_shader(batch)?;
                }
            }
        }

        let mut frag = Fragment {
            x: 0,
            y: 0,
            z: 0.0,
            back_facing: false,
            colors: [[0.0; 4]; MAX_DRAW_BUFFERS],
        };
        for (q, e) in pending.iter().enumerate() {
            for k in 0..4 {
                let lane = 4 * q + k;
                if !self.fragment_into(batch, &e.quad, q, k, prim.back, &mut frag) {
                    continue;
                }
                let passed = match record.as_mut().filter(|r| r.1 == lane) {
                    Some((p, _, r)) => p.process(fb, origin, self.state, &frag, r),
                    None => fragment_ops::process(fb, origin, self.state, &frag),
                };
                if let (true, Some(p)) = (passed && !watched.is_empty(), self.probe) {
                    p.view_store(frag.x, frag.y, &watched, lane);
                }
            }
        }
        if let Some((p, _, r)) = record {
            p.push(r);
        }
        Ok(())
    }

    /// The primitives `bin` (indices into `prims`, in draw order) inside
    /// `tile`, shading colors only for the fragments that end up visible.
    /// Only for a stage with [`FragmentStage::deferred`] and per-fragment
    /// operations where the last fragment to pass the depth test decides
    /// a pixel's color ([`fragment_ops::last_writer_wins`]).
    ///
    /// Pass 1 runs the depth-only slice on every fragment (without
    /// gl_FragDepth: every fragment early depth rejection keeps), four
    /// quads at a time, and sends them through the depth test in draw
    /// order, keeping
    /// per pixel the primitive of the last fragment that passed (and that
    /// quad's coverage). Pass 2 runs the full shader once per (primitive,
    /// quad) that won a pixel, with the same quad inputs, coverage and
    /// helper lanes as the straightforward path, and writes the colors of
    /// the winning pixels. The slice computes the same gl_FragDepth and
    /// discards as the full shader, and a lane depends only on its quad, so
    /// the tile ends with the same bytes as [`FragmentStage::shade`] over
    /// the bin. On an error `fb` is left partly drawn: the caller redraws
    /// the tile the straightforward way to get the same error and pixels.
    pub fn shade_deferred<'p>(
        &self,
        depth: &dyn ShaderStage,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        match self.isa {
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `isa` is only Avx512 when the CPU has the features
            // (`simd::detect`).
            Isa::Avx512 => unsafe {
                self.shade_deferred_avx512(depth, fb, prims, bin, tile, scratch)
            },
            #[cfg(target_arch = "x86_64")]
            // SAFETY: likewise for AVX2.
            Isa::Avx2 => unsafe { self.shade_deferred_avx2(depth, fb, prims, bin, tile, scratch) },
            _ => self.shade_deferred_with(depth, fb, prims, bin, tile, scratch),
        }
    }

    /// [`FragmentStage::shade_deferred`] compiled for AVX2 (its quad
    /// loops, depth tests and f64 quad set-up inlined: the same
    /// operations).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt")]
    unsafe fn shade_deferred_avx2<'p>(
        &self,
        depth: &dyn ShaderStage,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        self.shade_deferred_with(depth, fb, prims, bin, tile, scratch)
    }

    /// [`FragmentStage::shade_deferred`] compiled for AVX-512.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt,avx512f,avx512dq,avx512vl")]
    unsafe fn shade_deferred_avx512<'p>(
        &self,
        depth: &dyn ShaderStage,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        self.shade_deferred_with(depth, fb, prims, bin, tile, scratch)
    }

    /// The depth pass of [`FragmentStage::shade_deferred`] on the quads
    /// `pending`: the slice (when it runs), then the depth test of every
    /// fragment left, in order, keeping in `winner` each pixel's last.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn depth_pass(
        &self,
        pass: &DeferredPass,
        fb: &mut Framebuffer,
        batch: &mut Batch,
        winner: &mut [(u32, u8)],
        pending: &[Entry],
    ) -> Result<(), ExecError> {
        if pass.run_slice {
            self.fill(batch, pending, &self.depth_fills, pass.pack_depth);
            self.run_depth(pass.depth, batch)?;
        } else {
            batch.discarded = 0;
        }
        // Per quad: the pixels still alive (covered, not discarded) and
        // their window z, then their depth tests.
        let mut next = 0;
        let mut alive_z = |q: usize, e: &Entry| {
            let quad = &e.quad;
            let mut alive = 0u8;
            let mut z = [0f32; 4];
            for (k, z) in z.iter_mut().enumerate() {
                let Some(lane) = lane_of(pass.pack_depth, q, e, k, &mut next) else {
                    continue;
                };
                if quad.live & (1 << k) != 0 && batch.discarded & (1 << lane) == 0 {
                    alive |= 1 << k;
                    *z = self.frag_z(batch, lane, quad, k);
                }
            }
            (alive, z)
        };
        match &pass.quick {
            Some(q) => {
                // A quad's four pixels are distinct: tested together as
                // one after the other.
                let mut target = q.target(fb, pass.origin);
                for (q, e) in pending.iter().enumerate() {
                    let (alive, z) = alive_z(q, e);
                    if alive == 0 {
                        continue;
                    }
                    let quad = &e.quad;
                    let zf = match self.layout.frag_depth {
                        Some(_) => z.map(depth_to_fixed),
                        None => quad.zf,
                    };
                    let (pass, index, _) = target.test_quad((quad.x, quad.y), alive, z, zf);
                    for (k, &at) in index.iter().enumerate() {
                        if pass & (1 << k) != 0 {
                            if let Some(slot) = winner.get_mut(at) {
                                *slot = (e.index, quad.live);
                            }
                        }
                    }
                }
            }
            None => {
                for (q, e) in pending.iter().enumerate() {
                    let (alive, z) = alive_z(q, e);
                    let quad = &e.quad;
                    for (k, &z) in z.iter().enumerate() {
                        let (x, y) = quad.pixel(k);
                        if alive & (1 << k) == 0 || x < 0 || y < 0 {
                            continue;
                        }
                        let frag = Fragment {
                            x: x as u32,
                            y: y as u32,
                            z,
                            back_facing: e.prim.is_some_and(|p| p.back),
                            colors: [[0.0; 4]; MAX_DRAW_BUFFERS],
                        };
                        let passed = fragment_ops::tests(fb, pass.origin, self.state, &frag);
                        if let Some(slot) = passed.and_then(|i| winner.get_mut(i)) {
                            *slot = (e.index, quad.live);
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// The colour pass of [`FragmentStage::shade_deferred`] on the quads
    /// `todo`: the full shader, then the colours of the pixels each quad
    /// won (`Entry::write`).
    #[inline(always)]
    fn color_pass(
        &self,
        pass: &DeferredPass,
        fb: &mut Framebuffer,
        batch: &mut Batch,
        todo: &[Entry],
    ) -> Result<(), ExecError> {
        self.fill(batch, todo, &self.fills, pass.pack_colors);
        self.run_shader(batch)?;
        // (lane, pixel index) of the fragments to write, in order.
        let mut writes = [(0usize, 0usize); LANES];
        let mut count = 0;
        let mut next = 0;
        for (q, e) in todo.iter().enumerate() {
            for k in 0..4 {
                let Some(lane) = lane_of(pass.pack_colors, q, e, k, &mut next) else {
                    continue;
                };
                if e.write & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
                    continue;
                }
                let (x, y) = e.quad.pixel(k);
                let lx = x as usize - pass.origin.0 as usize;
                let ly = y as usize - pass.origin.1 as usize;
                if let Some(slot) = writes.get_mut(count) {
                    *slot = (lane, ly * fb.width as usize + lx);
                    count += 1;
                }
            }
        }
        let writes = &writes[..count];
        match pass.quick.and_then(|q| Some((q, q.color_output()?))) {
            Some((q, o)) => {
                let mut target = q.target(fb, pass.origin);
                match batch.outputs.get(o..o + 4) {
                    // Without blending, the batch's colours converted
                    // together (as `write_quick` does).
                    Some([r, g, b, a]) if target.opaque() => {
                        let rgba = fragment_ops::unorm8_batch(self.isa, [r, g, b, a]);
                        for &(lane, index) in writes {
                            if let Some(&c) = rgba.get(lane) {
                                target.write_rgba8(index, c);
                            }
                        }
                    }
                    _ => {
                        for &(lane, index) in writes {
                            target.write(index, [0, 1, 2, 3].map(|j| get(batch, o + j, lane)));
                        }
                    }
                }
            }
            None => {
                let mut colors = [[0.0; 4]; MAX_DRAW_BUFFERS];
                for &(lane, index) in writes {
                    self.colors_into(batch, lane, &mut colors);
                    fragment_ops::write_colors(fb, index, self.state, &colors);
                }
            }
        }
        Ok(())
    }

    #[inline(always)]
    fn shade_deferred_with<'p>(
        &self,
        depth: &dyn ShaderStage,
        fb: &mut Framebuffer,
        prims: &[&'p Prim],
        bin: &[u32],
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let (w, h) = (fb.width as usize, fb.height as usize);
        let Scratch {
            batch,
            slots,
            n,
            quads,
            packed,
        } = scratch;
        *n = 0;
        // Per pixel: (winning primitive, its quad's coverage).
        let mut winner: Vec<(u32, u8)> = vec![(NO_PRIM, 0); w * h];
        // Without gl_FragDepth a fragment's depth is known before the
        // slice runs: lanes the depth test will reject are dropped first
        // when that stays right against a depth buffer missing the
        // pending batch (as for `shade_batched`). A rejected lane cannot
        // win; a winner's quad keeps the coverage the forward path gives
        // it.
        let early = self.early && self.batches_primitives(fb);
        let quick = QuickOps::new(fb, self.state, &self.colors_out);
        // A slice without ops (no gl_FragDepth, no discard) decides
        // nothing: the pass only depth-tests.
        let run_slice = !depth.does_nothing() || self.layout.frag_depth.is_some();
        // Stages whose lanes are independent run the covered pixels of up
        // to `LANES` quads per batch, without helper lanes.
        let pack_depth = run_slice && self.deferred_lanes_independent;
        let pack_colors = self.lanes_independent;
        let pass = DeferredPass {
            depth,
            origin,
            quick,
            run_slice,
            pack_depth,
            pack_colors,
        };
        // Nothing to run and the common per-fragment operations: each
        // quad is depth-tested as soon as it is covered (the order and the
        // tests of the batched pass, which would only run the empty slice).
        match quick.as_ref().filter(|_| !run_slice) {
            Some(q) => {
                let mut target = q.target(fb, origin);
                for (i, &p) in bin.iter().enumerate() {
                    let Some(&prim) = prims.get(p as usize) else {
                        continue;
                    };
                    // (The pass interpolates nothing.)
                    self.prefetch_ahead(prims, bin, i, false);
                    let clip = clip_to(prim, tile);
                    prim.shape.quads_each(
                        clip,
                        quads,
                        #[inline(always)]
                        |qx, qy, live| {
                            let (z, zf) = quad_depths(prim, (qx, qy));
                            // The f32 z only for a quad tested pixel by pixel.
                            let z = || z.map(|z| z as f32);
                            let (pass, index, _) = target.test_quad_with((qx, qy), live, z, zf);
                            for (k, &at) in index.iter().enumerate() {
                                if pass & (1 << k) != 0 {
                                    if let Some(slot) = winner.get_mut(at) {
                                        *slot = (p, live);
                                    }
                                }
                            }
                        },
                    );
                }
            }
            None => {
                let pending: &mut [Entry<'p>] = match pack_depth {
                    true => &mut packed[..],
                    false => &mut slots[..],
                };
                let mut lanes = 0;
                for (i, &p) in bin.iter().enumerate() {
                    let Some(&prim) = prims.get(p as usize) else {
                        continue;
                    };
                    self.prefetch_ahead(prims, bin, i, pass.run_slice);
                    prim.shape.quads_into(clip_to(prim, tile), quads);
                    for &quad in quads.iter() {
                        let Some(e) = pending.get_mut(*n) else { break };
                        e.set(prim, p, quad, 0, self.window_z);
                        if early {
                            self.early_rejects(fb, origin, prim, &mut e.quad);
                            if e.quad.live == 0 {
                                continue;
                            }
                        }
                        e.write = e.quad.live;
                        let write = e.write;
                        if let Some((count, spill)) = admit(pack_depth, n, &mut lanes, write) {
                            self.depth_pass(&pass, fb, batch, &mut winner, &pending[..count])?;
                            if spill {
                                pending.swap(0, count);
                            }
                        }
                    }
                }
                if *n > 0 {
                    self.depth_pass(&pass, fb, batch, &mut winner, &pending[..*n])?;
                    *n = 0;
                }
            }
        }

        // Pass 2: (primitive, quad, coverage, lanes to write) per winner.
        let pending: &mut [Entry<'p>] = match pack_colors {
            true => &mut packed[..],
            false => &mut slots[..],
        };
        let mut used = 0;
        // The depth tests are behind: the window z only for gl_FragCoord
        // or the probe.
        let window_z = self.layout.frag_coord.is_some() || self.probe.is_some();
        for ly in (0..h).step_by(2) {
            for lx in (0..w).step_by(2) {
                // The quad's pixels (lane order) and their winners.
                let mut lanes = [(NO_PRIM, 0u8); 4];
                for (k, lane) in lanes.iter_mut().enumerate() {
                    let (x, y) = (lx + (k & 1), ly + (k >> 1));
                    if x < w && y < h {
                        *lane = winner.get(y * w + x).copied().unwrap_or((NO_PRIM, 0));
                    }
                }
                let mut done = 0u8;
                for k in 0..4 {
                    let (p, live) = lanes[k];
                    if p == NO_PRIM || done & (1 << k) != 0 {
                        continue;
                    }
                    let mut write = 0u8;
                    for (j, lane) in lanes.iter().enumerate() {
                        if lane.0 == p {
                            write |= 1 << j;
                        }
                    }
                    done |= write;
                    let Some(&prim) = prims.get(p as usize) else {
                        continue;
                    };
                    let (qx, qy) = (origin.0 as i64 + lx as i64, origin.1 as i64 + ly as i64);
                    let Some(e) = pending.get_mut(*n) else { break };
                    self.prefetch_attrs(prim);
                    e.set(prim, p, (qx, qy, live), write, window_z);
                    if let Some((count, spill)) = admit(pack_colors, n, &mut used, write) {
                        self.color_pass(&pass, fb, batch, &pending[..count])?;
                        if spill {
                            pending.swap(0, count);
                        }
                    }
                }
            }
        }
        if *n > 0 {
            self.color_pass(&pass, fb, batch, &pending[..*n])?;
            *n = 0;
        }
        Ok(())
    }
}

#[cfg(test)]
thread_local! {
    /// Tests: whether draws on this thread may use strips.
    static NO_STRIPS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether [`FragmentStage::strips`] may be set (tests turn them off to
/// compare).
fn strips_allowed() -> bool {
    #[cfg(test)]
    if NO_STRIPS.with(|c| c.get()) {
        return false;
    }
    true
}

/// Tests: runs `f` without strips on this thread (draws on one thread run
/// there).
#[cfg(test)]
pub(crate) fn without_strips<T>(f: impl FnOnce() -> T) -> T {
    let old = NO_STRIPS.with(|c| c.replace(true));
    let out = f();
    NO_STRIPS.with(|c| c.set(old));
    out
}

/// Asks the CPU to bring the cache lines of `data` closer (a hint with
/// no effect on results; nothing on targets without one).
#[inline(always)]
fn prefetch<T>(data: &[T]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let start = data.as_ptr() as *const i8;
        let bytes = std::mem::size_of_val(data);
        // Every line from the first byte's to the last byte's: from the
        // start of the first line, 64 bytes at a time.
        let skew = start as usize % 64;
        let mut offset = 0;
        while offset < bytes + skew {
            // SAFETY: a prefetch is a hint: it never faults and reads
            // nothing the program sees (the address may be before `data`
            // in its first line).
            unsafe { _mm_prefetch::<_MM_HINT_T0>(start.wrapping_sub(skew).wrapping_add(offset)) }
            offset += 64;
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = data;
}

/// `prim`'s bounds inside `tile` (an area of its shape:
/// `Shape::area`).
fn clip_to(prim: &Prim, tile: PixelRect) -> PixelRect {
    (
        prim.bounds.0.max(tile.0),
        prim.bounds.1.max(tile.1),
        prim.bounds.2.min(tile.2),
        prim.bounds.3.min(tile.3),
    )
}

fn set(batch: &mut Batch, component: usize, lane: usize, value: f32) {
    if let Some(c) = batch.inputs.get_mut(component) {
        if let Some(l) = c.get_mut(lane) {
            *l = value;
        }
    }
}

fn get(batch: &Batch, component: usize, lane: usize) -> f32 {
    batch
        .outputs
        .get(component)
        .and_then(|c| c.get(lane))
        .copied()
        .unwrap_or(0.0)
}
