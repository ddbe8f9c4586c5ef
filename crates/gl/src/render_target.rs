//! Render targets: the framebuffer an operation writes or reads. The
//! default framebuffer is used in place; a framebuffer object's attached
//! images are assembled into a [`raster::Framebuffer`] before the
//! operation and written back to them after it.
//!
//! Contract: write-back converts color and depth to each image's stored
//! texel form ([`crate::texture_format::texel_for`]) and bumps the
//! texture's generation; stencil lives only in renderbuffers.

use crate::enums::*;
use crate::objects::{self, Attachment};
use crate::Context;
use raster::{ColorBuffer, ColorFormat, Framebuffer};
use std::borrow::Cow;

/// A render target assembled for one operation.
pub(crate) struct Target {
    pub(crate) fb: Framebuffer,
    /// Framebuffer object name (0: default framebuffer).
    pub(crate) name: u32,
    /// Color attachment index of each raster color buffer.
    pub(crate) color_attachments: Vec<usize>,
    /// PipelineState::draw_buffers.
    pub(crate) draw_buffers: [Option<usize>; 8],
}

/// What a render target writes back into one attached image.
enum Pixels<'a> {
    /// A raster colour buffer, pixel for texel.
    Color(&'a ColorBuffer),
    /// RGBA values (depth as `[d, d, d, 1]`), pixel for texel.
    Values(Vec<[f32; 4]>),
    /// Stencil indices (renderbuffers only).
    Stencil(Vec<u8>),
}

impl Pixels<'_> {
    /// Converts the pixels into the texels `dst` of internal format `fmt`
    /// ([`crate::texture_format::texel_for`]; 8-bit colour buffers by the
    /// same results' table when the format allows).
    fn store(&self, dst: &mut [[f32; 4]], fmt: i32) {
        use crate::texture_format::{texel_for, Unorm8Texels};
        match self {
            Pixels::Color(ColorBuffer::Rgba8(v)) => match Unorm8Texels::new(fmt) {
                Some(conv) => {
                    for (d, s) in dst.iter_mut().zip(v.iter()) {
                        *d = conv.texel(*s);
                    }
                }
                None => {
                    for (d, s) in dst.iter_mut().zip(v.iter()) {
                        *d = texel_for(s.map(raster::unorm8_to_float), fmt);
                    }
                }
            },
            Pixels::Color(ColorBuffer::Rgba32F(v)) => {
                for (d, s) in dst.iter_mut().zip(v.iter()) {
                    *d = texel_for(*s, fmt);
                }
            }
            Pixels::Values(v) => {
                for (d, s) in dst.iter_mut().zip(v.iter()) {
                    *d = texel_for(*s, fmt);
                }
            }
            Pixels::Stencil(_) => {}
        }
    }
}

impl Context {
    /// The framebuffer the next draw or clear writes.
    pub(crate) fn draw_target(&mut self) -> Option<Target> {
        // Whatever the target, the queued draws run first: one into the
        // default framebuffer may sample a texture this operation writes.
        self.flush_draws();
        let name = self.objects.draw_framebuffer;
        if name == 0 {
            return Some(self.default_target());
        }
        let f = self.layer_view(self.objects.framebuffers.get(&name)?.clone());
        let mut attachments: Vec<usize> = Vec::new();
        let mut draw_buffers = [None; 8];
        for (i, &b) in f.draw_buffers.iter().enumerate().take(8) {
            if b == GL_NONE {
                continue;
            }
            let a = b.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize;
            if f.color.get(a).is_some_and(|c| c.is_some()) {
                let idx = match attachments.iter().position(|&x| x == a) {
                    Some(p) => p,
                    None => {
                        attachments.push(a);
                        attachments.len() - 1
                    }
                };
                draw_buffers[i] = Some(idx);
            }
        }
        Some(self.assemble(name, &f, attachments, draw_buffers))
    }

    /// The default framebuffer as a render target, its pixels as they are
    /// (behind the queued draws: the draw queue's own pushes only).
    pub(crate) fn default_target(&mut self) -> Target {
        let fb = std::mem::replace(
            &mut self.fb,
            Framebuffer::new(0, 0, ColorFormat::Rgba8, false, false),
        );
        let mut draw_buffers = [None; 8];
        for (i, b) in self.st.draw_buffers.iter().enumerate().take(8) {
            if *b != GL_NONE {
                draw_buffers[i] = Some(0);
            }
        }
        Target {
            fb,
            name: 0,
            color_attachments: vec![0],
            draw_buffers,
        }
    }

