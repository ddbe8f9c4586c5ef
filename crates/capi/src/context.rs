//! The OSMesa context object, the thread-local current context, and the
//! copy of the default framebuffer into the client's buffer.

use crate::arrays::ClientArrays;
use crate::osmesa_enums::*;
use std::cell::Cell;
use std::collections::BTreeSet;
use std::ffi::c_void;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// GL enums the context code needs.
use gl::enums::{
    GL_COMPILE, GL_FLOAT, GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_SHORT_5_6_5,
};

/// One OSMesa context: a [`gl::Context`] plus the client buffer it renders
/// into.
pub struct OsContext {
    pub gl: gl::Context,
    /// OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR or
    /// OSMESA_RGB_565.
    pub format: u32,
    pub depth_bits: i32,
    pub stencil_bits: i32,
    pub accum_bits: i32,
    /// The client buffer (null until the first OSMesaMakeCurrent).
    pub buffer: *mut c_void,
    pub ty: u32,
    pub width: i32,
    pub height: i32,
    /// OSMESA_ROW_LENGTH in pixels (0: the width).
    pub row_length: i32,
    /// OSMESA_Y_UP: true = bottom row first in memory (the default).
    pub y_up: bool,
    /// Whether a MakeCurrent has sized the framebuffer yet (the first one
    /// also sets the viewport and scissor box, GL 2.1 §2.11.1).
    pub sized: bool,
    /// Depth values handed out by OSMesaGetDepthBuffer.
    pub depth_copy: DepthCopy,
    /// Client-memory vertex array pointers.
    pub arrays: ClientArrays,
    /// Display lists.
    pub lists: crate::layer_state::Lists,
    /// Buffer objects mapped by glMapBuffer, by name.
    pub mapped: std::collections::BTreeMap<u32, crate::layer_state::Mapping>,
    /// State of the GL 1.x calls kept at the C level ([`crate::legacy`]).
    pub legacy: crate::layer_state::Legacy,
    /// glPushClientAttrib's stack (the client pointers of the arrays).
    pub client_attrib_stack: Vec<(u32, crate::arrays::ClientArrays)>,
    /// Pixels changed since the last copy to the client buffer.
    pub dirty: bool,
    /// glGetString results, kept alive for the context's lifetime.
    pub strings: std::collections::BTreeMap<u32, std::ffi::CString>,
    /// glGetStringi(GL_EXTENSIONS, i)'s strings, by index.
    pub extension_strings: std::collections::BTreeMap<u32, std::ffi::CString>,
    /// Pixel debugging asked for by the environment ([`crate::debug_env`]).
    pub debug: Option<crate::debug_env::DebugEnv>,
}

/// The depth buffer as OSMesaGetDepthBuffer exposes it.
pub enum DepthCopy {
    None,
    U16(Vec<u16>),
    U32(Vec<u32>),
}

impl OsContext {
    pub fn new(
        api: gl::Api,
        format: u32,
        depth_bits: i32,
        stencil_bits: i32,
        accum_bits: i32,
    ) -> OsContext {
        let debug = crate::debug_env::from_process();
        let mut gl = gl::Context::with_api(1, 1, api);
        if let Some(d) = &debug {
            gl.set_debug(Some(d.request.clone()));
        }
        OsContext {
            gl,
            debug,
            format,
            depth_bits,
            stencil_bits,
            accum_bits,
            buffer: std::ptr::null_mut(),
            ty: GL_UNSIGNED_BYTE,
            width: 0,
            height: 0,
            row_length: 0,
            y_up: true,
            sized: false,
            dirty: true,
            mapped: std::collections::BTreeMap::new(),
            client_attrib_stack: Vec::new(),
            legacy: crate::layer_state::Legacy::default(),
            depth_copy: DepthCopy::None,
            arrays: ClientArrays::default(),
            lists: Default::default(),
            strings: Default::default(),
            extension_strings: Default::default(),
        }
    }

