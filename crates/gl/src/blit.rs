//! glBlitFramebuffer (GL 3.0 §4.3.3, ARB_framebuffer_object): a
//! rectangle of the read framebuffer copied, scaled and possibly flipped,
//! into the draw framebuffer's draw buffers (color) and its depth and
//! stencil buffers.
//!
//! Contract: destination pixel centres map linearly onto the source
//! rectangle; `GL_NEAREST` takes the source pixel under the mapped centre,
//! `GL_LINEAR` (color only) blends the four nearest, clamped to the source
//! rectangle. Only the pixel-ownership and scissor tests apply (no
//! blending, masks other than the scissor, or fragment operations).
//! Source pixels outside the read framebuffer leave their destination
//! pixels unchanged (the spec leaves them undefined). A buffer named in
//! the mask that either framebuffer lacks is skipped, as the spec says.
//! Multisample buffers hold one sample per pixel ([`crate::framebuffer`]),
//! so a resolve is a copy.

use crate::enums::*;
use crate::render_target::Target;
use crate::Context;
use raster::{float_to_unorm8, ColorBuffer, Framebuffer};

/// How one destination coordinate maps onto the source axis.
#[derive(Clone, Copy, Debug)]
struct Axis {
    src0: f64,
    scale: f64,
    dst0: i32,
}

impl Axis {
    fn new(s0: i32, s1: i32, d0: i32, d1: i32) -> Axis {
        Axis {
            src0: s0 as f64,
            scale: (s1 as f64 - s0 as f64) / (d1 as f64 - d0 as f64),
            dst0: d0,
        }
    }

    /// The source coordinate of destination pixel `d`'s centre.
    fn map(&self, d: i32) -> f64 {
        self.src0 + (d as f64 + 0.5 - self.dst0 as f64) * self.scale
    }
}

impl Context {
    /// glBlitFramebuffer.
    #[allow(clippy::too_many_arguments)]
    pub fn blit_framebuffer(&mut self, src: [i32; 4], dst: [i32; 4], mask: u32, filter: u32) {
        if self.reject_in_begin() {
            return;
        }
        let all = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
        if mask & !all != 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !matches!(filter, GL_NEAREST | GL_LINEAR) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if filter == GL_LINEAR && mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT) != 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let (read, draw) = (self.objects.read_framebuffer, self.objects.draw_framebuffer);
        if self.framebuffer_status(read) != GL_FRAMEBUFFER_COMPLETE
            || self.framebuffer_status(draw) != GL_FRAMEBUFFER_COMPLETE
        {
            self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
            return;
        }
        let [sx0, sy0, sx1, sy1] = src;
        let [dx0, dy0, dx1, dy1] = dst;
        // GL 3.3 §4.3.2: no multisample destination; a multisample source
        // resolves only unscaled.
        let span = |a: i32, b: i32| (b as i64 - a as i64).abs();
        let same_size = span(sx0, sx1) == span(dx0, dx1) && span(sy0, sy1) == span(dy0, dy1);
        if self.framebuffer_samples(draw) > 0 || (self.framebuffer_samples(read) > 0 && !same_size)
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if mask == 0 || sx0 == sx1 || sy0 == sy1 || dx0 == dx1 || dy0 == dy1 {
            return;
        }
        let Some(source) = self.read_image().map(|f| f.into_owned()) else {
            return;
        };
        let Some(mut target) = self.draw_target() else {
            return;
        };
        let (ax, ay) = (Axis::new(sx0, sx1, dx0, dx1), Axis::new(sy0, sy1, dy0, dy1));
        let bounds = self.blit_bounds(
            &target,
            dx0.min(dx1),
            dy0.min(dy1),
            dx0.max(dx1),
            dy0.max(dy1),
        );
        let src_rect = (sx0.min(sx1), sy0.min(sy1), sx0.max(sx1), sy0.max(sy1));
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            if let Some(from) = source.color.first() {
                blit_color(from, &source, &mut target, ax, ay, bounds, src_rect, filter);
            }
        }
        if mask & GL_DEPTH_BUFFER_BIT != 0 {
            if let (Some(s), Some(d)) = (source.depth.as_ref(), target.fb.depth.as_mut()) {
                copy_nearest(
                    s,
                    source.width,
                    source.height,
                    d,
                    target.fb.width,
                    ax,
                    ay,
                    bounds,
                );
            }
        }
        if mask & GL_STENCIL_BUFFER_BIT != 0 {
            if let (Some(s), Some(d)) = (source.stencil.as_ref(), target.fb.stencil.as_mut()) {
                copy_nearest(
                    s,
                    source.width,
                    source.height,
                    d,
                    target.fb.width,
                    ax,
                    ay,
                    bounds,
                );
            }
        }
        self.store_target(target);
    }

    /// The destination rectangle clipped to the draw framebuffer and, when
    /// enabled, the scissor box: (x0, y0, x1, y1), exclusive ends.
    fn blit_bounds(&self, t: &Target, x0: i32, y0: i32, x1: i32, y1: i32) -> (i32, i32, i32, i32) {
        let (mut x0, mut y0) = (x0.max(0), y0.max(0));
        let (mut x1, mut y1) = (x1.min(t.fb.width as i32), y1.min(t.fb.height as i32));
        if self.st.is_on(GL_SCISSOR_TEST) {
            let [sx, sy, sw, sh] = self.st.scissor;
            x0 = x0.max(sx);
            y0 = y0.max(sy);
            x1 = x1.min(sx.saturating_add(sw));
            y1 = y1.min(sy.saturating_add(sh));
        }
        (x0, y0, x1.max(x0), y1.max(y0))
    }
}

