use super::*;
use super::{color::*, depth::*, quick::*, stencil::*, wide::*};
use crate::framebuffer::{depth_to_fixed, float_to_unorm8, ColorBuffer, ColorFormat};
use crate::state::{
    Blend, BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilFace, StencilOp, StencilState,
};

/// Every instruction set's batch conversion gives `unorm8_lanes`'s
/// bytes, on values in and out of [0, 1], near the rounding points,
/// signed zeros, infinities and NaNs.
#[test]
fn batch_conversion_matches_the_scalar_one() {
    let mut seed = 3u32;
    let special = [
        f32::NAN,
        -f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -0.0,
        0.0,
        1.0,
        1.0 + f32::EPSILON,
        0.5 / 255.0,
        1.5 / 255.0,
        -1e-30,
        1e-45,
    ];
    for round in 0..400 {
        let mut rgba = [[0f32; 16]; 4];
        for (c, lanes) in rgba.iter_mut().enumerate() {
            for (l, x) in lanes.iter_mut().enumerate() {
                seed = crate::lcg_step(seed);
                *x = match (round + l + c) % 5 {
                    0 => special[(seed >> 8) as usize % special.len()],
                    // Near k + 0.5 steps of 1/255.
                    1 => ((seed >> 8) % 256) as f32 / 255.0 + 0.5 / 255.0,
                    _ => (seed >> 8) as f32 / 16_777_216.0 * 1.4 - 0.2,
                };
            }
        }
        let [r, g, b, a] = &rgba;
        let want = unorm8_lanes([r, g, b, a]);
        for isa in [
            crate::simd::Level::Portable,
            crate::simd::Level::Avx2,
            crate::simd::Level::Avx512,
        ] {
            if isa.supported() {
                assert_eq!(unorm8_batch(isa, [r, g, b, a]), want, "{isa:?} {rgba:?}");
            }
        }
    }
}

fn frag(x: u32, y: u32, z: f32, color: [f32; 4]) -> Fragment {
    Fragment {
        x,
        y,
        z,
        back_facing: false,
        colors: [color; FRAG_COLORS],
    }
}

/// The 12×10 RGBA8 tile with depth of the quick-path tests, cleared.
fn tile_under_test() -> Framebuffer {
    let mut fb = Framebuffer::new(12, 10, ColorFormat::Rgba8, true, false);
    fb.clear_color(&[0], [0.2, 0.4, 0.6, 0.8], [true; 4], None);
    fb.clear_depth(0.5, true, None);
    fb
}
#[test]
fn every_blend_factor() {
    let s = [0.5, 0.25, 1.0, 0.75];
    let d = [0.2, 0.4, 0.6, 0.1];
    let k = [0.3, 0.6, 0.9, 0.5];
    use BlendFactor::*;
    // (factor, expected factor value for component 0 and for alpha)
    let cases = [
        (Zero, 0.0, 0.0),
        (One, 1.0, 1.0),
        (SrcColor, 0.5, 0.75),
        (OneMinusSrcColor, 0.5, 0.25),
        (DstColor, 0.2, 0.1),
        (OneMinusDstColor, 0.8, 0.9),
        (SrcAlpha, 0.75, 0.75),
        (OneMinusSrcAlpha, 0.25, 0.25),
        (DstAlpha, 0.1, 0.1),
        (OneMinusDstAlpha, 0.9, 0.9),
        (ConstantColor, 0.3, 0.5),
        (OneMinusConstantColor, 0.7, 0.5),
        (ConstantAlpha, 0.5, 0.5),
        (OneMinusConstantAlpha, 0.5, 0.5),
        (SrcAlphaSaturate, 0.75, 1.0),
    ];
    for (f, fc, fa) in cases {
        let b = Blend {
            src_rgb: f,
            dst_rgb: Zero,
            src_alpha: f,
            dst_alpha: Zero,
            color: k,
            ..Blend::default()
        };
        let out = blend_color(&b, s, d);
        assert_eq!(out[0], 0.5 * fc as f32, "{f:?} rgb");
        assert_eq!(out[3], 0.75 * fa as f32, "{f:?} alpha");
        // Same factor on the destination side.
        let b = Blend {
            src_rgb: Zero,
            dst_rgb: f,
            src_alpha: Zero,
            dst_alpha: f,
            color: k,
            ..Blend::default()
        };
        let out = blend_color(&b, s, d);
        assert_eq!(out[0], 0.2 * fc as f32, "{f:?} dst rgb");
        assert_eq!(out[3], 0.1 * fa as f32, "{f:?} dst alpha");
    }
}