    /// Bytes per pixel of the client buffer for `format`/`ty`, if the pair
    /// is one OSMesa accepts.
    pub fn pixel_bytes(format: u32, ty: u32) -> Option<usize> {
        let comps = match format {
            OSMESA_RGBA | OSMESA_BGRA | OSMESA_ARGB => 4,
            OSMESA_RGB | OSMESA_BGR => 3,
            OSMESA_RGB_565 => return (ty == GL_UNSIGNED_SHORT_5_6_5).then_some(2),
            _ => return None,
        };
        let size = match ty {
            GL_UNSIGNED_BYTE => 1,
            GL_UNSIGNED_SHORT => 2,
            GL_FLOAT => 4,
            _ => return None,
        };
        Some(comps * size)
    }

    /// Copies the default framebuffer into the client buffer if drawing
    /// changed it since the last copy ([`OsContext::copy_out`]).
    pub fn sync(&mut self) {
        if self.dirty {
            self.copy_out();
        }
        if let Some(d) = &self.debug {
            crate::debug_env::flush(&mut self.gl, d);
        }
    }

    /// Copies the default framebuffer into the client buffer in its format
    /// and type, rows bottom first unless OSMESA_Y_UP is 0.
    pub fn copy_out(&mut self) {
        self.dirty = false;
        if self.buffer.is_null() || self.width <= 0 || self.height <= 0 {
            return;
        }
        let Some(px) = Self::pixel_bytes(self.format, self.ty) else {
            return;
        };
        let (w, h) = (self.width as usize, self.height as usize);
        let row_px = if self.row_length > 0 {
            (self.row_length as usize).max(w)
        } else {
            w
        };
        let (fb, workers) = self.gl.default_framebuffer();
        // SAFETY: OSMesaMakeCurrent's contract: `buffer` holds at least
        // row_length * height pixels of the format and type given there
        // (row_length >= width), and stays valid while the context uses it.
        let out =
            unsafe { std::slice::from_raw_parts_mut(self.buffer as *mut u8, row_px * h * px) };
        // RGBA bytes from an RGBA8 framebuffer of the buffer's size (the
        // usual case): whole rows copied, the bytes `encode_pixel` writes
        // pixel by pixel.
        if let (OSMESA_RGBA, GL_UNSIGNED_BYTE, Some(raster::ColorBuffer::Rgba8(color))) =
            (self.format, self.ty, fb.color.first())
        {
            if (fb.width as usize, fb.height as usize) == (w, h) && color.len() >= w * h {
                copy_rgba8_rows(color, (w, h), row_px, self.y_up, out, workers);
                return;
            }
        }
        let pixels = fb.read_pixels_u8(0, 0, 0, w as u32, h as u32);
        for y in 0..h {
            let dst_row = if self.y_up { y } else { h - 1 - y };
            for x in 0..w {
                let Some(p) = pixels.get(y * w + x) else {
                    continue;
                };
                let at = (dst_row * row_px + x) * px;
                if let Some(dst) = out.get_mut(at..at + px) {
                    encode_pixel(*p, self.format, self.ty, dst);
                }
            }
        }
    }

    /// Loads the client buffer into the default framebuffer (Mesa renders
    /// in place, so what the buffer holds is the framebuffer's contents):
    /// at OSMesaMakeCurrent and after OSMesaPixelStore changes the layout.
    pub fn upload(&mut self) {
        self.dirty = false;
        if self.buffer.is_null() || self.width <= 0 || self.height <= 0 {
            return;
        }
        let Some(px) = Self::pixel_bytes(self.format, self.ty) else {
            return;
        };
        let (w, h) = (self.width as usize, self.height as usize);
        let row_px = if self.row_length > 0 {
            (self.row_length as usize).max(w)
        } else {
            w
        };
        // SAFETY: as in `copy_out`: the buffer holds row_length * height
        // pixels per OSMesaMakeCurrent's contract.
        let src = unsafe { std::slice::from_raw_parts(self.buffer as *const u8, row_px * h * px) };
        let mut pixels = vec![[0u8, 0, 0, 255]; w * h];
        for y in 0..h {
            let src_row = if self.y_up { y } else { h - 1 - y };
            for x in 0..w {
                let at = (src_row * row_px + x) * px;
                if let (Some(s), Some(d)) = (src.get(at..at + px), pixels.get_mut(y * w + x)) {
                    *d = decode_pixel(s, self.format, self.ty);
                }
            }
        }
        self.gl.load_default_color(&pixels);
    }

