//! The raster-position pixel path (GL 2.1 §2.13, §3.6.4, §3.7, §4.3.3):
//! glRasterPos / glWindowPos set the current raster position, and
//! glDrawPixels, glBitmap and glCopyPixels draw rectangles of fragments
//! there.
//!
//! - glRasterPos runs the current vertex stage (the program's vertex
//!   shader, or the generated fixed-function one with every texture
//!   coordinate set) on one vertex made of the given position and the
//!   current attributes, then clips the result against the view volume
//!   and the enabled user clip planes: outside, the raster position
//!   becomes invalid. Inside, the window coordinates, the (clamped) front
//!   color and secondary color, and the texture coordinates come from the
//!   stage's outputs; the raster distance is the fog coordinate (with
//!   GL_FOG_COORD_SRC = GL_FOG_COORD) or the eye-space distance.
//! - glWindowPos sets the window coordinates directly (z through the depth
//!   range), with the current color, secondary color and texture
//!   coordinates; the raster position is then valid.
//! - Pixel rectangles become fragments (a pixel at column i, row j covers
//!   the window rectangle from `(xr + zx*i, yr + zy*j)` to
//!   `(xr + zx*(i+1), yr + zy*(j+1))`; pixels whose centers lie inside, or
//!   on its left/bottom edge, get a fragment) that go through the
//!   per-fragment operations ([`raster::write_pixel_fragments`]), so the
//!   scissor, alpha, stencil and depth tests, blending, logic op, masks
//!   and occlusion queries apply. Color rectangles take the raster z;
//!   depth rectangles the raster color; stencil rectangles write the
//!   stencil buffer (scissor and stencil write mask apply). Bitmaps draw
//!   the raster color at the raster z where a bit is set, then move the
//!   raster position.
//!
//! Limitations: pixel-rectangle fragments are not shaded — texturing, fog,
//! color sum and a bound fragment shader do not apply to them (GL applies
//! them); of the pixel transfer operations only the scale and bias of
//! color and depth and the index shift/offset of stencil indices apply
//! (pixel maps do not); GL_COLOR_INDEX data and GL_BITMAP-typed rectangles
//! raise GL_INVALID_OPERATION. Images and bitmaps are given in the packed
//! layout (bitmaps most significant bit first): the caller applies the
//! glPixelStore modes ([`crate::pixel_store`]).

use crate::enums::*;
use crate::fetch::Fetcher;
use crate::pixel_transfer::{bitmap_row_bytes, clamp01, pixel_size, unpack_rgba, PixelTransfer};
use crate::Context;
use glsl::Stage;
use raster::PixelFragment;

/// The current raster position and its associated data (GL 2.1 §2.13).
#[derive(Clone, Debug, PartialEq)]
pub struct RasterPos {
    /// Window x, y, z and clip w.
    pub window: [f32; 4],
    pub valid: bool,
    pub color: [f32; 4],
    pub secondary: [f32; 4],
    pub tex: [[f32; 4]; crate::MAX_TEXTURE_UNITS],
    pub distance: f32,
}

impl Default for RasterPos {
    fn default() -> Self {
        RasterPos {
            window: [0.0, 0.0, 0.0, 1.0],
            valid: true,
            color: [1.0; 4],
            secondary: [0.0, 0.0, 0.0, 1.0],
            tex: [[0.0, 0.0, 0.0, 1.0]; crate::MAX_TEXTURE_UNITS],
            distance: 0.0,
        }
    }
}

/// How far below a whole pixel a bitmap's corner may lie and still start
/// at that pixel ([`Context::bitmap`]).
const BITMAP_SNAP: f64 = 1e-4;

/// A rectangle of pixel values ready to draw.
enum Block {
    Color(Vec<[f32; 4]>),
    Depth(Vec<f32>),
    Stencil(Vec<u8>),
}

