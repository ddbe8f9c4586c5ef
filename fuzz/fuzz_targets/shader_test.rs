//! Fuzzes the `.shader_test` reader of `shaderbox shader-runner` (the cli's
//! `shader_runner` module, compiled in here since the cli is a binary
//! crate): the bytes are lossily decoded as the command reads a file, the
//! sections parsed, every `[test]` line parsed, and then a script of at
//! most [`MAX_RUN_LINES`] test lines is run on a small context, so that
//! what the reader hands on is exercised too: requirements, compiling and
//! linking, vertex data, the commands, probes. The window is clamped to
//! [`MAX_SIDE`] pixels a side (a `SIZE` requirement can ask for any) and
//! the draw threads to one, which keeps each run short and the run
//! deterministic. Panics are not caught here (the command catches them to
//! report a crash to piglit; here any panic, hang or out-of-memory is a
//! bug).
#![no_main]
#![allow(dead_code, unused_imports)]

use libfuzzer_sys::fuzz_target;

#[path = "../../crates/cli/src/guard.rs"]
mod guard;
#[path = "../../crates/cli/src/shader_runner/mod.rs"]
mod shader_runner;

use shader_runner::script::{self, Requirement};

const MAX_RUN_LINES: usize = 64;
const MAX_SIDE: u32 = 16;

fuzz_target!(
    init: {
        std::env::set_var(gl::THREADS_ENV, "1");
    },
    |data: &[u8]| {
        let text = String::from_utf8_lossy(data);
        let Ok(mut script) = script::parse(&text) else {
            return;
        };
        if shader_runner::check_commands(&script).is_err() {
            return;
        }
        if script.test_lines.len() > MAX_RUN_LINES {
            return;
        }
        let (mut w, mut h) = (MAX_SIDE, MAX_SIDE);
        script.requirements.retain(|(_, r)| match r {
            Requirement::Size(rw, rh) => {
                (w, h) = ((*rw).clamp(1, MAX_SIDE), (*rh).clamp(1, MAX_SIDE));
                false
            }
            _ => true,
        });
        script.requirements.push((0, Requirement::Size(w, h)));
        let window = shader_runner::window_config(&script);
        let mut ctx = gl::Context::with_api(window.width, window.height, window.api);
        if window.api.is_core() {
            if let Some(&vao) = ctx.gen_vertex_arrays(1).first() {
                ctx.bind_vertex_array(vao);
            }
        }
        let opts = shader_runner::Options::default();
        let _ = shader_runner::execute_on(&mut ctx, &opts, "fuzz.shader_test", &script);
    }
);