    /// Refreshes and returns the depth copy.
    pub fn depth_buffer(&mut self) -> Option<(*mut c_void, i32)> {
        if self.depth_bits <= 0 || !self.sized {
            return None;
        }
        let (fb, _) = self.gl.default_framebuffer();
        let depth = fb.depth.as_ref()?;
        if self.depth_bits <= 16 {
            // 24-bit fixed point to 16-bit: keep the top bits.
            let v: Vec<u16> = depth.iter().map(|&k| (k >> 8) as u16).collect();
            self.depth_copy = DepthCopy::U16(v);
        } else {
            // 24-bit to 32-bit unsigned normalized: replicate the top bits.
            let v: Vec<u32> = depth.iter().map(|&k| (k << 8) | (k >> 16)).collect();
            self.depth_copy = DepthCopy::U32(v);
        }
        match &mut self.depth_copy {
            DepthCopy::U16(v) => Some((v.as_mut_ptr() as *mut c_void, 2)),
            DepthCopy::U32(v) => Some((v.as_mut_ptr() as *mut c_void, 4)),
            DepthCopy::None => None,
        }
    }
}

/// Writes one RGBA8 pixel in the client's format and type.
/// `color` (`w` × `h` RGBA8 pixels, bottom row first) into `out` as RGBA
/// bytes, rows `row_px` pixels apart, bottom row first when `y_up`: what
/// [`encode_pixel`] writes pixel by pixel for OSMESA_RGBA and
/// GL_UNSIGNED_BYTE, a row at a time.
fn copy_rgba8_rows(
    color: &[[u8; 4]],
    (w, h): (usize, usize),
    row_px: usize,
    y_up: bool,
    out: &mut [u8],
    workers: &raster::Workers,
) {
    let row_bytes = row_px * 4;
    if w == 0 || h == 0 || row_px < w {
        return;
    }
    // Bands of destination rows copied in parallel (a frame's copy runs
    // between draws, where nothing else does).
    let out = out.get_mut(..row_bytes * h).unwrap_or(&mut []);
    workers.for_each_chunk(out, row_bytes * COPY_ROWS, |band, rows| {
        for (r, dst) in rows.chunks_mut(row_bytes).enumerate() {
            let dst_row = band * COPY_ROWS + r;
            let y = if y_up { dst_row } else { h - 1 - dst_row };
            if let (Some(src), Some(dst)) = (color.get(y * w..(y + 1) * w), dst.get_mut(..w * 4)) {
                dst.copy_from_slice(src.as_flattened());
            }
        }
    });
}

/// Rows of the client buffer one task of [`copy_rgba8_rows`] copies.
const COPY_ROWS: usize = 64;

