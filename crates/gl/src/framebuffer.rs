//! Renderbuffer and framebuffer objects (EXT/ARB_framebuffer_object):
//! their names and storage, attachments, completeness
//! (glCheckFramebufferStatus) and the draw/read buffer selection
//! (glDrawBuffers, glDrawBuffer, glReadBuffer).
//!
//! Multisample renderbuffers and textures (glRenderbufferStorageMultisample,
//! glTexImage2DMultisample, up to
//! [`MAX_SAMPLES`]) keep one value per pixel: every sample of a pixel sits
//! at its centre, a placement GL leaves to the implementation (GL 3.3
//! §3.3.1), so coverage and shading equal single-sample rendering and a
//! resolve ([`crate::blit`]) is a copy. Edges are therefore not
//! antialiased.
//!
//! Contract: completeness follows EXT_framebuffer_object §4.4.4 (color
//! attachments must be RGB/RGBA/RED/RG; ALPHA, LUMINANCE and INTENSITY are
//! GL_FRAMEBUFFER_UNSUPPORTED); a draw, clear or read on an incomplete
//! framebuffer is GL_INVALID_FRAMEBUFFER_OPERATION. How attached images
//! become a render target is [`crate::render_target`]'s job. The EXT
//! names of these calls (glBindFramebufferEXT...) behave as the core ones:
//! the C layer maps both names to the one method here.

use crate::enums::*;
use crate::objects;
use crate::objects::{
    delete_names, image_target, Attachment, FramebufferObj, RenderbufferObj, MAX_LEVELS,
};
use crate::texture_format::{base_format, component_info, is_integer_format};
use crate::{Context, MAX_TEXTURE_SIZE};

/// GL_MAX_3D_TEXTURE_SIZE and GL_MAX_ARRAY_TEXTURE_LAYERS: the layers a
/// layer attachment may name.
const MAX_LAYERS: i32 = 2048;

/// Whether `level` is a level a texture of `target` can have (GL 3.3
/// §4.4.2: up to log2 of the target's largest size; multisample
/// textures have level 0 only).
fn level_ok(target: u32, level: i32) -> bool {
    match target {
        GL_TEXTURE_RECTANGLE | GL_TEXTURE_2D_MULTISAMPLE | GL_TEXTURE_2D_MULTISAMPLE_ARRAY => {
            level == 0
        }
        GL_TEXTURE_3D => (0..=MAX_LAYERS.ilog2() as i32).contains(&level),
        _ => (0..MAX_LEVELS).contains(&level),
    }
}

/// A renderbuffer's component sizes in bits: red, green, blue, alpha,
/// depth, stencil (GL_RENDERBUFFER_*_SIZE).
fn renderbuffer_bits(internal: u32) -> [i32; 6] {
    let float = matches!(internal, GL_RGBA32F | GL_RGB32F | GL_RG32F | GL_R32F);
    let c = if float { 32 } else { 8 };
    match base_format(internal as i32) {
        Some(GL_RGBA) => [c, c, c, c, 0, 0],
        Some(GL_RGB) => [c, c, c, 0, 0, 0],
        Some(GL_RG) => [c, c, 0, 0, 0, 0],
        Some(GL_RED) => [c, 0, 0, 0, 0, 0],
        // A DEPTH_COMPONENT16 renderbuffer stores 16 bits (GL 3.0
        // §4.4.2.2); the other depth formats are kept at 24.
        Some(GL_DEPTH_COMPONENT) if internal == GL_DEPTH_COMPONENT16 => [0, 0, 0, 0, 16, 0],
        Some(GL_DEPTH_COMPONENT) => [0, 0, 0, 0, 24, 0],
        Some(GL_DEPTH_STENCIL) => [0, 0, 0, 0, 24, 8],
        _ if internal != 0 => [0, 0, 0, 0, 0, 8],
        _ => [0; 6],
    }
}

/// GL_MAX_SAMPLES: the sample count multisample renderbuffers get (GL 3.0
/// requires at least 4).
pub const MAX_SAMPLES: i32 = 4;

impl Context {
    // ---- renderbuffers ----

