//! Filling a batch's inputs, the job every loop of the fragment stage
//! shares: for the quads of a batch (four lanes each, or packed: only
//! the pixels that run, one after another), each varying component the
//! stage's plan lists, evaluated from its primitive's plane at the lane's
//! pixel (`crate::interpolate`), and gl_FragCoord, gl_FrontFacing,
//! gl_PointCoord and gl_PrimitiveID where the stage reads them; a strip
//! (four whole quads of one triangle side by side) over its 16 lanes at
//! once. Every way of filling gives a lane the same f32 operations, so
//! the same bits, in every instruction-set variant.

use super::*;

/// Where [`FragmentStage::write_inputs`] puts the pixels a quad runs.
struct Place {
    /// The pixels, in increasing order (`order[..count]`).
    order: [u8; 4],
    count: usize,
    /// The lane of the first.
    first: usize,
}

/// Bit set in a lane mask for the `LANES / 4` quads of a batch.
pub(super) fn quads_mask(quads: usize) -> u32 {
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

/// Each link of `plan` evaluated from its plane in `varyings` at the
/// pixels `(x, y)` (with their `rw`, `Plane::values`) into the inputs'
/// lanes from `first` on. Its own function so that the positions stay in
/// registers across the links (in the caller's loop they were reloaded
/// from the stack for every link).
#[inline(always)]
fn put_varyings(
    inputs: &mut [[f32; LANES]],
    plan: &[FillLink],
    varyings: &[Plane],
    (x, y, rw): ([f32; 4], [f32; 4], [f32; 4]),
    first: usize,
) {
    for l in plan {
        let values = match varyings.get(l.li) {
            Some(p) => p.values(&x, &y, &rw),
            None => [0.0; 4],
        };
        put_input(inputs, l.offset, first, values);
    }
}

/// [`put_quad`] into input component `o`, if the batch has it.
#[inline(always)]
fn put_input(inputs: &mut [[f32; LANES]], o: usize, first: usize, values: [f32; 4]) {
    if let Some(lanes) = inputs.get_mut(o) {
        put_quad(lanes, first, values);
    }
}

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

/// Bit set in a lane mask for the first `lanes` lanes of a batch.
fn lanes_mask(lanes: usize) -> u32 {
    if lanes >= LANES {
        u32::MAX >> (32 - LANES)
    } else {
        (1u32 << lanes) - 1
    }
}

/// How [`FragmentStage::fill`] writes one varying component.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum FillKind {
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
    pub(super) li: usize,
    pub(super) offset: usize,
    pub(super) kind: FillKind,
}

