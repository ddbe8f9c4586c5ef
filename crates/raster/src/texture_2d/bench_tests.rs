use super::tests::sample_with;
use super::*;
use crate::texture::{Image, MagFilter, MinFilter, TextureUnit};
use crate::texture_units::TextureUnits;
use std::sync::Arc;

/// `cargo test --release -p shaderbox-raster bench_sample_2d -- --ignored --nocapture`:
/// trilinear lookups on a 512² RGBA8 mipmapped texture, quads of
/// lanes with derivatives like the benchmark's textured scene, through
/// each instruction set's fast path and the general path.
/// `BENCH_ISA=Avx2` (or `Portable`, `Avx512`) times that variant
/// alone (for profilers), `BENCH_ROUNDS=N` rounds of each (15),
/// `BENCH_FILTERS=all` also LINEAR and NEAREST without mipmaps
/// (`linear`, `nearest`: that one alone).
#[test]
#[ignore]
fn bench_sample_2d() {
    let mut levels = Vec::new();
    let mut n = 512u32;
    loop {
        let texels = (0..n * n)
            .map(|i| {
                [
                    (i % 251) as f32 / 255.0,
                    (i % 7) as f32 / 255.0,
                    0.5 * 0.0,
                    1.0,
                ]
            })
            .collect();
        levels.push(Image::new(n, n, 1, texels));
        if n == 1 {
            break;
        }
        n /= 2;
    }
    let tex = Texture::new(TextureTarget::Tex2D, levels);
    let mut reqs = Vec::new();
    for k in 0..4096u32 {
        let x0 = (k % 64) as f32 * 4.0;
        let y0 = (k / 64) as f32 * 1.0;
        let d = 0.004 + 0.002 * (k % 13) as f32;
        let mut coord = [[0.0; LANES]; 4];
        let mut ddx = [[0.0; LANES]; 3];
        let mut ddy = [[0.0; LANES]; 3];
        for l in 0..LANES {
            let (x, y) = (x0 + (l % 2 + 2 * (l / 4)) as f32, y0 + ((l / 2) % 2) as f32);
            coord[0][l] = x * d;
            coord[1][l] = y * d * 1.7 + 0.1 * x * d;
            ddx[0][l] = d;
            ddx[1][l] = 0.1 * d;
            ddy[1][l] = 1.7 * d;
        }
        reqs.push(super::tests::request_2d(coord, ddx, ddy, 0xffff));
    }
    // The scene's filter; then LINEAR and NEAREST without mipmaps
    // (`BENCH_FILTERS=all`).
    let trilinear = (MinFilter::LinearMipmapLinear, MagFilter::Linear);
    let linear = (MinFilter::Linear, MagFilter::Linear);
    let nearest = (MinFilter::Nearest, MagFilter::Nearest);
    let filters = match std::env::var("BENCH_FILTERS").as_deref() {
        Ok("all") => vec![trilinear, linear, nearest],
        Ok("linear") => vec![linear],
        Ok("nearest") => vec![nearest],
        _ => vec![trilinear],
    };
    for (min_filter, mag_filter) in filters {
        let mut tex = tex.clone();
        tex.min_filter = min_filter;
        tex.mag_filter = mag_filter;
        let units = TextureUnits::new(vec![TextureUnit {
            tex_2d: Some(Arc::new(tex)),
            ..TextureUnit::default()
        }]);
        println!("{min_filter:?}, {mag_filter:?}:");
        time_lookups(&units, &reqs);
    }
}

/// Times `reqs` through each instruction set's fast path and the
/// general path and prints the best time per lane of each.
fn time_lookups(units: &TextureUnits, reqs: &[SampleRequest]) {
    let mut out = [[0.0; LANES]; 4];
    let mut sink = 0.0f32;
    // Each supported instruction set's fast path, then the general
    // path; alternating rounds, best of each (the machine is shared).
    let isas: Vec<Level> = [Level::Portable, Level::Avx2, Level::Avx512]
        .into_iter()
        .filter(|i| {
            i.supported() && std::env::var("BENCH_ISA").map_or(true, |v| v == format!("{i:?}"))
        })
        .collect();
    let ways = isas.len() + usize::from(std::env::var("BENCH_ISA").is_err());
    let mut best = vec![f64::MAX; ways];
    let rounds: usize = std::env::var("BENCH_ROUNDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(15);
    for round in 0..rounds * ways {
        let way = round % ways;
        let t = std::time::Instant::now();
        for r in reqs {
            match isas.get(way) {
                Some(&isa) => {
                    sample_with(isa, units, r, &mut out);
                }
                None => units.sample_general(r, &mut out),
            }
            sink += out[0][3];
        }
        let b = &mut best[way];
        *b = b.min(t.elapsed().as_secs_f64());
    }
    for (way, b) in best.iter().enumerate() {
        let name = isas
            .get(way)
            .map_or("general".to_string(), |i| format!("fast {i:?}"));
        let per = b / (reqs.len() * LANES) as f64 * 1e9;
        println!("{name}: {per:.1} ns per lane");
    }
    assert!(sink.is_finite());
}
