//! Framebuffers: color buffers (RGBA8 unorm or RGBA32F), a depth buffer
//! of 24-bit fixed-point values (of 16-bit precision for a 16-bit
//! attachment: [`DepthFormat`]) and an 8-bit stencil buffer; pixel
//! reads, and tile copies for the draw's tile tasks. Clears, which run in
//! bands of rows on the workers, are `crate::clear`.
//!
//! Row 0 is the bottom row (GL window coordinates); pixel (x, y) lives at
//! index `y * width + x`.

use crate::state::Rect;

/// Largest width or height [`Framebuffer::new`] accepts; larger requests
/// are clamped (the gl layer reports GL errors before it gets here).
pub const MAX_FRAMEBUFFER_SIZE: u32 = 16384;

/// The largest 24-bit depth value (1.0).
pub const DEPTH_MAX: u32 = (1 << 24) - 1;

/// Most color buffers one framebuffer can hold (GL_MAX_DRAW_BUFFERS).
pub const MAX_DRAW_BUFFERS: usize = 8;

/// Rows `y0..` of a framebuffer's buffers, borrowed ([`Framebuffer::bands`]).
pub(crate) struct Band<'a> {
    y0: u32,
    width: usize,
    color: Vec<BandColor<'a>>,
    depth: Option<&'a mut [u32]>,
    stencil: Option<&'a mut [u8]>,
}

enum BandColor<'a> {
    Rgba8(&'a mut [[u8; 4]]),
    Rgba32F(&'a mut [[f32; 4]]),
}

impl Band<'_> {
    /// Copies `tile` (a [`Framebuffer::copy_tile`] of the framebuffer) back
    /// to (x0, y0), the rows inside this band.
    pub(crate) fn store_tile(&mut self, x0: u32, y0: u32, tile: &Framebuffer) {
        fn rows<T: Copy>(dst: &mut [T], width: usize, x0: u32, y: i64, src: &[T], w: usize) {
            if w == 0 || x0 as usize + w > width {
                return;
            }
            for (r, row) in src.chunks(w).enumerate() {
                let y = y + r as i64;
                if y < 0 {
                    continue;
                }
                let start = y as usize * width + x0 as usize;
                if let Some(d) = dst.get_mut(start..start + row.len()) {
                    d.copy_from_slice(row);
                }
            }
        }
        // Tile row r at band row y.
        let y = y0 as i64 - self.y0 as i64;
        let (width, w) = (self.width, tile.width as usize);
        for (dst, src) in self.color.iter_mut().zip(&tile.color) {
            match (dst, src) {
                (BandColor::Rgba8(d), ColorBuffer::Rgba8(s)) => rows(d, width, x0, y, s, w),
                (BandColor::Rgba32F(d), ColorBuffer::Rgba32F(s)) => rows(d, width, x0, y, s, w),
                _ => {}
            }
        }
        if let (Some(d), Some(s)) = (self.depth.as_deref_mut(), tile.depth.as_ref()) {
            rows(d, width, x0, y, s, w);
        }
        if let (Some(d), Some(s)) = (self.stencil.as_deref_mut(), tile.stencil.as_ref()) {
            rows(d, width, x0, y, s, w);
        }
    }
}

/// One tile's rows of a framebuffer's buffers, borrowed
/// ([`Framebuffer::tile_views`]): a tile task reads its pixels from here
/// and writes them back here when done, while other tasks hold the
/// other tiles' views.
pub(crate) struct TileView<'a> {
    width: u32,
    height: u32,
    depth_format: DepthFormat,
    color: Vec<TileColor<'a>>,
    depth: Option<Vec<&'a mut [u32]>>,
    stencil: Option<Vec<&'a mut [u8]>>,
}

