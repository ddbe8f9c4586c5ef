//! Rasterization controls (GL 2.1 §3.3-3.5) and pixel storage (§3.6.1):
//! culling, front face, polygon mode and offset, shade model, point size
//! and parameters, line width, glPixelStore, and glHint.
//!
//! Contract: each setter validates as GL 2.1 says and changes nothing on
//! error; glHint only validates its arguments (no hint changes an image).

use crate::enums::*;
use crate::param::Param;
use crate::Context;

/// GL_MAX_SAMPLE_MASK_WORDS.
pub const MAX_SAMPLE_MASK_WORDS: u32 = 1;

impl Context {
    /// glCullFace.
    pub fn cull_face(&mut self, mode: u32) {
        if self.setter_accepts(Self::faces(mode).is_some(), GL_INVALID_ENUM) {
            self.st.cull_face = mode;
        }
    }

    /// glFrontFace.
    pub fn front_face(&mut self, mode: u32) {
        if self.setter_accepts(matches!(mode, GL_CW | GL_CCW), GL_INVALID_ENUM) {
            self.st.front_face = mode;
        }
    }

    /// glPolygonMode.
    pub fn polygon_mode(&mut self, face: u32, mode: u32) {
        let faces = Self::faces(face).filter(|_| matches!(mode, GL_POINT | GL_LINE | GL_FILL));
        if self.setter_accepts(faces.is_some(), GL_INVALID_ENUM) {
            for &f in faces.unwrap_or_default() {
                self.st.polygon_mode[f] = mode;
            }
        }
    }

    /// glPolygonOffset.
    pub fn polygon_offset(&mut self, factor: f32, units: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.st.polygon_offset = [factor, units];
    }

    /// glShadeModel.
    pub fn shade_model(&mut self, mode: u32) {
        if self.setter_accepts(matches!(mode, GL_FLAT | GL_SMOOTH), GL_INVALID_ENUM) {
            self.st.shade_model = mode;
        }
    }

    /// glProvokingVertex (GL 3.3 §2.19): which vertex of a primitive
    /// gives flat-shaded values; GL_INVALID_ENUM for another mode.
    pub fn provoking_vertex(&mut self, mode: u32) {
        let valid = matches!(mode, GL_FIRST_VERTEX_CONVENTION | GL_LAST_VERTEX_CONVENTION);
        if self.setter_accepts(valid, GL_INVALID_ENUM) {
            self.st.provoking_vertex = mode;
        }
    }

    /// Whether the first-vertex provoking convention is in effect.
    pub(crate) fn provoking_first(&self) -> bool {
        self.st.provoking_vertex == GL_FIRST_VERTEX_CONVENTION
    }

    /// glSampleMaski (GL 3.3 §3.3.1): word `index` of the sample mask
    /// (GL_INVALID_VALUE past GL_MAX_SAMPLE_MASK_WORDS, 1). The mask, like
    /// the rest of multisample rasterization, applies only to
    /// framebuffers with sample buffers (GL_SAMPLE_BUFFERS 1), which
    /// shaderbox's are not yet: it is kept and queried.
    pub fn sample_maski(&mut self, index: u32, mask: u32) {
        if self.setter_accepts(index < MAX_SAMPLE_MASK_WORDS, GL_INVALID_VALUE) {
            self.st.sample_mask = mask;
        }
    }

