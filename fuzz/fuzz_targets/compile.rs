//! Fuzzes the whole front end: preprocessor, parser, analyzer, validator,
//! and the linker on the result. The first byte is the control byte
//! (`common/control.rs`: stage, context, default version); the rest is
//! the shader text (lossily decoded, as GL would receive arbitrary bytes).
//! Any panic, hang or out-of-memory is a bug.
#![no_main]

#[path = "common/control.rs"]
mod control;

use glsl::{compile, link::link, CompileOptions};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let c = control::control(first);
    let mut opts = CompileOptions::new(c.stage);
    opts.compatibility_context = c.compatibility_context;
    opts.default_version = c.default_version;
    let text = String::from_utf8_lossy(rest);
    let shader = compile(&[&text], &opts);
    let _ = shader.info_log();
    let _ = shader.render(false);
    if shader.ok() {
        let _ = link(&[&shader]);
    }
});
