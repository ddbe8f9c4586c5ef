use super::lanes::floor_lane;
use super::storage::*;
use super::*;
use crate::texture::{Image, TextureUnit};
use crate::texture_units::TextureUnits;
use std::sync::Arc;

/// [`super::sample_with`] through `units`, as `TextureUnits` calls it.
pub(super) fn sample_with(
    isa: Level,
    units: &TextureUnits,
    req: &SampleRequest,
    out: &mut [[f32; LANES]; 4],
) -> bool {
    super::sample_with(isa, &units.units, &units.checked_2d, req, out)
}

/// [`super::sample_implicit_with`] through `units`, as `TextureUnits`
/// calls it.
fn sample_implicit_with(
    isa: Level,
    units: &TextureUnits,
    unit: u32,
    st: [&[f32; LANES]; 2],
    mask: u32,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    super::sample_implicit_with(isa, &units.units, &units.checked_2d, unit, st, mask, out)
}

/// A lookup on unit 0's 2D texture for the lanes of `mask`, its LOD
/// from the derivatives `ddx`, `ddy` (no bias).
pub(super) fn request_2d(
    coord: [[f32; LANES]; 4],
    ddx: [[f32; LANES]; 3],
    ddy: [[f32; LANES]; 3],
    mask: u32,
) -> SampleRequest {
    SampleRequest {
        unit: [0; LANES],
        target: SamplerKind::Sampler2D,
        coord,
        compare: None,
        lod: Lod::Derivatives {
            ddx,
            ddy,
            bias: [0.0; LANES],
        },
        offset: None,
        compare_only: false,
        mask,
    }
}

/// A 2D texture with a full mipmap chain of random texels: unorm8,
/// or arbitrary on the levels whose bit is set in `float`.
fn random_texture(w: u32, h: u32, float: u32, seed: &mut u32) -> Texture {
    let mut next = move || {
        *seed = crate::lcg_step(*seed);
        *seed >> 8
    };
    let mut levels = Vec::new();
    let (mut lw, mut lh) = (w, h);
    loop {
        let float = float & (1 << levels.len()) != 0;
        let texels = (0..lw * lh)
            .map(|_| {
                [0; 4].map(|_| {
                    let r = next();
                    if float {
                        r as f32 / 65536.0 - 100.0
                    } else {
                        (r & 255) as f32 / 255.0
                    }
                })
            })
            .collect();
        let img = Image::new(lw, lh, 1, texels);
        assert_eq!(img.is_unorm8(), !float);
        levels.push(img);
        if lw == 1 && lh == 1 {
            break;
        }
        (lw, lh) = ((lw / 2).max(1), (lh / 2).max(1));
    }
    Texture::new(TextureTarget::Tex2D, levels)
}

/// The general path, lane by lane.
fn general(units: &TextureUnits, req: &SampleRequest) -> [[f32; LANES]; 4] {
    let mut out = [[0.0; LANES]; 4];
    units.sample_general(req, &mut out);
    out
}