    /// `f` with its layered attachments (glFramebufferTexture of a 3D,
    /// array or cube map texture) made attachments of the layer draws go
    /// to ([`Context::draw_layer`]: a cube map's face, another texture's
    /// layer), which is layer 0 outside a geometry stage's layered draw.
    fn layer_view(&self, mut f: objects::FramebufferObj) -> objects::FramebufferObj {
        let layer = self.draw_layer;
        let at = |a: &mut Option<Attachment>| {
            if let Some(Attachment::Texture {
                texture,
                face,
                layer: l,
                layered: layered @ true,
                ..
            }) = a
            {
                let cube = self
                    .objects
                    .textures
                    .get(texture)
                    .is_some_and(|t| t.target == GL_TEXTURE_CUBE_MAP);
                if cube {
                    *face = layer.clamp(0, 5) as u32;
                } else {
                    *l = layer;
                }
                *layered = false;
            }
        };
        f.color.iter_mut().for_each(&at);
        at(&mut f.depth);
        at(&mut f.stencil);
        f
    }

    /// Builds a raster framebuffer from a framebuffer object's images.
    pub(crate) fn assemble(
        &self,
        name: u32,
        f: &objects::FramebufferObj,
        attachments: Vec<usize>,
        draw_buffers: [Option<usize>; 8],
    ) -> Target {
        let mut size = None;
        let all = f.attachments();
        for a in all {
            if let Some((w, h, _)) = self.attachment_info(a) {
                size.get_or_insert((w, h));
            }
        }
        let (w, h) = size.unwrap_or((0, 0));
        let formats: Vec<ColorFormat> = attachments
            .iter()
            .map(|&a| {
                let fmt = f.color[a]
                    .and_then(|x| self.attachment_info(&x))
                    .map_or(0, |i| i.2);
                if crate::texture_format::is_float_format(fmt as i32) {
                    ColorFormat::Rgba32F
                } else {
                    ColorFormat::Rgba8
                }
            })
            .collect();
        let mut fb = Framebuffer::with_color_buffers(
            w as u32,
            h as u32,
            &formats,
            f.depth.is_some(),
            f.stencil.is_some(),
        );
        // A 16-bit depth attachment is a 16-bit depth buffer (GL 3.0
        // §4.4.2.2: its required formats allocate exactly their sizes), so
        // depth tests within a draw compare 16-bit values.
        let depth16 = f
            .depth
            .and_then(|x| self.attachment_info(&x))
            .is_some_and(|i| i.2 == GL_DEPTH_COMPONENT16);
        if depth16 {
            fb.depth_format = raster::DepthFormat::Bits16;
        }
        for (i, &a) in attachments.iter().enumerate() {
            let Some(att) = f.color[a] else { continue };
            let texels = self.attachment_texels(&att);
            if let Some(buf) = fb.color.get_mut(i) {
                match buf {
                    ColorBuffer::Rgba8(v) => {
                        for (d, s) in v.iter_mut().zip(texels.iter()) {
                            *d = s.map(raster::float_to_unorm8);
                        }
                    }
                    ColorBuffer::Rgba32F(v) => {
                        for (d, s) in v.iter_mut().zip(texels.iter()) {
                            *d = *s;
                        }
                    }
                }
            }
        }
        if let (Some(att), Some(depth)) = (f.depth, fb.depth.as_mut()) {
            let texels = self.attachment_texels(&att);
            for (d, s) in depth.iter_mut().zip(texels.iter()) {
                *d = raster::depth_to_fixed(s[0]);
            }
        }
        if let (Some(Attachment::Renderbuffer(rb)), Some(st)) = (f.stencil, fb.stencil.as_mut()) {
            if let Some(r) = self.objects.renderbuffers.get(&rb) {
                for (d, s) in st.iter_mut().zip(r.stencil.iter()) {
                    *d = *s;
                }
            }
        }
        Target {
            fb,
            name,
            color_attachments: attachments,
            draw_buffers,
        }
    }

    fn attachment_texels(&self, a: &Attachment) -> &[[f32; 4]] {
        match *a {
            Attachment::Texture { .. } => self
                .attached_image(a)
                .and_then(|(img, (start, w, h))| {
                    img.texels.get(start..start + w as usize * h as usize)
                })
                .unwrap_or_default(),
            Attachment::Renderbuffer(rb) => self
                .objects
                .renderbuffers
                .get(&rb)
                .map_or(&[], |r| r.texels.as_slice()),
        }
    }