/// Copies color into every color buffer of the target that a draw buffer
/// selects.
#[allow(clippy::too_many_arguments)]
fn blit_color(
    from: &ColorBuffer,
    source: &Framebuffer,
    target: &mut Target,
    ax: Axis,
    ay: Axis,
    (x0, y0, x1, y1): (i32, i32, i32, i32),
    (sx0, sy0, sx1, sy1): (i32, i32, i32, i32),
    filter: u32,
) {
    let (sw, sh) = (source.width as i32, source.height as i32);
    let fetch = |x: i32, y: i32| from.get((y * sw + x) as usize);
    let mut buffers: Vec<usize> = target.draw_buffers.iter().flatten().copied().collect();
    buffers.sort_unstable();
    buffers.dedup();
    let width = target.fb.width as i32;
    for y in y0..y1 {
        let fy = ay.map(y);
        for x in x0..x1 {
            let fx = ax.map(x);
            let texel = if filter == GL_LINEAR {
                // Bilinear among the four nearest centres, clamped to the
                // source rectangle (and the read framebuffer).
                let (lx, hx) = (sx0.max(0), (sx1 - 1).min(sw - 1));
                let (ly, hy) = (sy0.max(0), (sy1 - 1).min(sh - 1));
                if lx > hx || ly > hy {
                    continue;
                }
                let (u, v) = (fx - 0.5, fy - 0.5);
                let (i0, j0) = (u.floor(), v.floor());
                let (a, b) = ((u - i0) as f32, (v - j0) as f32);
                let cx = |i: f64| (i as i32).clamp(lx, hx);
                let cy = |j: f64| (j as i32).clamp(ly, hy);
                let (p00, p10) = (fetch(cx(i0), cy(j0)), fetch(cx(i0 + 1.0), cy(j0)));
                let (p01, p11) = (
                    fetch(cx(i0), cy(j0 + 1.0)),
                    fetch(cx(i0 + 1.0), cy(j0 + 1.0)),
                );
                std::array::from_fn(|c| {
                    let top = p00[c] + (p10[c] - p00[c]) * a;
                    let bottom = p01[c] + (p11[c] - p01[c]) * a;
                    top + (bottom - top) * b
                })
            } else {
                let (sx, sy) = (fx.floor() as i32, fy.floor() as i32);
                if !(0..sw).contains(&sx) || !(0..sh).contains(&sy) {
                    continue;
                }
                fetch(sx, sy)
            };
            let i = (y * width + x) as usize;
            for &b in &buffers {
                match target.fb.color.get_mut(b) {
                    Some(ColorBuffer::Rgba8(v)) => {
                        if let Some(p) = v.get_mut(i) {
                            *p = texel.map(float_to_unorm8);
                        }
                    }
                    Some(ColorBuffer::Rgba32F(v)) => {
                        if let Some(p) = v.get_mut(i) {
                            *p = texel;
                        }
                    }
                    None => {}
                }
            }
        }
    }
}