#[test]
fn fast_path_matches_the_general_path_bit_for_bit() {
    let mut seed = 0x5eed_u32;
    let mut rnd = {
        let mut s = 0x1234_u32;
        move || {
            s = crate::lcg_step(s);
            s
        }
    };
    let filters = [
        MinFilter::Nearest,
        MinFilter::Linear,
        MinFilter::NearestMipmapNearest,
        MinFilter::LinearMipmapNearest,
        MinFilter::NearestMipmapLinear,
        MinFilter::LinearMipmapLinear,
    ];
    let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];
    let mut checked = 0;
    let isas: Vec<Level> = [Level::Portable, Level::Avx2, Level::Avx512]
        .into_iter()
        .filter(|i| i.supported())
        .collect();
    // RGBA8 levels, f32 levels, some of each.
    for (size, float) in [
        ((16, 8), 0),
        ((5, 12), !0),
        ((1, 1), 0),
        ((8, 32), 0b1010),
        ((6, 3), 0),
    ] {
        let base = random_texture(size.0, size.1, float, &mut seed);
        let mixed = float != 0 && float != !0;
        let mut skipped = 0;
        for (k, &min_filter) in filters.iter().enumerate() {
            for mag_filter in [MagFilter::Nearest, MagFilter::Linear] {
                let mut tex = base.clone();
                tex.min_filter = min_filter;
                tex.mag_filter = mag_filter;
                tex.wrap = [wraps[k % 3], wraps[(k + 1) % 3], Wrap::Repeat];
                tex.lod_bias = if k % 2 == 0 { 0.25 } else { 0.0 };
                tex.base_level = (k % 2).min(tex.levels.len() - 1) as u32;
                tex.min_lod = -2.0 + k as f32 * 0.1;
                tex.max_lod = if k % 3 == 2 { 1.5 } else { 1000.0 };
                let units = TextureUnits::new(vec![
                    TextureUnit::default(),
                    TextureUnit {
                        tex_2d: Some(Arc::new(tex)),
                        lod_bias: -0.5,
                        ..TextureUnit::default()
                    },
                ]);
                for round in 0..40 {
                    let mut coord = [[0.0; LANES]; 4];
                    let mut ddx = [[0.0; LANES]; 3];
                    let mut ddy = [[0.0; LANES]; 3];
                    let mut v = |scale: f32| (rnd() >> 8) as f32 / 16_777_216.0 * scale;
                    for lane in 0..LANES {
                        coord[0][lane] = v(6.0) - 3.0;
                        coord[1][lane] = v(6.0) - 3.0;
                        for c in 0..2 {
                            ddx[c][lane] = v(0.6) - 0.3;
                            ddy[c][lane] = v(0.6) - 0.3;
                        }
                    }
                    // A few awkward values.
                    coord[0][3] = f32::NAN;
                    coord[1][4] = f32::INFINITY;
                    coord[0][5] = -1e-9;
                    // Signaling NaNs (`floor_of`).
                    coord[1][2] = f32::from_bits(0x7f80_0001);
                    coord[0][13] = f32::from_bits(0xff80_0101);
                    ddx[0][6] = 0.0;
                    ddy[1][6] = 0.0;
                    ddx[0][7] = f32::NAN;
                    ddy[1][8] = f32::INFINITY;
                    ddx[1][10] = 1e30;
                    // Half the rounds: derivatives the same in each
                    // quad, as the executor's (λ once per quad).
                    if round % 4 >= 2 {
                        if round % 8 == 2 {
                            ddx[1][4] = f32::NAN;
                            ddy[0][12] = 1e30;
                        }
                        for c in 0..2 {
                            for lane in 0..LANES {
                                // (Round 6 of 8: the same in every
                                // lane, so one level for all.)
                                let from = if round % 8 == 6 { 0 } else { lane & !3 };
                                ddx[c][lane] = ddx[c][from];
                                ddy[c][lane] = ddy[c][from];
                            }
                        }
                    }
                    let lod = if round % 3 == 0 {
                        Lod::Explicit(std::array::from_fn(|l| {
                            if l == 11 {
                                f32::NAN
                            } else {
                                l as f32 * 0.4 - 2.0
                            }
                        }))
                    } else {
                        Lod::Derivatives {
                            ddx,
                            ddy,
                            bias: [if round % 3 == 1 { 0.0 } else { 0.75 }; LANES],
                        }
                    };
                    let req = SampleRequest {
                        unit: [1; LANES],
                        target: SamplerKind::Sampler2D,
                        coord,
                        compare: None,
                        lod,
                        offset: None,
                        compare_only: false,
                        mask: 0xffff & !(1 << 9),
                    };
                    let slow = general(&units, &req);
                    // The request-free entry on the same coordinates
                    // (derivatives their quad differences, no bias).
                    let st = [&req.coord[0], &req.coord[1]];
                    let implicit = general(&units, &exec::implicit_2d_request(1, st, req.mask));
                    for &isa in &isas {
                        let mut got = [[7.0; LANES]; 4];
                        // (Levels of both storages take the general
                        // path, which filters each as it is stored.)
                        let sampled = sample_implicit_with(isa, &units, 1, st, req.mask, &mut got);
                        let taken = sampled != Sampled::No;
                        if mixed && !taken {
                            skipped += 1;
                            continue;
                        }
                        assert!(taken);
                        for c in 0..4 {
                            for lane in 0..LANES {
                                let want = if lane == 9 { 7.0 } else { implicit[c][lane] };
                                assert_eq!(
                                    got[c][lane].to_bits(),
                                    want.to_bits(),
                                    "implicit {isa:?} {min_filter:?} lane {lane} c {c}"
                                );
                                // RGBA8 results need no flush.
                                let v = got[c][lane];
                                if sampled == Sampled::Unorm8 && lane != 9 {
                                    assert!(v == 0.0 || v.is_normal(), "{v:e}");
                                }
                            }
                        }
                    }
                    for &isa in &isas {
                        let mut fast = [[7.0; LANES]; 4];
                        let taken = sample_with(isa, &units, &req, &mut fast);
                        if mixed && !taken {
                            continue;
                        }
                        assert!(taken);
                        for c in 0..4 {
                            for lane in 0..LANES {
                                if lane == 9 {
                                    assert_eq!(fast[c][lane], 7.0, "masked lane untouched");
                                    continue;
                                }
                                assert_eq!(
                                fast[c][lane].to_bits(),
                                slow[c][lane].to_bits(),
                                "{isa:?} {min_filter:?} {mag_filter:?} lane {lane} c {c}: {} vs {}",
                                fast[c][lane],
                                slow[c][lane]
                            );
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(mixed, skipped > 0, "mixed storage takes the general path");
    }
    assert!(checked > 10_000);
}

/// Requests like the executor's on a large RGBA8 texture (nearby
/// lanes, derivatives the same in each quad, often one level for the
/// whole request and no lane at a wrap edge: the AVX-512 variant's
/// `wide` filtering and its paired reads), against the general path.
#[test]
fn nearby_lanes_match_the_general_path() {
    let mut seed = 0x0dd_u32;
    let mut rnd = move || {
        seed = crate::lcg_step(seed);
        (seed >> 8) as f32 / 16_777_216.0
    };
    let isas: Vec<Level> = [Level::Portable, Level::Avx2, Level::Avx512]
        .into_iter()
        .filter(|i| i.supported())
        .collect();
    let mut tex_seed = 0x77aa_u32;
    let base = random_texture(64, 32, 0, &mut tex_seed);
    let mut checked = 0;
    for (min_filter, mag_filter) in [
        (MinFilter::LinearMipmapLinear, MagFilter::Linear),
        (MinFilter::NearestMipmapLinear, MagFilter::Nearest),
        (MinFilter::Linear, MagFilter::Linear),
        (MinFilter::LinearMipmapNearest, MagFilter::Nearest),
        (MinFilter::Nearest, MagFilter::Nearest),
    ] {
        for wrap in [
            [Wrap::Repeat, Wrap::Repeat],
            [Wrap::ClampToEdge, Wrap::Repeat],
            [Wrap::ClampToEdge, Wrap::ClampToEdge],
        ] {
            let mut tex = base.clone();
            tex.min_filter = min_filter;
            tex.mag_filter = mag_filter;
            tex.wrap = [wrap[0], wrap[1], Wrap::Repeat];
            let units = TextureUnits::new(vec![TextureUnit {
                tex_2d: Some(Arc::new(tex)),
                ..TextureUnit::default()
            }]);
            for round in 0..400 {
                // A 8×2-pixel run of four quads at a random place
                // (now and then across the texture's edge), scaled
                // from magnified to a few levels down.
                let d = 0.002 * (1.0 + 30.0 * rnd()) * if round % 5 == 0 { 8.0 } else { 1.0 };
                let (s0, t0) = if round % 7 == 0 {
                    (-0.01, 0.99)
                } else {
                    (rnd() * 3.0 - 1.0, rnd() * 3.0 - 1.0)
                };
                let (ds, dt) = (d, d * (0.5 + rnd()));
                let mut coord = [[0.0; LANES]; 4];
                let mut ddx = [[0.0; LANES]; 3];
                let mut ddy = [[0.0; LANES]; 3];
                for l in 0..LANES {
                    let (x, y) = ((l % 2 + 2 * (l / 4)) as f32, ((l / 2) % 2) as f32);
                    coord[0][l] = s0 + x * ds + 0.1 * y * dt;
                    coord[1][l] = t0 + y * dt;
                    ddx[0][l] = ds;
                    ddy[0][l] = 0.1 * dt;
                    ddy[1][l] = dt;
                }
                let req = request_2d(coord, ddx, ddy, [0xffff, 0xfff0, 0x0f0f][round % 3]);
                let slow = general(&units, &req);
                for &isa in &isas {
                    let mut fast = [[9.0; LANES]; 4];
                    assert!(sample_with(isa, &units, &req, &mut fast));
                    for c in 0..4 {
                        for l in 0..LANES {
                            let want = if req.mask & (1 << l) != 0 {
                                slow[c][l]
                            } else {
                                9.0
                            };
                            assert_eq!(
                                fast[c][l].to_bits(),
                                want.to_bits(),
                                "{isa:?} {min_filter:?} {wrap:?} round {round} lane {l} c {c}"
                            );
                            checked += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(checked > 100_000);
}

#[test]
fn level_table_finds_the_last_level_as_texture_does() {
    let mut seed = 0x51ed_2701_u32;
    let mut rnd = move |n: u32| {
        seed = crate::lcg_step(seed);
        (seed >> 8) % n
    };
    let mut complete = 0;
    for _ in 0..4000 {
        let (mut w, mut h): (u32, u32) = (1 << rnd(6), 1 << rnd(6));
        let mut levels = Vec::new();
        for _ in 0..rnd(9) + 1 {
            let (mut lw, mut lh, mut ld) = (w, h, [1, 1, 1, 1, 1, 0, 2][rnd(7) as usize]);
            // Now and then a wrong size or too few texels.
            match rnd(14) {
                0 => lw += 1,
                1 => lh = lh.saturating_sub(1),
                2 => (lw, lh) = (0, 0),
                _ => {}
            }
            let mut n = (lw * lh * ld) as usize;
            if rnd(16) == 0 {
                n = n.saturating_sub(1);
                ld = ld.max(1);
            }
            let float = rnd(4) == 0;
            let texel = if float {
                [0.3; 4]
            } else {
                [0.0, 1.0, 0.0, 1.0]
            };
            let mut img = Image::new(lw, lh, ld, vec![texel; n]);
            img.depth = ld;
            levels.push(img);
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
        let mut tex = Texture::new(TextureTarget::Tex2D, levels);
        tex.min_filter = [MinFilter::Nearest, MinFilter::LinearMipmapLinear][rnd(2) as usize];
        tex.base_level = rnd(3);
        tex.max_level = [1000, rnd(6)][rnd(2) as usize];
        let want = tex.last_level();
        let tex = Arc::new(tex);
        let checked = Checked::new(&tex);
        assert_eq!(checked.as_ref().map(|c| c.q), want, "{tex:?}");
        if let Some(checked) = checked {
            let (table, q) = (LevelTable::new(&tex, &checked), checked.q);
            complete += 1;
            // Storage as the levels have it.
            let levels = &tex.levels[tex.base_level as usize..=q];
            let unorm8 = levels.iter().filter(|l| l.is_unorm8()).count();
            let empty = levels.iter().any(|l| l.is_empty());
            match table.store {
                Store::Unorm8(_) => assert!(unorm8 == levels.len() && !empty),
                Store::F32(_) => assert!(unorm8 == 0 && !empty),
                Store::Mixed => assert!(empty || (unorm8 != 0 && unorm8 != levels.len())),
            }
        }
    }
    assert!(complete > 400, "{complete} complete");
}

/// An entry of `TextureUnits::checked_2d` serves only the texture it
/// was found for: after a unit's texture changes, lookups still match
/// the general path.
#[test]
fn checked_entries_follow_the_units_textures() {
    let mut seed = 0x77_u32;
    let mut units = TextureUnits::new(vec![TextureUnit::default()]);
    let req = SampleRequest {
        unit: [0; LANES],
        target: SamplerKind::Sampler2D,
        coord: [
            std::array::from_fn(|l| l as f32 * 0.13 - 0.4),
            std::array::from_fn(|l| l as f32 * -0.07 + 0.2),
            [0.0; LANES],
            [1.0; LANES],
        ],
        compare: None,
        lod: Lod::Explicit(std::array::from_fn(|l| l as f32 * 0.3 - 1.0)),
        offset: None,
        compare_only: false,
        mask: 0xffff,
    };
    // Complete, another size, f32 texels, incomplete (a missing level).
    let mut textures = vec![
        random_texture(8, 8, 0, &mut seed),
        random_texture(16, 4, 0, &mut seed),
        random_texture(4, 4, !0, &mut seed),
    ];
    let mut incomplete = random_texture(8, 8, 0, &mut seed);
    incomplete.levels.truncate(2);
    textures.push(incomplete);
    for mut tex in textures {
        tex.min_filter = MinFilter::LinearMipmapLinear;
        units.units[0].tex_2d = Some(Arc::new(tex));
        let slow = general(&units, &req);
        let mut fast = [[0.0; LANES]; 4];
        if sample_with(current_level(), &units, &req, &mut fast) {
            assert_eq!(
                fast.map(|c| c.map(f32::to_bits)),
                slow.map(|c| c.map(f32::to_bits))
            );
        }
    }
    assert!(units.checked_2d.get().is_some());
}

#[test]
fn lane_floor_is_exact() {
    let mut values = vec![
        0.0f32,
        -0.0,
        0.5,
        -0.5,
        -1.0,
        8_388_607.5,
        -8_388_607.5,
        8_388_608.0,
        -8_388_609.0,
        1e30,
        -1e30,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        -1e-45,
    ];
    let mut bits = 0x9e37_79b9u32;
    for _ in 0..100_000 {
        bits = crate::lcg_step(bits);
        values.push(f32::from_bits(bits));
        values.push((bits >> 8) as f32 / 4096.0 - 2048.0);
    }
    for x in values {
        let (a, b) = (floor_lane(x), glsl::math::floor(x));
        assert!(
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            "floor({x:e})"
        );
        // The instruction's floor (`floor_of::<true>`): the same bits
        // but for NaNs (which it may quiet).
        let c = x.floor();
        assert!(
            a.to_bits() == c.to_bits() || (a.is_nan() && c.is_nan()),
            "floor({x:e}) (instruction)"
        );
    }
}

#[test]
fn other_requests_take_the_general_path() {
    let mut seed = 7;
    let tex = random_texture(4, 4, 0, &mut seed);
    let req = |unit: [u32; LANES]| SampleRequest {
        unit,
        target: SamplerKind::Sampler2D,
        coord: [[0.5; LANES]; 4],
        compare: None,
        lod: Lod::Explicit([0.0; LANES]),
        offset: None,
        compare_only: false,
        mask: 0b1111,
    };
    let units = |tex: Texture| {
        TextureUnits::new(vec![TextureUnit {
            tex_2d: Some(Arc::new(tex)),
            ..TextureUnit::default()
        }])
    };
    let mut out = [[0.0; LANES]; 4];
    assert!(sample_with(
        current_level(),
        &units(tex.clone()),
        &req([0; LANES]),
        &mut out
    ));
    // Two units in one request.
    let mut two = [0; LANES];
    two[2] = 1;
    assert!(!sample_with(
        current_level(),
        &units(tex.clone()),
        &req(two),
        &mut out
    ));
    // ... unless the other unit's lane is masked off.
    let masked = SampleRequest {
        offset: None,
        compare_only: false,
        mask: 0b1011,
        ..req(two)
    };
    assert!(sample_with(
        current_level(),
        &units(tex.clone()),
        &masked,
        &mut out
    ));
    // Border wrapping, depth textures, incomplete textures.
    let mut border = tex.clone();
    border.wrap[1] = Wrap::ClampToBorder;
    assert!(!sample_with(
        current_level(),
        &units(border),
        &req([0; LANES]),
        &mut out
    ));
    let mut depth = tex.clone();
    depth.depth_format = true;
    assert!(!sample_with(
        current_level(),
        &units(depth),
        &req([0; LANES]),
        &mut out
    ));
    let mut incomplete = tex;
    incomplete.levels.truncate(1);
    assert!(!sample_with(
        current_level(),
        &units(incomplete),
        &req([0; LANES]),
        &mut out
    ));
}