fn encode_pixel(p: [u8; 4], format: u32, ty: u32, dst: &mut [u8]) {
    let [r, g, b, a] = p;
    if format == OSMESA_RGB_565 {
        let v: u16 = ((r as u16 >> 3) << 11) | ((g as u16 >> 2) << 5) | (b as u16 >> 3);
        dst.copy_from_slice(&v.to_ne_bytes());
        return;
    }
    let order: &[u8] = match format {
        OSMESA_RGBA => &[r, g, b, a],
        OSMESA_BGRA => &[b, g, r, a],
        OSMESA_ARGB => &[a, r, g, b],
        OSMESA_RGB => &[r, g, b],
        OSMESA_BGR => &[b, g, r],
        _ => return,
    };
    match ty {
        GL_UNSIGNED_BYTE => {
            for (d, s) in dst.iter_mut().zip(order) {
                *d = *s;
            }
        }
        GL_UNSIGNED_SHORT => {
            for (d, s) in dst.chunks_exact_mut(2).zip(order) {
                d.copy_from_slice(&(*s as u16 * 257).to_ne_bytes());
            }
        }
        GL_FLOAT => {
            for (d, s) in dst.chunks_exact_mut(4).zip(order) {
                d.copy_from_slice(&(*s as f32 / 255.0).to_ne_bytes());
            }
        }
        _ => {}
    }
}

/// Reads one client pixel back as RGBA8 (the inverse of `encode_pixel`;
/// formats without alpha read alpha 255).
fn decode_pixel(src: &[u8], format: u32, ty: u32) -> [u8; 4] {
    if format == OSMESA_RGB_565 {
        let v = match src {
            [a, b, ..] => u16::from_ne_bytes([*a, *b]),
            _ => 0,
        };
        let (r, g, b) = ((v >> 11) & 31, (v >> 5) & 63, v & 31);
        return [
            ((r * 255 + 15) / 31) as u8,
            ((g * 255 + 31) / 63) as u8,
            ((b * 255 + 15) / 31) as u8,
            255,
        ];
    }
    let size = match ty {
        GL_UNSIGNED_SHORT => 2,
        GL_FLOAT => 4,
        _ => 1,
    };
    let comp = |i: usize| -> u8 {
        let Some(c) = src.get(i * size..(i + 1) * size) else {
            return 0;
        };
        match c {
            [a] => *a,
            [a, b] => ((u16::from_ne_bytes([*a, *b]) as u32 * 255 + 32767) / 65535) as u8,
            [a, b, cc, d] => raster::float_to_unorm8(f32::from_ne_bytes([*a, *b, *cc, *d])),
            _ => 0,
        }
    };
    match format {
        OSMESA_RGBA => [comp(0), comp(1), comp(2), comp(3)],
        OSMESA_BGRA => [comp(2), comp(1), comp(0), comp(3)],
        OSMESA_ARGB => [comp(1), comp(2), comp(3), comp(0)],
        OSMESA_RGB => [comp(0), comp(1), comp(2), 255],
        OSMESA_BGR => [comp(2), comp(1), comp(0), 255],
        _ => [0, 0, 0, 255],
    }
}

impl OsContext {
    /// Records `cmd` into the list being compiled. True when the call
    /// must not execute now (GL_COMPILE).
    pub fn record(&mut self, cmd: impl Fn() + 'static) -> bool {
        if self.lists.replaying > 0 {
            return false;
        }
        match &mut self.lists.compiling {
            Some((_, mode, cmds)) => {
                cmds.push(Box::new(cmd));
                *mode == GL_COMPILE
            }
            None => false,
        }
    }

    /// Whether a list is being compiled (outside replay).
    pub fn compiling(&self) -> bool {
        self.lists.compiling.is_some() && self.lists.replaying == 0
    }
}

thread_local! {
    static CURRENT: Cell<*mut OsContext> = const { Cell::new(std::ptr::null_mut()) };
}

/// Every live context (addresses), so a stale or foreign pointer passed to
/// OSMesaMakeCurrent/DestroyContext is refused instead of dereferenced.
static LIVE: Mutex<BTreeSet<usize>> = Mutex::new(BTreeSet::new());

pub fn register(ctx: *mut OsContext) {
    if let Ok(mut l) = LIVE.lock() {
        l.insert(ctx as usize);
    }
}

/// Removes `ctx` from the live set; false if it was not live.
pub fn unregister(ctx: *mut OsContext) -> bool {
    LIVE.lock()
        .map(|mut l| l.remove(&(ctx as usize)))
        .unwrap_or(false)
}

