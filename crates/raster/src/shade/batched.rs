//! The fragment stage's batched loop: the quads of consecutive
//! primitives of a tile share batches when early depth rejection against
//! the depth buffer stays exact ([`FragmentStage::batches_primitives`]),
//! and whole strips of four quads of one triangle make a batch of their
//! own. Takes a tile and its bin; gives the tile's pixels, the same bytes
//! as [`FragmentStage::shade`] over the bin (tests compare them).

use super::*;

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

impl<'a> FragmentStage<'a> {
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
            colors: [[0.0; 4]; FRAG_COLORS],
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

    exec::multiversion! {
        /// The primitives `bin` (indices into `prims`, in draw order) inside
        /// `tile`, quads of consecutive primitives sharing batches (a
        /// primitive covering a pixel or two no longer costs a whole batch).
        /// Fragments still go through the per-fragment operations in draw
        /// order after their batch ran, so the bytes are those of
        /// [`FragmentStage::shade`] per primitive, provided early rejection
        /// against a depth buffer that misses the batch's pending fragments is
        /// still right: [`FragmentStage::batches_primitives`] says when. On an
        /// error the caller redraws the tile with [`FragmentStage::shade`].
        ///
        /// Compiled for the stage's level (the quad loop, early depth test
        /// and writes inlined into each copy: the same operations).
        pub fn shade_batched<'p>(
            &self,
            fb: &mut Framebuffer,
            prims: &[&'p Prim],
            bin: &[u32],
            tile: PixelRect,
            scratch: &mut Scratch<'p>,
        ) -> Result<(), ExecError>;
        level = self.level,
        copies = [shade_batched_portable, shade_batched_avx2, shade_batched_avx512],
        body = self.shade_batched_with(fb, prims, bin, tile, scratch)
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
        e.set(prim, p, quad, 0, self.window_z.then_some(self.depth_format));
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
        self.strip_pixel_inputs(batch, prim, slots, (qx, qy), (&x, &y));
        self.run_shader(batch)?;
        // Every pixel passing (no depth test: the write does not test
        // one), none discarded: the strip's two rows at once.
        if live_mask == 0xffff && batch.discarded == 0 && self.layout.frag_depth.is_none() {
            if let Some([r, g, b, a]) = batch.outputs.get(o..o + 4) {
                if target.write_strip(self.level, (qx, qy), [r, g, b, a]) {
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
                // The fixed-point depths only for a depth test (the
                // quick write tests and stores nothing without one).
                if self.state.depth_test.is_some() {
                    (q.z, q.zf) = window_depths(&iz, prim.z_offset, self.depth_format);
                } else {
                    q.z = window_z(&iz, prim.z_offset);
                }
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
}
