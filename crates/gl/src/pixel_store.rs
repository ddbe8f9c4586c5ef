//! Client images under the pixel storage modes (glPixelStore: GL 2.1
//! §3.6.1 Table 3.1 and §3.6.4 "Unpacking" for images read from the
//! client, §4.3.2 Table 4.5 and "Placement in Client Memory" for images
//! written to it; the 3D modes GL_*_IMAGE_HEIGHT and GL_*_SKIP_IMAGES of
//! §3.8.1): where each pixel of a client image lies, and the copies
//! between that layout and the packed one the rest of the crate works on.
//!
//! Contract: the packed layout is the client layout with the default
//! modes but the alignment: rows padded to the alignment
//! ([`crate::pixel_transfer::row_stride`], [`bitmap_row_bytes`]), images
//! one after another, the first pixel first, components in the machine's
//! byte order and bitmaps most significant bit first. [`PixelStore::gather`]
//! and [`PixelStore::gather_bitmap`] read a client image into it (a short
//! client buffer reads as zero bytes); [`PixelStore::scatter`] writes a
//! packed image into client memory, touching only the bytes of its pixels
//! (GL leaves the rest of the client buffer as it was). Pure functions of
//! the modes and their arguments.

use crate::pixel_transfer::{bitmap_row_bytes, pixel_size, row_stride};

/// The storage modes of one direction (unpack or pack). Values are
/// checked by glPixelStore (no negative count, alignment 1, 2, 4 or 8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelStore {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    pub row_length: usize,
    pub skip_rows: usize,
    pub skip_pixels: usize,
    pub alignment: usize,
    pub image_height: usize,
    pub skip_images: usize,
}

impl Default for PixelStore {
    /// The initial modes (Table 3.1): everything 0 or false, alignment 4.
    fn default() -> PixelStore {
        PixelStore {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            skip_rows: 0,
            skip_pixels: 0,
            alignment: 4,
            image_height: 0,
            skip_images: 0,
        }
    }
}

/// Where the pixels of a `w × h × d` client image lie: pixel `(i, j, k)`
/// at `first + k·image + j·row + i·group` bytes from the image's address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Layout {
    first: usize,
    image: usize,
    row: usize,
    /// Bytes per pixel.
    group: usize,
    /// Bytes per byte-swapped element (a component, or a packed pixel).
    element: usize,
}

impl PixelStore {
    /// Whether client images have the packed layout already (no copy
    /// needed either way).
    pub fn is_packed(&self) -> bool {
        *self
            == PixelStore {
                alignment: self.alignment,
                ..PixelStore::default()
            }
    }

    /// The layout of a `w × h × d` image of `format`/`ty`; `volume` for
    /// three-dimensional images (the image modes apply to those only).
    /// None for an invalid format/type pair or sizes whose offsets
    /// overflow.
    fn layout(&self, w: usize, h: usize, volume: bool, format: u32, ty: u32) -> Option<Layout> {
        let (group, element) = pixel_size(format, ty)?;
        let length = if self.row_length > 0 {
            self.row_length
        } else {
            w
        };
        let row = row_stride(length, format, ty, self.alignment);
        let (rows, skip_images) = match volume {
            true if self.image_height > 0 => (self.image_height, self.skip_images),
            true => (h, self.skip_images),
            false => (h, 0),
        };
        let image = row.checked_mul(rows)?;
        let first = skip_images
            .checked_mul(image)?
            .checked_add(self.skip_rows.checked_mul(row)?)?
            .checked_add(self.skip_pixels.checked_mul(group)?)?;
        Some(Layout {
            first,
            image,
            row,
            group,
            element,
        })
    }

    /// The bytes of client memory a `w × h × d` image spans from its
    /// address (what a reader or writer may touch); None for an invalid
    /// format/type pair, an empty image or one past the address space.
    pub fn image_extent(
        &self,
        [w, h, d]: [usize; 3],
        volume: bool,
        format: u32,
        ty: u32,
    ) -> Option<usize> {
        if w == 0 || h == 0 || d == 0 {
            return None;
        }
        let l = self.layout(w, h, volume, format, ty)?;
        l.first
            .checked_add((d - 1).checked_mul(l.image)?)?
            .checked_add((h - 1).checked_mul(l.row)?)?
            .checked_add(w.checked_mul(l.group)?)
    }

