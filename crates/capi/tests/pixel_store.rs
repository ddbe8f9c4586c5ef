//! The glPixelStore modes through the C ABI: a sub-rectangle of a larger
//! client image uploaded with row length and skips, byte-swapped texels,
//! a volume's image modes, glReadPixels into a sub-rectangle (pixels
//! between stay untouched), bitmaps least significant bit first, and the
//! queries.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::null_mut;
use OSMesa::*;

const W: i32 = 8;
const H: i32 = 8;

/// A current 2.1 context drawing into `buf` (W x H RGBA8).
unsafe fn context(buf: &mut [u8]) -> OSMesaContext {
    context_of_size(buf, W, H)
}

/// A current 2.1 context drawing into `buf` (`w` x `h` RGBA8).
unsafe fn context_of_size(buf: &mut [u8], w: i32, h: i32) -> OSMesaContext {
    assert!(buf.len() >= (w * h * 4) as usize);
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
    assert!(!ctx.is_null());
    let ok = OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, w, h);
    assert_eq!(ok, OSMesa::GL_TRUE);
    ctx
}

/// Byte `c` of client pixel (x, y) of a 4-pixel-wide RGBA8 image.
fn client(x: usize, y: usize, c: usize) -> u8 {
    (((y * 4 + x) * 4 + c) * 3) as u8
}