/// The SRC1 factors read the second source colour, on either side; with
/// none (`blend_color`) they read zeros. Through `write_colors`, only
/// output 0 has one.
#[test]
fn src1_factors_read_the_second_colour() {
    use BlendFactor::*;
    let (s, s1, d) = (
        [0.5, 0.25, 1.0, 0.75],
        [0.25, 0.5, 0.75, 0.5],
        [0.2, 0.4, 0.6, 0.1],
    );
    let b = |src, dst| Blend {
        src_rgb: src,
        dst_rgb: dst,
        src_alpha: src,
        dst_alpha: dst,
        ..Blend::default()
    };
    let mix = |fs: [f32; 4], fd: [f32; 4]| -> [f32; 4] {
        std::array::from_fn(|c| s[c] * fs[c] + d[c] * fd[c])
    };
    let cases = [
        (b(Src1Color, Zero), mix(s1, [0.0; 4])),
        (b(One, Src1Color), mix([1.0; 4], s1)),
        (
            b(OneMinusSrc1Color, Src1Alpha),
            mix(s1.map(|x| 1.0 - x), [s1[3]; 4]),
        ),
        (
            b(Src1Alpha, OneMinusSrc1Alpha),
            mix([s1[3]; 4], [1.0 - s1[3]; 4]),
        ),
    ];
    for (blend, want) in cases {
        assert!(blend.uses_src1());
        assert_eq!(blend_dual(&blend, s, s1, d), want, "{blend:?}");
        assert_eq!(
            blend_color(&blend, s, d),
            blend_dual(&blend, s, [0.0; 4], d)
        );
    }
    assert!(!b(SrcAlpha, OneMinusSrcAlpha).uses_src1());

    // Two float draw buffers, ONE / SRC1_COLOR: buffer 0 adds dst · s1,
    // buffer 1 (no second colour) keeps the source alone.
    let mut fb = Framebuffer::with_color_buffers(1, 1, &[ColorFormat::Rgba32F; 2], false, false);
    for buf in fb.color.iter_mut() {
        if let ColorBuffer::Rgba32F(v) = buf {
            v[0] = d;
        }
    }
    let mut state = PipelineState {
        blend: Some(b(One, Src1Color)),
        clamp_fragment_color: false,
        ..PipelineState::default()
    };
    state.draw_buffers[1] = Some(1);
    let mut colors = [[0.0; 4]; FRAG_COLORS];
    colors[0] = s;
    colors[1] = s;
    colors[SRC1] = s1;
    write_colors(&mut fb, 0, &state, &colors);
    assert_eq!(fb.color[0].get(0), mix([1.0; 4], s1));
    assert_eq!(fb.color[1].get(0), s);
}

#[test]
fn every_blend_equation() {
    let s = [0.5, 0.25, 1.0, 0.75];
    let d = [0.2, 0.4, 0.6, 0.1];
    let b = |eq_rgb, eq_a| Blend {
        src_rgb: BlendFactor::One,
        dst_rgb: BlendFactor::One,
        src_alpha: BlendFactor::SrcAlpha,
        dst_alpha: BlendFactor::One,
        equation_rgb: eq_rgb,
        equation_alpha: eq_a,
        color: [0.0; 4],
    };
    use BlendEquation::*;
    let add = blend_color(&b(Add, Add), s, d);
    assert_eq!(add[1], 0.25 + 0.4);
    assert_eq!(add[3], 0.75 * 0.75 + 0.1);
    let sub = blend_color(&b(Subtract, ReverseSubtract), s, d);
    assert_eq!(sub[0], 0.5 - 0.2);
    assert_eq!(sub[3], 0.1 - 0.75 * 0.75);
    let rsub = blend_color(&b(ReverseSubtract, Subtract), s, d);
    assert_eq!(rsub[1], 0.4 - 0.25);
    // MIN/MAX ignore the factors.
    let min = blend_color(&b(Min, Max), s, d);
    assert_eq!(min, [0.2, 0.25, 0.6, 0.75]);
    let max = blend_color(&b(Max, Min), s, d);
    assert_eq!(max, [0.5, 0.4, 1.0, 0.1]);
}