enum TileColor<'a> {
    Rgba8(Vec<&'a mut [[u8; 4]]>),
    Rgba32F(Vec<&'a mut [[f32; 4]]>),
}

impl TileView<'_> {
    /// The tile's pixels as a framebuffer of its own, as
    /// [`Framebuffer::copy_tile`] gives them.
    pub(crate) fn load(&self) -> Framebuffer {
        fn rows<T: Copy>(rows: &[&mut [T]]) -> Vec<T> {
            let mut out = Vec::with_capacity(rows.iter().map(|r| r.len()).sum());
            for r in rows {
                out.extend_from_slice(r);
            }
            out
        }
        Framebuffer {
            width: self.width,
            height: self.height,
            color: (self.color.iter())
                .map(|c| match c {
                    TileColor::Rgba8(r) => ColorBuffer::Rgba8(rows(r)),
                    TileColor::Rgba32F(r) => ColorBuffer::Rgba32F(rows(r)),
                })
                .collect(),
            depth: self.depth.as_deref().map(rows),
            depth_format: self.depth_format,
            stencil: self.stencil.as_deref().map(rows),
            samples_passed: 0,
        }
    }

    /// Writes `tile` (from [`TileView::load`]) back; buffers the view or
    /// the tile lacks are left as they are.
    pub(crate) fn store(&mut self, tile: &Framebuffer) {
        fn rows<T: Copy>(dst: &mut [&mut [T]], src: &[T], w: usize) {
            for (d, s) in dst.iter_mut().zip(src.chunks(w.max(1))) {
                if d.len() == s.len() {
                    d.copy_from_slice(s);
                }
            }
        }
        let w = self.width as usize;
        if tile.width != self.width || tile.height != self.height {
            return;
        }
        for (dst, src) in self.color.iter_mut().zip(&tile.color) {
            match (dst, src) {
                (TileColor::Rgba8(d), ColorBuffer::Rgba8(s)) => rows(d, s, w),
                (TileColor::Rgba32F(d), ColorBuffer::Rgba32F(s)) => rows(d, s, w),
                _ => {}
            }
        }
        if let (Some(d), Some(s)) = (self.depth.as_mut(), tile.depth.as_ref()) {
            rows(d, s, w);
        }
        if let (Some(d), Some(s)) = (self.stencil.as_mut(), tile.stencil.as_ref()) {
            rows(d, s, w);
        }
    }
}

/// The rows of `buf` (rows of `width` elements) that belong to the tiles
/// `wanted` (sorted indices into a grid of `size`-square tiles, `cols`
/// per row): entry `i` holds `wanted[i]`'s rows, bottom row first.
fn split_tiles<'a, T>(
    buf: &'a mut [T],
    (width, size, cols): (usize, usize, usize),
    wanted: &[usize],
) -> Vec<Vec<&'a mut [T]>> {
    let mut out: Vec<Vec<&mut [T]>> = (0..wanted.len()).map(|_| Vec::new()).collect();
    let (width, size, cols) = (width.max(1), size.max(1), cols.max(1));
    for (ty, band) in buf.chunks_mut(width * size).enumerate() {
        let first = wanted.partition_point(|&t| t / cols < ty);
        let end = wanted.partition_point(|&t| t / cols <= ty);
        if first == end {
            continue;
        }
        for row in band.chunks_mut(width) {
            let mut want = first;
            for (tx, piece) in row.chunks_mut(size).enumerate() {
                if want == end {
                    break;
                }
                if wanted.get(want).is_some_and(|&t| t % cols == tx) {
                    if let Some(o) = out.get_mut(want) {
                        o.push(piece);
                    }
                    want += 1;
                }
            }
        }
    }
    out
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorFormat {
    Rgba8,
    Rgba32F,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ColorBuffer {
    Rgba8(Vec<[u8; 4]>),
    Rgba32F(Vec<[f32; 4]>),
}

impl ColorBuffer {
    fn new(format: ColorFormat, len: usize) -> ColorBuffer {
        match format {
            ColorFormat::Rgba8 => ColorBuffer::Rgba8(vec![[0; 4]; len]),
            ColorFormat::Rgba32F => ColorBuffer::Rgba32F(vec![[0.0; 4]; len]),
        }
    }

    pub fn format(&self) -> ColorFormat {
        match self {
            ColorBuffer::Rgba8(_) => ColorFormat::Rgba8,
            ColorBuffer::Rgba32F(_) => ColorFormat::Rgba32F,
        }
    }

    /// The pixel at `index` as floats (unorm: `b / 255`); zeros when out of range.
    pub fn get(&self, index: usize) -> [f32; 4] {
        match self {
            ColorBuffer::Rgba8(v) => v.get(index).map_or([0.0; 4], |p| p.map(unorm8_to_float)),
            ColorBuffer::Rgba32F(v) => v.get(index).copied().unwrap_or([0.0; 4]),
        }
    }
}

/// GL 2.1 §2.14.9 / §4.3.1 conversion of a float to an 8-bit unorm:
/// clamp to [0, 1], then round to nearest (`floor(c * 255 + 0.5)`). NaN → 0.
pub fn float_to_unorm8(c: f32) -> u8 {
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    // The value is in [0.5, 255.5]: truncation is floor.
    (c * 255.0 + 0.5) as u8
}

pub fn unorm8_to_float(b: u8) -> f32 {
    b as f32 / 255.0
}

/// GL 2.1 §2.11.1: a window z in [0, 1] as a 24-bit fixed-point value
/// `k / (2^24 - 1)`: `z · (2^24 − 1)` computed in f32, then rounded to the
/// nearest integer, ties to even. Values outside [0, 1] are clamped, NaN
/// becomes 0.
///
/// The product is rounded to f32 before the integer is taken, as GPUs and
/// Mesa's llvmpipe do (measured on Mesa 22.3.6: the same `k` for 3,000
/// random depths, where rounding the exact product differs for 8 % of
/// them). Two fragments whose depths differ by an ulp at a surface
/// intersection then land in the same or different steps in both
/// implementations alike, so the depth test keeps the same one.
// Not `clamp`: NaN must become 0 (`max` drops it; `clamp` keeps it).
#[allow(clippy::manual_clamp)]
#[inline(always)]
pub fn depth_to_fixed(z: f32) -> u32 {
    let x = z.max(0.0).min(1.0) * DEPTH_MAX as f32;
    // Below 2^23, adding 2^23 leaves a sum whose ulp is 1, so the f32
    // addition rounds x to an integer, ties to even; at or above 2^23 an
    // f32 is already an integer.
    const HALF: f32 = (1u32 << 23) as f32;
    let k = if x < HALF { (x + HALF) - HALF } else { x };
    // SAFETY: `max` turns NaN into 0, so `k` is an integer in
    // [0, 2^24 - 1]: representable in i32, and the conversion is exact.
    unsafe { k.to_int_unchecked::<i32>() as u32 }
}

/// The precision of a depth buffer. Every depth buffer holds the 24-bit
/// values of [`depth_to_fixed`]; a 16-bit one (a `GL_DEPTH_COMPONENT16`
/// attachment, of which GL 3.0 §4.4.2.2 says requesting it "will allocate
/// exactly the internal component sizes" of the format) holds only the
/// 2^16 of them that are `k / 65535`, so that the depth test within a
/// draw sees the steps of a 16-bit buffer (a fragment's depth rounded to
/// 16 bits ties with a nearer one that 24 bits would keep apart).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DepthFormat {
    #[default]
    Bits24,
    Bits16,
}

