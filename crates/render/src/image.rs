//! RGBA8 images: the box filter of supersampled renders, and PNG output.

use std::io::Write;
use thiserror::Error;

/// An 8-bit RGBA image, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    /// `width * height` pixels, top row first.
    pub pixels: Vec<[u8; 4]>,
    /// Whether alpha matters (transparent background): PNG gets RGBA,
    /// else RGB.
    pub has_alpha: bool,
}

/// PNG encoding failed.
#[derive(Debug, Error)]
#[error("cannot write PNG: {0}")]
pub struct PngError(String);

fn to_u8(v: f32) -> u8 {
    // NaN maps to 0 (clamp keeps NaN; the cast saturates NaN to 0).
    (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Box-filters `pixels` (`fw` x `fh`, bottom row first, as glReadPixels
/// returns them) by `ss` x `ss` blocks into an image of `fw/ss` x `fh/ss`,
/// top row first. With `alpha`, colours are averaged weighted by alpha
/// (so a transparent background does not darken edges).
pub fn downsample(pixels: &[[f32; 4]], fw: u32, fh: u32, ss: u32, alpha: bool) -> Image {
    let ss = ss.max(1);
    let (w, h) = (fw / ss, fh / ss);
    let mut out = Vec::with_capacity((w as usize) * (h as usize));
    let n = (ss * ss) as f32;
    for oy in 0..h {
        // Output row oy (from the top) covers framebuffer rows counted
        // from the bottom: fh - (oy + 1) * ss .. fh - oy * ss.
        let y0 = fh - (oy + 1) * ss;
        for ox in 0..w {
            let mut sum = [0.0f32; 4];
            for sy in 0..ss {
                for sx in 0..ss {
                    let i = ((y0 + sy) as usize) * (fw as usize) + (ox * ss + sx) as usize;
                    let p = pixels.get(i).copied().unwrap_or([0.0; 4]);
                    let wgt = if alpha { p[3] } else { 1.0 };
                    for k in 0..3 {
                        sum[k] += p[k] * wgt;
                    }
                    sum[3] += p[3];
                }
            }
            let px = if alpha {
                let a = sum[3];
                if a > 0.0 {
                    [
                        to_u8(sum[0] / a),
                        to_u8(sum[1] / a),
                        to_u8(sum[2] / a),
                        to_u8(a / n),
                    ]
                } else {
                    [0, 0, 0, 0]
                }
            } else {
                [to_u8(sum[0] / n), to_u8(sum[1] / n), to_u8(sum[2] / n), 255]
            };
            out.push(px);
        }
    }
    Image {
        width: w,
        height: h,
        pixels: out,
        has_alpha: alpha,
    }
}

impl Image {
    /// The pixel at (`x`, `y`), `y` from the top; `None` outside.
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 4]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.pixels
            .get(y as usize * self.width as usize + x as usize)
            .copied()
    }

    /// Encodes the image as PNG (8-bit RGB, or RGBA with alpha).
    pub fn write_png(&self, out: impl Write) -> Result<(), PngError> {
        let mut enc = png::Encoder::new(out, self.width, self.height);
        let data: Vec<u8> = if self.has_alpha {
            enc.set_color(png::ColorType::Rgba);
            self.pixels.iter().flatten().copied().collect()
        } else {
            enc.set_color(png::ColorType::Rgb);
            self.pixels
                .iter()
                .flat_map(|p| [p[0], p[1], p[2]])
                .collect()
        };
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().map_err(|e| PngError(e.to_string()))?;
        writer
            .write_image_data(&data)
            .map_err(|e| PngError(e.to_string()))?;
        writer.finish().map_err(|e| PngError(e.to_string()))
    }

    /// The PNG bytes of the image.
    pub fn to_png(&self) -> Result<Vec<u8>, PngError> {
        let mut v = Vec::new();
        self.write_png(&mut v)?;
        Ok(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_filter_flips_and_averages() {
        // 2x2 framebuffer, bottom row first: bottom white, top black.
        let px = [
            [1.0, 1.0, 1.0, 1.0],
            [1.0, 1.0, 1.0, 1.0],
            [0.0, 0.0, 0.0, 1.0],
            [0.0; 4],
        ];
        let one = downsample(&px, 2, 2, 1, false);
        assert_eq!(
            one.pixel(0, 0),
            Some([0, 0, 0, 255]),
            "top row is the last one read"
        );
        assert_eq!(one.pixel(0, 1), Some([255, 255, 255, 255]));
        let avg = downsample(&px, 2, 2, 2, false);
        assert_eq!((avg.width, avg.height), (1, 1));
        assert_eq!(avg.pixel(0, 0), Some([128, 128, 128, 255]));
        // Alpha-weighted: the transparent sample does not darken.
        let a = downsample(&px, 2, 2, 2, true);
        assert_eq!(a.pixel(0, 0), Some([170, 170, 170, 191]));
    }

    #[test]
    fn png_round_trip() {
        let img = Image {
            width: 2,
            height: 1,
            pixels: vec![[1, 2, 3, 4], [5, 6, 7, 8]],
            has_alpha: true,
        };
        let bytes = img.to_png().unwrap();
        let dec = png::Decoder::new(&bytes[..]);
        let mut r = dec.read_info().unwrap();
        let mut buf = vec![0; r.output_buffer_size()];
        let info = r.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (2, 1));
        assert_eq!(&buf[..8], &[1, 2, 3, 4, 5, 6, 7, 8]);
    }
}