#[test]
fn four_channel_conversions_match() {
    use crate::framebuffer::unorm8_to_float;
    for k in 0..=255u8 {
        assert_eq!((k as f32 / 255.0).to_bits(), unorm8_to_float(k).to_bits());
    }
    let mut values = vec![0.0f32, -0.0, 1.0, 2.0, -1.0, f32::NAN, f32::INFINITY];
    values.extend([f32::NEG_INFINITY, 0.5 / 255.0, 1.5 / 255.0, 254.5 / 255.0]);
    let mut bits = 17u32;
    for _ in 0..200_000 {
        bits = crate::lcg_step(bits);
        values.push(f32::from_bits(bits));
        values.push((bits >> 8) as f32 / 16_777_216.0 * 1.2 - 0.1);
    }
    for x in values {
        assert_eq!(to_unorm8([x; 4]), [float_to_unorm8(x); 4], "{x:e}");
    }
}

#[test]
fn common_blends_match_the_general_equation() {
    use crate::framebuffer::unorm8_to_float;
    use BlendFactor::*;
    let mut next = crate::lcg_bits(99);
    let pairs = [
        (SrcAlpha, OneMinusSrcAlpha),
        (One, Zero),
        (One, One),
        (DstColor, Zero),
    ];
    for (src, dst) in pairs {
        let b = Blend {
            src_rgb: src,
            dst_rgb: dst,
            src_alpha: src,
            dst_alpha: dst,
            ..Blend::default()
        };
        for i in 0..20_000 {
            // Sources: arbitrary values in [0, 1] and the ends;
            // destinations: stored bytes.
            let s = [0; 4].map(|_| match i % 7 {
                0 => 0.0,
                1 => 1.0,
                _ => clamp01(next() as f32 / 16_777_216.0 * 1.2 - 0.1),
            });
            let d = [0; 4].map(|_| unorm8_to_float((next() & 255) as u8));
            let fast = blend_unit(&b, s, d).map(f32::to_bits);
            let general = blend_color(&b, s, d).map(f32::to_bits);
            assert_eq!(fast, general, "{src:?}/{dst:?} {s:?} {d:?}");
        }
    }
}

#[test]
#[cfg(target_arch = "x86_64")]
fn strip_writes_match_the_pixel_writes() {
    use crate::simd::Level;
    let isas: Vec<Level> = [Level::Avx2, Level::Avx512]
        .into_iter()
        .filter(|i| i.supported())
        .collect();
    let special = [
        f32::NAN,
        -0.0,
        0.0,
        -1.0,
        2.0,
        0.5,
        f32::INFINITY,
        1e-40,
        0.999,
        1.0,
    ];
    let mut seed = 0x1234_5678u32;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed
    };
    let w = 11;
    for round in 0..200 {
        let mut rgba = [[0.0f32; 16]; 4];
        for (c, lanes) in rgba.iter_mut().enumerate() {
            for (l, x) in lanes.iter_mut().enumerate() {
                let r = next();
                *x = if (round + l + c) % 3 == 0 {
                    special[r as usize % special.len()]
                } else {
                    (r % 1000) as f32 / 997.0
                };
            }
        }
        let rows: Vec<[u8; 4]> = (0..w + 8).map(|_| next().to_le_bytes()).collect();
        for (over, &isa) in [false, true]
            .into_iter()
            .flat_map(|o| isas.iter().map(move |i| (o, i)))
        {
            let mut got = rows.clone();
            let [r, g, b, a] = &rgba;
            // SAFETY: the CPU has the instruction set (checked above);
            // `got` holds w + 8 pixels.
            unsafe {
                match isa {
                    Level::Avx512 => write_strip_avx512(&mut got, w, [r, g, b, a], over),
                    _ => write_strip_avx2(&mut got, w, [r, g, b, a], over),
                }
            };
            let mut want = rows.clone();
            for (l, src) in (0..16).map(|l| (l, rgba.map(|c| c[l]))) {
                let (row, col) = ((l >> 1) & 1, 2 * (l / 4) + (l & 1));
                let i = row * w + col;
                // SAFETY: SSE2 is part of the x86-64 baseline.
                want[i] = unsafe { write_sse2(src, want[i], over) };
            }
            assert_eq!(got, want, "round {round}, over {over}, {isa:?}");
        }
    }
}

