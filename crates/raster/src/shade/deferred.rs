//! The fragment stage's deferred (two-pass) loop: the depth-only slice on
//! every fragment, then the full shader once per visible (primitive,
//! quad). Takes a tile and its bin; gives the tile's pixels, the same
//! bytes as [`FragmentStage::shade`] over the bin (tests compare them).
//! See [`FragmentStage::shade_deferred`].

use super::*;
use crate::ex;
use crate::interpolate::Region;
use crate::state::CompareFunc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// The lanes of the four pixels of `e`, the `q`-th quad of a batch, and
/// the pixels that have one: `4q + k` for every pixel, or in a packed
/// batch the pixels the quad runs (`e.write`), in order, from lane
/// `*next` on (then counted). Called for the quads in order.
#[inline(always)]
fn quad_lanes(packed: bool, q: usize, e: &Entry, next: &mut usize) -> ([usize; 4], u8) {
    if !packed {
        return ([0, 1, 2, 3].map(|k| 4 * q + k), 0xf);
    }
    let run = e.write & 0xf;
    let first = *next;
    *next += run.count_ones() as usize;
    let before = |k: u8| (run & ((1u8 << k) - 1)).count_ones() as usize;
    ([0, 1, 2, 3].map(|k| first + before(k)), run)
}

/// Whether lane `lane` of `mask` is set (lanes past the mask's are not).
#[inline(always)]
fn lane_set(mask: exec::LaneMask, lane: usize) -> bool {
    lane < LANES && mask & (1 << lane) != 0
}

/// The depth test under `func` (LESS, LEQUAL, GREATER or GEQUAL) of the
/// pixels `alive` of the quad at `(lx, ly)` (tile coordinates) of
/// primitive `p`, at the fixed-point depths `zf`, in a tile whose
/// primitives run out of draw order: a pixel passes when its depth beats
/// the stored one, or equals it and draw order would have let it pass
/// last: for LESS and GREATER when it comes before the pixel's winner
/// `winner` (the first of equal depths stays), for LEQUAL and GEQUAL
/// after it (the last stays); a depth stored before the draw (no winner)
/// comes before every fragment. So each pixel ends with the depth and
/// the winner that draw order gives. Writes the depths that pass and
/// returns those pixels and their indices.
#[inline(always)]
fn unordered_test(
    (depth, winner, width): (&mut [u32], &[(u32, u8)], usize),
    func: CompareFunc,
    (lx, ly): (i64, i64),
    (alive, zf, p): (u8, [u32; 4], u32),
) -> (u8, [usize; 4]) {
    let first_stays = matches!(func, CompareFunc::Less | CompareFunc::Greater);
    // The comparison without ties: LESS's for LESS and LEQUAL.
    let beats = match func {
        CompareFunc::Less | CompareFunc::LessEqual => CompareFunc::Less,
        _ => CompareFunc::Greater,
    };
    let mut pass = 0u8;
    let mut index = [0usize; 4];
    for (k, (at, &z)) in index.iter_mut().zip(&zf).enumerate() {
        let (x, y) = (lx + (k as i64 & 1), ly + (k as i64 >> 1));
        if alive & (1 << k) == 0 || x < 0 || y < 0 || x >= width as i64 {
            continue;
        }
        *at = y as usize * width + x as usize;
        let (Some(stored), Some(&(w, _))) = (depth.get_mut(*at), winner.get(*at)) else {
            continue;
        };
        let wins = beats.test(z, *stored)
            || (z == *stored
                && match first_stays {
                    true => w != NO_PRIM && p < w,
                    false => w == NO_PRIM || p > w,
                });
        if wins {
            *stored = z;
            pass |= 1 << k;
        }
    }
    (pass, index)
}

/// The depth function a bound is tested with when fragments may meet
/// the depth test out of draw order: one that lets equal depths through
/// (a fragment as deep as the stored one may still win its tie).
fn ties_pass(func: CompareFunc) -> CompareFunc {
    match func {
        CompareFunc::Less => CompareFunc::LessEqual,
        CompareFunc::Greater => CompareFunc::GreaterEqual,
        f => f,
    }
}