    /// glGenRenderbuffers(EXT).
    pub fn gen_renderbuffers(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.renderbuffers, &mut o.next_renderbuffer),
            RenderbufferObj::default,
        )
    }

    /// glBindRenderbuffer(EXT).
    pub fn bind_renderbuffer(&mut self, target: u32, rb: u32) {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if rb != 0 {
            self.objects.renderbuffers.entry(rb).or_default();
        }
        self.objects.bound_renderbuffer = rb;
    }

    /// glDeleteRenderbuffers(EXT).
    pub fn delete_renderbuffers(&mut self, names: &[u32]) {
        let o = &mut self.objects;
        delete_names(
            &mut o.renderbuffers,
            names,
            &mut [&mut o.bound_renderbuffer],
        );
    }

    /// glIsRenderbuffer(EXT): a name bound at least once and not deleted.
    pub fn is_renderbuffer(&self, rb: u32) -> bool {
        rb != 0 && self.objects.renderbuffers.contains_key(&rb)
    }

    /// glRenderbufferStorageMultisample (GL 3.0): `samples` up to
    /// [`MAX_SAMPLES`] (else GL_INVALID_VALUE); see the module docs for
    /// how samples are kept.
    pub fn renderbuffer_storage_multisample(
        &mut self,
        target: u32,
        samples: i32,
        internal: u32,
        w: i32,
        h: i32,
    ) {
        if target == GL_RENDERBUFFER && !(0..=MAX_SAMPLES).contains(&samples) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if self.storage(target, internal, w, h) {
            let rb = self.objects.bound_renderbuffer;
            if let Some(r) = self.objects.renderbuffers.get_mut(&rb) {
                r.samples = if samples == 0 { 0 } else { MAX_SAMPLES };
            }
        }
    }

    /// glGetRenderbufferParameteriv(EXT) of the bound renderbuffer.
    pub fn get_renderbuffer_parameteriv(&mut self, target: u32, pname: u32) -> Option<i32> {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let rb = self.objects.bound_renderbuffer;
        let Some(r) = self.objects.renderbuffers.get(&rb).filter(|_| rb != 0) else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        let sizes = renderbuffer_bits(r.internal_format);
        let v = match pname {
            GL_RENDERBUFFER_WIDTH => r.width,
            GL_RENDERBUFFER_HEIGHT => r.height,
            GL_RENDERBUFFER_INTERNAL_FORMAT => {
                if r.internal_format == 0 {
                    GL_RGBA as i32
                } else {
                    r.internal_format as i32
                }
            }
            GL_RENDERBUFFER_SAMPLES => r.samples,
            GL_RENDERBUFFER_RED_SIZE => sizes[0],
            GL_RENDERBUFFER_GREEN_SIZE => sizes[1],
            GL_RENDERBUFFER_BLUE_SIZE => sizes[2],
            GL_RENDERBUFFER_ALPHA_SIZE => sizes[3],
            GL_RENDERBUFFER_DEPTH_SIZE => sizes[4],
            GL_RENDERBUFFER_STENCIL_SIZE => sizes[5],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }

    /// The sample count of the draw framebuffer (its multisample
    /// renderbuffers'; 0 for the default framebuffer and single-sampled
    /// attachments).
    pub(crate) fn draw_framebuffer_samples(&self) -> i32 {
        self.framebuffer_samples(self.objects.draw_framebuffer)
    }

    /// The sample count of one attached image (0: single-sampled).
    fn attachment_samples(&self, a: &Attachment) -> i32 {
        match a {
            Attachment::Renderbuffer(rb) => {
                self.objects.renderbuffers.get(rb).map_or(0, |r| r.samples)
            }
            Attachment::Texture { texture, .. } => {
                self.objects.textures.get(texture).map_or(0, |t| t.samples)
            }
        }
    }

    /// The sample count of framebuffer object `name` (0: single-sampled).
    pub(crate) fn framebuffer_samples(&self, name: u32) -> i32 {
        let Some(f) = self.objects.framebuffers.get(&name) else {
            return 0;
        };
        f.attachments()
            .map(|a| self.attachment_samples(a))
            .max()
            .unwrap_or(0)
    }

    /// glTexImage2DMultisample / glTexImage3DMultisample (GL 3.2):
    /// `size` is `[w, h]` or `[w, h, layers]`. The image keeps one value
    /// per texel (see the module docs); `fixed_locations` holds either
    /// way, every sample sitting at the texel centre.
    pub fn tex_image_multisample<const D: usize>(
        &mut self,
        target: u32,
        samples: i32,
        internal: u32,
        size: [i32; D],
        _fixed_locations: bool,
    ) {
        let want = if D == 2 {
            GL_TEXTURE_2D_MULTISAMPLE
        } else {
            GL_TEXTURE_2D_MULTISAMPLE_ARRAY
        };
        if target != want {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let renderable = matches!(
            base_format(internal as i32),
            Some(GL_RGBA | GL_RGB | GL_RG | GL_RED | GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL)
        );
        if !renderable {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if size.iter().any(|&s| !(0..=MAX_TEXTURE_SIZE).contains(&s)) || samples < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if samples > MAX_SAMPLES {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let (w, h) = (size[0], size[1]);
        let d = if D == 3 { size[2] } else { 1 };
        let n = (w as usize)
            .saturating_mul(h as usize)
            .saturating_mul(d as usize);
        if n > crate::MAX_TEXELS {
            self.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let img = crate::objects::Image {
            width: w,
            height: h,
            depth: d,
            internal_format: internal,
            texels: vec![[0.0; 4]; n],
        };
        crate::objects::set_image(tex, 0, 0, img);
        tex.samples = if samples == 0 { 0 } else { MAX_SAMPLES };
        tex.generation = tex.generation.wrapping_add(1);
    }

    /// glRenderbufferStorage(EXT).
    pub fn renderbuffer_storage(&mut self, target: u32, internal: u32, w: i32, h: i32) {
        self.storage(target, internal, w, h);
    }

    /// The body of glRenderbufferStorage*: false when an error was
    /// recorded.
    fn storage(&mut self, target: u32, internal: u32, w: i32, h: i32) -> bool {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        let ok_format = base_format(internal as i32).is_some()
            || matches!(
                internal,
                GL_STENCIL_INDEX8
                    | GL_STENCIL_INDEX
                    | GL_STENCIL_INDEX1
                    | GL_STENCIL_INDEX4
                    | GL_STENCIL_INDEX16
            );
        if !ok_format {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if !(0..=MAX_TEXTURE_SIZE).contains(&w) || !(0..=MAX_TEXTURE_SIZE).contains(&h) {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        let rb = self.objects.bound_renderbuffer;
        let Some(r) = self.objects.renderbuffers.get_mut(&rb).filter(|_| rb != 0) else {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        };
        let n = w as usize * h as usize;
        *r = RenderbufferObj {
            internal_format: internal,
            width: w,
            height: h,
            texels: vec![[0.0, 0.0, 0.0, 0.0]; n],
            stencil: vec![0; n],
            samples: 0,
        };
        true
    }

    // ---- framebuffers ----

    /// glGenFramebuffers(EXT).
    pub fn gen_framebuffers(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.framebuffers, &mut o.next_framebuffer),
            FramebufferObj::new,
        )
    }

    /// glBindFramebuffer(EXT).
    pub fn bind_framebuffer(&mut self, target: u32, fb: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(
            target,
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER | GL_READ_FRAMEBUFFER
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if fb != 0 {
            self.objects.framebuffers.entry(fb).or_default();
        }
        if target != GL_READ_FRAMEBUFFER {
            self.objects.draw_framebuffer = fb;
        }
        if target != GL_DRAW_FRAMEBUFFER {
            self.objects.read_framebuffer = fb;
        }
    }

    /// glDeleteFramebuffers(EXT): bindings revert to the default framebuffer.
    pub fn delete_framebuffers(&mut self, names: &[u32]) {
        let o = &mut self.objects;
        let bindings = &mut [&mut o.draw_framebuffer, &mut o.read_framebuffer];
        delete_names(&mut o.framebuffers, names, bindings);
    }

    /// glIsFramebuffer.
    pub fn is_framebuffer(&self, name: u32) -> bool {
        name != 0 && self.objects.framebuffers.contains_key(&name)
    }

    /// The framebuffer bound to `target` (0 for the default one); None
    /// with GL_INVALID_ENUM for a target that is not a framebuffer's.
    fn bound_framebuffer(&mut self, target: u32) -> Option<u32> {
        match target {
            GL_READ_FRAMEBUFFER => Some(self.objects.read_framebuffer),
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => Some(self.objects.draw_framebuffer),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// The framebuffer a glFramebufferTexture* call attaches `texture`
    /// to; None when the call is done (an error recorded, or texture 0
    /// detached whatever was attached).
    fn texture_attachment_slot(
        &mut self,
        target: u32,
        attachment: u32,
        texture: u32,
    ) -> Option<u32> {
        let fb = self.attachment_slot(target, attachment)?;
        if texture == 0 {
            self.set_attachment(fb, attachment, None);
            return None;
        }
        Some(fb)
    }

    fn attachment_slot(&mut self, target: u32, attachment: u32) -> Option<u32> {
        let fb = self.bound_framebuffer(target)?;
        if fb == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let ok = (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + crate::MAX_DRAW_BUFFERS as u32)
            .contains(&attachment)
            || matches!(
                attachment,
                GL_DEPTH_ATTACHMENT | GL_STENCIL_ATTACHMENT | GL_DEPTH_STENCIL_ATTACHMENT
            );
        if !ok {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        Some(fb)
    }

    fn set_attachment(&mut self, fb: u32, attachment: u32, a: Option<Attachment>) {
        let Some(f) = self.objects.framebuffers.get_mut(&fb) else {
            return;
        };
        match attachment {
            GL_DEPTH_ATTACHMENT => f.depth = a,
            GL_STENCIL_ATTACHMENT => f.stencil = a,
            GL_DEPTH_STENCIL_ATTACHMENT => {
                f.depth = a;
                f.stencil = a;
            }
            _ => {
                if let Some(c) = f
                    .color
                    .get_mut(attachment.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize)
                {
                    *c = a;
                }
            }
        }
    }

    /// glFramebufferTexture2D(EXT).
    pub fn framebuffer_texture_2d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        let Some(fb) = self.texture_attachment_slot(target, attachment, texture) else {
            return;
        };
        let image = image_target(textarget, 2).or_else(|| image_target(textarget, 1));
        // A 1D array's layers are attached by layer, not as a 2D image.
        let Some((bind, face)) = image.filter(|&(t, _)| t != GL_TEXTURE_1D_ARRAY) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let tex_target = self.objects.textures.get(&texture).map(|t| t.target);
        match tex_target {
            None => {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            Some(t) if t != bind => {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            _ => {}
        }
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.set_attachment(
            fb,
            attachment,
            Some(Attachment::texture_image(texture, level, face as u32, 0)),
        );
    }

    /// glFramebufferTexture3D: layer `layer` of level `level` of a 3D
    /// texture (GL 3.3 §4.4.2; `textarget` must be GL_TEXTURE_3D).
    pub fn framebuffer_texture_3d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
        layer: i32,
    ) {
        if texture != 0 && textarget != GL_TEXTURE_3D {
            // A texture target, but not this call's; or no target at all.
            let is_target =
                objects::target_index(textarget).is_some() || image_target(textarget, 2).is_some();
            self.set_error(if is_target {
                GL_INVALID_OPERATION
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let tex_target = self.objects.textures.get(&texture).map(|t| t.target);
        if texture != 0 && tex_target != Some(GL_TEXTURE_3D) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.framebuffer_texture_layer(target, attachment, texture, level, layer);
    }

    /// glFramebufferTextureLayer: layer `layer` of level `level` of a 3D,
    /// 1D or 2D array (or 2D multisample array) texture (GL 3.3 §4.4.2).
    pub fn framebuffer_texture_layer(
        &mut self,
        target: u32,
        attachment: u32,
        texture: u32,
        level: i32,
        layer: i32,
    ) {
        let Some(fb) = self.texture_attachment_slot(target, attachment, texture) else {
            return;
        };
        let tex_target = self.objects.textures.get(&texture).map(|t| t.target);
        let Some(
            tt @ (GL_TEXTURE_3D
            | GL_TEXTURE_1D_ARRAY
            | GL_TEXTURE_2D_ARRAY
            | GL_TEXTURE_2D_MULTISAMPLE_ARRAY
            | GL_TEXTURE_CUBE_MAP_ARRAY_ARB),
        ) = tex_target
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        if !level_ok(tt, level) || !(0..MAX_LAYERS).contains(&layer) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.set_attachment(
            fb,
            attachment,
            Some(Attachment::texture_image(texture, level, 0, layer)),
        );
    }

    /// glFramebufferTexture (and glFramebufferTextureEXT/ARB): level
    /// `level` of a texture; of a 3D, cube map or array texture the whole
    /// level, a layered attachment (GL 3.3 §4.4.2, §4.4.7), whose layer a
    /// geometry stage's gl_Layer chooses (`crate::layered`; layer 0
    /// without one).
    pub fn framebuffer_texture(&mut self, target: u32, attachment: u32, texture: u32, level: i32) {
        let Some(fb) = self.texture_attachment_slot(target, attachment, texture) else {
            return;
        };
        let Some(tt) = self.objects.textures.get(&texture).map(|t| t.target) else {
            self.set_error(GL_INVALID_VALUE);
            return;
        };
        // A name glGenTextures returned but never bound has no target yet,
        // hence no images to attach.
        if tt == 0 || tt == GL_TEXTURE_BUFFER {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !level_ok(tt, level) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let layered = matches!(
            tt,
            GL_TEXTURE_3D
                | GL_TEXTURE_CUBE_MAP
                | GL_TEXTURE_1D_ARRAY
                | GL_TEXTURE_2D_ARRAY
                | GL_TEXTURE_2D_MULTISAMPLE_ARRAY
                | GL_TEXTURE_CUBE_MAP_ARRAY_ARB
        );
        self.set_attachment(
            fb,
            attachment,
            Some(Attachment::Texture {
                texture,
                face: 0,
                level,
                layer: 0,
                layered,
            }),
        );
    }

    /// glFramebufferTextureFaceEXT/ARB (GL_ARB_geometry_shader4): face
    /// `face` of level `level` of a cube map texture, as
    /// glFramebufferTexture2D attaches it; GL_INVALID_OPERATION for
    /// another kind of texture, GL_INVALID_ENUM for a face that is none.
    pub fn framebuffer_texture_face(
        &mut self,
        target: u32,
        attachment: u32,
        texture: u32,
        level: i32,
        face: u32,
    ) {
        if texture != 0 {
            if !(GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z).contains(&face) {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
            match self.objects.textures.get(&texture).map(|t| t.target) {
                None => {
                    self.set_error(GL_INVALID_VALUE);
                    return;
                }
                Some(GL_TEXTURE_CUBE_MAP) => {}
                Some(_) => {
                    self.set_error(GL_INVALID_OPERATION);
                    return;
                }
            }
        }
        self.framebuffer_texture_2d(target, attachment, face, texture, level);
    }

    /// glFramebufferTexture1D(EXT).
    pub fn framebuffer_texture_1d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        self.framebuffer_texture_2d(target, attachment, textarget, texture, level);
    }

    /// glFramebufferRenderbuffer(EXT).
    pub fn framebuffer_renderbuffer(
        &mut self,
        target: u32,
        attachment: u32,
        rbtarget: u32,
        rb: u32,
    ) {
        let Some(fb) = self.attachment_slot(target, attachment) else {
            return;
        };
        if rbtarget != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if rb != 0 && !self.objects.renderbuffers.contains_key(&rb) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let a = (rb != 0).then_some(Attachment::Renderbuffer(rb));
        self.set_attachment(fb, attachment, a);
    }

    /// glGetFramebufferAttachmentParameteriv(EXT) (EXT_framebuffer_object
    /// §6.1.3, with GL 3.0 §6.1.17's queries of the default framebuffer:
    /// GL_FRONT_LEFT, GL_BACK_LEFT, GL_DEPTH, GL_STENCIL). On an object:
    /// the object type and name, texture level, cube face and layer, the
    /// color encoding (linear) and component type (unsigned normalized);
    /// and the bit sizes of the attached image (GL 3.0 §6.1.17, which
    /// ARB_framebuffer_object adds; 0 for a component its format lacks).
    /// Other pnames are GL_INVALID_ENUM. None after recording an error.
    pub fn get_framebuffer_attachment_parameter(
        &mut self,
        target: u32,
        attachment: u32,
        pname: u32,
    ) -> Option<i32> {
        if self.bound_framebuffer(target)? == 0 {
            return self.default_attachment_parameter(attachment, pname);
        }
        let fb = self.attachment_slot(target, attachment)?;
        let f = self.objects.framebuffers.get(&fb)?;
        let a = match attachment {
            GL_DEPTH_ATTACHMENT => f.depth,
            GL_STENCIL_ATTACHMENT => f.stencil,
            GL_DEPTH_STENCIL_ATTACHMENT if f.depth != f.stencil => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            GL_DEPTH_STENCIL_ATTACHMENT => f.depth,
            _ => f
                .color
                .get(attachment.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize)
                .copied()
                .flatten(),
        };
        let v = match (pname, a) {
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, None) => GL_NONE as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Texture { .. })) => {
                GL_TEXTURE as i32
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Renderbuffer(_))) => {
                GL_RENDERBUFFER as i32
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, None) => 0,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Some(Attachment::Texture { texture, .. })) => {
                texture as i32
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Some(Attachment::Renderbuffer(rb))) => {
                rb as i32
            }
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Some(Attachment::Texture { level, .. })) => {
                level
            }
            (
                GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
                Some(Attachment::Texture { texture, face, .. }),
            ) => {
                let cube = self
                    .objects
                    .textures
                    .get(&texture)
                    .is_some_and(|t| t.target == GL_TEXTURE_CUBE_MAP);
                if cube {
                    (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) as i32
                } else {
                    0
                }
            }
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Some(Attachment::Texture { layer, .. })) => {
                layer
            }
            (GL_FRAMEBUFFER_ATTACHMENT_LAYERED, Some(Attachment::Texture { layered, .. })) => {
                layered as i32
            }
            (GL_FRAMEBUFFER_ATTACHMENT_LAYERED, Some(Attachment::Renderbuffer(_))) => 0,
            (
                GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                Some(a),
            ) => self.attachment_bits(&a, pname),
            (GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, Some(_)) => GL_LINEAR as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, Some(_)) => GL_UNSIGNED_NORMALIZED as i32,
            // GL 3.0 §6.1.17: with nothing attached, the queries other than
            // the object type and name are GL_INVALID_OPERATION.
            (
                GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING
                | GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE
                | GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
                | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
                | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER
                | GL_FRAMEBUFFER_ATTACHMENT_LAYERED,
                None,
            ) => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }

    /// The default framebuffer's part of
    /// [`Context::get_framebuffer_attachment_parameter`].
    fn default_attachment_parameter(&mut self, attachment: u32, pname: u32) -> Option<i32> {
        let present = match attachment {
            GL_FRONT_LEFT | GL_BACK_LEFT => true,
            GL_DEPTH => self.fb.depth.is_some(),
            GL_STENCIL => self.fb.stencil.is_some(),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let size = |bits: i32, which: bool| if which { bits } else { 0 };
        let color = matches!(attachment, GL_FRONT_LEFT | GL_BACK_LEFT);
        let v = match pname {
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE if present => GL_FRAMEBUFFER_DEFAULT as i32,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE => GL_NONE as i32,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME => 0,
            GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE
            | GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE
            | GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE
            | GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => size(8, color),
            GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => size(24, attachment == GL_DEPTH && present),
            GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => size(8, attachment == GL_STENCIL && present),
            GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING if present => GL_LINEAR as i32,
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE if present => GL_UNSIGNED_NORMALIZED as i32,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }

    /// glGet of GL_RED_BITS … GL_ALPHA_BITS, GL_DEPTH_BITS and
    /// GL_STENCIL_BITS: the draw framebuffer's (GL 3.0 §6.1.3, "framebuffer
    /// dependent values"). The default framebuffer has 8-bit colour and the
    /// 24-bit depth and 8-bit stencil buffers it was made with, if any; a
    /// framebuffer object, the component sizes of its first draw buffer's
    /// image and of its depth and stencil images (0 where nothing is
    /// attached).
    pub(crate) fn framebuffer_bits(&self, pname: u32) -> i32 {
        let query = match pname {
            GL_RED_BITS => GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
            GL_GREEN_BITS => GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
            GL_BLUE_BITS => GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE,
            GL_ALPHA_BITS => GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE,
            GL_DEPTH_BITS => GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
            _ => GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
        };
        let name = self.objects.draw_framebuffer;
        let Some(f) = (name != 0)
            .then(|| self.objects.framebuffers.get(&name))
            .flatten()
        else {
            return match query {
                GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => 24 * self.fb.depth.is_some() as i32,
                GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => 8 * self.fb.stencil.is_some() as i32,
                _ => 8,
            };
        };
        let image = match query {
            GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => f.depth,
            GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => f.stencil,
            _ => f
                .draw_buffers
                .first()
                .and_then(|b| f.color.get(b.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize))
                .copied()
                .flatten(),
        };
        image.map_or(0, |a| self.attachment_bits(&a, query))
    }

    /// The bits of one component (`pname`, a GL_FRAMEBUFFER_ATTACHMENT_*_SIZE)
    /// of an attachment's image: a renderbuffer's as
    /// glGetRenderbufferParameteriv reports them, a texture image's as
    /// glGetTexLevelParameteriv does (depth 24 bits unless a 32-bit float
    /// format, stencil 8).
    fn attachment_bits(&self, a: &Attachment, pname: u32) -> i32 {
        let which = match pname {
            GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE => 0,
            GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => 1,
            GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => 2,
            GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => 3,
            GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => 4,
            _ => 5,
        };
        let Some((_, _, internal)) = self.attachment_info(a) else {
            return 0;
        };
        if let Attachment::Renderbuffer(_) = a {
            return renderbuffer_bits(internal)[which];
        }
        let base = base_format(internal as i32).unwrap_or(GL_RGBA);
        let has = match which {
            0 => matches!(base, GL_RGB | GL_RGBA | GL_RED | GL_RG),
            1 => matches!(base, GL_RGB | GL_RGBA | GL_RG),
            2 => matches!(base, GL_RGB | GL_RGBA),
            3 => matches!(base, GL_RGBA | GL_ALPHA | GL_LUMINANCE_ALPHA),
            4 => matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL),
            _ => base == GL_DEPTH_STENCIL,
        };
        match (has, which) {
            (false, _) => 0,
            (true, 4) if matches!(internal, GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8) => 32,
            (true, 4) => 24,
            (true, 5) => 8,
            (true, 2) if internal == GL_R11F_G11F_B10F => 10,
            (true, _) => component_info(internal as i32).0 as i32,
        }
    }

    /// Size and internal format of an attachment's image.
    pub(crate) fn attachment_info(&self, a: &Attachment) -> Option<(i32, i32, u32)> {
        match *a {
            Attachment::Texture { .. } => {
                let (img, (_, w, h)) = self.attached_image(a)?;
                Some((w, h, img.internal_format))
            }
            Attachment::Renderbuffer(rb) => {
                let r = self.objects.renderbuffers.get(&rb)?;
                Some((r.width, r.height, r.internal_format))
            }
        }
    }

    /// A texture attachment's level image and where its attached 2D image
    /// lies in it ([`objects::layer_span`]; a layered attachment draws
    /// into its layer 0). None for a renderbuffer, a missing image or a
    /// layer the level does not have.
    pub(crate) fn attached_image(
        &self,
        a: &Attachment,
    ) -> Option<(&objects::Image, (usize, i32, i32))> {
        let Attachment::Texture {
            texture,
            face,
            level,
            layer,
            layered,
        } = *a
        else {
            return None;
        };
        let t = self.objects.textures.get(&texture)?;
        let img = t.image(face as usize, level.max(0) as usize)?;
        let layer = if layered { 0 } else { layer };
        Some((img, objects::layer_span(t.target, img, layer)?))
    }

    /// Completeness of a framebuffer object (GL 3.3 §4.4.4).
    pub(crate) fn framebuffer_status(&self, fb: u32) -> u32 {
        if fb == 0 {
            return GL_FRAMEBUFFER_COMPLETE;
        }
        let Some(f) = self.objects.framebuffers.get(&fb) else {
            return GL_FRAMEBUFFER_UNSUPPORTED;
        };
        let mut sizes = Vec::new();
        for c in f.color.iter().flatten() {
            let Some((w, h, fmt)) = self.attachment_info(c) else {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            };
            if w == 0 || h == 0 {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            // Integer colour buffers are not drawn into (a fragment's
            // colour is not converted to integers).
            if is_integer_format(fmt as i32) {
                return GL_FRAMEBUFFER_UNSUPPORTED;
            }
            match base_format(fmt as i32) {
                Some(GL_RGB | GL_RGBA | GL_RED | GL_RG) => {}
                Some(GL_ALPHA | GL_LUMINANCE | GL_LUMINANCE_ALPHA | GL_INTENSITY) => {
                    return GL_FRAMEBUFFER_UNSUPPORTED
                }
                _ => return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
            }
            sizes.push((w, h));
        }
        for (a, want_depth) in [(&f.depth, true), (&f.stencil, false)] {
            let Some(a) = a else { continue };
            let Some((w, h, fmt)) = self.attachment_info(a) else {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            };
            if w == 0 || h == 0 {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            let base = base_format(fmt as i32);
            let ok = if want_depth {
                matches!(base, Some(GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL))
            } else {
                base == Some(GL_DEPTH_STENCIL)
                    || matches!(
                        fmt,
                        GL_STENCIL_INDEX8
                            | GL_STENCIL_INDEX
                            | GL_STENCIL_INDEX1
                            | GL_STENCIL_INDEX4
                            | GL_STENCIL_INDEX16
                    )
            };
            if !ok {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            sizes.push((w, h));
        }
        if sizes.is_empty() {
            return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
        }
        // Either every attachment is layered or none is (GL 3.3 §4.4.4).
        let layered: Vec<bool> = f
            .attachments()
            .map(|a| matches!(a, Attachment::Texture { layered: true, .. }))
            .collect();
        if layered.iter().any(|&l| l != layered[0]) {
            return GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS;
        }
        if sizes.iter().any(|s| *s != sizes[0]) {
            return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT;
        }
        // Every attachment has the same sample count (textures: 0).
        let samples: Vec<i32> = f
            .attachments()
            .map(|a| self.attachment_samples(a))
            .collect();
        if samples.iter().any(|&n| n != samples[0]) {
            return GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
        }
        for &db in &f.draw_buffers {
            if db != GL_NONE {
                let i = db.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize;
                if f.color.get(i).is_none_or(|c| c.is_none()) {
                    return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
                }
            }
        }
        GL_FRAMEBUFFER_COMPLETE
    }

    /// glCheckFramebufferStatus(EXT).
    pub fn check_framebuffer_status(&mut self, target: u32) -> u32 {
        let fb = match target {
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => self.objects.draw_framebuffer,
            GL_READ_FRAMEBUFFER => self.objects.read_framebuffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return 0;
            }
        };
        self.framebuffer_status(fb)
    }

    /// glDrawBuffers.
    pub fn draw_buffers(&mut self, bufs: &[u32]) {
        if self.reject_in_begin() {
            return;
        }
        if bufs.len() > crate::MAX_DRAW_BUFFERS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let fb = self.objects.draw_framebuffer;
        for (i, &b) in bufs.iter().enumerate() {
            let ok = if fb == 0 {
                window_draw_buffer(b)
            } else {
                b == GL_NONE
                    || (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + crate::MAX_DRAW_BUFFERS as u32)
                        .contains(&b)
            };
            if !ok {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
            if bufs[..i].contains(&b) && b != GL_NONE {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
        }
        if fb == 0 {
            self.st.draw_buffers = bufs.to_vec();
        } else if let Some(f) = self.objects.framebuffers.get_mut(&fb) {
            f.draw_buffers = bufs.to_vec();
        }
    }

    /// glDrawBuffer.
    pub fn draw_buffer(&mut self, buf: u32) {
        let fb = self.objects.draw_framebuffer;
        if fb == 0 && !window_draw_buffer(buf) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.draw_buffers(&[buf]);
    }

    /// glReadBuffer.
    pub fn read_buffer(&mut self, buf: u32) {
        if self.reject_in_begin() {
            return;
        }
        let fb = self.objects.read_framebuffer;
        if fb == 0 {
            self.st.read_buffer = buf;
        } else if let Some(f) = self.objects.framebuffers.get_mut(&fb) {
            f.read_buffer = buf;
        }
    }
}

/// Whether `b` names a draw buffer of the window (framebuffer 0), or none.
fn window_draw_buffer(b: u32) -> bool {
    matches!(
        b,
        GL_NONE | GL_FRONT_LEFT | GL_BACK_LEFT | GL_FRONT | GL_BACK | GL_LEFT | GL_FRONT_AND_BACK
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attachment_sizes_follow_the_attached_formats() {
        let mut ctx = Context::new(4, 4);
        let f = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, f);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGB8 as i32,
            [2, 2],
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&[0u8; 12]),
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
        let r = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, r);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 2, 2);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r);
        let q = |ctx: &mut Context, a, pname| {
            ctx.get_framebuffer_attachment_parameter(GL_FRAMEBUFFER, a, pname)
        };
        let color = GL_COLOR_ATTACHMENT0;
        assert_eq!(
            q(&mut ctx, color, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE),
            Some(8)
        );
        assert_eq!(
            q(&mut ctx, color, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE),
            Some(0)
        );
        assert_eq!(
            q(&mut ctx, color, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE),
            Some(0)
        );
        let depth = GL_DEPTH_ATTACHMENT;
        assert_eq!(
            q(&mut ctx, depth, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE),
            Some(24)
        );
        assert_eq!(
            q(&mut ctx, depth, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE),
            Some(8)
        );
        assert_eq!(
            q(&mut ctx, depth, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE),
            Some(0)
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        // Nothing attached: the object type and name only.
        let none = GL_COLOR_ATTACHMENT0 + 1;
        assert_eq!(
            q(&mut ctx, none, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME),
            Some(0)
        );
        assert_eq!(
            q(&mut ctx, none, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE),
            None
        );
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(q(&mut ctx, none, GL_TEXTURE_2D), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn gen_and_delete_unbind() {
        let mut ctx = Context::new(4, 4);
        assert!(ctx.gen_framebuffers(-1).is_empty());
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        let [f, g] = ctx.gen_framebuffers(2)[..] else {
            panic!("two names")
        };
        let r = ctx.gen_renderbuffers(1)[0];
        let b = ctx.gen_buffers(1)[0];
        assert!(f != 0 && g == f + 1);
        ctx.bind_framebuffer(GL_DRAW_FRAMEBUFFER, f);
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, g);
        ctx.bind_renderbuffer(GL_RENDERBUFFER, r);
        ctx.bind_buffer(GL_ARRAY_BUFFER, b);
        ctx.bind_buffer(GL_PIXEL_PACK_BUFFER, b);
        ctx.delete_framebuffers(&[0, g]);
        assert_eq!(ctx.objects.draw_framebuffer, f);
        assert_eq!(ctx.objects.read_framebuffer, 0);
        assert!(!ctx.is_framebuffer(g));
        ctx.delete_renderbuffers(&[r]);
        assert_eq!(ctx.objects.bound_renderbuffer, 0);
        ctx.delete_buffers(&[b]);
        assert_eq!(ctx.bound_buffer(GL_ARRAY_BUFFER), 0);
        assert_eq!(ctx.bound_buffer(GL_PIXEL_PACK_BUFFER), 0);
        assert!(!ctx.is_buffer(b));
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn framebuffer_completeness() {
        let mut ctx = Context::new(4, 4);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT
        );
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            [8, 8],
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        let rb = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 4, 4);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT
        );
        ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
        ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
    }
}
