use super::levels::{floor, fract, lod_log2};
use super::*;
use glsl::math;

/// `lod_log2` is exact at powers of two (normal and subnormal), within
/// 2·10⁻⁷ plus one step of the result of log2 elsewhere, and gives
/// log2's special values.
#[test]
fn lod_log2_is_close_and_exact_at_powers_of_two() {
    for n in -149..=127 {
        let x = 2f64.powi(n) as f32;
        assert_eq!(lod_log2(x), n as f32, "2^{n}");
    }
    let mut seed = 0x1d0f_u32;
    for i in 0..200_000u32 {
        seed = crate::lcg_step(seed);
        let x = match i % 3 {
            // Every positive float's bits, and the magnitudes of
            // derivatives scaled by texture sizes.
            0 => f32::from_bits(seed >> 1),
            1 => (seed >> 8) as f32 / 16_777_216.0 * 4096.0,
            _ => 1.0 + (seed >> 8) as f32 / 16_777_216.0 / 64.0,
        };
        if !x.is_finite() || x <= 0.0 {
            continue;
        }
        let want = (x as f64).log2();
        let got = lod_log2(x) as f64;
        let step = f32::EPSILON as f64 * want.abs().max(1.0);
        assert!((got - want).abs() <= 2e-7 + step, "{x:e}: {got} vs {want}");
    }
    assert_eq!(lod_log2(0.0), f32::NEG_INFINITY);
    assert_eq!(lod_log2(-0.0), f32::NEG_INFINITY);
    assert_eq!(lod_log2(f32::INFINITY), f32::INFINITY);
    assert!(lod_log2(f32::NAN).is_nan());
    assert!(lod_log2(-1.0).is_nan());
}

/// The padded copy appends column 0 / row 0 (REPEAT) or the last
/// column / row again (CLAMP_TO_EDGE); it is built for one pair of
/// wrap modes (others get none), not for f32 levels, and a clone
/// builds its own.
#[test]
fn padded_copy_holds_the_wrap_neighbours() {
    // Texel (i, j) of a 3 × 2 level is (10j + i) / 255 in red.
    let texels = (0..6)
        .map(|n| [(10 * (n / 3) + n % 3) as f32 / 255.0, 0.0, 0.0, 1.0])
        .collect();
    let img = Image::new(3, 2, 1, texels);
    let red = |p: &[[u8; 4]]| p.iter().map(|t| t[0]).collect::<Vec<_>>();
    let rep = [Wrap::Repeat, Wrap::Repeat];
    assert_eq!(
        red(img.padded(rep).unwrap()),
        [0, 1, 2, 0, 10, 11, 12, 10, 0, 1, 2, 0]
    );
    assert!(img.padded([Wrap::ClampToEdge; 2]).is_none());
    let other = img.clone();
    let mixed = [Wrap::ClampToEdge, Wrap::Repeat];
    assert_eq!(
        red(other.padded(mixed).unwrap()),
        [0, 1, 2, 2, 10, 11, 12, 12, 0, 1, 2, 2]
    );
    let clamp = [Wrap::Repeat, Wrap::ClampToEdge];
    let third = img.clone();
    assert_eq!(
        red(third.padded(clamp).unwrap()),
        [0, 1, 2, 0, 10, 11, 12, 10, 10, 11, 12, 10]
    );
    let float = Image::new(1, 1, 1, vec![[0.3, 0.0, 0.0, 1.0]]);
    assert!(float.padded(rep).is_none());
    assert!(img
        .clone()
        .padded([Wrap::MirroredRepeat, Wrap::Repeat])
        .is_none());
}

#[test]
fn fast_floor_is_exact() {
    let mut values = vec![
        0.0f32,
        -0.0,
        0.5,
        -0.5,
        1.0,
        -1.0,
        8_388_607.5,
        -8_388_607.5,
        8_388_608.0,
        -8_388_609.0,
        1e30,
        -1e30,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MIN_POSITIVE,
        -f32::MIN_POSITIVE,
        1e-45,
        -1e-45,
    ];
    let mut bits = 0x1234_5678u32;
    for _ in 0..100_000 {
        bits = crate::lcg_step(bits);
        values.push(f32::from_bits(bits));
        values.push((bits >> 8) as f32 / 4096.0 - 2048.0);
    }
    for x in values {
        assert_eq!(floor(x).to_bits(), math::floor(x).to_bits(), "floor({x:e})");
        assert_eq!(fract(x).to_bits(), math::fract(x).to_bits(), "fract({x:e})");
    }
    assert!(floor(f32::NAN).is_nan());
}