pub fn is_live(ctx: *mut OsContext) -> bool {
    LIVE.lock()
        .map(|l| l.contains(&(ctx as usize)))
        .unwrap_or(false)
}

pub fn current() -> *mut OsContext {
    CURRENT.with(|c| c.get())
}

pub fn set_current(ctx: *mut OsContext) {
    CURRENT.with(|c| c.set(ctx));
}

/// Panics caught at the C boundary since the process started (a bug in
/// shaderbox each; tests assert none).
static CAUGHT_PANICS: AtomicU64 = AtomicU64::new(0);

/// The number of panics caught at the C boundary so far.
pub fn caught_panics() -> u64 {
    CAUGHT_PANICS.load(Ordering::Relaxed)
}

fn caught<R>(r: std::thread::Result<R>, default: R) -> R {
    r.unwrap_or_else(|_| {
        CAUGHT_PANICS.fetch_add(1, Ordering::Relaxed);
        default
    })
}

/// Runs `f` on the current context, or returns `default` when there is
/// none. Panics are caught: they never unwind into C.
pub fn with_ctx<R>(default: R, f: impl FnOnce(&mut OsContext) -> R) -> R {
    let p = current();
    if p.is_null() {
        return default;
    }
    // SAFETY: `p` came from Box::into_raw in OSMesaCreateContext* and is
    // current on this thread only while live (DestroyContext clears it);
    // GL entry points do not re-enter, so this is the only reference.
    let ctx = unsafe { &mut *p };
    caught(catch_unwind(AssertUnwindSafe(|| f(ctx))), default)
}

/// For a hand-written entry point the core profile removes: true (the
/// call must return at once) when the current context is a core one,
/// which then records GL_INVALID_OPERATION; the `gl_entry_points!` macro
/// does the same for its entries.
pub fn refused_in_core() -> bool {
    with_ctx(false, |c| c.gl.refuse_removed())
}

/// [`OsContext::record`] on the current context, from outside `with_ctx`.
pub fn record_call(cmd: impl Fn() + 'static) -> bool {
    let p = current();
    if p.is_null() {
        return false;
    }
    // SAFETY: the current context, not otherwise borrowed here (entry
    // points call this before `with_ctx`).
    guard(false, || unsafe { &mut *p }.record(cmd))
}

/// While a display list is being compiled, records a replay of a vector
/// call: the `N` values at `v` are read now (a list keeps values, not the
/// caller's pointer) and `replay` gets a pointer to the copy. True when
/// the call must not also run now (GL_COMPILE); false when it must
/// (GL_COMPILE_AND_EXECUTE, or not compiling, or a null pointer).
pub(crate) fn record_vector<const N: usize, T: Copy + 'static>(
    c: &mut OsContext,
    v: *const T,
    replay: impl Fn(*const T) + 'static,
) -> bool {
    if !c.compiling() {
        return false;
    }
    // SAFETY: GL's contract for vector arguments: N values at v (or null).
    match unsafe { crate::abi::rd::<N, T>(v) } {
        Some(arr) => c.record(move || replay(arr.as_ptr())),
        None => false,
    }
}

/// The body of a vector entry point whose value count depends on its
/// pname (glLightfv, glFogiv...): the `n` values at `v` are read once;
/// while a display list is compiled `replay` is recorded with a copy of
/// them, and unless that is all (GL_COMPILE) `apply` runs on them. Nothing
/// happens for a null pointer.
pub(crate) fn vector_call_n<T: Copy + 'static>(
    c: &mut OsContext,
    v: *const T,
    n: i64,
    replay: impl Fn(*const T) + 'static,
    apply: impl FnOnce(&mut OsContext, &[T]),
) {
    if v.is_null() {
        return;
    }
    // SAFETY: GL's contract for vector arguments: n values at v.
    let values = unsafe { crate::abi::rd_vec(v, n) };
    if c.compiling() {
        let copy = values.clone();
        if c.record(move || replay(copy.as_ptr())) {
            return;
        }
    }
    apply(c, &values);
}