/// Half-open range of integer pixel columns (or rows) whose centers lie in
/// the window interval between `a` and `b`.
fn covered(a: f64, b: f64, limit: u32) -> std::ops::Range<u32> {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    let first = (lo - 0.5).ceil().clamp(0.0, limit as f64) as u32;
    let end = (hi - 0.5).ceil().clamp(0.0, limit as f64) as u32;
    first..end.max(first)
}

impl Context {
    /// The current raster position.
    pub fn raster_pos(&self) -> &RasterPos {
        &self.raster
    }

    /// glRasterPos4f (every glRasterPos* variant: z 0 and w 1 by default).
    pub fn raster_pos_4f(&mut self, x: f32, y: f32, z: f32, w: f32) {
        if self.reject_in_begin() {
            return;
        }
        match self.transform_raster_pos([x, y, z, w]) {
            Some(r) => self.raster = r,
            None => self.raster.valid = false,
        }
    }

    /// The raster position of object-space `pos`, or None when it is
    /// clipped (or the vertex stage cannot run).
    fn transform_raster_pos(&mut self, pos: [f32; 4]) -> Option<RasterPos> {
        let user = self
            .stage_executable(Stage::Vertex)
            .and_then(|e| e.kernels.vs.clone());
        let (vs, is_user) = match user {
            Some(k) => (k, true),
            None => {
                let src = self.ff_vertex_source(crate::MAX_TEXTURE_UNITS);
                (self.ff_kernel(src, Stage::Vertex).ok()?, false)
            }
        };
        let words = self.uniform_words(&vs, is_user);
        let units = self.texture_units();
        let vertex = [self.va.snapshot(pos)];
        let mut batch = exec::Batch::for_kernel(&vs, 1);
        {
            let fetch = Fetcher::new(
                self,
                &vs,
                Some(&vertex),
                crate::fetch::InstanceBatch::one(0),
            );
            raster::fetch_vertex(vs.interface(), &fetch, 0, &mut batch, 0);
        }
        vs.run(&mut batch, &words, &units).ok()?;
        let iface = vs.interface();
        let out = |name: &str, n: usize| -> Option<Vec<f32>> {
            let s = iface.output(name)?;
            Some(
                (0..n.min(s.components))
                    .map(|c| batch.outputs.get(s.offset + c).map_or(0.0, |l| l[0]))
                    .collect(),
            )
        };
        let v4 = |v: Option<Vec<f32>>, default: [f32; 4]| -> [f32; 4] {
            match v {
                Some(v) => std::array::from_fn(|i| v.get(i).copied().unwrap_or(default[i])),
                None => default,
            }
        };
        let clip = v4(out("gl_Position", 4), [0.0, 0.0, 0.0, 1.0]);
        let [cx, cy, cz, cw] = clip.map(|c| c as f64);
        if !(cw > 0.0 && cx.abs() <= cw && cy.abs() <= cw && cz.abs() <= cw) {
            return None;
        }
        let clip_vertex = v4(out("gl_ClipVertex", 4).or(out("gl_Position", 4)), clip);
        // GL 3.3 §2.20: a shader writing gl_ClipDistance clips against its
        // elements instead of the plane equations (elements it lacks do
        // not clip).
        let distances = iface
            .output("gl_ClipDistance")
            .filter(|s| s.written)
            .and_then(|s| out("gl_ClipDistance", s.components));
        for (i, p) in self.clip_planes.iter().enumerate() {
            if self.st.is_on(GL_CLIP_PLANE0 + i as u32) {
                let d: f64 = match &distances {
                    Some(d) => d.get(i).map_or(0.0, |&d| d as f64),
                    None => (0..4).map(|k| p[k] as f64 * clip_vertex[k] as f64).sum(),
                };
                if d.is_nan() || d < 0.0 {
                    return None;
                }
            }
        }
        let vp = self.viewport.map(|v| v as f64);
        let (n, f) = (self.depth_range[0] as f64, self.depth_range[1] as f64);
        let window = [
            (vp[0] + (cx / cw + 1.0) * vp[2] / 2.0) as f32,
            (vp[1] + (cy / cw + 1.0) * vp[3] / 2.0) as f32,
            ((f - n) / 2.0 * (cz / cw) + (n + f) / 2.0) as f32,
            cw as f32,
        ];
        let color = v4(out("gl_FrontColor", 4), self.va.color).map(clamp01);
        let secondary = v4(out("gl_FrontSecondaryColor", 4), self.va.secondary).map(clamp01);
        let tc = out("gl_TexCoord", 4 * crate::MAX_TEXTURE_UNITS).unwrap_or_default();
        let tex = std::array::from_fn(|u| {
            if tc.len() >= 4 * (u + 1) {
                [tc[4 * u], tc[4 * u + 1], tc[4 * u + 2], tc[4 * u + 3]]
            } else {
                self.va.tex[u]
            }
        });
        let distance = if self.st.fog.coord_src == GL_FOG_COORD {
            self.va.fog[0]
        } else {
            let mv = self
                .modelview
                .last()
                .copied()
                .unwrap_or(crate::matrix::IDENTITY);
            let eye = crate::matrix::mul_vec(&mv, pos);
            let d: f64 = eye[..3].iter().map(|&e| e as f64 * e as f64).sum();
            d.sqrt() as f32
        };
        Some(RasterPos {
            window,
            valid: true,
            color,
            secondary,
            tex,
            distance,
        })
    }