#[test]
fn whole_quad_depth_test_matches_the_portable_one() {
    let funcs = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::LessEqual,
        CompareFunc::Greater,
        CompareFunc::NotEqual,
        CompareFunc::GreaterEqual,
        CompareFunc::Always,
    ];
    let mut x = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    // Values near each other (equal ones included), and extremes.
    let mut value = |r: u64| match r % 4 {
        0 => (next() % 8) as u32,
        1 => u32::MAX - (next() % 4) as u32,
        2 => 0x8000_0000 + (next() % 4) as u32 - 2,
        _ => next() as u32 & 0x00ff_ffff,
    };
    for i in 0..50_000u64 {
        let func = funcs[i as usize % funcs.len()];
        let kind = i / 8;
        let d: Vec<u32> = (0..12).map(|_| value(kind)).collect();
        let zf: [u32; 4] = std::array::from_fn(|_| value(kind));
        let lanes = (i % 16) as u8 | if i % 7 == 0 { 0xf0 } else { 0 };
        let (r0, r1) = ((i % 3) as usize, 6 + (i % 4) as usize);
        for write in [false, true] {
            let (mut a, mut b) = (d.clone(), d.clone());
            let pa = depth_quad(func, &mut a, (r0, r1), zf, lanes, write);
            let pb = depth_quad_portable(func, &mut b, (r0, r1), zf, lanes, write);
            assert_eq!((pa, &a), (pb, &b), "{func:?} {d:?} {zf:?} {lanes:#x}");
        }
    }
    // Rows out of the buffer: nothing passes, nothing is written.
    let mut d = vec![5u32; 4];
    assert_eq!(
        depth_quad(CompareFunc::Always, &mut d, (0, 3), [1; 4], 0xf, true),
        0
    );
    assert_eq!(d, [5; 4]);
}

/// `depth_to_fixed` (its 2^23 addition) against rounding the clamped
/// f32 product to even in f64, over edge cases and random depths.
#[test]
fn depth_to_fixed_rounds_the_f32_product_to_even() {
    let mut zs = vec![
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        -0.0,
        0.0,
        1.0,
        -1.0,
        2.0,
        1e-300,
        f64::MIN_POSITIVE,
        0.5,
        1.0 - 1e-9,
        1.0 + 1e-9,
    ];
    let mut x = 0x1234_5678_9abc_def0u64;
    for i in 0..100_000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        zs.push(match i % 3 {
            0 => (x >> 11) as f64 / (1u64 << 53) as f64,
            1 => f64::from_bits(x),
            _ => f32::from_bits(x as u32) as f64,
        });
    }
    let mut ties = 0;
    for z in zs {
        let z = z as f32;
        let clamped = if z > 0.0 { z.min(1.0) } else { 0.0 };
        let product = (clamped * crate::DEPTH_MAX as f32) as f64;
        ties += (product.fract() == 0.5) as usize;
        assert_eq!(depth_to_fixed(z), product.round_ties_even() as u32, "{z:?}");
    }
    // Exact halves, where ties to even differs from rounding up,
    // are among the random depths.
    assert!(ties > 100, "{ties} ties");
}