    /// The packed image of a `w × h × d` client image read from `src` (its
    /// bytes from the image's address on; bytes past its end read as
    /// zero). Empty for an invalid format/type pair.
    pub fn gather(
        &self,
        src: &[u8],
        [w, h, d]: [usize; 3],
        volume: bool,
        format: u32,
        ty: u32,
    ) -> Vec<u8> {
        let Some(l) = self.layout(w, h, volume, format, ty) else {
            return Vec::new();
        };
        let packed_row = row_stride(w, format, ty, self.alignment);
        let mut out = vec![0u8; packed_row * h * d];
        let bytes = w * l.group;
        for k in 0..d {
            for j in 0..h {
                let from = l
                    .first
                    .saturating_add(k.saturating_mul(l.image))
                    .saturating_add(j.saturating_mul(l.row));
                let to = (k * h + j) * packed_row;
                let dst = &mut out[to..to + bytes];
                if let Some(s) = src.get(from..) {
                    let n = s.len().min(bytes);
                    dst[..n].copy_from_slice(&s[..n]);
                }
                if self.swap_bytes {
                    swap_elements(dst, l.element);
                }
            }
        }
        out
    }

    /// Writes the packed `w × h × d` image `packed` into the client image
    /// at `dst` (its bytes from the image's address on): only its pixels'
    /// bytes, those past the end of `dst` dropped.
    pub fn scatter(
        &self,
        packed: &[u8],
        dst: &mut [u8],
        [w, h, d]: [usize; 3],
        volume: bool,
        format: u32,
        ty: u32,
    ) {
        let Some(l) = self.layout(w, h, volume, format, ty) else {
            return;
        };
        let packed_row = row_stride(w, format, ty, self.alignment);
        let bytes = w * l.group;
        let mut row = vec![0u8; bytes];
        for k in 0..d {
            for j in 0..h {
                let from = (k * h + j) * packed_row;
                let Some(src) = packed.get(from..from + bytes) else {
                    return;
                };
                row.copy_from_slice(src);
                if self.swap_bytes {
                    swap_elements(&mut row, l.element);
                }
                let to = l
                    .first
                    .saturating_add(k.saturating_mul(l.image))
                    .saturating_add(j.saturating_mul(l.row));
                if let Some(out) = dst.get_mut(to..) {
                    let n = out.len().min(bytes);
                    out[..n].copy_from_slice(&row[..n]);
                }
            }
        }
    }

    /// Bytes per row of a client bitmap (one bit per pixel, rows padded
    /// to the alignment: §3.6.4 with `s` below `a`).
    fn bitmap_row(&self, w: usize) -> usize {
        let length = if self.row_length > 0 {
            self.row_length
        } else {
            w
        };
        bitmap_row_bytes(length, self.alignment)
    }

    /// The bytes of client memory a `w × h` bitmap spans from its address
    /// (None: empty, or past the address space).
    pub fn bitmap_extent(&self, w: usize, h: usize) -> Option<usize> {
        if w == 0 || h == 0 {
            return None;
        }
        let row = self.bitmap_row(w);
        self.skip_rows
            .checked_add(h - 1)?
            .checked_mul(row)?
            .checked_add(self.skip_pixels.checked_add(w)?.div_ceil(8))
    }

    /// The bit of pixel `i` of a client bitmap row: its byte, and its mask
    /// in the bit order GL_*_LSB_FIRST chooses (SKIP_PIXELS skips bits).
    fn bitmap_bit(&self, i: usize) -> (usize, u8) {
        let b = self.skip_pixels.saturating_add(i);
        let mask = match self.lsb_first {
            true => 1u8 << (b % 8),
            false => 0x80u8 >> (b % 8),
        };
        (b / 8, mask)
    }

    /// The packed `w × h` bitmap (most significant bit first, rows at the
    /// alignment) of a client bitmap read from `src` (short: zero bits).
    pub fn gather_bitmap(&self, src: &[u8], w: usize, h: usize) -> Vec<u8> {
        let packed_row = bitmap_row_bytes(w, self.alignment);
        let row = self.bitmap_row(w);
        let mut out = vec![0u8; packed_row * h];
        for j in 0..h {
            let base = self.skip_rows.saturating_add(j).saturating_mul(row);
            for i in 0..w {
                let (byte, mask) = self.bitmap_bit(i);
                if src
                    .get(base.saturating_add(byte))
                    .is_some_and(|b| b & mask != 0)
                {
                    out[j * packed_row + i / 8] |= 0x80 >> (i % 8);
                }
            }
        }
        out
    }

