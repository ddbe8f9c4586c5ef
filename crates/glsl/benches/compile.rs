//! Compile+link time of the seed talk's sphere-impostor program (the pair
//! in `tests/seeds/000-sphere.{vert,frag}`), the figure compared with Mesa's
//! in `docs/PERFORMANCE.md` (`bench/mesa_compile.py` times Mesa on the same
//! files).
//!
//!     cargo bench -p shaderbox-glsl --bench compile

use criterion::{criterion_group, criterion_main, Criterion};
use glsl::{compile, link::link, CompileOptions, Stage};
use std::hint::black_box;

// The same allocator as the shipped binaries (crates/cli, the C library).
#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn seed(name: &str) -> String {
    let path = format!("{}/tests/seeds/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn sphere_program(c: &mut Criterion) {
    let vs = seed("000-sphere.vert");
    let fs = seed("000-sphere.frag");
    // No #version in the seed: GLSL 1.10, as Mesa compiles it.
    let opts = CompileOptions::new;
    let (vo, fo) = (opts(Stage::Vertex), opts(Stage::Fragment));
    // Warm the per-version built-in tables, as a running application has.
    assert!(link(&[&compile(&[&vs], &vo), &compile(&[&fs], &fo)]).ok());
    c.bench_function("compile+link sphere impostor", |b| {
        b.iter(|| {
            let v = compile(&[black_box(&vs)], &vo);
            let f = compile(&[black_box(&fs)], &fo);
            black_box(link(&[&v, &f]))
        })
    });
}

/// The same program read as GLSL 1.50 (compatibility profile, which keeps
/// the fixed-function built-ins it uses), behind a first source string
/// `#version 150 compatibility`: what a 1.50 program of the same size
/// costs beside the 1.10 one above.
fn sphere_program_150(c: &mut Criterion) {
    let vs = seed("000-sphere.vert");
    let fs = seed("000-sphere.frag");
    let first = "#version 150 compatibility\n";
    let opts = CompileOptions::new;
    let (vo, fo) = (opts(Stage::Vertex), opts(Stage::Fragment));
    assert!(link(&[&compile(&[first, &vs], &vo), &compile(&[first, &fs], &fo)]).ok());
    c.bench_function("compile+link sphere impostor, 1.50 compatibility", |b| {
        b.iter(|| {
            let v = compile(&[first, black_box(&vs)], &vo);
            let f = compile(&[first, black_box(&fs)], &fo);
            black_box(link(&[&v, &f]))
        })
    });
}

criterion_group!(benches, sphere_program, sphere_program_150);
criterion_main!(benches);