/// `test_quad_with` and `write_rgba8_quad` (whole quads blended row by
/// row) against the per-fragment `test` and `write_rgba8`, and
/// `depth_live` against the per-pixel depth test, quads inside and
/// across the tile's edges, random coverage and depths.
#[test]
fn quad_tests_and_writes_match_the_fragment_ones() {
    use crate::state::Rect;
    let mut next = crate::lcg_bits(97);
    let mut inside = 0;
    for (i, depth_test) in [
        None,
        Some(CompareFunc::Less),
        Some(CompareFunc::GreaterEqual),
    ]
    .into_iter()
    .enumerate()
    {
        for depth_mask in [true, false] {
            let state = PipelineState {
                depth_test,
                depth_mask,
                scissor: (i == 2).then(|| Rect::new(5, 3, 9, 7)),
                ..PipelineState::default()
            };
            let origin = (4, 2);
            let mut want = tile_under_test();
            let mut got = want.clone();
            let ops = QuickOps::new(&got, &state, &[(0, 0)]).expect("qualifies");
            for _ in 0..3000 {
                let (x, y) = ((next() % 18) as i64 & !1, (next() % 14) as i64 & !1);
                let lanes = (next() % 16) as u8;
                let z: [f32; 4] = std::array::from_fn(|_| {
                    [0.25, 0.5, 0.75, next() as f32 / 16_777_216.0][next() as usize % 4]
                });
                let zf = z.map(depth_to_fixed);
                let c: [[u8; 4]; 4] = std::array::from_fn(|_| [0; 4].map(|_| next() as u8));
                let mut w = ops.target(&mut want, origin);
                let mut pass_want = 0u8;
                for k in 0..4 {
                    let (px, py) = (x + (k as i64 & 1), y + (k as i64 >> 1));
                    if lanes & (1 << k) == 0 {
                        continue;
                    }
                    if let Some(index) = w.test(px as u32, py as u32, z[k]) {
                        w.write_rgba8(index, c[k]);
                        pass_want |= 1 << k;
                    }
                }
                // Early rejection: a lane stays unless it is inside
                // the target and fails the depth test.
                let keep_want = (0..4).fold(0u8, |m, k| {
                    let (lx, ly) = (x + (k & 1) - 4, y + (k >> 1) - 2);
                    let fails = (0..12).contains(&lx)
                        && (0..10).contains(&ly)
                        && depth_test.is_some_and(|f| {
                            let stored = got.depth.as_ref().unwrap()[(ly * 12 + lx) as usize];
                            !f.test(zf[k as usize], stored)
                        });
                    m | (u8::from(lanes & (1 << k) != 0 && !fails) << k)
                });
                let mut t = ops.target(&mut got, origin);
                assert_eq!(t.depth_live((x, y), lanes, zf), keep_want);
                let (pass, index, quad_inside) = t.test_quad_with((x, y), lanes, || z, zf);
                t.write_rgba8_quad(pass, index, quad_inside, c);
                assert_eq!(pass, pass_want, "{x},{y} {lanes:#b}");
                inside += usize::from(quad_inside);
            }
            assert!(want == got, "{depth_test:?} {depth_mask}");
        }
    }
    assert!(inside > 1000);
}