/// The pixels of `r` (none when it is empty).
fn rect_area(r: PixelRect) -> u64 {
    ((r.2 - r.0).max(0) * (r.3 - r.1).max(0)) as u64
}

/// How crowded a tile is for its primitives to be taken near first
/// ([`FragmentStage::unordered_func`]): the sum of their areas in the
/// tile against the tile's (a quad's two triangles count twice).
const CROWDED: u64 = 8;

/// The fragments a primitive's depth bound must be expected to reject
/// for the depth pass to find it: a bound costs about two thirds of a
/// microsecond, what the pass spends on a few dozen fragments.
const BOUND_PAYS: u64 = 64;

/// Counts of what depth bounds did, for the tests to see that a scene
/// exercises them: primitives found hidden whole ([`FragmentStage::bound_hides`]),
/// bounds found for two primitives at once (`prim_bound`'s twin), tiles
/// taken near first ([`FragmentStage::near_first`]).
#[cfg(test)]
pub(crate) static BOUND_USES: [AtomicU64; 3] = [const { AtomicU64::new(0) }; 3];

/// When a tile finds depth bounds ([`FragmentStage::shade_deferred`]):
/// for primitives whose expected rejections pay for one, their area
/// times the share of the tile's recent fragments that failed the depth
/// test (at a bound or in the depth pass: what a tight bound would have
/// rejected). The share grows as the tile's depth buffer fills, so the
/// counts decay. Only the time depends on this choice, never the pixels.
#[derive(Default)]
struct BoundPolicy {
    /// Fragments depth-tested recently, and those that failed.
    tested: u64,
    failed: u64,
}

impl BoundPolicy {
    /// Counts that halve past this many fragments tested.
    const WINDOW: u64 = 4096;

    /// Whether to find the bound of a primitive of `area` pixels.
    #[inline(always)]
    fn worth(&mut self, area: u64) -> bool {
        if self.tested > Self::WINDOW {
            self.tested /= 2;
            self.failed /= 2;
        }
        area >= BOUND_PAYS && area * self.failed >= BOUND_PAYS * self.tested.max(1)
    }

