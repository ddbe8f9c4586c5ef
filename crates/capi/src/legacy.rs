//! GL 1.x entry points whose effect an RGBA, single-sampled, render-mode
//! OSMesa context either does not see or that shaderbox keeps as state
//! only. Each keeps the state GL 2.1 defines (so glGet* returns it) and
//! validates its arguments with the errors the spec gives; what is *not*
//! applied when drawing is listed in the crate docs:
//! - color-index calls (glIndexMask, glClearIndex, glIndexPointer; glIndex*
//!   is generated in [`crate::variants`]): legal in RGBA mode, no effect on RGBA rendering
//!   (GL 2.1 §2.7, §4.2.2) — as the spec says;
//! - glSampleCoverage: no multisample buffer, so no effect — as the spec
//!   says;
//! - selection and feedback: glRenderMode(GL_SELECT / GL_FEEDBACK) raises
//!   GL_INVALID_OPERATION (not implemented); the name-stack commands are
//!   ignored outside selection mode and glPassThrough outside feedback
//!   mode, as the spec says for render mode;
//! - glAccum: the context has no accumulation buffer: GL_INVALID_OPERATION
//!   (GL 2.1 §4.2.4);
//! - glLineStipple / glPolygonStipple, edge flags, glPixelMap*: kept and
//!   queryable, **not applied** (lines and polygons draw unstippled, edge
//!   flags do not hide edges, pixel maps are identity); glPixelZoom and
//!   the scale/bias/index values of glPixelTransfer* apply to pixel
//!   rectangles ([`crate::pixel_path`]) and nowhere else (texture uploads
//!   and glReadPixels ignore them);
//! - compressed textures: no compressed internal format exists
//!   (GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0), so glCompressedTex* raise
//!   GL_INVALID_ENUM and glGetCompressedTexImage GL_INVALID_OPERATION;
//! - glPrioritizeTextures / glAreTexturesResident: every texture is
//!   resident; priorities are validated, not kept.

use crate::abi::*;
use crate::context::{record_call, with_ctx, OsContext};
use crate::layer_state::{MAX_PIXEL_MAP_TABLE, PIXEL_MAPS};
use gl::enums::*;
use std::ffi::c_void;

/// The 128 bytes of a polygon stipple (four per row, bottom row first)
/// from a packed 32x32 bitmap whose rows are padded to `alignment`.
fn stipple_rows(packed: &[u8], alignment: usize) -> [u8; 128] {
    let row = gl::pixel_transfer::bitmap_row_bytes(32, alignment);
    let mut m = [0u8; 128];
    for (dst, src) in m.chunks_exact_mut(4).zip(packed.chunks(row)) {
        dst.copy_from_slice(&src[..4]);
    }
    m
}

/// glPixelMap*: validation and storage of `vals` for `map`.
fn pixel_map(c: &mut OsContext, map: GLenum, size: GLsizei, vals: Vec<f32>) {
    if c.gl.reject_in_begin() {
        return;
    }
    if !PIXEL_MAPS.contains(&map) {
        c.gl.record_error(GL_INVALID_ENUM);
        return;
    }
    let indexed = matches!(
        map,
        GL_PIXEL_MAP_I_TO_I
            | GL_PIXEL_MAP_S_TO_S
            | GL_PIXEL_MAP_I_TO_R
            | GL_PIXEL_MAP_I_TO_G
            | GL_PIXEL_MAP_I_TO_B
            | GL_PIXEL_MAP_I_TO_A
    );
    if !(1..=MAX_PIXEL_MAP_TABLE).contains(&size) || (indexed && (size & (size - 1)) != 0) {
        c.gl.record_error(GL_INVALID_VALUE);
        return;
    }
    if vals.len() == size as usize {
        c.legacy.pixel_maps.insert(map, vals);
    }
}

/// glGetPixelMap*: the stored map (GL_INVALID_ENUM for another name).
fn get_pixel_map(c: &mut OsContext, map: GLenum) -> Option<Vec<f32>> {
    if c.gl.reject_in_begin() {
        return None;
    }
    match c.legacy.pixel_maps.get(&map) {
        Some(v) => Some(v.clone()),
        None => {
            c.gl.record_error(GL_INVALID_ENUM);
            None
        }
    }
}

/// Texture names for glAreTexturesResident / glPrioritizeTextures: n < 0
/// or a name that is not a texture is GL_INVALID_VALUE.
fn texture_names(c: &mut OsContext, n: GLsizei, names: *const GLuint) -> Option<Vec<u32>> {
    if c.gl.reject_in_begin() {
        return None;
    }
    if n < 0 {
        c.gl.record_error(GL_INVALID_VALUE);
        return None;
    }
    // SAFETY: GL's contract: n names at `names` (or null).
    let v = unsafe { rd_vec(names, n as i64) };
    if v.iter().any(|&t| !c.gl.is_texture(t)) {
        c.gl.record_error(GL_INVALID_VALUE);
        return None;
    }
    Some(v)
}