    /// glWindowPos3f (every glWindowPos* variant: z 0 by default).
    pub fn window_pos_3f(&mut self, x: f32, y: f32, z: f32) {
        if self.reject_in_begin() {
            return;
        }
        let (n, f) = (self.depth_range[0], self.depth_range[1]);
        let z = clamp01(z);
        self.raster = RasterPos {
            window: [x, y, n + z * (f - n), 1.0],
            valid: true,
            color: self.va.color.map(clamp01),
            secondary: self.va.secondary.map(clamp01),
            tex: self.va.tex,
            distance: if self.st.fog.coord_src == GL_FOG_COORD {
                self.va.fog[0]
            } else {
                0.0
            },
        };
    }

    /// Checks of glDrawPixels' format/type pair (GL 2.1 §3.6.4): Some when
    /// drawable. Records the error otherwise.
    fn check_pixel_format(&mut self, format: u32, ty: u32) -> bool {
        let known_format = matches!(
            format,
            GL_COLOR_INDEX
                | GL_STENCIL_INDEX
                | GL_DEPTH_COMPONENT
                | GL_RED
                | GL_GREEN
                | GL_BLUE
                | GL_ALPHA
                | GL_RGB
                | GL_RGBA
                | GL_BGR
                | GL_BGRA
                | GL_LUMINANCE
                | GL_LUMINANCE_ALPHA
        );
        let known_type = ty == GL_BITMAP
            || pixel_size(GL_RGBA, ty).is_some()
            || pixel_size(GL_RGB, ty).is_some();
        if !known_format || !known_type {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if ty == GL_BITMAP && !matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX) {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if pixel_size(format, ty).is_none() || format == GL_COLOR_INDEX {
            // Packed types with the wrong component count; color-index
            // and bitmap data (not implemented).
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    /// Whether the draw (and, for copies, read) framebuffer has the buffer
    /// a depth or stencil rectangle needs.
    fn has_buffer(&self, fb: u32, what: u32) -> bool {
        if fb == 0 {
            return true;
        }
        let Some(f) = self.objects.framebuffers.get(&fb) else {
            return false;
        };
        match what {
            GL_DEPTH_COMPONENT => f.depth.is_some(),
            GL_STENCIL_INDEX => f.stencil.is_some(),
            _ => true,
        }
    }

    /// glDrawPixels: `data` holds the client image (rows at `alignment`,
    /// the unpack alignment when it was read; bottom row first; None: no
    /// data, nothing drawn).
    #[allow(clippy::too_many_arguments)]
    pub fn draw_pixels(
        &mut self,
        w: i32,
        h: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
        alignment: usize,
        transfer: &PixelTransfer,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_pixel_format(format, ty) {
            return;
        }
        // Conditional rendering discards pixel rectangles (GL 3.3
        // compatibility §2.19).
        if self.render_discarded() {
            return;
        }
        let what = match format {
            GL_DEPTH_COMPONENT | GL_STENCIL_INDEX => format,
            _ => GL_RGBA,
        };
        if !self.has_buffer(self.objects.draw_framebuffer, what) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !self.check_fbo_complete() || !self.raster.valid {
            return;
        }
        let Some(data) = data else { return };
        let (wu, hu) = (w as usize, h as usize);
        let px = unpack_rgba(data, wu, hu, format, ty, alignment.max(1));
        let block = match format {
            GL_DEPTH_COMPONENT => Block::Depth(px.iter().map(|p| transfer.depth(p[0])).collect()),
            GL_STENCIL_INDEX => {
                let max = match ty {
                    GL_UNSIGNED_BYTE => 255.0,
                    GL_BYTE => 127.0,
                    GL_UNSIGNED_SHORT => 65535.0,
                    GL_SHORT => 32767.0,
                    GL_UNSIGNED_INT => 4294967295.0,
                    GL_INT => 2147483647.0,
                    _ => 1.0,
                };
                Block::Stencil(
                    px.iter()
                        .map(|p| transfer.index((p[0] as f64 * max).round() as i64))
                        .collect(),
                )
            }
            _ => Block::Color(px.iter().map(|&p| transfer.color(p)).collect()),
        };
        self.draw_block(wu, hu, &block, transfer.zoom);
    }

    /// glCopyPixels: the `w` x `h` rectangle at (x, y) of the read
    /// framebuffer (`ty` GL_COLOR, GL_DEPTH or GL_STENCIL) drawn at the
    /// raster position as glDrawPixels would.
    pub fn copy_pixels(
        &mut self,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
        ty: u32,
        transfer: &PixelTransfer,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let what = match ty {
            GL_COLOR => GL_RGBA,
            GL_DEPTH => GL_DEPTH_COMPONENT,
            GL_STENCIL => GL_STENCIL_INDEX,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        if self.render_discarded() {
            return;
        }
        if !self.has_buffer(self.objects.draw_framebuffer, what)
            || !self.has_buffer(self.objects.read_framebuffer, what)
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let rb = self.objects.read_framebuffer;
        if !self.check_fbo_complete() {
            return;
        }
        if self.framebuffer_status(rb) != GL_FRAMEBUFFER_COMPLETE {
            self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
            return;
        }
        if !self.raster.valid {
            return;
        }
        let (wu, hu) = (
            (w as u32).min(crate::MAX_TEXTURE_SIZE as u32),
            (h as u32).min(crate::MAX_TEXTURE_SIZE as u32),
        );
        let Some(px) = self.read_block(x, y, wu, hu, what) else {
            return;
        };
        let block = match what {
            GL_DEPTH_COMPONENT => Block::Depth(px.iter().map(|p| transfer.depth(p[0])).collect()),
            GL_STENCIL_INDEX => {
                Block::Stencil(px.iter().map(|p| transfer.index(p[0] as i64)).collect())
            }
            _ => Block::Color(px.iter().map(|&p| transfer.color(p)).collect()),
        };
        self.draw_block(wu as usize, hu as usize, &block, transfer.zoom);
    }

    /// glBitmap: `bits` holds `h` rows of [`bitmap_row_bytes`] bytes at
    /// `alignment` (most significant bit first; None: no image, only the
    /// move).
    #[allow(clippy::too_many_arguments)]
    pub fn bitmap(
        &mut self,
        w: i32,
        h: i32,
        xorig: f32,
        yorig: f32,
        xmove: f32,
        ymove: f32,
        bits: Option<&[u8]>,
        alignment: usize,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        // A discarded glBitmap does not move the raster position either.
        if !self.check_fbo_complete() || !self.raster.valid || self.render_discarded() {
            return;
        }
        if let (Some(bits), true) = (bits, w > 0 && h > 0) {
            let stride = bitmap_row_bytes(w as usize, alignment);
            // (x_ll, y_ll) = (floor(x_rp - x_bo), floor(y_rp - y_bo)) (GL 2.1
            // §3.7) of a raster position that carries the rounding of the
            // vertex transform: one meant to be a whole pixel (text drawn
            // at glRasterPos2i) can come out an ulp below it, and the floor
            // would then move the bitmap a whole pixel. Positions within
            // BITMAP_SNAP below a whole number count as that number, as
            // llvmpipe does.
            let x0 = (self.raster.window[0] as f64 - xorig as f64 + BITMAP_SNAP).floor();
            let y0 = (self.raster.window[1] as f64 - yorig as f64 + BITMAP_SNAP).floor();
            let finite = x0.is_finite() && y0.is_finite();
            let (z, color) = (self.raster.window[2], self.raster.color);
            // (draw_target moves the framebuffer out: only when drawing.)
            let target = if finite { self.draw_target() } else { None };
            if let Some(mut t) = target {
                let (fw, fh) = (t.fb.width as f64, t.fb.height as f64);
                let mut frags = Vec::new();
                for j in 0..h as usize {
                    let y = y0 + j as f64;
                    if y < 0.0 || y >= fh {
                        continue;
                    }
                    for i in 0..w as usize {
                        let x = x0 + i as f64;
                        let byte = bits.get(j * stride + i / 8).copied().unwrap_or(0);
                        if x < 0.0 || x >= fw || byte & (0x80 >> (i % 8)) == 0 {
                            continue;
                        }
                        frags.push(PixelFragment {
                            x: x as u32,
                            y: y as u32,
                            z,
                            color,
                        });
                    }
                }
                self.write_fragments(&mut t, &frags);
                self.store_target(t);
            }
        }
        self.raster.window[0] += xmove;
        self.raster.window[1] += ymove;
    }

    fn write_fragments(&mut self, t: &mut crate::render_target::Target, frags: &[PixelFragment]) {
        let state = self.pipeline_state(t);
        let n = raster::write_pixel_fragments(&mut t.fb, &state, frags);
        self.count_samples(n);
    }

    /// Draws a `w` x `h` block at the raster position with `zoom`.
    fn draw_block(&mut self, w: usize, h: usize, block: &Block, zoom: (f32, f32)) {
        let Some(mut t) = self.draw_target() else {
            return;
        };
        let (xr, yr) = (self.raster.window[0] as f64, self.raster.window[1] as f64);
        let (zx, zy) = (zoom.0 as f64, zoom.1 as f64);
        let (fw, fh) = (t.fb.width, t.fb.height);
        let (z, color) = (self.raster.window[2], self.raster.color);
        let scissor = self.st.is_on(GL_SCISSOR_TEST).then_some(self.st.scissor);
        let stencil_mask = self.st.stencil[0].write_mask as u8;
        let mut frags = Vec::new();
        for j in 0..h {
            let rows = covered(yr + zy * j as f64, yr + zy * (j + 1) as f64, fh);
            if rows.is_empty() {
                continue;
            }
            for i in 0..w {
                let cols = covered(xr + zx * i as f64, xr + zx * (i + 1) as f64, fw);
                let k = j * w + i;
                for y in rows.clone() {
                    for x in cols.clone() {
                        match block {
                            Block::Color(v) => frags.push(PixelFragment {
                                x,
                                y,
                                z,
                                color: v.get(k).copied().unwrap_or(color),
                            }),
                            Block::Depth(v) => frags.push(PixelFragment {
                                x,
                                y,
                                z: v.get(k).copied().unwrap_or(z),
                                color,
                            }),
                            Block::Stencil(v) => {
                                let inside = scissor.is_none_or(|s| {
                                    let (x, y) = (x as i64, y as i64);
                                    x >= s[0] as i64
                                        && y >= s[1] as i64
                                        && x < s[0] as i64 + s[2] as i64
                                        && y < s[1] as i64 + s[3] as i64
                                });
                                let idx = y as usize * fw as usize + x as usize;
                                if let (true, Some(p)) =
                                    (inside, t.fb.stencil.as_mut().and_then(|s| s.get_mut(idx)))
                                {
                                    let s = v.get(k).copied().unwrap_or(0);
                                    *p = (*p & !stencil_mask) | (s & stencil_mask);
                                }
                            }
                        }
                    }
                }
            }
        }
        if !frags.is_empty() {
            self.write_fragments(&mut t, &frags);
        }
        self.store_target(t);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pixel_ortho(ctx: &mut Context, w: f64, h: f64) {
        ctx.matrix_mode(GL_PROJECTION);
        ctx.load_identity();
        ctx.ortho(0.0, w, 0.0, h, -1.0, 1.0);
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.load_identity();
    }

    #[test]
    fn raster_pos_transforms_and_clips() {
        let mut ctx = Context::new(16, 8);
        pixel_ortho(&mut ctx, 16.0, 8.0);
        ctx.color_4f(0.5, 2.0, 0.25, 1.0);
        ctx.raster_pos_4f(3.0, 5.0, 0.0, 1.0);
        let r = ctx.raster_pos().clone();
        assert!(r.valid);
        assert_eq!(r.window, [3.0, 5.0, 0.5, 1.0]);
        assert_eq!(r.color, [0.5, 1.0, 0.25, 1.0]);
        ctx.raster_pos_4f(-1.0, 5.0, 0.0, 1.0);
        assert!(!ctx.raster_pos().valid);
        ctx.window_pos_3f(-4.0, 2.0, 1.0);
        assert!(ctx.raster_pos().valid);
        assert_eq!(ctx.raster_pos().window, [-4.0, 2.0, 1.0, 1.0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn draw_pixels_with_zoom_and_bitmap() {
        let mut ctx = Context::new(8, 8);
        ctx.window_pos_3f(1.0, 2.0, 0.0);
        let data = [255u8, 0, 0, 255, 0, 255, 0, 255];
        let t = PixelTransfer {
            zoom: (2.0, 3.0),
            ..PixelTransfer::default()
        };
        ctx.draw_pixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&data), 4, &t);
        let px = ctx.read_pixels_f32(0, 0, 8, 8);
        let at = |x: usize, y: usize| px[y * 8 + x];
        assert_eq!(at(1, 2), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(at(2, 4), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(at(4, 3), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(at(5, 5), [0.0; 4]);
        assert_eq!(at(0, 2), [0.0; 4]);
        // A 3x2 bitmap, bits 101 / 010, at (5, 0) with origin (1, 0).
        ctx.color_4f(0.0, 0.0, 1.0, 1.0);
        ctx.window_pos_3f(5.0, 0.0, 0.0);
        ctx.bitmap(
            3,
            2,
            1.0,
            0.0,
            2.0,
            1.0,
            Some(&[0b1010_0000, 0, 0, 0, 0b0100_0000]),
            4,
        );
        let px = ctx.read_pixels_f32(0, 0, 8, 8);
        let at = |x: usize, y: usize| px[y * 8 + x];
        assert_eq!(at(4, 0), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(at(5, 0), [0.0; 4]);
        assert_eq!(at(6, 0), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(at(5, 1), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(ctx.raster_pos().window[..2], [7.0, 1.0]);
        // Copy the 2x2 block at (4, 0) to (0, 6).
        ctx.window_pos_3f(0.0, 6.0, 0.0);
        ctx.copy_pixels(4, 0, 2, 2, GL_COLOR, &PixelTransfer::default());
        let px = ctx.read_pixels_f32(0, 0, 8, 8);
        assert_eq!(px[6 * 8], [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(px[7 * 8 + 1], [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.draw_pixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, None, 4, &t);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.copy_pixels(0, 0, 1, 1, GL_RGBA, &t);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }
}
