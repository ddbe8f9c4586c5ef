//! Pixel probes: piglit's tolerance and comparison rules, and the
//! coordinate arithmetic of the commands that take window fractions.
//!
//! piglit's `piglit_tolerance` starts at 0.01 for each of R, G, B, A (the
//! window system framework never changes it; only the `tolerance` command
//! does). A probe passes when, for every compared channel,
//! `|observed - expected| <= tolerance` in single precision, where
//! `observed` is the pixel read back with `glReadPixels(GL_FLOAT)` (for an
//! RGBA8 buffer, `byte / 255`).
//!
//! piglit has a second path for rectangle probes, taken when the driver
//! exposes `GL_ARB_framebuffer_object` and the read buffer has at most 8
//! bits per channel: it compares bytes, the expected byte being
//! `(GLubyte)(expected * 255)` (truncated) and the tolerance
//! `ceil(0.01 * 255) = 3`. shaderbox exposes no extensions, so piglit's
//! `shader_runner` would take the float path on it for every probe, and so
//! does this one ([`ProbeMode::Float`]); [`ProbeMode::Ubyte`] is there to
//! compare with drivers that take the byte path.
//!
//! Depth probes pass when `|observed - expected| < 0.01` (strictly).

/// piglit's initial `piglit_tolerance`.
pub const DEFAULT_TOLERANCE: [f32; 4] = [0.01; 4];

/// Which comparison rectangle probes use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProbeMode {
    /// Floats read back, compared with the float tolerance.
    Float,
    /// Bytes read back, compared with the tolerance rounded up to bytes.
    Ubyte,
}

/// `piglit_compare_pixels_float`: every channel within its tolerance.
pub fn pixel_matches(observed: &[f32], expected: &[f32], tolerance: &[f32; 4]) -> bool {
    observed
        .iter()
        .zip(expected)
        .zip(tolerance)
        .all(|((o, e), t)| (o - e).abs() <= *t)
}

/// The byte comparison of piglit's rectangle probes on 8-bit buffers.
pub fn pixel_matches_ubyte(observed: &[u8], expected: &[f32], tolerance: &[f32; 4]) -> bool {
    observed
        .iter()
        .zip(expected)
        .zip(tolerance)
        .all(|((&o, &e), &t)| {
            let tol = (t * 255.0).ceil() as u8 as i32;
            let exp = float_to_ubyte_truncating(e) as i32;
            (i32::from(o) - exp).abs() <= tol
        })
}

/// C's `(GLubyte)(f * 255)` for values in range; out-of-range values (for
/// which C's conversion is undefined) saturate.
fn float_to_ubyte_truncating(f: f32) -> u8 {
    (f * 255.0) as u8
}

/// `piglit_probe_pixel_depth`.
pub fn depth_matches(observed: f32, expected: f32) -> bool {
    f64::from(observed - expected).abs() < 0.01
}

/// The window coordinate of a `relative probe` fraction: `(int)(r * size)`,
/// clamped to the last pixel when it reaches `size` (not below 0, as piglit).
pub fn relative_coord(r: f32, size: i32) -> i32 {
    let v = (r * size as f32) as i32;
    if v >= size {
        size - 1
    } else {
        v
    }
}

/// The window coordinate of a `relative probe rect` fraction (no clamp).
pub fn relative_extent(r: f32, size: i32) -> i32 {
    (r * size as f32) as i32
}

/// `draw rect ortho X Y W H`: the rectangle in normalized device
/// coordinates, computed as piglit does (the quotient in single precision,
/// the rest in double, the result rounded to single).
pub fn ortho_rect(rect: [f32; 4], width: i32, height: i32) -> [f32; 4] {
    let (w, h) = (width as f32, height as f32);
    [
        (-1.0 + 2.0 * f64::from(rect[0] / w)) as f32,
        (-1.0 + 2.0 * f64::from(rect[1] / h)) as f32,
        (2.0 * f64::from(rect[2] / w)) as f32,
        (2.0 * f64::from(rect[3] / h)) as f32,
    ]
}

/// The four corners of `piglit_draw_rect` (a triangle strip): (x, y),
/// (x + w, y), (x, y + h), (x + w, y + h), each with z = 0 and w = 1.
pub fn rect_vertices(rect: [f32; 4]) -> [f32; 16] {
    let [x, y, w, h] = rect;
    [
        x,
        y,
        0.0,
        1.0,
        x + w,
        y,
        0.0,
        1.0,
        x,
        y + h,
        0.0,
        1.0,
        x + w,
        y + h,
        0.0,
        1.0,
    ]
}

/// The texture coordinates of `piglit_draw_rect_tex` for the same corners.
pub fn rect_texcoords(tex: [f32; 4]) -> [f32; 8] {
    let [tx, ty, tw, th] = tex;
    [tx, ty, tx + tw, ty, tx, ty + th, tx + tw, ty + th]
}