#[test]
fn quick_ops_match_the_general_ones() {
    use crate::state::Rect;
    use BlendFactor::*;
    let mut next = crate::lcg_bits(4321);
    let blends = [
        None,
        Some((SrcAlpha, OneMinusSrcAlpha)),
        Some((One, Zero)),
        Some((One, One)),
        Some((DstColor, SrcColor)),
    ];
    let funcs = [
        None,
        Some(CompareFunc::Less),
        Some(CompareFunc::LessEqual),
        Some(CompareFunc::GreaterEqual),
        Some(CompareFunc::Equal),
    ];
    let mut checked = 0;
    for (i, blend) in blends.into_iter().enumerate() {
        for (j, depth_test) in funcs.into_iter().enumerate() {
            let state = PipelineState {
                depth_test,
                depth_mask: (i + j) % 3 != 0,
                scissor: ((i + j) % 2 == 0).then(|| Rect::new(3, 2, 9, 7)),
                blend: blend.map(|(src, dst)| Blend {
                    src_rgb: src,
                    dst_rgb: dst,
                    src_alpha: src,
                    dst_alpha: dst,
                    ..Blend::default()
                }),
                ..PipelineState::default()
            };
            let origin = (4, 2);
            let mut general = tile_under_test();
            let mut quick = general.clone();
            let ops = QuickOps::new(&quick, &state, &[(0, 0)]).expect("qualifies");
            assert_eq!(ops.color_output(), Some(0));
            for _ in 0..3000 {
                let f = Fragment {
                    x: next() % 18,
                    y: next() % 14,
                    z: [0.25, 0.5, 0.75, next() as f32 / 16_777_216.0][next() as usize % 4],
                    back_facing: false,
                    colors: [[0; 4].map(|_| next() as f32 / 16_777_216.0 * 1.4 - 0.2); FRAG_COLORS],
                };
                let want = tests(&mut general, origin, &state, &f);
                if let Some(index) = want {
                    write_colors(&mut general, index, &state, &f.colors);
                }
                let mut t = ops.target(&mut quick, origin);
                let got = t.test(f.x, f.y, f.z);
                if let Some(index) = got {
                    t.write(index, f.colors[0]);
                }
                assert_eq!(want, got);
                checked += usize::from(got.is_some());
            }
            assert!(general == quick, "{blend:?} {depth_test:?}");
        }
    }
    assert!(checked > 5000);
    // States the quick operations leave to the general ones.
    let fb = Framebuffer::new(4, 4, ColorFormat::Rgba8, true, true);
    let alpha = PipelineState {
        alpha_test: Some((CompareFunc::Greater, 0.5)),
        ..PipelineState::default()
    };
    assert!(QuickOps::new(&fb, &alpha, &[(0, 0)]).is_none());
    let stencil = PipelineState {
        stencil: Some(StencilState::default()),
        ..PipelineState::default()
    };
    assert!(QuickOps::new(&fb, &stencil, &[(0, 0)]).is_none());
    let no_color = [
        PipelineState {
            color_mask: [true, true, false, true],
            ..PipelineState::default()
        },
        PipelineState {
            logic_op: Some(LogicOp::Xor),
            ..PipelineState::default()
        },
    ];
    for state in no_color {
        let ops = QuickOps::new(&fb, &state, &[(0, 0)]).expect("tests qualify");
        assert_eq!(ops.color_output(), None);
    }
    // The output is not carried (written as zeros): the general path.
    let ops = QuickOps::new(&fb, &PipelineState::default(), &[]).expect("tests qualify");
    assert_eq!(ops.color_output(), None);
    let float = Framebuffer::new(4, 4, ColorFormat::Rgba32F, true, false);
    let ops = QuickOps::new(&float, &PipelineState::default(), &[(0, 0)]).expect("tests");
    assert_eq!(ops.color_output(), None);
}

/// `write_sse2` gives the scalar code's bytes: every destination
/// byte, sources across and outside [0, 1], ±0, NaN and infinities.
#[cfg(target_arch = "x86_64")]
#[test]
fn sse2_write_matches_the_scalar_code() {
    let mut values = vec![
        0.0f32,
        -0.0,
        1.0,
        -1.0,
        0.5,
        1.0 - f32::EPSILON / 2.0,
        1.0 + f32::EPSILON,
        f32::MIN_POSITIVE,
        1e-45,
        f32::NAN,
        -f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.5 / 255.0,
        1.5 / 255.0,
    ];
    let mut seed = 0x2b1e_u32;
    let mut next = move || {
        seed = crate::lcg_step(seed);
        seed
    };
    for k in 0..=255 {
        values.push(k as f32 / 255.0);
        values.push((k as f32 + 0.5) / 255.0);
    }
    for _ in 0..2000 {
        values.push((next() >> 8) as f32 / 16_777_216.0 * 1.4 - 0.2);
    }
    let n = values.len() as u32;
    for round in 0..200_000u32 {
        let src = [0; 4].map(|_| values[(next() % n) as usize]);
        let dst = next().to_le_bytes();
        let over = round % 4 != 0;
        // SAFETY: SSE2 is part of the x86-64 baseline.
        let got = unsafe { write_sse2(src, dst, over) };
        assert_eq!(got, write_scalar(src, dst, over), "{src:?} {dst:?} {over}");
    }
}