    #[inline(always)]
    fn count(&mut self, tested: u32, failed: u32) {
        self.tested += tested as u64;
        self.failed += failed as u64;
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
    /// The depth function when the tile's primitives are depth-tested
    /// out of draw order ([`FragmentStage::unordered_func`]).
    unordered: Option<CompareFunc>,
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

impl<'a> FragmentStage<'a> {
    exec::multiversion! {
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
        ///
        /// Compiled for the stage's level (its quad loops, depth tests and
        /// f64 quad set-up inlined into each copy: the same operations).
        pub fn shade_deferred<'p>(
            &self,
            depth: &dyn ShaderStage,
            fb: &mut Framebuffer,
            prims: &[&'p Prim],
            bin: &[u32],
            tile: PixelRect,
            scratch: &mut Scratch<'p>,
        ) -> Result<(), ExecError>;
        level = self.level,
        copies = [shade_deferred_portable, shade_deferred_avx2, shade_deferred_avx512],
        body = self.shade_deferred_with(depth, fb, prims, bin, tile, scratch)
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
        (winner, policy): (&mut [(u32, u8)], &mut BoundPolicy),
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
        match &pass.quick {
            Some(q) => {
                // A quad's four pixels are distinct: tested together as
                // one after the other, by the target or, out of draw
                // order, here (ties decided by draw order).
                let width = fb.width as usize;
                let (mut target, mut depth) = match pass.unordered {
                    Some(_) => (None, fb.depth.as_deref_mut()),
                    None => (Some(q.target(fb, pass.origin)), None),
                };
                for (q, e) in pending.iter().enumerate() {
                    let (alive, z) = self.alive_z(pass.pack_depth, batch, q, e, &mut next);
                    if alive == 0 {
                        continue;
                    }
                    let quad = &e.quad;
                    let zf = match self.layout.frag_depth {
                        Some(_) => self.depth_format.to_fixed4_f32(z),
                        None => quad.zf,
                    };
                    let (passed, index) = match (&mut target, &mut depth, pass.unordered) {
                        (_, Some(depth), Some(func)) => {
                            let at = (quad.x - pass.origin.0 as i64, quad.y - pass.origin.1 as i64);
                            let with = (&mut **depth, &*winner, width);
                            unordered_test(with, func, at, (alive, zf, e.index))
                        }
                        (Some(t), ..) => {
                            let (pass, index, _) = t.test_quad((quad.x, quad.y), alive, z, zf);
                            (pass, index)
                        }
                        _ => (0, [0; 4]),
                    };
                    policy.count(alive.count_ones(), (alive & !passed).count_ones());
                    for (k, &at) in index.iter().enumerate() {
                        if passed & (1 << k) != 0 {
                            if let Some(slot) = winner.get_mut(at) {
                                *slot = (e.index, quad.live);
                            }
                        }
                    }
                }
            }
            None => {
                for (q, e) in pending.iter().enumerate() {
                    let (alive, z) = self.alive_z(pass.pack_depth, batch, q, e, &mut next);
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
                            colors: [[0.0; 4]; FRAG_COLORS],
                        };
                        let passed = fragment_ops::tests(fb, pass.origin, self.state, &frag);
                        policy.count(1, passed.is_none() as u32);
                        if let Some(slot) = passed.and_then(|i| winner.get_mut(i)) {
                            *slot = (e.index, quad.live);
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// The pixels of `e`, the `q`-th quad of the depth pass's batch
    /// (lanes as [`quad_lanes`] gives them), still alive after the slice
    /// (covered, not discarded), and their window z (0 for the others).
    #[inline(always)]
    fn alive_z(
        &self,
        packed: bool,
        batch: &Batch,
        q: usize,
        e: &Entry,
        next: &mut usize,
    ) -> (u8, [f32; 4]) {
        let quad = &e.quad;
        let (lanes, has) = quad_lanes(packed, q, e, next);
        let mut alive = quad.live & has;
        for (k, &lane) in lanes.iter().enumerate() {
            if lane_set(batch.discarded, lane) {
                alive &= !(1 << k);
            }
        }
        let mut z = [0f32; 4];
        for (k, z) in z.iter_mut().enumerate() {
            if alive & (1 << k) != 0 {
                *z = self.frag_z(batch, lanes[k], quad, k);
            }
        }
        (alive, z)
    }

    /// Makes `e` the quad `quad` of primitive `p` (`prim`) for the depth
    /// pass, with the pixels the early depth test leaves (with `early`)
    /// to run and to write; returns those.
    #[inline(always)]
    fn depth_entry<'p>(
        &self,
        e: &mut Entry<'p>,
        (prim, p): (&'p Prim, u32),
        quad: (i64, i64, u8),
        early: bool,
        fb: &Framebuffer,
        origin: (u32, u32),
    ) -> u8 {
        e.set(prim, p, quad, 0, self.window_z.then_some(self.depth_format));
        if early {
            self.early_rejects(fb, origin, prim, &mut e.quad);
        }
        e.write = e.quad.live;
        e.write
    }

    /// Drops from `quads` (single quads, no strips) the pixels the depth
    /// test `func` rejects at the fixed-point depth `zf` (a primitive's
    /// bound: none of its fragments can beat it), and the quads left
    /// without any; counts the pixels tested and rejected in `policy`.
    fn bound_rejects(
        &self,
        (fb, origin): (&Framebuffer, (u32, u32)),
        (func, zf): (CompareFunc, u32),
        quads: &mut Vec<(i64, i64, u8)>,
        policy: &mut BoundPolicy,
    ) {
        // `bound_func` checked it.
        let Some(depth) = fb.depth.as_deref() else {
            return;
        };
        let size = (fb.width, fb.height);
        let mut tested = 0u32;
        let mut kept = 0u32;
        quads.retain_mut(|(x, y, mask)| {
            let at = (*x - origin.0 as i64, *y - origin.1 as i64);
            let live = *mask & 0xf;
            let left = fragment_ops::depth_live_in(func, depth, size, at, live, [zf; 4]);
            tested += live.count_ones();
            kept += left.count_ones();
            *mask = (*mask & !0xf) | left;
            left != 0
        });
        policy.count(tested, tested - kept);
    }

    /// Whether the depth test `func` rejects the fixed-point depth `zf` (a
    /// primitive's bound, see [`FragmentStage::bound_rejects`]) at every
    /// pixel of `clip` (inside the tile at `origin`): then none of the
    /// primitive's fragments there can pass, and its quads need not be
    /// made. A row at a time, stopping at the first that holds a pixel
    /// where it may pass.
    fn bound_hides(
        &self,
        (fb, origin): (&Framebuffer, (u32, u32)),
        (func, zf): (CompareFunc, u32),
        clip: PixelRect,
    ) -> bool {
        use CompareFunc::*;
        let Some(depth) = fb.depth.as_deref() else {
            return false;
        };
        let local = |v: i64, o: u32| usize::try_from(v - o as i64).ok();
        let (Some(x0), Some(x1)) = (local(clip.0, origin.0), local(clip.2, origin.0)) else {
            return false;
        };
        let w = fb.width as usize;
        for y in clip.1..clip.3 {
            let Some(start) = local(y, origin.1).map(|ly| ly * w) else {
                return false;
            };
            let Some(row) = depth.get(start + x0..start + x1) else {
                return false;
            };
            let max = || row.iter().fold(0, |m, &s| m.max(s));
            let min = || row.iter().fold(u32::MAX, |m, &s| m.min(s));
            let hidden = match func {
                Less => max() <= zf,
                LessEqual => max() < zf,
                Greater => min() >= zf,
                GreaterEqual => min() > zf,
                _ => false,
            };
            if !hidden {
                return false;
            }
        }
        true
    }

    /// The depth function when a tile may depth-test its primitives out
    /// of draw order, near ones first (by their bounds), so that the far
    /// ones meet a depth buffer that already hides most of them: where
    /// the pixels cannot tell the order. The last fragment to pass decides
    /// a pixel (no blending: the deferred path), depths are written and
    /// move one way (`bound_func`), no samples are counted, no scissor
    /// test (the quads are tested whole) and no probe; the tests then
    /// keep on ties the fragment draw order would keep
    /// ([`unordered_test`]). Only for tiles crowded enough ([`CROWDED`]:
    /// `bin`'s primitives in `tile`, against the tile's `fb`) for the
    /// bounds of all their primitives to pay.
    fn unordered_func(
        &self,
        fb: &Framebuffer,
        quick: bool,
        (prims, bin, tile): (&[&Prim], &[u32], PixelRect),
    ) -> Option<CompareFunc> {
        let s = self.state;
        let plain = quick && s.depth_mask && !s.count_samples && s.scissor.is_none();
        let func = self
            .bound_func(fb)
            .filter(|_| plain && self.probe.is_none())?;
        let prims_area: u64 = (bin.iter().filter_map(|&p| prims.get(p as usize)))
            .map(|prim| rect_area(clip_to(prim, tile)))
            .sum();
        let tile_area = fb.width as u64 * fb.height as u64;
        (prims_area >= CROWDED * tile_area).then_some(func)
    }

    /// `bin` in the order the depth pass takes it: near primitives first
    /// (by their bounds under `func`; those without one last), else as
    /// drawn. Finds the bounds of all but the smallest primitives.
    fn near_first(
        &self,
        func: CompareFunc,
        scratch: &mut ex::RangeScratch,
        (prims, bin, tile): (&[&Prim], &[u32], PixelRect),
    ) -> Vec<u32> {
        // Every primitive is worth a bound here (see `BoundPolicy::worth`).
        let mut policy = BoundPolicy {
            tested: 1,
            failed: 1,
        };
        let mut order: Vec<(u32, u32)> = bin
            .iter()
            .map(|&p| {
                let bound = prims.get(p as usize).and_then(|&prim| {
                    let clip = clip_to(prim, tile);
                    (clip.0 < clip.2 && clip.1 < clip.3)
                        .then(|| self.prim_bound(func, scratch, (prims, p), clip, &mut policy))
                        .flatten()
                });
                let key = match (bound, func) {
                    (None, _) => u32::MAX,
                    (Some(z), CompareFunc::Less | CompareFunc::LessEqual) => z,
                    (Some(z), _) => !z,
                };
                (key, p)
            })
            .collect();
        order.sort_by_key(|&(key, _)| key);
        #[cfg(test)]
        BOUND_USES[2].fetch_add(1, Relaxed);
        order.into_iter().map(|(_, p)| p).collect()
    }

    /// The depth function for which the depth pass may drop fragments at
    /// a primitive's bound: one whose stored depths
    /// only move one way (or do not move), so that testing against the
    /// buffer without the pending batch rejects only fragments the test
    /// would reject later; no stencil test, a depth buffer, a bound.
    fn bound_func(&self, fb: &Framebuffer) -> Option<CompareFunc> {
        use CompareFunc::*;
        self.depth_range.as_ref()?;
        if (self.state.stencil.is_some() && fb.stencil.is_some()) || fb.depth.is_none() {
            return None;
        }
        self.state
            .depth_test
            .filter(|f| matches!(f, Less | LessEqual | Greater | GreaterEqual))
    }

    /// Makes room for the bounds of `n` primitives, found once each (with
    /// a bound to find: the draw's primitives, in the order of the
    /// indices [`FragmentStage::shade_deferred`] takes).
    pub fn cache_bounds(&mut self, n: usize) {
        if self.depth_range.is_some() {
            self.bounds = (0..n).map(|_| AtomicU64::new(0)).collect();
        }
    }

    /// [`FragmentStage::depth_bound`] of primitive `p` of `prims` over its
    /// bounds, found once (by whichever tile comes first: any tile's is a
    /// bound) when the draw keeps them, else over `clip`; none
    /// when it is not known yet and `policy` passes it over, or when the
    /// draw's program has given none for most primitives tried.
    ///
    /// A polygon's triangles (a quad's two, which cover the same bounds)
    /// are found together: one evaluation over the hull of their
    /// varyings, kept for both (`twin`, the next primitive of `prims`).
    fn prim_bound(
        &self,
        func: CompareFunc,
        scratch: &mut ex::RangeScratch,
        (prims, p): (&[&Prim], u32),
        clip: PixelRect,
        policy: &mut BoundPolicy,
    ) -> Option<u32> {
        let prim = *prims.get(p as usize)?;
        let b = prim.bounds;
        let slot = self.bounds.get(p as usize);
        match slot.map_or(0, |s| s.load(Relaxed)) {
            0 => {}
            1 => return None,
            z => return Some((z - 2) as u32),
        }
        let [tried, failed] = self.bound_stats.each_ref().map(|s| s.load(Relaxed));
        if failed >= 16 && 2 * failed >= tried {
            return None;
        }
        if !policy.worth(rect_area(b)) {
            return None;
        }
        let Some(slot) = slot else {
            return self.depth_bound(func, scratch, (prim, None), clip);
        };
        let twin = prims
            .get(p as usize + 1)
            .filter(|t| t.source == prim.source && t.bounds == b)
            .and_then(|&t| Some((t, self.bounds.get(p as usize + 1)?)));
        let z = self.depth_bound(func, scratch, (prim, twin.map(|t| t.0)), b);
        let value = z.map_or(1, |z| 2 + z as u64);
        slot.store(value, Relaxed);
        if let Some((_, twin_slot)) = twin {
            twin_slot.store(value, Relaxed);
            #[cfg(test)]
            BOUND_USES[1].fetch_add(1, Relaxed);
        }
        self.bound_stats[0].fetch_add(1, Relaxed);
        if z.is_none() {
            self.bound_stats[1].fetch_add(1, Relaxed);
        }
        z
    }

    /// The fixed-point depth that no fragment of `prim` inside `clip`
    /// (not empty) can beat under `func` (see [`FragmentStage::bound_func`]):
    /// the near end of the slice's gl_FragDepth range over those pixels
    /// for LESS and LEQUAL, the far end for GREATER and GEQUAL, clamped and
    /// converted as the depth test converts a fragment's.
    ///
    /// With `twin` (a primitive of the same bounds), a bound on its
    /// fragments too: each varying's form is the hull of the two.
    fn depth_bound(
        &self,
        func: CompareFunc,
        scratch: &mut ex::RangeScratch,
        (prim, twin): (&Prim, Option<&Prim>),
        clip: PixelRect,
    ) -> Option<u32> {
        use ex::Affine;
        let range = self.depth_range.as_ref()?;
        // The pixels, and the positions the planes take for them.
        let pixels = Region {
            x: (clip.0 as f64, (clip.2 - 1) as f64),
            y: (clip.1 as f64, (clip.3 - 1) as f64),
        };
        let region = match prim.planes.top.map(f64::from) {
            Some(t) => Region {
                y: (t - pixels.y.1, t - pixels.y.0),
                ..pixels
            },
            None => pixels,
        };
        let attrs = self.prim_attrs(prim);
        let twin = twin.map(|t| (t, self.prim_attrs(t)));
        let coord = self.layout.frag_coord;
        // gl_FragCoord.xy: the pixel centres, exactly.
        let (x, y) = (pixels.x(), pixels.y());
        let mut input = |c: usize| -> Option<Affine> {
            match coord.map(|o| c.wrapping_sub(o)) {
                Some(0) => return Some(Affine::new(x.c + 0.5, x.gx, 0.0, 0.0)),
                Some(1) => return Some(Affine::new(y.c + 0.5, 0.0, y.gy, 0.0)),
                _ => {}
            }
            let fill = self.depth_fills.iter().find(|f| f.offset == c)?;
            match fill.kind {
                FillKind::Interp => {
                    let form = attrs.get(fill.li)?.form(&prim.planes, &region)?;
                    match twin {
                        Some((t, a)) => Some(Affine::hull(
                            form,
                            a.get(fill.li)?.form(&t.planes, &region)?,
                        )),
                        None => Some(form),
                    }
                }
                FillKind::Replace(_) => None,
            }
        };
        let (lo, hi) = range.eval(scratch, &mut input)?;
        let z = match func {
            CompareFunc::Less | CompareFunc::LessEqual => lo,
            _ => hi,
        };
        Some(self.depth_format.to_fixed(clamp01(z as f64) as f32))
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
            let (lanes, has) = quad_lanes(pass.pack_colors, q, e, &mut next);
            for (k, &lane) in lanes.iter().enumerate() {
                if has & e.write & (1 << k) == 0 || lane_set(batch.discarded, lane) {
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
                        let rgba = fragment_ops::unorm8_batch(self.level, [r, g, b, a]);
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
                let mut colors = [[0.0; 4]; FRAG_COLORS];
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
        let bound_func = self.bound_func(fb);
        let mut range_scratch = ex::RangeScratch::default();
        let mut policy = BoundPolicy::default();
        let quick = QuickOps::new(fb, self.state, &self.colors_out);
        // A slice without ops (no gl_FragDepth, no discard) decides
        // nothing: the pass only depth-tests.
        let run_slice = !depth.does_nothing() || self.layout.frag_depth.is_some();
        // Stages whose lanes are independent run the covered pixels of up
        // to `LANES` quads per batch, without helper lanes.
        let pack_depth = run_slice && self.deferred_lanes_independent;
        let pack_colors = self.lanes_independent;
        let tile_prims = (prims, bin, tile);
        let unordered = self.unordered_func(fb, quick.is_some() && run_slice, tile_prims);
        let pass = DeferredPass {
            depth,
            origin,
            quick,
            run_slice,
            pack_depth,
            pack_colors,
            unordered,
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
                            let (z, zf) = quad_depths(prim, (qx, qy), self.depth_format);
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
                // A strip's four quads, run as a batch of their own.
                let mut strip: [Entry<'p>; LANES / 4] = Default::default();
                let near_first: Vec<u32>;
                let bin = match unordered {
                    Some(func) => {
                        near_first = self.near_first(func, &mut range_scratch, tile_prims);
                        &near_first[..]
                    }
                    None => bin,
                };
                // Out of draw order a bound is tested letting ties through.
                let bound_test = bound_func.map(|f| match unordered {
                    Some(_) => ties_pass(f),
                    None => f,
                });
                for (i, &p) in bin.iter().enumerate() {
                    let Some(&prim) = prims.get(p as usize) else {
                        continue;
                    };
                    self.prefetch_ahead(prims, bin, i, pass.run_slice);
                    // Strips (four whole quads side by side) only where a
                    // row can hold one besides its edges.
                    let clip = clip_to(prim, tile);
                    // Without gl_FragDepth the quads' own depths reject
                    // (`early`), with it a bound on the slice's.
                    let bound = match bound_func {
                        Some(func) if clip.0 < clip.2 && clip.1 < clip.3 => {
                            self.prim_bound(func, &mut range_scratch, (prims, p), clip, &mut policy)
                        }
                        _ => None,
                    };
                    let test = bound_test.zip(bound);
                    if test.is_some_and(|t| self.bound_hides((fb, origin), t, clip)) {
                        // Every fragment fails (counted as `bound_rejects`
                        // counts, by the clip's area).
                        let area = rect_area(clip) as u32;
                        policy.count(area, area);
                        #[cfg(test)]
                        BOUND_USES[0].fetch_add(1, Relaxed);
                        continue;
                    }
                    let wide = clip.2 - clip.0 >= 16 && bound.is_none();
                    prim.shape
                        .quads_into_strips(clip, quads, pass.run_slice && wide);
                    if let Some(t) = test {
                        self.bound_rejects((fb, origin), t, quads, &mut policy);
                    }
                    for &quad in quads.iter() {
                        // Fragments of one primitive cover distinct pixels:
                        // a strip runs at once when only quads of its
                        // primitive wait (else as four quads, in order).
                        let (qx, qy, mask) = quad;
                        // The entry's quads: a strip's four or the one.
                        let quads_here = if mask & STRIP != 0 { LANES / 4 } else { 1 };
                        let quad_at = |q: usize| (qx + 2 * q as i64, qy, mask & 0xf);
                        if quads_here > 1 && (*n == 0 || pending[0].index == p) {
                            let mut live = 0;
                            for (q, e) in strip.iter_mut().enumerate() {
                                live |=
                                    self.depth_entry(e, (prim, p), quad_at(q), early, fb, origin);
                            }
                            if live != 0 {
                                self.depth_pass(
                                    &pass,
                                    fb,
                                    batch,
                                    (&mut winner, &mut policy),
                                    &strip,
                                )?;
                            }
                            continue;
                        }
                        for q in 0..quads_here {
                            let Some(e) = pending.get_mut(*n) else { break };
                            let write =
                                self.depth_entry(e, (prim, p), quad_at(q), early, fb, origin);
                            if early && write == 0 {
                                continue;
                            }
                            if let Some((count, spill)) = admit(pack_depth, n, &mut lanes, write) {
                                let with = (&mut winner[..], &mut policy);
                                self.depth_pass(&pass, fb, batch, with, &pending[..count])?;
                                if spill {
                                    pending.swap(0, count);
                                }
                            }
                        }
                    }
                }
                if *n > 0 {
                    let with = (&mut winner[..], &mut policy);
                    self.depth_pass(&pass, fb, batch, with, &pending[..*n])?;
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
        let window_z = self.frag_zw[0] || self.probe.is_some();
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
                    e.set(
                        prim,
                        p,
                        (qx, qy, live),
                        write,
                        window_z.then_some(self.depth_format),
                    );
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
mod tests;