impl DepthFormat {
    /// The stored form of window z `z` in a buffer of this precision.
    #[inline(always)]
    pub fn to_fixed(self, z: f32) -> u32 {
        match self {
            DepthFormat::Bits24 => depth_to_fixed(z),
            DepthFormat::Bits16 => depth16_to_fixed(z),
        }
    }

    /// [`DepthFormat::to_fixed`] of four depths (`z[k] as f32`).
    #[inline(always)]
    pub fn to_fixed4(self, z: [f64; 4]) -> [u32; 4] {
        self.to_fixed4_f32([z[0] as f32, z[1] as f32, z[2] as f32, z[3] as f32])
    }

    /// [`DepthFormat::to_fixed`] of four depths; the format chosen once
    /// and the four conversions inlined (a closure per element through
    /// `array::map` stays a call in the hot loops).
    #[inline(always)]
    pub fn to_fixed4_f32(self, z: [f32; 4]) -> [u32; 4] {
        let mut out = [0; 4];
        match self {
            DepthFormat::Bits24 => {
                for (o, z) in out.iter_mut().zip(z) {
                    *o = depth_to_fixed(z);
                }
            }
            DepthFormat::Bits16 => {
                for (o, z) in out.iter_mut().zip(z) {
                    *o = depth16_to_fixed(z);
                }
            }
        }
        out
    }
}

/// A window z stored in a 16-bit depth buffer, in [`depth_to_fixed`]'s
/// 24-bit form: the 16-bit value `k` as llvmpipe converts a depth to a
/// 16-bit unorm (`z · 65535/65536` in f32, then plus 2^7 in f32: that
/// sum's ulp is 2^-16, so the addition rounds `z · 65535` to the nearest
/// integer, ties to even), then `depth_to_fixed(k / 65535)`, the value a
/// 16-bit attachment's texel holds, so that storing the buffer in its
/// attachment and loading it again keeps every value.
#[allow(clippy::manual_clamp)]
#[inline(always)]
pub fn depth16_to_fixed(z: f32) -> u32 {
    let x = z.max(0.0).min(1.0) * (65535.0 / 65536.0);
    let k = ((x + 128.0) - 128.0) * 65536.0;
    depth_to_fixed(k / 65535.0)
}

pub fn fixed_to_depth(k: u32) -> f32 {
    (k.min(DEPTH_MAX) as f64 / DEPTH_MAX as f64) as f32
}

#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    pub width: u32,
    pub height: u32,
    /// The color buffers; `PipelineState::draw_buffers` selects which
    /// fragment output goes where.
    pub color: Vec<ColorBuffer>,
    /// 24-bit depth values in [0, 2^24 - 1] (for
    /// [`DepthFormat::Bits16`], only the forms of `k / 65535`).
    pub depth: Option<Vec<u32>>,
    /// The precision of `depth`'s values.
    pub depth_format: DepthFormat,
    pub stencil: Option<Vec<u8>>,
    /// Fragments that have passed the per-fragment tests up to and
    /// including the depth test (scissor, alpha, stencil, depth) in this
    /// framebuffer, summed over draws: GL_SAMPLES_PASSED (GL 2.1 §4.1.7)
    /// is the difference across the draws of a query. Exact whatever the
    /// thread count (tiles count their own fragments; the counts are added
    /// when the tiles are stored).
    pub samples_passed: u64,
}