#[test]
fn blended_write_to_rgba8_clamps() {
    let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, false, false);
    fb.clear_color(&[0], [1.0, 0.5, 0.0, 1.0], [true; 4], None);
    let state = PipelineState {
        blend: Some(Blend {
            dst_rgb: BlendFactor::One,
            dst_alpha: BlendFactor::One,
            ..Blend::default()
        }),
        ..PipelineState::default()
    };
    process(
        &mut fb,
        (0, 0),
        &state,
        &frag(0, 0, 0.0, [0.5, 0.25, 2.0, -1.0]),
    );
    assert_eq!(fb.read_pixels_u8(0, 0, 0, 1, 1), vec![[255, 192, 255, 255]]);
}

#[test]
fn logic_op_and_color_mask() {
    let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, false, false);
    fb.clear_color(&[0], [1.0, 1.0, 1.0, 1.0], [true; 4], None);
    let state = PipelineState {
        logic_op: Some(LogicOp::Xor),
        color_mask: [true, true, false, true],
        ..PipelineState::default()
    };
    process(
        &mut fb,
        (0, 0),
        &state,
        &frag(0, 0, 0.0, [1.0, 0.0, 0.0, 0.0]),
    );
    assert_eq!(fb.read_pixels_u8(0, 0, 0, 1, 1), vec![[0, 255, 255, 255]]);
}

#[test]
fn depth_funcs() {
    use CompareFunc::*;
    let table = [
        (Never, [false, false, false]),
        (Less, [true, false, false]),
        (Equal, [false, true, false]),
        (LessEqual, [true, true, false]),
        (Greater, [false, false, true]),
        (NotEqual, [true, false, true]),
        (GreaterEqual, [false, true, true]),
        (Always, [true, true, true]),
    ];
    for (func, expect) in table {
        for (i, z) in [0.25f32, 0.5, 0.75].into_iter().enumerate() {
            assert_eq!(depth_passes(func, z, 0.5), expect[i], "{func:?} {z}");
            let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, true, false);
            fb.clear_depth(0.5, true, None);
            let state = PipelineState {
                depth_test: Some(func),
                ..PipelineState::default()
            };
            process(&mut fb, (0, 0), &state, &frag(0, 0, z, [1.0; 4]));
            let written = fb.read_pixels_u8(0, 0, 0, 1, 1)[0] == [255; 4];
            assert_eq!(written, expect[i], "{func:?} {z}");
            let depth = fb.read_depth(0, 0, 1, 1)[0];
            let same = depth_to_fixed(depth) == depth_to_fixed(z);
            assert_eq!(same, expect[i] || z == 0.5, "{func:?} {z}");
        }
    }
}

#[test]
fn depth_mask_off_keeps_depth() {
    let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, true, false);
    fb.clear_depth(1.0, true, None);
    let state = PipelineState {
        depth_test: Some(CompareFunc::Less),
        depth_mask: false,
        ..PipelineState::default()
    };
    process(&mut fb, (0, 0), &state, &frag(0, 0, 0.25, [1.0; 4]));
    assert_eq!(fb.read_depth(0, 0, 1, 1)[0], 1.0);
    assert_eq!(fb.read_pixels_u8(0, 0, 0, 1, 1)[0], [255; 4]);
}

#[test]
fn stencil_ops() {
    use StencilOp::*;
    assert_eq!(stencil_op(Keep, 7, 3), 7);
    assert_eq!(stencil_op(Zero, 7, 3), 0);
    assert_eq!(stencil_op(Replace, 7, 3), 3);
    assert_eq!(stencil_op(Incr, 255, 3), 255);
    assert_eq!(stencil_op(Incr, 7, 3), 8);
    assert_eq!(stencil_op(Decr, 0, 3), 0);
    assert_eq!(stencil_op(Decr, 7, 3), 6);
    assert_eq!(stencil_op(Invert, 0x0f, 3), 0xf0);
    assert_eq!(stencil_op(IncrWrap, 255, 3), 0);
    assert_eq!(stencil_op(DecrWrap, 0, 3), 255);
}

