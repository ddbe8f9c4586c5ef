//! Fuzzes the whole front end: preprocessor, parser, analyzer, validator,
//! and the linker on the result. The first byte picks the stage (bit 0),
//! whether the context offers the compatibility profile (bit 1, clear =
//! yes) and the version of a shader without `#version` (bits 2-4, an index
//! into `Version::ALL`); the rest is the shader text (lossily decoded, as
//! GL would receive arbitrary bytes). Any panic, hang or out-of-memory is
//! a bug.
#![no_main]

use glsl::{compile, link::link, CompileOptions, Stage, Version};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let stage = if first & 1 == 0 {
        Stage::Vertex
    } else {
        Stage::Fragment
    };
    let mut opts = CompileOptions::new(stage);
    opts.compatibility_context = first & 2 == 0;
    opts.default_version = Version::ALL.get(usize::from(first >> 2 & 7)).copied();
    let text = String::from_utf8_lossy(rest);
    let shader = compile(&[&text], &opts);
    let _ = shader.info_log();
    let _ = shader.render(false);
    if shader.ok() {
        let _ = link(&[&shader]);
    }
});