impl Framebuffer {
    /// One color buffer of `format`, optional depth and stencil buffers,
    /// everything zero.
    pub fn new(width: u32, height: u32, format: ColorFormat, depth: bool, stencil: bool) -> Self {
        Framebuffer::with_color_buffers(width, height, &[format], depth, stencil)
    }

    /// Up to [`MAX_DRAW_BUFFERS`] color buffers (more are ignored).
    pub fn with_color_buffers(
        width: u32,
        height: u32,
        formats: &[ColorFormat],
        depth: bool,
        stencil: bool,
    ) -> Self {
        let width = width.min(MAX_FRAMEBUFFER_SIZE);
        let height = height.min(MAX_FRAMEBUFFER_SIZE);
        let len = width as usize * height as usize;
        Framebuffer {
            width,
            height,
            color: formats
                .iter()
                .take(MAX_DRAW_BUFFERS)
                .map(|&f| ColorBuffer::new(f, len))
                .collect(),
            depth: depth.then(|| vec![0; len]),
            depth_format: DepthFormat::Bits24,
            stencil: stencil.then(|| vec![0; len]),
            samples_passed: 0,
        }
    }

    /// The whole framebuffer as a rectangle.
    pub fn bounds(&self) -> Rect {
        Rect::new(0, 0, self.width as i32, self.height as i32)
    }

    /// `rect` (or the whole buffer) intersected with the buffer, as
    /// half-open pixel ranges `(x0, y0, x1, y1)`.
    pub(crate) fn clip_rect(&self, rect: Option<Rect>) -> (u32, u32, u32, u32) {
        let (w, h) = (self.width as i64, self.height as i64);
        match rect {
            None => (0, 0, self.width, self.height),
            Some(r) => {
                let x0 = (r.x as i64).clamp(0, w);
                let y0 = (r.y as i64).clamp(0, h);
                let x1 = (r.x as i64 + (r.w as i64).max(0)).clamp(x0, w);
                let y1 = (r.y as i64 + (r.h as i64).max(0)).clamp(y0, h);
                (x0 as u32, y0 as u32, x1 as u32, y1 as u32)
            }
        }
    }

    /// A copy of the pixels in `[x0, x1) × [y0, y1)` (clipped to the
    /// buffer) as a framebuffer of its own, for one tile task: its colour
    /// buffers, and its depth and stencil buffers where `depth` and
    /// `stencil` ask for them (a draw without the depth or stencil test
    /// neither reads nor writes that buffer: the tile goes without it, and
    /// storing the tile back leaves the framebuffer's as it is).
    pub(crate) fn copy_tile(
        &self,
        (x0, y0, x1, y1): (u32, u32, u32, u32),
        depth: bool,
        stencil: bool,
    ) -> Framebuffer {
        let (x1, y1) = (x1.min(self.width), y1.min(self.height));
        let (x0, y0) = (x0.min(x1), y0.min(y1));
        let (w, h) = ((x1 - x0) as usize, (y1 - y0) as usize);
        let width = self.width as usize;
        fn rows<T: Copy>(src: &[T], width: usize, x0: u32, y0: u32, w: usize, h: usize) -> Vec<T> {
            let mut out = Vec::with_capacity(w * h);
            for y in y0 as usize..y0 as usize + h {
                let start = y * width + x0 as usize;
                if let Some(row) = src.get(start..start + w) {
                    out.extend_from_slice(row);
                }
            }
            out
        }
        Framebuffer {
            width: w as u32,
            height: h as u32,
            color: self
                .color
                .iter()
                .map(|c| match c {
                    ColorBuffer::Rgba8(v) => ColorBuffer::Rgba8(rows(v, width, x0, y0, w, h)),
                    ColorBuffer::Rgba32F(v) => ColorBuffer::Rgba32F(rows(v, width, x0, y0, w, h)),
                })
                .collect(),
            depth: (self.depth.as_ref())
                .filter(|_| depth)
                .map(|d| rows(d, width, x0, y0, w, h)),
            depth_format: self.depth_format,
            stencil: (self.stencil.as_ref())
                .filter(|_| stencil)
                .map(|s| rows(s, width, x0, y0, w, h)),
            samples_passed: 0,
        }
    }

    /// Writes `tile` (from [`Framebuffer::copy_tile`]) back at (x0, y0),
    /// with its samples passed. Parts that do not fit, or buffers that do
    /// not match, are skipped. (Draws write tiles back by [`Band`]s.)
    #[cfg(test)]
    pub(crate) fn store_tile(&mut self, x0: u32, y0: u32, tile: &Framebuffer) {
        self.samples_passed = self.samples_passed.wrapping_add(tile.samples_passed);
        let height = self.height;
        let mut all = self.bands(height.max(1));
        if let Some(band) = all.first_mut() {
            band.store_tile(x0, y0, tile);
        }
    }