impl<'a> FragmentStage<'a> {
    exec::multiversion! {
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
        ///
        /// Compiled for the stage's level (AVX2: four pixels' f64
        /// arithmetic in one register instead of two; the same operations).
        pub(super) fn fill(&self, batch: &mut Batch, pending: &[Entry], plan: &[FillLink], packed: bool);
        level = self.level,
        copies = [fill_portable, fill_avx2, fill_avx512],
        body = self.fill_with(batch, pending, plan, packed)
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
            let inputs = &mut batch.inputs[..];
            let mut clear = |o: usize| {
                if let Some(tail) = inputs.get_mut(o).and_then(|l| l.get_mut(total..)) {
                    tail.fill(0.0);
                }
            };
            for l in plan {
                clear(l.offset);
            }
            let layout = self.layout;
            let pixel = [
                (layout.frag_coord, 4),
                (layout.front_facing, 1),
                (layout.point_coord, 2),
                (layout.primitive_id, 1),
            ];
            for (o, n) in pixel {
                if let Some(o) = o {
                    (o..o + n).for_each(&mut clear);
                }
            }
        }
    }

    /// Writes the inputs `plan` lists, and gl_FragCoord, gl_FrontFacing,
    /// gl_PointCoord and gl_PrimitiveID where the stage reads them, for the pixels of
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
            || layout.point_coord.is_some()
            || layout.primitive_id.is_some();
        if let Some((strip, prim)) = self.as_strip(pending, &place) {
            return self.write_strip_inputs(batch, strip, prim, plan);
        }
        for (q, e) in pending.iter().enumerate() {
            let (Some(prim), quad) = (e.prim, &e.quad) else {
                continue;
            };
            let Place { order, first, .. } = place(q, e);
            // The pixels of `order`, in that order.
            let planes = &prim.planes;
            // QUAD_X and QUAD_Y of the pixels, computed (a table lookup
            // per element becomes a slow gather instruction).
            let ox = order.map(|k| (k & 1) as f32);
            let oy = order.map(|k| ((k >> 1) & 1) as f32);
            let (x, y) = prim.offsets((quad.x, quad.y), &ox, &oy);
            let rw = planes.reciprocal_w(&x, &y);
            let varyings = self.prim_attrs(prim);
            let sprite = sprite && matches!(prim.shape, Shape::Point { .. });
            let inputs = &mut batch.inputs[..];
            put_varyings(inputs, plan, varyings, (x, y, rw), first);
            // On a point sprite the coordinates GL_COORD_REPLACE names
            // take gl_PointCoord's place.
            if sprite {
                let pc = point_coords(quad, prim, order);
                for l in plan {
                    if let FillKind::Replace(c) = l.kind {
                        let values = pc.map(|pc| [pc.0, pc.1, 0.0, 1.0][c]);
                        put_input(inputs, l.offset, first, values);
                    }
                }
            }
            if !pixel_inputs {
                continue;
            }
            // The per-pixel inputs four lanes at once, as the varyings (a
            // lane at a time, converting and storing scalars, gl_FragCoord
            // cost as much as all the varyings of a sphere impostor).
            let put =
                |inputs: &mut [[f32; LANES]], o: usize, values| put_input(inputs, o, first, values);
            if let Some(o) = layout.frag_coord {
                let [frag_z, frag_w] = self.frag_zw;
                put(
                    inputs,
                    o,
                    order.map(|k| quad.pixel(k as usize & 3).0 as f32 + 0.5),
                );
                put(
                    inputs,
                    o + 1,
                    order.map(|k| quad.pixel(k as usize & 3).1 as f32 + 0.5),
                );
                if frag_z {
                    put(inputs, o + 2, order.map(|k| quad.z[k as usize & 3] as f32));
                }
                if frag_w {
                    put(inputs, o + 3, planes.inv_w_at(&x, &y));
                }
            }
            if let Some(o) = layout.front_facing {
                put(inputs, o, [if prim.back { 0.0 } else { 1.0 }; 4]);
            }
            if let Some(o) = layout.point_coord {
                let pc = match prim.shape {
                    Shape::Point { .. } => point_coords(quad, prim, order),
                    _ => [(0.0, 0.0); 4],
                };
                put(inputs, o, pc.map(|c| c.0));
                put(inputs, o + 1, pc.map(|c| c.1));
            }
            if let Some(o) = layout.primitive_id {
                let id = self.state.primitive_ids.of(prim.source);
                put(inputs, o, [f32::from_bits(id); 4]);
            }
        }
    }

    /// `pending` as a strip: four quads of one triangle side by side
    /// (at `x`, `x + 2`, `x + 4`, `x + 6` of one row), each placed in
    /// its four lanes in pixel order, with no input but those a strip
    /// gives (no gl_PointCoord or gl_PrimitiveID); their lanes are then
    /// those of [`FragmentStage::shade_strip`].
    #[inline(always)]
    fn as_strip<'e, 'p>(
        &self,
        pending: &'e [Entry<'p>],
        place: &impl Fn(usize, &Entry) -> Place,
    ) -> Option<(&'e [Entry<'p>; LANES / 4], &'p Prim)> {
        let strip: &[Entry; LANES / 4] = pending.try_into().ok()?;
        let prim = strip[0].prim?;
        if self.layout.point_coord.is_some()
            || self.layout.primitive_id.is_some()
            || !matches!(
                prim.shape,
                Shape::Triangle { .. } | Shape::Quadrilateral { .. }
            )
        {
            return None;
        }
        let (x0, y0) = (strip[0].quad.x, strip[0].quad.y);
        for (q, e) in strip.iter().enumerate() {
            let p = place(q, e);
            let same = e.prim.is_some_and(|p| std::ptr::eq(p, prim));
            if !same
                || (e.quad.x, e.quad.y) != (x0 + 2 * q as i64, y0)
                || p.order != [0, 1, 2, 3]
                || p.count != 4
                || p.first != 4 * q
            {
                return None;
            }
        }
        Some((strip, prim))
    }

    /// [`FragmentStage::write_inputs`] of a strip ([`FragmentStage::as_strip`]):
    /// each varying over the 16 lanes at once (the same operations per
    /// lane, so the same bits), then gl_FragCoord and gl_FrontFacing.
    #[inline(always)]
    fn write_strip_inputs(
        &self,
        batch: &mut Batch,
        strip: &[Entry; LANES / 4],
        prim: &Prim,
        plan: &[FillLink],
    ) {
        let at = (strip[0].quad.x, strip[0].quad.y);
        let (x, y) = prim.offsets(at, &STRIP_X, &STRIP_Y);
        let rw = prim.planes.reciprocal_w(&x, &y);
        let varyings = self.prim_attrs(prim);
        for l in plan {
            if let Some(lanes) = batch.inputs.get_mut(l.offset) {
                *lanes = match varyings.get(l.li) {
                    Some(p) => p.values(&x, &y, &rw),
                    None => [0.0; LANES],
                };
            }
        }
        self.strip_pixel_inputs(batch, prim, strip, at, (&x, &y));
    }

    /// gl_FragCoord and gl_FrontFacing of the lanes of the strip at
    /// `(qx, qy)`, as [`FragmentStage::fill`] gives them to a quad's (with
    /// gl_FragCoord the strip's entries hold its quads' window depths:
    /// reading it makes `window_z` true).
    #[inline(always)]
    pub(super) fn strip_pixel_inputs(
        &self,
        batch: &mut Batch,
        prim: &Prim,
        slots: &[Entry; LANES / 4],
        (qx, qy): (i64, i64),
        (x, y): (&[f32; LANES], &[f32; LANES]),
    ) {
        if let Some([fx, fy, fz, fw]) = self
            .layout
            .frag_coord
            .and_then(|o| batch.inputs.get_mut(o..o + 4))
        {
            // The pixels' centres: the strip's first plus whole offsets
            // (exact in f32 inside any window).
            let (cx, cy) = (qx as f32 + 0.5, qy as f32 + 0.5);
            for l in 0..LANES {
                fx[l] = cx + STRIP_X[l];
                fy[l] = cy + STRIP_Y[l];
            }
            let [frag_z, frag_w] = self.frag_zw;
            if frag_z {
                for (q, e) in slots.iter().enumerate() {
                    for k in 0..4 {
                        fz[4 * q + k] = e.quad.z[k] as f32;
                    }
                }
            }
            if frag_w {
                *fw = prim.planes.inv_w_at(x, y);
            }
        }
        if let Some(o) = self.layout.front_facing {
            let facing = if prim.back { 0.0 } else { 1.0 };
            for l in 0..LANES {
                set(batch, o, l, facing);
            }
        }
    }
}