/// The body of a vector entry point (glColor3ubv...): while a display list
/// is compiled the values are recorded ([`record_vector`]); unless that is
/// all (GL_COMPILE), `apply` runs on the `N` values at `v` (nothing for a
/// null pointer).
pub(crate) fn vector_call<const N: usize, T: Copy + 'static>(
    c: &mut OsContext,
    v: *const T,
    replay: impl Fn(*const T) + 'static,
    apply: impl FnOnce(&mut OsContext, [T; N]),
) {
    if record_vector::<N, T>(c, v, replay) {
        return;
    }
    // SAFETY: GL's contract for vector arguments: N values at v (or null).
    if let Some(values) = unsafe { crate::abi::rd::<N, T>(v) } {
        apply(c, values);
    }
}

/// Runs `f` with panics caught (for entry points without a context).
pub fn guard<R>(default: R, f: impl FnOnce() -> R) -> R {
    caught(catch_unwind(AssertUnwindSafe(f)), default)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The row copy of `copy_out` against `encode_pixel` pixel by pixel.
    #[test]
    fn rgba8_rows_match_encode_pixel() {
        // Fewer rows than a copy task takes, and several tasks' worth.
        for (w, h) in [(5, 3), (7, 2 * COPY_ROWS + 9)] {
            rows_match(w, h);
        }
    }

    fn rows_match(w: usize, h: usize) {
        let color: Vec<[u8; 4]> = (0..w * h)
            .map(|i| [i as u8, (i * 7) as u8, (i * 13) as u8, 255 - i as u8])
            .collect();
        for (row_px, y_up) in [(w, true), (w, false), (w + 3, true), (w + 3, false)] {
            let mut want = vec![0xAAu8; row_px * h * 4];
            for y in 0..h {
                let dst_row = if y_up { y } else { h - 1 - y };
                for x in 0..w {
                    let at = (dst_row * row_px + x) * 4;
                    encode_pixel(
                        color[y * w + x],
                        OSMESA_RGBA,
                        GL_UNSIGNED_BYTE,
                        &mut want[at..at + 4],
                    );
                }
            }
            let mut got = vec![0xAAu8; row_px * h * 4];
            for threads in [1, 2] {
                let workers = raster::Workers::new(threads);
                got.fill(0xAA);
                copy_rgba8_rows(&color, (w, h), row_px, y_up, &mut got, &workers);
                assert_eq!(got, want, "{row_px} {y_up} {threads}");
            }
        }
    }

    #[test]
    fn pixel_encodings() {
        let p = [10, 20, 30, 40];
        let mut d = [0u8; 4];
        encode_pixel(p, OSMESA_ARGB, GL_UNSIGNED_BYTE, &mut d);
        assert_eq!(d, [40, 10, 20, 30]);
        let mut d = [0u8; 3];
        encode_pixel(p, OSMESA_BGR, GL_UNSIGNED_BYTE, &mut d);
        assert_eq!(d, [30, 20, 10]);
        let mut d = [0u8; 2];
        encode_pixel(
            [255, 0, 255, 255],
            OSMESA_RGB_565,
            GL_UNSIGNED_SHORT_5_6_5,
            &mut d,
        );
        assert_eq!(u16::from_ne_bytes(d), 0xf81f);
        let mut d = [0u8; 16];
        encode_pixel([255, 0, 0, 51], OSMESA_RGBA, GL_FLOAT, &mut d);
        assert_eq!(f32::from_ne_bytes([d[12], d[13], d[14], d[15]]), 0.2);
        assert_eq!(
            OsContext::pixel_bytes(OSMESA_RGB_565, GL_UNSIGNED_BYTE),
            None
        );
        assert_eq!(
            OsContext::pixel_bytes(OSMESA_RGB, GL_UNSIGNED_SHORT),
            Some(6)
        );
    }
}