/// piglit's `Probe color at (x,y)` report (`%f` has 6 decimals).
pub fn report(x: i32, y: i32, expected: &[f32], observed: &[f32]) -> String {
    let list = |v: &[f32]| v.iter().map(|c| format!(" {c:.6}")).collect::<String>();
    format!(
        "Probe color at ({x},{y})\n  Expected:{}\n  Observed:{}",
        list(expected),
        list(observed)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn byte(b: u8) -> f32 {
        f32::from(b) / 255.0
    }

    #[test]
    fn float_tolerance_is_inclusive_and_per_channel() {
        let t = DEFAULT_TOLERANCE;
        assert!(pixel_matches(&[0.5, 0.0, 1.0], &[0.5, 0.0, 1.0], &t));
        // 0.5 expected: bytes 125..=130 pass (|b/255 - 0.5| <= 0.01).
        assert!(!pixel_matches(&[byte(124)], &[0.5], &t));
        assert!(pixel_matches(&[byte(125)], &[0.5], &t));
        assert!(pixel_matches(&[byte(130)], &[0.5], &t));
        assert!(!pixel_matches(&[byte(131)], &[0.5], &t));
        // 1.0 expected: 253 passes (0.00784), 252 does not (0.01176).
        assert!(pixel_matches(&[byte(253)], &[1.0], &t));
        assert!(!pixel_matches(&[byte(252)], &[1.0], &t));
        // Only the channels given are compared (rgb probes).
        assert!(pixel_matches(&[0.0, 0.0, 0.0, 0.7], &[0.0, 0.0, 0.0], &t));
        assert!(!pixel_matches(
            &[0.0, 0.0, 0.0, 0.7],
            &[0.0, 0.0, 0.0, 1.0],
            &t
        ));
        // NaN never matches.
        assert!(!pixel_matches(&[f32::NAN], &[0.0], &t));
        // Per-channel tolerance.
        assert!(pixel_matches(
            &[0.2, 0.0],
            &[0.0, 0.0],
            &[0.25, 0.01, 0.01, 0.01]
        ));
        assert!(!pixel_matches(
            &[0.0, 0.2],
            &[0.0, 0.0],
            &[0.25, 0.01, 0.01, 0.01]
        ));
    }

    #[test]
    fn ubyte_path_truncates_and_rounds_tolerance_up() {
        let t = DEFAULT_TOLERANCE;
        // expected 0.5 -> 127 (truncated), tolerance 3: 124..=130.
        assert!(pixel_matches_ubyte(&[124], &[0.5], &t));
        assert!(pixel_matches_ubyte(&[130], &[0.5], &t));
        assert!(!pixel_matches_ubyte(&[123], &[0.5], &t));
        assert!(!pixel_matches_ubyte(&[131], &[0.5], &t));
        assert!(pixel_matches_ubyte(&[252], &[1.0], &t));
    }

    #[test]
    fn depth_is_strict() {
        assert!(depth_matches(0.5, 0.5));
        assert!(depth_matches(0.509, 0.5));
        assert!(!depth_matches(0.52, 0.5));
    }

    #[test]
    fn relative_coordinates() {
        assert_eq!(relative_coord(0.5, 250), 125);
        assert_eq!(relative_coord(1.0, 250), 249);
        assert_eq!(relative_coord(0.999, 250), 249);
        assert_eq!(relative_coord(0.25, 250), 62);
        assert_eq!(relative_coord(0.0, 250), 0);
        assert_eq!(relative_extent(0.5, 250), 125);
    }

    #[test]
    fn ortho_rectangles() {
        assert_eq!(
            ortho_rect([0., 0., 250., 250.], 250, 250),
            [-1., -1., 2., 2.]
        );
        assert_eq!(
            ortho_rect([125., 0., 125., 125.], 250, 250),
            [0., -1., 1., 1.]
        );
        // 10/250 = 0.04 in single precision, then doubled in double.
        let r = ortho_rect([10., 20., 5., 5.], 250, 250);
        assert_eq!(r[0], (-1.0 + 2.0 * f64::from(10.0f32 / 250.0)) as f32);
        assert_eq!(r[2], (2.0 * f64::from(5.0f32 / 250.0)) as f32);
    }

    #[test]
    fn rect_corners() {
        let v = rect_vertices([-1., -1., 2., 2.]);
        assert_eq!(&v[..4], &[-1., -1., 0., 1.]);
        assert_eq!(&v[4..8], &[1., -1., 0., 1.]);
        assert_eq!(&v[8..12], &[-1., 1., 0., 1.]);
        assert_eq!(&v[12..], &[1., 1., 0., 1.]);
        assert_eq!(
            rect_texcoords([0., 0., 1., 1.]),
            [0., 0., 1., 0., 0., 1., 1., 1.]
        );
    }

    #[test]
    fn reports() {
        assert_eq!(
            report(1, 2, &[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0]),
            "Probe color at (1,2)\n  Expected: 1.000000 0.000000 0.000000\n  Observed: 0.000000 1.000000 0.000000"
        );
    }
}