/// `Texture::last_level` as it was first written (every axis of every
/// level compared through `size`), the reference for the faster one.
fn last_level_reference(tex: &Texture) -> Option<usize> {
    let base = tex.base_level as usize;
    if tex.base_level > tex.max_level {
        return None;
    }
    let b = tex.levels.get(base)?;
    let dims = [tex.size(b, 0), tex.size(b, 1), tex.size(b, 2)];
    let ok = |img: &Image, want: [u32; 3]| {
        let have = [tex.size(img, 0), tex.size(img, 1), tex.size(img, 2)];
        have == want && img.len() == img.width as usize * img.height as usize * img.depth as usize
    };
    if dims.contains(&0) || !ok(b, dims) {
        return None;
    }
    if tex.target == TextureTarget::Cube && b.width != b.height {
        return None;
    }
    if !tex.mipmapped() {
        return Some(base);
    }
    let largest = dims[..tex.dims()].iter().copied().max().unwrap_or(1);
    let p = base + (31 - largest.leading_zeros()) as usize;
    let q = p.min(tex.max_level as usize);
    for (i, level) in (base + 1..=q).enumerate() {
        let shift = (i + 1) as u32;
        let mut want = dims.map(|d| (d >> shift).max(1));
        for (a, w) in want.iter_mut().enumerate() {
            if a >= tex.dims() {
                *w = dims[a];
            }
        }
        if !ok(tex.levels.get(level)?, want) {
            return None;
        }
    }
    Some(q)
}

#[test]
fn last_level_matches_the_reference() {
    let mut seed = 0x2545_f491_u32;
    let mut rnd = move |n: u32| {
        seed = crate::lcg_step(seed);
        (seed >> 8) % n
    };
    let mut complete = 0;
    for round in 0..4000 {
        let target = [
            TextureTarget::Tex1D,
            TextureTarget::Tex2D,
            TextureTarget::Tex3D,
            TextureTarget::Cube,
        ][round % 4];
        let (mut w, mut h, mut d): (u32, u32, u32) = (1 << rnd(5), 1 << rnd(5), 1 << rnd(3));
        match target {
            TextureTarget::Tex1D => h = [1, 1, 2][rnd(3) as usize],
            TextureTarget::Tex2D => d = [1, 1, 1, 0, 2][rnd(5) as usize],
            TextureTarget::Cube => (h, d) = (if rnd(8) == 0 { h } else { w }, 6),
            // Only the four targets above are drawn.
            _ => {}
        }
        let mut levels = Vec::new();
        for _ in 0..rnd(8) + 1 {
            let (mut lw, mut lh, mut ld) = (w, h, d);
            // Now and then a wrong size or too few texels.
            match rnd(12) {
                0 => lw += 1,
                1 => lh = lh.saturating_sub(1),
                2 => ld += 1,
                _ => {}
            }
            let mut n = (lw * lh * ld) as usize;
            if rnd(16) == 0 {
                n = n.saturating_sub(1);
            }
            let mut img = Image::new(lw, lh, ld, vec![[0.5; 4]; n]);
            img.depth = ld;
            levels.push(img);
            w = (w / 2).max(1);
            if target != TextureTarget::Tex1D {
                h = (h / 2).max(1);
            }
            if target == TextureTarget::Tex3D {
                d = (d / 2).max(1);
            }
        }
        let mut tex = Texture::new(target, levels);
        tex.min_filter = [MinFilter::Linear, MinFilter::LinearMipmapLinear][rnd(2) as usize];
        tex.base_level = rnd(3);
        tex.max_level = [1000, rnd(6)][rnd(2) as usize];
        let want = last_level_reference(&tex);
        assert_eq!(tex.last_level(), want, "{tex:?}");
        complete += usize::from(want.is_some());
    }
    assert!(complete > 400, "{complete} complete");
}

/// One-channel integer levels keep 16 bits of red when every texel fits
/// (zero-extended, or sign-extended when some red is negative) and read
/// back bit for bit; anything else stays f32.
#[test]
fn red16_levels_keep_the_texels_bits() {
    let texel = |r: u32, a: u32| [r, 0, 0, a].map(f32::from_bits);
    let cases: [(Vec<[f32; 4]>, Option<bool>); 5] = [
        (
            vec![texel(0, 1), texel(65535, 1), texel(300, 1)],
            Some(false),
        ),
        (
            vec![
                texel(-2i32 as u32, 1),
                texel(32767, 1),
                texel(-32768i32 as u32, 1),
            ],
            Some(true),
        ),
        // Red past 16 bits either way.
        (vec![texel(65536, 1), texel(1, 1)], None),
        (vec![texel(-1i32 as u32, 1), texel(40000, 1)], None),
        // Alpha not the same everywhere.
        (vec![texel(5, 1), texel(6, 2)], None),
    ];
    for (texels, want) in cases {
        let img = Image::new(texels.len() as u32, 1, 1, texels.clone());
        match (&img.texels, want) {
            (Texels::Red16(r), Some(signed)) => assert_eq!(r.signed, signed),
            (Texels::F32(_), None) => {}
            (t, _) => panic!("{t:?} for {want:?}"),
        }
        for (i, t) in texels.iter().enumerate() {
            assert_eq!(img.texel_at(i).map(f32::to_bits), t.map(f32::to_bits));
        }
        assert_eq!(
            img.texel_at(texels.len()).map(f32::to_bits),
            MISSING.map(f32::to_bits)
        );
    }
}