    /// Writes the packed `w × h` bitmap `packed` into the client bitmap
    /// at `dst`: only its pixels' bits.
    pub fn scatter_bitmap(&self, packed: &[u8], dst: &mut [u8], w: usize, h: usize) {
        let packed_row = bitmap_row_bytes(w, self.alignment);
        let row = self.bitmap_row(w);
        for j in 0..h {
            let base = self.skip_rows.saturating_add(j).saturating_mul(row);
            for i in 0..w {
                let set = packed
                    .get(j * packed_row + i / 8)
                    .is_some_and(|b| b & (0x80 >> (i % 8)) != 0);
                let (byte, mask) = self.bitmap_bit(i);
                if let Some(out) = dst.get_mut(base.saturating_add(byte)) {
                    *out = if set { *out | mask } else { *out & !mask };
                }
            }
        }
    }
}

/// Reverses the bytes of each `size`-byte element of `bytes`
/// (GL_*_SWAP_BYTES; one-byte elements stay).
fn swap_elements(bytes: &mut [u8], size: usize) {
    if size > 1 {
        for e in bytes.chunks_exact_mut(size) {
            e.reverse();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::enums::*;

    #[test]
    fn default_modes_are_the_packed_layout() {
        let s = PixelStore::default();
        assert!(s.is_packed());
        assert!(PixelStore { alignment: 1, ..s }.is_packed());
        assert!(!PixelStore { row_length: 3, ..s }.is_packed());
        // 3 RGB bytes per pixel, 2 pixels: rows of 6 padded to 8.
        let src: Vec<u8> = (0..16).collect();
        let out = s.gather(&src, [2, 2, 1], false, GL_RGB, GL_UNSIGNED_BYTE);
        assert_eq!(out, [0, 1, 2, 3, 4, 5, 0, 0, 8, 9, 10, 11, 12, 13, 0, 0]);
        assert_eq!(
            s.image_extent([2, 2, 1], false, GL_RGB, GL_UNSIGNED_BYTE),
            Some(14)
        );
    }

    #[test]
    fn row_length_and_skips_select_a_sub_rectangle() {
        // A 4x3 RGBA8 client image; read the 2x2 block at (1, 1).
        let s = PixelStore {
            row_length: 4,
            skip_rows: 1,
            skip_pixels: 1,
            ..PixelStore::default()
        };
        let src: Vec<u8> = (0..48).collect();
        let out = s.gather(&src, [2, 2, 1], false, GL_RGBA, GL_UNSIGNED_BYTE);
        let px = |x: u8, y: u8| {
            let b = (y * 4 + x) * 4;
            [b, b + 1, b + 2, b + 3]
        };
        let want: Vec<u8> = [px(1, 1), px(2, 1), px(1, 2), px(2, 2)].concat();
        assert_eq!(out, want);
        assert_eq!(
            s.image_extent([2, 2, 1], false, GL_RGBA, GL_UNSIGNED_BYTE),
            Some(4 * 4 * 2 + 4 * 3)
        );
        // Writing it back touches those 16 bytes only.
        let mut dst = vec![0xAAu8; 48];
        s.scatter(&want, &mut dst, [2, 2, 1], false, GL_RGBA, GL_UNSIGNED_BYTE);
        for (i, b) in dst.iter().enumerate() {
            let (x, y) = ((i / 4) % 4, i / 16);
            let inside = (1..3).contains(&x) && (1..3).contains(&y);
            assert_eq!(*b == 0xAA, !inside, "byte {i}");
        }
    }

    #[test]
    fn alignment_pads_rows_of_the_row_length() {
        // Row length 3 of one-byte pixels at alignment 4: rows of 4 bytes,
        // the packed rows of 2 pixels also padded to 4.
        let s = PixelStore {
            row_length: 3,
            ..PixelStore::default()
        };
        let src = [1, 2, 3, 0, 4, 5, 6, 0];
        let out = s.gather(&src, [2, 2, 1], false, GL_ALPHA, GL_UNSIGNED_BYTE);
        assert_eq!(out, [1, 2, 0, 0, 4, 5, 0, 0]);
        // Components of 4 bytes are not padded at alignment 4 or less.
        let f = PixelStore { row_length: 3, ..s };
        assert_eq!(
            f.image_extent([1, 2, 1], false, GL_ALPHA, GL_FLOAT),
            Some(12 + 4)
        );
    }

    #[test]
    fn image_modes_apply_to_volumes_only() {
        let s = PixelStore {
            image_height: 3,
            skip_images: 1,
            alignment: 1,
            ..PixelStore::default()
        };
        // 1x2x2 luminance volume in images of 3 rows, the first skipped.
        let src: Vec<u8> = (0..9).collect();
        let out = s.gather(&src, [1, 2, 2], true, GL_LUMINANCE, GL_UNSIGNED_BYTE);
        assert_eq!(out, [3, 4, 6, 7]);
        let flat = s.gather(&src, [1, 2, 1], false, GL_LUMINANCE, GL_UNSIGNED_BYTE);
        assert_eq!(flat, [0, 1]);
    }

    #[test]
    fn swap_bytes_reverses_each_element() {
        let s = PixelStore {
            swap_bytes: true,
            ..PixelStore::default()
        };
        let src = [1, 2, 3, 4, 5, 6, 7, 8];
        assert_eq!(
            s.gather(
                &src,
                [2, 1, 1],
                false,
                GL_LUMINANCE_ALPHA,
                GL_UNSIGNED_SHORT
            ),
            [2, 1, 4, 3, 6, 5, 8, 7]
        );
        assert_eq!(
            s.gather(&src, [2, 1, 1], false, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8),
            [4, 3, 2, 1, 8, 7, 6, 5]
        );
        assert_eq!(
            s.gather(&src[..4], [4, 1, 1], false, GL_RED, GL_UNSIGNED_BYTE),
            [1, 2, 3, 4]
        );
        let mut dst = [0u8; 8];
        s.scatter(&src, &mut dst, [1, 1, 1], false, GL_RG, GL_FLOAT);
        assert_eq!(dst, [4, 3, 2, 1, 8, 7, 6, 5]);
    }

    #[test]
    fn bitmaps_in_either_bit_order_with_skipped_bits() {
        // The heart of piglit's gl-1.0-bitmap-heart-dance: bottom row
        // first, least significant bit leftmost.
        let heart = [0x00u8, 0x10, 0x38, 0x7C, 0xFE, 0xFE, 0xEE, 0x44];
        let lsb = PixelStore {
            lsb_first: true,
            alignment: 1,
            ..PixelStore::default()
        };
        let packed = lsb.gather_bitmap(&heart, 8, 8);
        assert_eq!(packed, [0x00, 0x08, 0x1C, 0x3E, 0x7F, 0x7F, 0x77, 0x22]);
        let msb = PixelStore {
            alignment: 1,
            ..PixelStore::default()
        };
        assert_eq!(msb.gather_bitmap(&heart, 8, 8), heart);
        // Skipping 3 pixels of a 16-bit row, most significant bit first.
        let skip = PixelStore {
            skip_pixels: 3,
            alignment: 1,
            ..PixelStore::default()
        };
        assert_eq!(
            skip.gather_bitmap(&[0b0001_1111, 0b1100_0000], 5, 1),
            [0b1111_1000]
        );
        assert_eq!(skip.bitmap_extent(5, 1), Some(1));
        assert_eq!(skip.bitmap_extent(6, 1), Some(2));
        // And back.
        let mut dst = [0u8; 8];
        lsb.scatter_bitmap(&packed, &mut dst, 8, 8);
        assert_eq!(dst, heart);
    }

    #[test]
    fn extents_overflow_to_none() {
        let s = PixelStore {
            skip_rows: usize::MAX / 2,
            ..PixelStore::default()
        };
        assert_eq!(s.image_extent([4, 4, 1], false, GL_RGBA, GL_FLOAT), None);
        assert_eq!(s.bitmap_extent(8, 8), None);
        assert_eq!(
            PixelStore::default().image_extent([0, 4, 1], false, GL_RGBA, GL_FLOAT),
            None
        );
    }
}