/// A compressed-texture entry point: every internal format given is not
/// a compressed one this context supports.
fn compressed(c: &mut OsContext) {
    if !c.gl.reject_in_begin() {
        c.gl.record_error(GL_INVALID_ENUM);
    }
}

gl_entry_points! {
    // ---- colour index (RGBA contexts keep the values only; glIndex* are in
    // crate::variants) ----
    [list] fn glIndexMask(mask: GLuint) => |c| {
        if !c.gl.reject_in_begin() { c.legacy.index_mask = mask }
    }
    [list] fn glClearIndex(v: GLfloat) => |c| {
        if !c.gl.reject_in_begin() { c.legacy.clear_index = v }
    }
    fn glIndexPointer(ty: GLenum, stride: GLsizei, p: *const c_void) => |c| {
        if !matches!(ty, GL_UNSIGNED_BYTE | GL_SHORT | GL_INT | GL_FLOAT | GL_DOUBLE) {
            c.gl.record_error(GL_INVALID_ENUM);
        } else if stride < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
        } else {
            c.legacy.index_type = ty;
            c.legacy.index_stride = stride;
            c.legacy.index_pointer = p as usize;
        }
    }

    // ---- edge flags (kept, not applied) ----
    [list] fn glEdgeFlag(flag: GLboolean) => |c| { c.legacy.edge_flag = flag != 0 }
    fn glEdgeFlagv(v: *const GLboolean) => |c| {
        if let Some([x]) = rd::<1, u8>(v) {
            if c.record(move || unsafe { glEdgeFlag(x) }) {
                return;
            }
            c.legacy.edge_flag = x != 0
        }
    }
    fn glEdgeFlagPointer(stride: GLsizei, p: *const c_void) => |c| {
        if stride < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
        } else {
            c.legacy.edge_flag_stride = stride;
            c.legacy.edge_flag_pointer = p as usize;
        }
    }

    // ---- selection and feedback (GL_RENDER only) ----
    fn glRenderMode(mode: GLenum) -> GLint [0] => |c| {
        if c.gl.reject_in_begin() {
            return 0;
        }
        match mode {
            GL_RENDER => 0,
            GL_SELECT | GL_FEEDBACK => {
                // Not implemented: refused rather than drawing as if in
                // GL_RENDER and returning no hits.
                c.gl.record_error(GL_INVALID_OPERATION);
                0
            }
            _ => {
                c.gl.record_error(GL_INVALID_ENUM);
                0
            }
        }
    }
    fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        if size < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        c.legacy.select_size = size;
        c.legacy.select_buffer = buffer as usize;
    }
    fn glFeedbackBuffer(size: GLsizei, ty: GLenum, buffer: *mut GLfloat) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        if !matches!(ty, GL_2D | GL_3D | GL_3D_COLOR | GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
            c.gl.record_error(GL_INVALID_ENUM);
            return;
        }
        if size < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        c.legacy.feedback_size = size;
        c.legacy.feedback_type = ty;
        c.legacy.feedback_buffer = buffer as usize;
    }
    // Ignored outside selection mode (GL 2.1 §5.2); the context is always
    // in GL_RENDER mode.
    [list] fn glInitNames() => |c| { c.gl.reject_in_begin(); }
    [list] fn glLoadName(name: GLuint) => |c| { let _ = name; c.gl.reject_in_begin(); }
    [list] fn glPushName(name: GLuint) => |c| { let _ = name; c.gl.reject_in_begin(); }
    [list] fn glPopName() => |c| { c.gl.reject_in_begin(); }
    // Ignored outside feedback mode (GL 2.1 §5.3).
    [list] fn glPassThrough(token: GLfloat) => |c| { let _ = token; c.gl.reject_in_begin(); }

    // ---- accumulation buffer (absent) ----
    [list] fn glAccum(op: GLenum, value: GLfloat) => |c| {
        let _ = value;
        if c.gl.reject_in_begin() {
            return;
        }
        if !matches!(op, GL_ACCUM | GL_LOAD | GL_RETURN | GL_MULT | GL_ADD) {
            c.gl.record_error(GL_INVALID_ENUM);
        } else {
            c.gl.record_error(GL_INVALID_OPERATION);
        }
    }
    [list] fn glClearAccum(r: GLfloat, g: GLfloat, bl: GLfloat, a: GLfloat) => |c| {
        if !c.gl.reject_in_begin() {
            c.legacy.accum_clear = [r, g, bl, a].map(|x| x.clamp(-1.0, 1.0));
        }
    }

    // ---- stipples (kept, not applied) ----
    [list] fn glLineStipple(factor: GLint, pattern: GLushort) => |c| {
        if !c.gl.reject_in_begin() {
            c.legacy.line_stipple = (factor.clamp(1, 256), pattern);
        }
    }
    fn glPolygonStipple(mask: *const GLubyte) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        // Unpacked as a 32x32 bitmap would be (GL 2.1 §3.5.2): the
        // unpack modes apply.
        let Ok(Some(packed)) = crate::pixel_path::bitmap_bytes(c, 32, 32, mask) else {
            return;
        };
        let m = stipple_rows(&packed, c.gl.unpack_modes().alignment);
        if c.record(move || with_stipple(&m)) {
            return;
        }
        c.legacy.polygon_stipple = m;
    }
    fn glGetPolygonStipple(mask: *mut GLubyte) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        // Packed as a 32x32 bitmap would be (GL 2.1 §6.1.6).
        let store = c.gl.pack_modes();
        let Some(len) = store.bitmap_extent(32, 32) else {
            return;
        };
        let row = gl::pixel_transfer::bitmap_row_bytes(32, store.alignment);
        let mut packed = vec![0u8; row * 32];
        for (dst, src) in packed.chunks_exact_mut(row).zip(c.legacy.polygon_stipple.chunks_exact(4)) {
            dst[..4].copy_from_slice(src);
        }
        // With a pack buffer bound the pointer is an offset into it.
        if c.gl.bound_buffer(GL_PIXEL_PACK_BUFFER) != 0 {
            let Ok(mut range) = crate::buffers::read_pixel_buffer(c, GL_PIXEL_PACK_BUFFER, mask as usize, len) else {
                return;
            };
            store.scatter_bitmap(&packed, &mut range, 32, 32);
            crate::buffers::write_pixel_buffer(c, mask as usize, &range);
        } else if !mask.is_null() {
            // SAFETY: GL's contract: the pattern's bits, laid out per the
            // pack modes, lie within `len` bytes of `mask`.
            store.scatter_bitmap(&packed, std::slice::from_raw_parts_mut(mask, len), 32, 32);
        }
    }

    // ---- multisample (none: no effect) ----
    [list] fn glSampleCoverage(value: GLclampf, invert: GLboolean) => |c| {
        if !c.gl.reject_in_begin() {
            c.legacy.sample_coverage = (value.clamp(0.0, 1.0), invert != 0);
        }
    }

    // ---- pixel transfer state (kept, not applied) ----
    [list] fn glPixelZoom(x: GLfloat, y: GLfloat) => |c| {
        if !c.gl.reject_in_begin() { c.legacy.pixel_zoom = (x, y) }
    }
    [list] fn glPixelTransferf(pname: GLenum, v: GLfloat) => |c| { pixel_transfer(c, pname, v) }
    [list] fn glPixelTransferi(pname: GLenum, v: GLint) => |c| { pixel_transfer(c, pname, v as f32) }
    fn glPixelMapfv(map: GLenum, size: GLsizei, v: *const GLfloat) => |c| {
        let vals = rd_vec(v, size.clamp(0, MAX_PIXEL_MAP_TABLE) as i64);
        record_map(c, map, size, vals);
    }
    fn glPixelMapuiv(map: GLenum, size: GLsizei, v: *const GLuint) => |c| {
        let vals = rd_vec(v, size.clamp(0, MAX_PIXEL_MAP_TABLE) as i64);
        let color = !matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        let f: Vec<f32> = vals.iter().map(|&x| if color { (x as f64 / u32::MAX as f64) as f32 } else { x as f32 }).collect();
        record_map(c, map, size, f);
    }
    fn glPixelMapusv(map: GLenum, size: GLsizei, v: *const GLushort) => |c| {
        let vals = rd_vec(v, size.clamp(0, MAX_PIXEL_MAP_TABLE) as i64);
        let color = !matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        let f: Vec<f32> = vals.iter().map(|&x| if color { x as f32 / 65535.0 } else { x as f32 }).collect();
        record_map(c, map, size, f);
    }
    fn glGetPixelMapfv(map: GLenum, v: *mut GLfloat) => |c| {
        if let Some(m) = get_pixel_map(c, map) { wr(v, &m) }
    }
    fn glGetPixelMapuiv(map: GLenum, v: *mut GLuint) => |c| {
        let color = !matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        if let Some(m) = get_pixel_map(c, map) {
            let r: Vec<u32> = m.iter().map(|&x| if color { (x.clamp(0.0, 1.0) as f64 * u32::MAX as f64 + 0.5) as u32 } else { x.max(0.0) as u32 }).collect();
            wr(v, &r)
        }
    }
    fn glGetPixelMapusv(map: GLenum, v: *mut GLushort) => |c| {
        let color = !matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        if let Some(m) = get_pixel_map(c, map) {
            let r: Vec<u16> = m.iter().map(|&x| if color { (x.clamp(0.0, 1.0) * 65535.0 + 0.5) as u16 } else { x.clamp(0.0, 65535.0) as u16 }).collect();
            wr(v, &r)
        }
    }

    // ---- texture residency ----
    fn glAreTexturesResident(n: GLsizei, names: *const GLuint, residences: *mut GLboolean) -> GLboolean [0] => |c| {
        let _ = residences;
        // All resident: GL_TRUE, `residences` untouched (GL 2.1 §3.8.12).
        texture_names(c, n, names).is_some() as GLboolean
    }
    fn glPrioritizeTextures(n: GLsizei, names: *const GLuint, priorities: *const GLclampf) => |c| {
        let _ = priorities;
        if c.gl.reject_in_begin() {
            return;
        }
        if n < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
        }
        // Names that are not textures are silently ignored (§3.8.12).
        let _ = names;
    }

    // ---- compressed textures (no compressed format exists) ----
    fn glCompressedTexImage1D(target: GLenum, level: GLint, internal: GLenum, w: GLsizei, border: GLint, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, internal, w, border, size, data);
        compressed(c)
    }
    fn glCompressedTexImage2D(target: GLenum, level: GLint, internal: GLenum, w: GLsizei, h: GLsizei, border: GLint, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, internal, w, h, border, size, data);
        compressed(c)
    }
    fn glCompressedTexImage3D(target: GLenum, level: GLint, internal: GLenum, w: GLsizei, h: GLsizei, d: GLsizei, border: GLint, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, internal, w, h, d, border, size, data);
        compressed(c)
    }
    fn glCompressedTexSubImage1D(target: GLenum, level: GLint, x: GLint, w: GLsizei, format: GLenum, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, x, w, format, size, data);
        compressed(c)
    }
    fn glCompressedTexSubImage2D(target: GLenum, level: GLint, x: GLint, y: GLint, w: GLsizei, h: GLsizei, format: GLenum, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, x, y, w, h, format, size, data);
        compressed(c)
    }
    fn glCompressedTexSubImage3D(target: GLenum, level: GLint, x: GLint, y: GLint, z: GLint, w: GLsizei, h: GLsizei, d: GLsizei, format: GLenum, size: GLsizei, data: *const c_void) => |c| {
        let _ = (target, level, x, y, z, w, h, d, format, size, data);
        compressed(c)
    }
    fn glGetCompressedTexImage(target: GLenum, level: GLint, data: *mut c_void) => |c| {
        let _ = data;
        // Validates target and level, then: the image is not compressed.
        let before = c.gl.get_error();
        let _ = c.gl.get_tex_level_parameteriv(target, level, GL_TEXTURE_WIDTH);
        let e = c.gl.get_error();
        c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
        if e == GL_NO_ERROR && target != GL_TEXTURE_CUBE_MAP {
            c.gl.record_error(GL_INVALID_OPERATION);
        }
    }
}

/// Replays a recorded glPolygonStipple.
fn with_stipple(m: &[u8]) {
    crate::context::with_ctx((), |c| {
        if !c.gl.reject_in_begin() && m.len() == 128 {
            c.legacy.polygon_stipple.copy_from_slice(m);
        }
    })
}

/// glPixelTransfer{f,i}.
fn pixel_transfer(c: &mut OsContext, pname: GLenum, v: f32) {
    if c.gl.reject_in_begin() {
        return;
    }
    match c.legacy.pixel_transfer.get_mut(&pname) {
        Some(x) => {
            *x = if matches!(pname, GL_MAP_COLOR | GL_MAP_STENCIL) {
                (v != 0.0) as i32 as f32
            } else {
                v
            }
        }
        None => c.gl.record_error(GL_INVALID_ENUM),
    }
}

/// glPixelMap*: recorded (values copied) while compiling, else applied.
fn record_map(c: &mut OsContext, map: GLenum, size: GLsizei, vals: Vec<f32>) {
    let rec = vals.clone();
    if c.record(move || crate::context::with_ctx((), |c| pixel_map(c, map, size, rec.clone()))) {
        return;
    }
    pixel_map(c, map, size, vals);
}