    /// Writes a render target back (default framebuffer, or the images of
    /// a framebuffer object).
    pub(crate) fn store_target(&mut self, t: Target) {
        if t.name == 0 {
            self.fb = t.fb;
            return;
        }
        let Some(f) = self.objects.framebuffers.get(&t.name).cloned() else {
            return;
        };
        let f = self.layer_view(f);
        for (i, &a) in t.color_attachments.iter().enumerate() {
            let (Some(att), Some(buf)) = (f.color.get(a).copied().flatten(), t.fb.color.get(i))
            else {
                continue;
            };
            self.write_attachment(&att, Pixels::Color(buf));
        }
        if let (Some(att), Some(depth)) = (f.depth, t.fb.depth.as_ref()) {
            let px: Vec<[f32; 4]> = depth
                .iter()
                .map(|&k| {
                    let d = raster::fixed_to_depth(k);
                    [d, d, d, 1.0]
                })
                .collect();
            self.write_attachment(&att, Pixels::Values(px));
        }
        if let (Some(att @ Attachment::Renderbuffer(_)), Some(st)) =
            (f.stencil, t.fb.stencil.as_ref())
        {
            if f.depth != Some(att) {
                self.write_attachment(&att, Pixels::Stencil(st.clone()));
            } else if let Attachment::Renderbuffer(rb) = att {
                if let Some(r) = self.objects.renderbuffers.get_mut(&rb) {
                    r.stencil = st.clone();
                }
            }
        }
    }

    fn write_attachment(&mut self, a: &Attachment, px: Pixels<'_>) {
        match *a {
            Attachment::Texture {
                texture,
                face,
                level,
                ..
            } => {
                let Some((_, (start, _, _))) = self.attached_image(a) else {
                    return;
                };
                let Some(t) = self.objects.textures.get_mut(&texture) else {
                    return;
                };
                if let Some(img) = t
                    .faces
                    .get_mut(face as usize)
                    .and_then(|f| f.get_mut(level.max(0) as usize))
                    .and_then(|i| i.as_mut())
                {
                    let fmt = img.internal_format as i32;
                    let slice = img.texels.get_mut(start..).unwrap_or_default();
                    px.store(slice, fmt);
                    t.generation += 1;
                }
            }
            Attachment::Renderbuffer(rb) => {
                if let Some(r) = self.objects.renderbuffers.get_mut(&rb) {
                    match px {
                        Pixels::Stencil(s) => r.stencil = s,
                        px => px.store(&mut r.texels, r.internal_format as i32),
                    }
                }
            }
        }
    }

    /// The read framebuffer as a raster framebuffer: the default one in
    /// place, or a framebuffer object's read buffer (as its only color
    /// buffer), depth and stencil images assembled.
    pub(crate) fn read_image(&mut self) -> Option<Cow<'_, Framebuffer>> {
        self.flush_draws();
        let name = self.objects.read_framebuffer;
        if name == 0 {
            return Some(Cow::Borrowed(&self.fb));
        }
        let f = self.objects.framebuffers.get(&name)?.clone();
        let a = f.read_buffer.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize;
        let atts = if f.color.get(a).is_some_and(|c| c.is_some()) {
            vec![a]
        } else {
            Vec::new()
        };
        Some(Cow::Owned(self.assemble(name, &f, atts, [None; 8]).fb))
    }

    /// The read framebuffer's selected color buffer, depth and stencil
    /// values over a rectangle (bottom row first).
    pub(crate) fn read_block(
        &mut self,
        x: i32,
        y: i32,
        w: u32,
        h: u32,
        what: u32,
    ) -> Option<Vec<[f32; 4]>> {
        let fb = self.read_image()?;
        Some(match what {
            GL_DEPTH_COMPONENT => fb
                .read_depth(x, y, w, h)
                .into_iter()
                .map(|d| [d, 0.0, 0.0, 1.0])
                .collect(),
            GL_STENCIL_INDEX => fb
                .read_stencil(x, y, w, h)
                .into_iter()
                .map(|s| [s as f32, 0.0, 0.0, 1.0])
                .collect(),
            _ => fb.read_pixels(0, x, y, w, h),
        })
    }
}