/// Copies depth or stencil values, nearest source pixel.
#[allow(clippy::too_many_arguments)]
fn copy_nearest<T: Copy>(
    src: &[T],
    sw: u32,
    sh: u32,
    dst: &mut [T],
    dw: u32,
    ax: Axis,
    ay: Axis,
    (x0, y0, x1, y1): (i32, i32, i32, i32),
) {
    for y in y0..y1 {
        let sy = ay.map(y).floor() as i32;
        if !(0..sh as i32).contains(&sy) {
            continue;
        }
        for x in x0..x1 {
            let sx = ax.map(x).floor() as i32;
            if !(0..sw as i32).contains(&sx) {
                continue;
            }
            let (Some(&v), Some(d)) = (
                src.get((sy * sw as i32 + sx) as usize),
                dst.get_mut((y * dw as i32 + x) as usize),
            ) else {
                continue;
            };
            *d = v;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::enums::*;
    use crate::Context;

    /// A 4x2 framebuffer object with one RGBA8 renderbuffer.
    fn fbo(ctx: &mut Context, w: i32, h: i32) -> u32 {
        let rb = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
        fb
    }

    #[test]
    fn copies_scales_and_flips() {
        let mut ctx = Context::new(8, 8);
        let src = fbo(&mut ctx, 2, 1);
        // Left pixel red, right pixel green.
        ctx.enable(GL_SCISSOR_TEST);
        ctx.scissor(0, 0, 1, 1);
        ctx.clear_color(1.0, 0.0, 0.0, 1.0);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.scissor(1, 0, 1, 1);
        ctx.clear_color(0.0, 1.0, 0.0, 1.0);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.disable(GL_SCISSOR_TEST);
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, src);
        ctx.bind_framebuffer(GL_DRAW_FRAMEBUFFER, 0);
        // Scaled to 4x1 and flipped horizontally.
        ctx.blit_framebuffer([0, 0, 2, 1], [4, 0, 0, 1], GL_COLOR_BUFFER_BIT, GL_NEAREST);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, 0);
        let px = ctx.read_pixels_f32(0, 0, 4, 1);
        assert_eq!(px[0], [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(px[1], [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(px[2], [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(px[3], [1.0, 0.0, 0.0, 1.0]);
        // Linear filtering blends the two at the middle of a 3-pixel copy.
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, src);
        ctx.blit_framebuffer([0, 0, 2, 1], [0, 1, 3, 2], GL_COLOR_BUFFER_BIT, GL_LINEAR);
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, 0);
        let mid = ctx.read_pixels_f32(1, 1, 1, 1)[0];
        assert!(
            (mid[0] - 0.5).abs() < 0.01 && (mid[1] - 0.5).abs() < 0.01,
            "{mid:?}"
        );
    }

    #[test]
    fn multisample_texture_and_renderbuffer_resolve() {
        let mut ctx = Context::new(4, 4);
        let tex = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D_MULTISAMPLE, tex);
        ctx.tex_image_multisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, [4, 4], true);
        let rb = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage_multisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, 4, 4);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_texture_2d(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_TEXTURE_2D_MULTISAMPLE,
            tex,
            0,
        );
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        assert_eq!(ctx.get_integerv(GL_SAMPLES), vec![4]);
        assert_eq!(ctx.get_integerv(GL_SAMPLE_BUFFERS), vec![1]);
        ctx.clear_color(1.0, 0.0, 0.0, 1.0);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.bind_framebuffer(GL_DRAW_FRAMEBUFFER, 0);
        // A resolve must not scale.
        ctx.blit_framebuffer([0, 0, 4, 4], [0, 0, 2, 2], GL_COLOR_BUFFER_BIT, GL_NEAREST);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.blit_framebuffer([0, 0, 4, 4], [0, 0, 4, 4], GL_COLOR_BUFFER_BIT, GL_NEAREST);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, 0);
        assert_eq!(ctx.read_pixels_f32(1, 1, 1, 1)[0], [1.0, 0.0, 0.0, 1.0]);
        // A single-sampled depth buffer beside it is incomplete.
        let rb1 = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb1);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 4, 4);
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb1);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE
        );
        ctx.tex_image_multisample(GL_TEXTURE_2D_MULTISAMPLE, 8, GL_RGBA8, [4, 4], true);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.tex_image_multisample(GL_TEXTURE_2D, 4, GL_RGBA8, [4, 4], true);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn errors() {
        let mut ctx = Context::new(4, 4);
        ctx.blit_framebuffer([0, 0, 1, 1], [0, 0, 1, 1], 0x1, GL_NEAREST);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.blit_framebuffer([0, 0, 1, 1], [0, 0, 1, 1], GL_COLOR_BUFFER_BIT, GL_RGBA);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.blit_framebuffer([0, 0, 1, 1], [0, 0, 1, 1], GL_DEPTH_BUFFER_BIT, GL_LINEAR);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // Extreme rectangles: no panic, no error.
        for r in [
            [i32::MIN, i32::MIN, i32::MAX, i32::MAX],
            [i32::MAX, 0, i32::MIN, 4],
        ] {
            ctx.blit_framebuffer(r, [0, 0, 4, 4], GL_COLOR_BUFFER_BIT, GL_LINEAR);
            ctx.blit_framebuffer([0, 0, 4, 4], r, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, fb);
        ctx.blit_framebuffer([0, 0, 1, 1], [0, 0, 1, 1], GL_COLOR_BUFFER_BIT, GL_NEAREST);
        assert_eq!(ctx.get_error(), GL_INVALID_FRAMEBUFFER_OPERATION);
    }
}