    /// The framebuffer cut into bands of `rows` rows (the last may have
    /// fewer), each borrowing its rows of every buffer: tiles of different
    /// bands are written back in parallel. `samples_passed` is not theirs.
    pub(crate) fn bands(&mut self, rows: u32) -> Vec<Band<'_>> {
        let width = self.width as usize;
        let per = width * rows.max(1) as usize;
        let n = (self.height as usize).div_ceil(rows.max(1) as usize);
        let mut bands: Vec<Band> = (0..n)
            .map(|i| Band {
                y0: i as u32 * rows.max(1),
                width,
                color: Vec::new(),
                depth: None,
                stencil: None,
            })
            .collect();
        for c in self.color.iter_mut() {
            match c {
                ColorBuffer::Rgba8(v) => {
                    for (b, rows) in bands.iter_mut().zip(v.chunks_mut(per.max(1))) {
                        b.color.push(BandColor::Rgba8(rows));
                    }
                }
                ColorBuffer::Rgba32F(v) => {
                    for (b, rows) in bands.iter_mut().zip(v.chunks_mut(per.max(1))) {
                        b.color.push(BandColor::Rgba32F(rows));
                    }
                }
            }
        }
        if let Some(d) = self.depth.as_mut() {
            for (b, rows) in bands.iter_mut().zip(d.chunks_mut(per.max(1))) {
                b.depth = Some(rows);
            }
        }
        if let Some(st) = self.stencil.as_mut() {
            for (b, rows) in bands.iter_mut().zip(st.chunks_mut(per.max(1))) {
                b.stencil = Some(rows);
            }
        }
        bands
    }

    /// Views of the tiles `wanted` (sorted indices into this
    /// framebuffer's grid of `size`×`size` tiles, row by row from the
    /// bottom) that tasks can fill in parallel: `wanted[i]`'s is the
    /// `i`th. With the colour buffers, and the depth and stencil buffers
    /// where `depth` and `stencil` ask for them (as
    /// [`Framebuffer::copy_tile`]).
    pub(crate) fn tile_views(
        &mut self,
        size: u32,
        wanted: &[usize],
        depth: bool,
        stencil: bool,
    ) -> Vec<TileView<'_>> {
        let (width, size) = (self.width as usize, size.max(1) as usize);
        let (height, cols) = (self.height as usize, width.div_ceil(size).max(1));
        let mut views: Vec<TileView> = wanted
            .iter()
            .map(|&t| TileView {
                width: width.saturating_sub(t % cols * size).min(size) as u32,
                height: height.saturating_sub(t / cols * size).min(size) as u32,
                depth_format: self.depth_format,
                color: Vec::new(),
                depth: None,
                stencil: None,
            })
            .collect();
        let grid = (width, size, cols);
        for c in self.color.iter_mut() {
            match c {
                ColorBuffer::Rgba8(v) => {
                    for (view, rows) in views.iter_mut().zip(split_tiles(v, grid, wanted)) {
                        view.color.push(TileColor::Rgba8(rows));
                    }
                }
                ColorBuffer::Rgba32F(v) => {
                    for (view, rows) in views.iter_mut().zip(split_tiles(v, grid, wanted)) {
                        view.color.push(TileColor::Rgba32F(rows));
                    }
                }
            }
        }
        if let Some(d) = self.depth.as_mut().filter(|_| depth) {
            for (view, rows) in views.iter_mut().zip(split_tiles(d, grid, wanted)) {
                view.depth = Some(rows);
            }
        }
        if let Some(st) = self.stencil.as_mut().filter(|_| stencil) {
            for (view, rows) in views.iter_mut().zip(split_tiles(st, grid, wanted)) {
                view.stencil = Some(rows);
            }
        }
        views
    }

    /// Reads a `w`×`h` block of color buffer `buffer` starting at (x, y),
    /// bottom row first, as floats. Pixels outside the buffer (or of a
    /// missing buffer) read as zeros.
    pub fn read_pixels(&self, buffer: usize, x: i32, y: i32, w: u32, h: u32) -> Vec<[f32; 4]> {
        self.read_block(x, y, w, h, |i| {
            self.color.get(buffer).map_or([0.0; 4], |b| b.get(i))
        })
    }

    /// Like [`Framebuffer::read_pixels`], converted to 8-bit unorm.
    pub fn read_pixels_u8(&self, buffer: usize, x: i32, y: i32, w: u32, h: u32) -> Vec<[u8; 4]> {
        self.read_block(x, y, w, h, |i| match self.color.get(buffer) {
            Some(ColorBuffer::Rgba8(v)) => v.get(i).copied().unwrap_or([0; 4]),
            Some(ColorBuffer::Rgba32F(v)) => v.get(i).map_or([0; 4], |p| p.map(float_to_unorm8)),
            None => [0; 4],
        })
    }

    /// Depth values in [0, 1]; zeros outside or without a depth buffer.
    pub fn read_depth(&self, x: i32, y: i32, w: u32, h: u32) -> Vec<f32> {
        self.read_block(x, y, w, h, |i| {
            self.depth
                .as_ref()
                .and_then(|d| d.get(i))
                .map_or(0.0, |&k| fixed_to_depth(k))
        })
    }

    pub fn read_stencil(&self, x: i32, y: i32, w: u32, h: u32) -> Vec<u8> {
        self.read_block(x, y, w, h, |i| {
            self.stencil
                .as_ref()
                .and_then(|s| s.get(i))
                .copied()
                .unwrap_or(0)
        })
    }

    fn read_block<T: Default>(
        &self,
        x: i32,
        y: i32,
        w: u32,
        h: u32,
        get: impl Fn(usize) -> T,
    ) -> Vec<T> {
        let w = w.min(MAX_FRAMEBUFFER_SIZE);
        let h = h.min(MAX_FRAMEBUFFER_SIZE);
        let mut out = Vec::with_capacity(w as usize * h as usize);
        for row in 0..h as i64 {
            for col in 0..w as i64 {
                let (px, py) = (x as i64 + col, y as i64 + row);
                if px >= 0 && py >= 0 && px < self.width as i64 && py < self.height as i64 {
                    out.push(get(py as usize * self.width as usize + px as usize));
                } else {
                    out.push(T::default());
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The row-by-row clears against the per-pixel rule: inside the
    /// (clipped) scissor box the masked channels, depth and stencil bits
    /// take the clear values, everything else keeps its bytes.
    #[test]
    fn clears_touch_the_scissor_box_only() {
        let (w, h) = (7u32, 5u32);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
        let mut float = Framebuffer::new(w, h, ColorFormat::Rgba32F, false, false);
        let fill = |i: usize| [i as u8, (3 * i) as u8, (7 * i) as u8, (11 * i) as u8];
        if let ColorBuffer::Rgba8(v) = &mut fb.color[0] {
            v.iter_mut().enumerate().for_each(|(i, p)| *p = fill(i));
        }
        if let ColorBuffer::Rgba32F(v) = &mut float.color[0] {
            v.iter_mut()
                .enumerate()
                .for_each(|(i, p)| *p = fill(i).map(f32::from));
        }
        for (i, d) in fb.depth.as_mut().unwrap().iter_mut().enumerate() {
            *d = i as u32;
        }
        for (i, s) in fb.stencil.as_mut().unwrap().iter_mut().enumerate() {
            *s = (5 * i) as u8;
        }
        for (scissor, mask) in [
            (None, [true; 4]),
            (Some(Rect::new(2, 1, 3, 9)), [true; 4]),
            (Some(Rect::new(-2, 3, 5, 1)), [true, false, true, false]),
            (Some(Rect::new(9, 0, 3, 3)), [false, true, false, true]),
        ] {
            let (mut a, mut f) = (fb.clone(), float.clone());
            a.clear_color(&[0, 3], [0.5, 0.25, 1.0, 0.0], mask, scissor);
            f.clear_color(&[0], [0.5, 0.25, 1.0, 0.0], mask, scissor);
            a.clear_depth(0.75, true, scissor);
            a.clear_stencil(0x1ab, 0x0f, scissor);
            let r = scissor.unwrap_or(Rect::new(0, 0, w as i32, h as i32));
            for y in 0..h as i32 {
                for x in 0..w as i32 {
                    let i = (y as u32 * w + x as u32) as usize;
                    let inside = x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h;
                    let old = fill(i);
                    let want: [u8; 4] = std::array::from_fn(|c| {
                        if inside && mask[c] {
                            [128, 64, 255, 0][c]
                        } else {
                            old[c]
                        }
                    });
                    let ColorBuffer::Rgba8(v) = &a.color[0] else {
                        unreachable!()
                    };
                    assert_eq!(v[i], want, "{x},{y} {scissor:?}");
                    let ColorBuffer::Rgba32F(v) = &f.color[0] else {
                        unreachable!()
                    };
                    let want_f: [f32; 4] = std::array::from_fn(|c| {
                        if inside && mask[c] {
                            [0.5, 0.25, 1.0, 0.0][c]
                        } else {
                            f32::from(old[c])
                        }
                    });
                    assert_eq!(v[i], want_f);
                    let depth = a.depth.as_ref().unwrap()[i];
                    assert_eq!(
                        depth,
                        if inside {
                            depth_to_fixed(0.75)
                        } else {
                            i as u32
                        }
                    );
                    let old_s = (5 * i) as u8;
                    let want_s = if inside {
                        (old_s & !0x0f) | 0x0b
                    } else {
                        old_s
                    };
                    assert_eq!(a.stencil.as_ref().unwrap()[i], want_s);
                }
            }
        }
    }

    /// Tile views read what `copy_tile` copies (edge tiles narrower and
    /// shorter, depth and stencil only when asked) and write back only
    /// their own tile's pixels.
    #[test]
    fn tile_views_load_and_store_their_tiles() {
        let (w, h) = (150u32, 70u32);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
        fb.color
            .push(ColorBuffer::Rgba32F(vec![[0.0; 4]; (w * h) as usize]));
        for (i, p) in fb.color.iter_mut().enumerate() {
            match p {
                ColorBuffer::Rgba8(v) => v
                    .iter_mut()
                    .enumerate()
                    .for_each(|(k, p)| *p = [k as u8, (k >> 8) as u8, i as u8, 1]),
                ColorBuffer::Rgba32F(v) => v
                    .iter_mut()
                    .enumerate()
                    .for_each(|(k, p)| *p = [k as f32, 2.0, 3.0, 4.0]),
            }
        }
        for (k, d) in fb.depth.as_mut().unwrap().iter_mut().enumerate() {
            *d = 3 * k as u32;
        }
        for (k, st) in fb.stencil.as_mut().unwrap().iter_mut().enumerate() {
            *st = (7 * k) as u8;
        }
        // Three columns (64, 64, 22 wide), two rows (64, 6 high).
        let wanted = [0usize, 2, 3, 5];
        for (depth, stencil) in [(true, false), (false, true)] {
            let before = fb.clone();
            let mut expected = fb.clone();
            let mut views = fb.tile_views(64, &wanted, depth, stencil);
            assert_eq!(views.len(), wanted.len());
            for (view, &t) in views.iter_mut().zip(&wanted) {
                let (x0, y0) = ((t % 3) as u32 * 64, (t / 3) as u32 * 64);
                let area = (x0, y0, x0 + 64, y0 + 64);
                let mut tile = view.load();
                assert_eq!(tile, before.copy_tile(area, depth, stencil), "tile {t}");
                // Every pixel changed, written back through the view and
                // through the bands (the reference).
                for c in tile.color.iter_mut() {
                    match c {
                        ColorBuffer::Rgba8(v) => v.iter_mut().for_each(|p| p[3] = 200 + t as u8),
                        ColorBuffer::Rgba32F(v) => v.iter_mut().for_each(|p| p[1] = -(t as f32)),
                    }
                }
                tile.depth.iter_mut().flatten().for_each(|d| *d = 9);
                tile.stencil
                    .iter_mut()
                    .flatten()
                    .for_each(|st| *st = t as u8);
                view.store(&tile);
                expected.store_tile(x0, y0, &tile);
            }
            drop(views);
            assert_eq!(fb, expected);
            assert_ne!(fb, before);
        }
    }

    #[test]
    fn unorm_conversion_rounds_to_nearest() {
        assert_eq!(float_to_unorm8(0.5), 128);
        assert_eq!(float_to_unorm8(127.4 / 255.0), 127);
        assert_eq!(float_to_unorm8(-1.0), 0);
        assert_eq!(float_to_unorm8(2.0), 255);
        assert_eq!(float_to_unorm8(f32::NAN), 0);
    }

    #[test]
    fn depth_conversion() {
        assert_eq!(depth_to_fixed(0.0), 0);
        assert_eq!(depth_to_fixed(1.0), DEPTH_MAX);
        assert_eq!(depth_to_fixed(0.5), 1 << 23);
        assert_eq!(depth_to_fixed(-0.5), 0);
        assert_eq!(depth_to_fixed(2.0), DEPTH_MAX);
        assert_eq!(depth_to_fixed(f32::NAN), 0);
        // Rounded after the f32 product, ties to even: 2.5 / (2^24 - 1)
        // times 2^24 - 1 is 2.5 in f32 (as Mesa computes it), which goes
        // to 2, and 3.5 to 4.
        let at = |k: f64| (k / DEPTH_MAX as f64) as f32;
        assert_eq!((at(2.5) * DEPTH_MAX as f32), 2.5);
        assert_eq!(depth_to_fixed(at(2.5)), 2);
        assert_eq!(depth_to_fixed(at(3.5)), 4);
        assert_eq!(fixed_to_depth(DEPTH_MAX), 1.0);
    }

    /// A 16-bit buffer's values are the 24-bit forms of `k / 65535`: the
    /// ends map to the 24-bit ends, a value already `k / 65535` (an
    /// attachment's stored texel) keeps its form, depths within half a
    /// 16-bit step share one value that 24 bits keep apart, and the
    /// rounding is llvmpipe's (ties to even on `z · 65535/65536` in f32).
    #[test]
    fn depth16_conversion() {
        let d16 = DepthFormat::Bits16;
        assert_eq!(d16.to_fixed(0.0), 0);
        assert_eq!(d16.to_fixed(1.0), DEPTH_MAX);
        assert_eq!(d16.to_fixed(-1.0), 0);
        assert_eq!(d16.to_fixed(f32::NAN), 0);
        for k in [1u32, 2, 255, 256, 32767, 32768, 65534] {
            let z = (k as f64 / 65535.0) as f32;
            assert_eq!(d16.to_fixed(z), depth_to_fixed(z), "k = {k}");
        }
        // 0.99968 and 0.9996803 are 5 24-bit steps apart, and in the same
        // 16-bit step.
        let (a, b) = (0.99968f32, 0.9996803f32);
        assert_ne!(depth_to_fixed(a), depth_to_fixed(b));
        assert_eq!(d16.to_fixed(a), d16.to_fixed(b));
        assert_eq!(DepthFormat::Bits24.to_fixed(a), depth_to_fixed(a));
        // (k + ½) / 65536 · 65536/65535 · 65535/65536 lands on the tie
        // k + ½ of z · 65535: even k keeps k, odd k goes up.
        let tie = |k: u32| ((k as f64 + 0.5) / 65535.0) as f32;
        let step = |k: u32| depth_to_fixed((k as f64 / 65535.0) as f32);
        assert_eq!(d16.to_fixed(tie(2)), step(2));
        assert_eq!(d16.to_fixed(tie(3)), step(4));
        assert_eq!(
            d16.to_fixed4([0.0, 1.0, a as f64, 2.0]),
            [0, DEPTH_MAX, d16.to_fixed(a), DEPTH_MAX]
        );
    }

    #[test]
    fn tiles_copy_out_and_back() {
        let mut fb = Framebuffer::new(5, 4, ColorFormat::Rgba8, true, true);
        fb.clear_color(&[0], [1.0; 4], [true; 4], Some(Rect::new(1, 1, 2, 2)));
        let mut tile = fb.copy_tile((1, 1, 3, 9), true, true);
        assert_eq!((tile.width, tile.height), (2, 3));
        assert_eq!(tile.read_pixels_u8(0, 0, 0, 2, 2), vec![[255; 4]; 4]);
        assert_eq!(tile.read_pixels_u8(0, 0, 2, 2, 1), vec![[0; 4]; 2]);
        tile.clear_color(
            &[0],
            [0.0, 1.0, 0.0, 1.0],
            [true; 4],
            Some(Rect::new(1, 0, 1, 1)),
        );
        tile.clear_depth(1.0, true, None);
        tile.clear_stencil(7, 0xff, None);
        fb.store_tile(1, 1, &tile);
        assert_eq!(fb.read_pixels_u8(0, 2, 1, 1, 1), vec![[0, 255, 0, 255]]);
        assert_eq!(fb.read_pixels_u8(0, 1, 1, 1, 1), vec![[255; 4]]);
        assert_eq!(fb.read_depth(0, 0, 5, 1), vec![0.0; 5]);
        assert_eq!(fb.read_depth(1, 1, 3, 1), vec![1.0, 1.0, 0.0]);
        assert_eq!(fb.read_stencil(2, 3, 1, 1), vec![7]);
        assert_eq!(fb.read_stencil(3, 3, 1, 1), vec![0]);
        // A tile without depth and stencil leaves the framebuffer's.
        let mut tile = fb.copy_tile((0, 0, 5, 4), false, false);
        assert!(tile.depth.is_none() && tile.stencil.is_none());
        tile.clear_color(&[0], [0.0; 4], [true; 4], None);
        fb.store_tile(0, 0, &tile);
        assert_eq!(fb.read_pixels_u8(0, 1, 1, 1, 1), vec![[0; 4]]);
        assert_eq!(fb.read_depth(1, 1, 3, 1), vec![1.0, 1.0, 0.0]);
        assert_eq!(fb.read_stencil(2, 3, 1, 1), vec![7]);
    }

    #[test]
    fn clear_respects_scissor_and_masks() {
        let mut fb = Framebuffer::new(4, 4, ColorFormat::Rgba8, true, true);
        fb.clear_color(&[0], [1.0, 0.5, 0.25, 1.0], [true, true, false, true], None);
        fb.clear_color(&[0], [0.0; 4], [true; 4], Some(Rect::new(1, 1, 2, 10)));
        let px = fb.read_pixels_u8(0, 0, 0, 4, 4);
        assert_eq!(px[0], [255, 128, 0, 255]);
        assert_eq!(px[5], [0, 0, 0, 0]);
        assert_eq!(px[4 * 3 + 2], [0, 0, 0, 0]);
        assert_eq!(px[4 * 3 + 3], [255, 128, 0, 255]);
        fb.clear_depth(1.0, true, None);
        fb.clear_depth(0.0, false, None);
        assert_eq!(fb.read_depth(0, 0, 1, 1), vec![1.0]);
        fb.clear_stencil(0x1ff, 0x0f, None);
        assert_eq!(fb.read_stencil(0, 0, 1, 1), vec![0x0f]);
        // Outside reads are zero.
        assert_eq!(fb.read_pixels(0, -1, 0, 1, 1), vec![[0.0; 4]]);
    }
}
