//! The texel images of the `texture` commands, as piglit's utility library
//! builds them (RGBA floats, rows bottom to top).

/// piglit's color wheel: red, green, blue, white.
pub const COLOR_WHEEL: [[f32; 4]; 4] = [
    [1.0, 0.0, 0.0, 1.0],
    [0.0, 1.0, 0.0, 1.0],
    [0.0, 0.0, 1.0, 1.0],
    [1.0, 1.0, 1.0, 1.0],
];

/// `piglit_rgbw_image` (opaque, unsigned normalized): the lower-left
/// quadrant red, lower-right green, upper-left blue, upper-right white
/// (`x < w / 2`, `y < h / 2` in integer division).
pub fn rgbw(width: u32, height: u32) -> Vec<f32> {
    let (w, h) = (width as usize, height as usize);
    let mut out = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let c = if x < w / 2 && y < h / 2 {
                COLOR_WHEEL[0]
            } else if y < h / 2 {
                COLOR_WHEEL[1]
            } else if x < w / 2 {
                COLOR_WHEEL[2]
            } else {
                COLOR_WHEEL[3]
            };
            out.extend_from_slice(&c);
        }
    }
    out
}

/// The 4-texel 1D rgbw texture: red, green, blue, white.
pub fn rgbw_1d() -> Vec<f32> {
    COLOR_WHEEL.concat()
}

/// The 2x2x2 rgbw 3D texture: red, green, blue, white, yellow, magenta,
/// cyan, black.
pub fn rgbw_3d() -> Vec<f32> {
    [
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [1.0, 1.0, 1.0, 1.0],
        [1.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, 1.0, 1.0],
        [0.0, 1.0, 1.0, 1.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
    .concat()
}

/// `piglit_quads_texture`: tiles of `square` texels; rows of tiles alternate
/// starting with the bottom row (`bl`, `br`, `bl`, ...), odd tile rows use
/// `tl`, `tr`.
pub fn quads(width: u32, height: u32, square: [u32; 2], colors: [[f32; 4]; 4]) -> Vec<f32> {
    let [bl, br, tl, tr] = colors;
    let (sx, sy) = (square[0].max(1), square[1].max(1));
    let mut out = Vec::with_capacity(width as usize * height as usize * 4);
    for i in 0..height {
        let row = i / sy;
        for j in 0..width {
            let col = j / sx;
            let c = match (row & 1 == 1, col & 1 == 1) {
                (true, true) => tr,
                (true, false) => tl,
                (false, true) => br,
                (false, false) => bl,
            };
            out.extend_from_slice(&c);
        }
    }
    out
}

/// `piglit_checkerboard_texture`: squares of half the size, `black` at the
/// lower left.
pub fn checkerboard(width: u32, height: u32, black: [f32; 4], white: [f32; 4]) -> Vec<f32> {
    quads(
        width,
        height,
        [width / 2, height / 2],
        [black, white, white, black],
    )
}

/// The levels of `piglit_miptree_texture`: 8x8, 4x4, 2x2, 1x1, each a solid
/// color of the wheel.
pub fn miptree() -> Vec<(u32, Vec<f32>)> {
    (0..4)
        .map(|level| {
            let size = 8u32 >> level;
            let texels = (size * size) as usize;
            (size, COLOR_WHEEL[level].repeat(texels))
        })
        .collect()
}

/// `piglit_array_texture` level 0: `layers` layers of `width × height`
/// texels, layer k solid in colour k of red, green, blue, white (cycling).
pub fn array_layers(width: u32, height: u32, layers: u32) -> Vec<f32> {
    let n = width as usize * height as usize;
    let mut out = Vec::with_capacity(n * layers as usize * 4);
    for k in 0..layers as usize {
        for _ in 0..n {
            out.extend_from_slice(&COLOR_WHEEL[k % COLOR_WHEEL.len()]);
        }
    }
    out
}

/// `piglit_depth_texture` level 0: depth `x / (w - 1)` in single precision
/// (a 1-texel-wide image divides 0 by 0, as piglit does).
pub fn depth_gradient(width: u32, height: u32) -> Vec<f32> {
    let w = width as usize;
    let denom = width as f32 - 1.0;
    let mut out = Vec::with_capacity(w * height as usize);
    for _ in 0..height {
        for x in 0..w {
            out.push(x as f32 / denom);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texel(img: &[f32], w: u32, x: u32, y: u32) -> [f32; 4] {
        let i = ((y * w + x) * 4) as usize;
        [img[i], img[i + 1], img[i + 2], img[i + 3]]
    }

    #[test]
    fn rgbw_quadrants() {
        let img = rgbw(4, 4);
        assert_eq!(img.len(), 64);
        assert_eq!(texel(&img, 4, 0, 0), COLOR_WHEEL[0]);
        assert_eq!(texel(&img, 4, 3, 0), COLOR_WHEEL[1]);
        assert_eq!(texel(&img, 4, 0, 3), COLOR_WHEEL[2]);
        assert_eq!(texel(&img, 4, 3, 3), COLOR_WHEEL[3]);
        // Odd sizes: the lower half is rows y < h / 2.
        let img = rgbw(3, 3);
        assert_eq!(texel(&img, 3, 0, 0), COLOR_WHEEL[0]);
        assert_eq!(texel(&img, 3, 1, 0), COLOR_WHEEL[1]);
        assert_eq!(texel(&img, 3, 0, 1), COLOR_WHEEL[2]);
    }

    #[test]
    fn checkerboard_tiles() {
        let b = [0.0, 0.0, 0.0, 1.0];
        let w = [1.0; 4];
        let img = checkerboard(4, 4, b, w);
        assert_eq!(texel(&img, 4, 0, 0), b);
        assert_eq!(texel(&img, 4, 1, 1), b);
        assert_eq!(texel(&img, 4, 2, 0), w);
        assert_eq!(texel(&img, 4, 0, 2), w);
        assert_eq!(texel(&img, 4, 3, 3), b);
    }

    #[test]
    fn mip_levels() {
        let m = miptree();
        assert_eq!(m.len(), 4);
        assert_eq!(m[0].0, 8);
        assert_eq!(m[0].1.len(), 8 * 8 * 4);
        assert_eq!(&m[3].1[..], &COLOR_WHEEL[3]);
        assert_eq!(&m[1].1[..4], &COLOR_WHEEL[1]);
    }

    #[test]
    fn depth_ramp() {
        let d = depth_gradient(5, 2);
        assert_eq!(
            d,
            vec![0.0, 0.25, 0.5, 0.75, 1.0, 0.0, 0.25, 0.5, 0.75, 1.0]
        );
        assert!(depth_gradient(1, 1)[0].is_nan());
    }

    #[test]
    fn small_fixed_images() {
        assert_eq!(rgbw_1d().len(), 16);
        assert_eq!(rgbw_3d().len(), 32);
    }
}
