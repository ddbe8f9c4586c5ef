//! Fuzzes the preprocessor alone (`glsl::pp::preprocess` over the raw
//! lexer), which the `compile` target leaves after the first error it
//! reports. The first byte is the control byte of the GLSL targets
//! (`common/control.rs`: stage, context, default version); the rest is split at
//! every NUL byte into separate source strings, as `glShaderSource` with a
//! count above one passes them (each lossily decoded). Every token's and
//! diagnostic's position is mapped back through the `#line` table and the
//! info log rendered. Any panic, hang or out-of-memory is a bug.
#![no_main]

use glsl::diag::render_info_log;
use glsl::pp::{preprocess, PpOptions};
use glsl::source::SourceMap;
use libfuzzer_sys::fuzz_target;

#[path = "common/control.rs"]
mod control;

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let c = control::control(first);
    let mut opts = PpOptions::new(c.stage);
    opts.compatibility_context = c.compatibility_context;
    if let Some(v) = c.default_version {
        opts.default_version = v;
    }
    let strings: Vec<String> = rest
        .split(|&b| b == 0)
        .map(|s| String::from_utf8_lossy(s).into_owned())
        .collect();
    let refs: Vec<&str> = strings.iter().map(String::as_str).collect();
    let mut map = SourceMap::from_strings("fuzz", &refs);
    let out = preprocess(&mut map, &opts);
    assert!(
        out.tokens.last().is_some(),
        "the token list always ends with Eof"
    );
    for t in &out.tokens {
        let _ = map.loc(t.span.start);
        let _ = map.slice(t.span);
    }
    let _ = render_info_log(&out.diagnostics, &map);
});