#[test]
fn stencil_test_paths_and_masks() {
    // fail / depth-fail / depth-pass each pick their op; write mask applies.
    let face = StencilFace {
        func: CompareFunc::Equal,
        reference: 1,
        value_mask: 0xff,
        fail: StencilOp::Invert,
        depth_fail: StencilOp::Incr,
        depth_pass: StencilOp::Replace,
        write_mask: 0x0f,
    };
    let state = PipelineState {
        stencil: Some(StencilState {
            front: face,
            back: StencilFace::default(),
        }),
        depth_test: Some(CompareFunc::Less),
        ..PipelineState::default()
    };
    let run = |stored: u8, z: f32| {
        let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, true, true);
        fb.clear_stencil(stored as i32, 0xff, None);
        fb.clear_depth(0.5, true, None);
        process(&mut fb, (0, 0), &state, &frag(0, 0, z, [1.0; 4]));
        (
            fb.read_stencil(0, 0, 1, 1)[0],
            fb.read_pixels_u8(0, 0, 0, 1, 1)[0][0],
        )
    };
    // Stencil fails (stored 0x20 != 1): invert under mask 0x0f.
    assert_eq!(run(0x20, 0.0), (0x2f, 0));
    // Passes stencil, fails depth: incr.
    assert_eq!(run(1, 0.75), (2, 0));
    // Passes both: replace with 1, color written.
    assert_eq!(run(1, 0.25), (1, 255));
    // Back-facing fragments use the back state (always pass, keep).
    let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, true, true);
    fb.clear_stencil(0x20, 0xff, None);
    fb.clear_depth(1.0, true, None);
    let mut f = frag(0, 0, 0.25, [1.0; 4]);
    f.back_facing = true;
    process(&mut fb, (0, 0), &state, &f);
    assert_eq!(fb.read_stencil(0, 0, 1, 1)[0], 0x20);
    assert_eq!(fb.read_pixels_u8(0, 0, 0, 1, 1)[0][0], 255);
}

#[test]
fn alpha_test_and_scissor() {
    let mut fb = Framebuffer::new(2, 1, ColorFormat::Rgba8, false, false);
    let state = PipelineState {
        alpha_test: Some((CompareFunc::Greater, 0.5)),
        scissor: Some(crate::state::Rect::new(1, 0, 1, 1)),
        ..PipelineState::default()
    };
    process(&mut fb, (0, 0), &state, &frag(0, 0, 0.0, [1.0; 4]));
    process(
        &mut fb,
        (0, 0),
        &state,
        &frag(1, 0, 0.0, [1.0, 1.0, 1.0, 0.5]),
    );
    assert_eq!(fb.read_pixels_u8(0, 0, 0, 2, 1), vec![[0; 4], [0; 4]]);
    process(
        &mut fb,
        (0, 0),
        &state,
        &frag(1, 0, 0.0, [1.0, 1.0, 1.0, 0.6]),
    );
    assert_eq!(fb.read_pixels_u8(0, 1, 0, 1, 1), vec![[255, 255, 255, 153]]);
}

#[test]
fn early_reject_only_without_side_effects() {
    let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba8, true, true);
    fb.clear_depth(0.5, true, None);
    let mut state = PipelineState {
        depth_test: Some(CompareFunc::Less),
        ..PipelineState::default()
    };
    assert!(early_reject(&fb, &state, 0, depth_to_fixed(0.75), false));
    assert!(!early_reject(&fb, &state, 0, depth_to_fixed(0.25), false));
    state.stencil = Some(StencilState {
        front: StencilFace {
            depth_fail: StencilOp::Incr,
            ..StencilFace::default()
        },
        back: StencilFace::default(),
    });
    assert!(!early_reject(&fb, &state, 0, depth_to_fixed(0.75), false));
    assert!(early_reject(&fb, &state, 0, depth_to_fixed(0.75), true));
}