    /// glGetMultisamplefv(GL_SAMPLE_POSITION, index): GL_INVALID_ENUM for
    /// another pname; every index is GL_INVALID_VALUE, being at least
    /// GL_SAMPLES, which is 0 for shaderbox's single-sampled framebuffers
    /// (Mesa answers the same for them).
    pub fn get_multisamplefv(&mut self, pname: u32, _index: u32) -> Option<[f32; 2]> {
        if self.reject_in_begin() {
            return None;
        }
        if pname != GL_SAMPLE_POSITION {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        self.set_error(GL_INVALID_VALUE);
        None
    }

    /// glPointSize.
    pub fn point_size(&mut self, size: f32) {
        // NaN is not above 0 either.
        if self.setter_accepts(size > 0.0, GL_INVALID_VALUE) {
            self.st.point.size = size;
        }
    }

    /// glLineWidth.
    pub fn line_width(&mut self, width: f32) {
        // NaN is not above 0 either.
        if self.setter_accepts(width > 0.0, GL_INVALID_VALUE) {
            self.st.line_width = width;
        }
    }

    /// glPointParameter{f,i,fv,iv} (a scalar form of
    /// GL_POINT_DISTANCE_ATTENUATION is too few values: GL_INVALID_VALUE).
    pub fn point_parameter(&mut self, pname: u32, v: Param) {
        if self.reject_in_begin() {
            return;
        }
        let v = &v.floats(pname)[..];
        let need = if pname == GL_POINT_DISTANCE_ATTENUATION {
            3
        } else {
            1
        };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let x = v[0];
        let p = &mut self.st.point;
        match pname {
            GL_POINT_SIZE_MIN | GL_POINT_SIZE_MAX | GL_POINT_FADE_THRESHOLD_SIZE if x < 0.0 => {
                self.set_error(GL_INVALID_VALUE)
            }
            GL_POINT_SIZE_MIN => p.size_min = x,
            GL_POINT_SIZE_MAX => p.size_max = x,
            GL_POINT_FADE_THRESHOLD_SIZE => p.fade_threshold = x,
            GL_POINT_DISTANCE_ATTENUATION => p.attenuation = [v[0], v[1], v[2]],
            GL_POINT_SPRITE_COORD_ORIGIN => {
                let o = x as u32;
                if o == GL_LOWER_LEFT || o == GL_UPPER_LEFT {
                    p.sprite_origin = o;
                } else {
                    self.set_error(GL_INVALID_VALUE);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// The glPixelStore modes images are read from client memory with.
    pub fn unpack_modes(&self) -> crate::pixel_store::PixelStore {
        self.st.unpack
    }

    /// The glPixelStore modes images are written to client memory with.
    pub fn pack_modes(&self) -> crate::pixel_store::PixelStore {
        self.st.pack
    }

    /// glPixelStorei.
    pub fn pixel_storei(&mut self, pname: u32, v: i32) {
        if self.reject_in_begin() {
            return;
        }
        let unpack = matches!(
            pname,
            GL_UNPACK_ALIGNMENT
                | GL_UNPACK_ROW_LENGTH
                | GL_UNPACK_SKIP_ROWS
                | GL_UNPACK_SKIP_PIXELS
                | GL_UNPACK_IMAGE_HEIGHT
                | GL_UNPACK_SKIP_IMAGES
                | GL_UNPACK_SWAP_BYTES
                | GL_UNPACK_LSB_FIRST
        );
        let store = if unpack {
            &mut self.st.unpack
        } else {
            &mut self.st.pack
        };
        // Counts are non-negative and the alignment 1, 2, 4 or 8
        // (GL 2.1 §3.6.1): GL_INVALID_VALUE otherwise.
        let count = usize::try_from(v).ok();
        let ok = match pname {
            GL_UNPACK_ALIGNMENT | GL_PACK_ALIGNMENT => {
                let ok = [1, 2, 4, 8].contains(&v);
                if ok {
                    store.alignment = v as usize;
                }
                ok
            }
            GL_UNPACK_SWAP_BYTES | GL_PACK_SWAP_BYTES => {
                store.swap_bytes = v != 0;
                true
            }
            GL_UNPACK_LSB_FIRST | GL_PACK_LSB_FIRST => {
                store.lsb_first = v != 0;
                true
            }
            GL_UNPACK_ROW_LENGTH | GL_PACK_ROW_LENGTH => {
                count.map(|n| store.row_length = n).is_some()
            }
            GL_UNPACK_SKIP_ROWS | GL_PACK_SKIP_ROWS => count.map(|n| store.skip_rows = n).is_some(),
            GL_UNPACK_SKIP_PIXELS | GL_PACK_SKIP_PIXELS => {
                count.map(|n| store.skip_pixels = n).is_some()
            }
            GL_UNPACK_IMAGE_HEIGHT | GL_PACK_IMAGE_HEIGHT => {
                count.map(|n| store.image_height = n).is_some()
            }
            GL_UNPACK_SKIP_IMAGES | GL_PACK_SKIP_IMAGES => {
                count.map(|n| store.skip_images = n).is_some()
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        if !ok {
            self.set_error(GL_INVALID_VALUE);
        }
    }

    /// glHint (accepted and ignored).
    pub fn hint(&mut self, target: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        let target_ok = matches!(
            target,
            GL_PERSPECTIVE_CORRECTION_HINT
                | GL_POINT_SMOOTH_HINT
                | GL_LINE_SMOOTH_HINT
                | GL_POLYGON_SMOOTH_HINT
                | GL_FOG_HINT
                | GL_GENERATE_MIPMAP_HINT
                | GL_TEXTURE_COMPRESSION_HINT
                | GL_FRAGMENT_SHADER_DERIVATIVE_HINT
        );
        if !target_ok || !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            self.set_error(GL_INVALID_ENUM);
        }
    }
}