#[test]
fn unpack_modes_select_swap_and_slice_client_images() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let ctx = context(&mut buf);
        let image: Vec<u8> = (0..4 * 4)
            .flat_map(|p| (0..4).map(move |c| client(p % 4, p / 4, c)))
            .collect();
        let mut t = 0;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_2D, t);
        // The 2x2 block at (1, 2) of the 4x4 client image.
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            image.as_ptr() as *const c_void,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        let mut v = 0;
        for (pname, want) in [
            (GL_UNPACK_ROW_LENGTH, 4),
            (GL_UNPACK_SKIP_PIXELS, 1),
            (GL_UNPACK_SKIP_ROWS, 2),
        ] {
            glGetIntegerv(pname, &mut v);
            assert_eq!(v, want, "{pname:#x}");
        }
        for (pname, value) in [
            (GL_UNPACK_ROW_LENGTH, 0),
            (GL_UNPACK_SKIP_PIXELS, 0),
            (GL_UNPACK_SKIP_ROWS, 0),
        ] {
            glPixelStorei(pname, value);
        }
        let mut back = [0u8; 16];
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            back.as_mut_ptr() as *mut c_void,
        );
        let want: Vec<u8> = [(1, 2), (2, 2), (1, 3), (2, 3)]
            .iter()
            .flat_map(|&(x, y)| (0..4).map(move |c| client(x, y, c)))
            .collect();
        assert_eq!(back.to_vec(), want);

        // Byte-swapped 16-bit luminance: 0x0102 stored as [1, 2] big-end
        // first reads back, unswapped, as [2, 1].
        glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
        let shorts: [u8; 4] = [0x12, 0x34, 0xAB, 0xCD];
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE16 as i32,
            2,
            1,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_SHORT,
            shorts.as_ptr() as *const c_void,
        );
        glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
        let mut lum = [0u16; 2];
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_SHORT,
            lum.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(lum, [0x1234, 0xABCD]);

        // A 1x1x2 volume out of images of 3 rows, the first image skipped.
        let mut t3 = 0;
        glGenTextures(1, &mut t3);
        glBindTexture(GL_TEXTURE_3D, t3);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
        glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
        let slab: Vec<u8> = (0..9).map(|i| i * 10).collect();
        glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_ALPHA8 as i32,
            1,
            1,
            2,
            0,
            GL_ALPHA,
            GL_UNSIGNED_BYTE,
            slab.as_ptr() as *const c_void,
        );
        glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
        glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
        let mut alpha = [0u8; 2];
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(
            GL_TEXTURE_3D,
            0,
            GL_ALPHA,
            GL_UNSIGNED_BYTE,
            alpha.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(alpha, [30, 60]);
        assert_eq!(glGetError(), GL_NO_ERROR);

        // Negative counts and bad alignments are GL_INVALID_VALUE.
        glPixelStorei(GL_UNPACK_ROW_LENGTH, -1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glPixelStorei(GL_PACK_ALIGNMENT, 3);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glPixelStorei(GL_PACK_SWAP_BYTES + 0x100, 0);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn pack_modes_place_read_pixels_and_leave_the_rest() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let ctx = context(&mut buf);
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        // A 2x2 read into the middle of a 4x4 client image.
        let mut out = [7u8; 4 * 4 * 4];
        glPixelStorei(GL_PACK_ROW_LENGTH, 4);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
        glPixelStorei(GL_PACK_SKIP_ROWS, 1);
        glReadPixels(
            0,
            0,
            2,
            2,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        for (i, b) in out.iter().enumerate() {
            let (x, y, c) = ((i / 4) % 4, i / 16, i % 4);
            let inside = (1..3).contains(&x) && (1..3).contains(&y);
            let want = match (inside, c) {
                (false, _) => 7,
                (true, 0) | (true, 3) => 255,
                (true, _) => 0,
            };
            assert_eq!(*b, want, "byte {i} (pixel {x},{y})");
        }
        // Swapped 32-bit floats.
        for (pname, value) in [
            (GL_PACK_ROW_LENGTH, 0),
            (GL_PACK_SKIP_PIXELS, 0),
            (GL_PACK_SKIP_ROWS, 0),
        ] {
            glPixelStorei(pname, value);
        }
        glPixelStorei(GL_PACK_SWAP_BYTES, 1);
        let mut f = [0u8; 4];
        glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, f.as_mut_ptr() as *mut c_void);
        assert_eq!(f, 1.0f32.to_be_bytes());
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn bitmaps_least_significant_bit_first() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let ctx = context(&mut buf);
        glViewport(0, 0, W, H);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor4f(1.0, 1.0, 1.0, 1.0);
        glRasterPos2f(0.0, 0.0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
        // Row 0: bits 0 and 2 (pixels 0 and 2); row 1: bit 7 (pixel 7).
        let bits = [0b0000_0101u8, 0b1000_0000];
        glBitmap(8, 2, 0.0, 0.0, 0.0, 0.0, bits.as_ptr());
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        let lit = |x: i32, y: i32| buf[((y * W + x) * 4) as usize] == 255;
        let row0: Vec<bool> = (0..8).map(|x| lit(x, 0)).collect();
        let row1: Vec<bool> = (0..8).map(|x| lit(x, 1)).collect();
        assert_eq!(row0, [true, false, true, false, false, false, false, false]);
        assert_eq!(
            row1,
            [false, false, false, false, false, false, false, true]
        );
        let mut v = 0;
        glGetIntegerv(GL_UNPACK_LSB_FIRST, &mut v);
        assert_eq!(v, 1);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn bitmaps_at_whole_raster_positions_start_there() {
    // In a 340x200 orthographic window, glRasterPos2f(20, 30) comes out a
    // few ulps below x = 20 after the transform; the bitmap still starts
    // at pixel column 20 (and row 30).
    unsafe {
        let (w, h) = (340, 200);
        let mut buf = vec![0u8; w * h * 4];
        let ctx = context_of_size(&mut buf, w as i32, h as i32);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
        glColor4f(1.0, 1.0, 1.0, 1.0);
        for x in 0..w {
            glRasterPos2f(x as f32, 30.0);
            let one = [0x80u8];
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glBitmap(1, 1, 0.0, 0.0, 0.0, 0.0, one.as_ptr());
        }
        glFinish();
        let row: Vec<bool> = (0..w).map(|x| buf[(30 * w + x) * 4] == 255).collect();
        assert!(
            row.iter().all(|&lit| lit),
            "unlit columns: {:?}",
            row.iter()
                .enumerate()
                .filter(|(_, &l)| !l)
                .map(|(x, _)| x)
                .collect::<Vec<_>>()
        );
        OSMesaDestroyContext(ctx);
    }
}
