//! A crude runner for piglit's generated built-in function execution tests
//! (`generated_tests/spec/glsl-1.{10,20}/execution/built-in-functions/`):
//! per `draw rect`, the vertex kernel runs on one lane group, its outputs
//! feed the fragment kernel's inputs by name (`gl_FrontColor` → `gl_Color`),
//! and the fragment color of lane 0 is compared with the matching
//! `probe rect` color. No rasterization: these tests draw constant colors.
//!
//! Ignored by default (needs the piglit files); run with
//! `cargo test -p shaderbox-exec piglit -- --ignored --nocapture`.

use super::link_one;
use crate::{Batch, Kernel, NoTextures, LANES};
use glsl::ir::Stage;
use glsl::{compile, CompileOptions};

const ROOT: &str = "/work/main/.piglit/root/usr/lib/x86_64-linux-gnu/piglit/generated_tests/spec";

struct Test {
    /// `GLSL >= 1.20` in `[require]`: shaders without `#version` are
    /// compiled as 1.20 (as the project's piglit harness does).
    v120: bool,
    vs: String,
    fs: String,
    commands: Vec<String>,
}

/// Runs `k` with the executor and with the reference interpreter and
/// checks they agree bit for bit.
fn run_both(k: &Kernel, b: &mut Batch, u: &[u32]) -> Result<(), crate::ExecError> {
    let mut r = b.clone();
    let input = b.clone();
    let got = k.run(b, u, &NoTextures);
    let want = k.run_reference(&mut r, u, &NoTextures);
    assert_eq!(got, want, "executor vs reference: result");
    if got.is_ok() {
        assert_eq!(b.discarded, r.discarded, "executor vs reference: discarded");
        assert_eq!(
            super::bits_of(&b.outputs),
            super::bits_of(&r.outputs),
            "executor vs reference: outputs"
        );
    }
    if crate::Variant::Jit.supported() {
        let mut n = input;
        let native = k.run_variant(crate::Variant::Jit, &mut n, u, &NoTextures);
        assert_eq!(native, want, "native vs reference: result");
        if native.is_ok() {
            assert_eq!(n.discarded, r.discarded, "native vs reference: discarded");
            assert_eq!(
                super::bits_of(&n.outputs),
                super::bits_of(&r.outputs),
                "native vs reference: outputs"
            );
        }
    }
    got
}

fn parse(text: &str) -> Test {
    let mut t = Test {
        v120: text.contains("GLSL >= 1.20"),
        vs: String::new(),
        fs: String::new(),
        commands: Vec::new(),
    };
    let mut section = "";
    for line in text.lines() {
        if line.starts_with('[') {
            section = match line.trim() {
                "[vertex shader]" => "vs",
                "[fragment shader]" => "fs",
                "[test]" => "test",
                _ => "",
            };
            continue;
        }
        match section {
            "vs" => {
                t.vs.push_str(line);
                t.vs.push('\n');
            }
            "fs" => {
                t.fs.push_str(line);
                t.fs.push('\n');
            }
            "test" => t.commands.push(line.trim().to_string()),
            _ => {}
        }
    }
    t
}

fn words(ty: &str, values: &[&str]) -> Vec<u32> {
    values
        .iter()
        .map(|v| {
            if ty.starts_with('i') || ty == "int" {
                v.parse::<i32>().unwrap_or(0) as u32
            } else if ty.starts_with('b') {
                matches!(*v, "true" | "1") as u32
            } else {
                v.parse::<f32>().unwrap_or(0.0).to_bits()
            }
        })
        .collect()
}

fn numbers(s: &str) -> Vec<f32> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e' || c == '+'))
        .filter(|x| !x.is_empty())
        .filter_map(|x| x.parse().ok())
        .collect()
}

fn set(k: &Kernel, words_out: &mut [u32], name: &str, v: &[u32]) {
    if let Some((off, _)) = k.interface().locate_uniform(name) {
        for (i, w) in v.iter().enumerate() {
            if let Some(slot) = words_out.get_mut(off + i) {
                *slot = *w;
            }
        }
    }
}

/// Runs one test; `Err` describes the first failure.
fn run_test(text: &str) -> Result<(), String> {
    let t = parse(text);
    let opts = |stage| {
        let mut o = CompileOptions::new(stage);
        if t.v120 {
            o.default_version = Some(glsl::Version::V120);
        }
        o
    };
    let vsh = compile(&[&t.vs], &opts(Stage::Vertex));
    let fsh = compile(&[&t.fs], &opts(Stage::Fragment));
    let prog = glsl::link::link(&[&vsh, &fsh]);
    if !prog.ok() {
        return Err(format!("link: {}", prog.info_log()));
    }
    let _ = link_one;
    let vs = Kernel::new(prog.stage(Stage::Vertex).ok_or("no vs")?).map_err(|e| e.to_string())?;
    let fs = Kernel::new(prog.stage(Stage::Fragment).ok_or("no fs")?).map_err(|e| e.to_string())?;
    let mut vu = vec![0u32; vs.interface().uniform_words];
    let mut fu = vec![0u32; fs.interface().uniform_words];
    let mut colors: Vec<[f32; 4]> = Vec::new();
    let mut probes = 0;
    for cmd in &t.commands {
        let parts: Vec<&str> = cmd.split_whitespace().collect();
        match parts.as_slice() {
            ["uniform", ty, name, values @ ..] => {
                let w = words(ty, values);
                set(&vs, &mut vu, name, &w);
                set(&fs, &mut fu, name, &w);
            }
            ["draw", "rect", ..] => {
                let mut vb = Batch::for_kernel(&vs, 0xf);
                if let Some(s) = vs.interface().input("gl_Vertex") {
                    for l in 0..4 {
                        vb.inputs[s.offset][l] = (l & 1) as f32;
                        vb.inputs[s.offset + 1][l] = (l >> 1) as f32;
                        vb.inputs[s.offset + 3][l] = 1.0;
                    }
                }
                run_both(&vs, &mut vb, &vu).map_err(|e| e.to_string())?;
                let mut fb = Batch::for_kernel(&fs, 0xffff);
                for input in &fs.interface().inputs {
                    let from = match input.name.as_str() {
                        "gl_Color" => "gl_FrontColor",
                        "gl_SecondaryColor" => "gl_FrontSecondaryColor",
                        n => n,
                    };
                    if let Some(out) = vs.interface().output(from) {
                        for c in 0..input.components.min(out.components) {
                            fb.inputs[input.offset + c] = [vb.outputs[out.offset + c][0]; LANES];
                        }
                    }
                }
                run_both(&fs, &mut fb, &fu).map_err(|e| e.to_string())?;
                let s = fs
                    .interface()
                    .output("gl_FragColor")
                    .ok_or("no gl_FragColor")?;
                let c: Vec<f32> = (0..4)
                    .map(|i| fb.outputs[s.offset + i][0].clamp(0.0, 1.0))
                    .collect();
                colors.push([c[0], c[1], c[2], c[3]]);
            }
            ["probe", "rect", "rgba", ..] => {
                let n = numbers(cmd);
                let want = &n[n.len().saturating_sub(4)..];
                let got = colors.get(probes).ok_or("probe without draw")?;
                if want.len() != 4 || got.iter().zip(want).any(|(g, w)| (g - w).abs() > 0.01) {
                    return Err(format!("probe {probes}: got {got:?}, want {want:?}"));
                }
                probes += 1;
            }
            ["probe", "all", kind @ ("rgb" | "rgba"), ..] => {
                let n = numbers(cmd);
                let comps = kind.len();
                let got = colors.last().ok_or("probe without draw")?;
                if n.len() != comps || got.iter().zip(&n).any(|(g, w)| (g - w).abs() > 0.01) {
                    return Err(format!("probe all: got {got:?}, want {n:?}"));
                }
                probes += 1;
            }
            _ => {}
        }
    }
    if probes == 0 {
        return Err("no probes".into());
    }
    Ok(())
}

#[test]
#[ignore = "needs the piglit files"]
fn piglit_builtin_function_tests() {
    let mut total = 0;
    let mut passed = 0;
    let mut failures = Vec::new();
    for version in ["glsl-1.10", "glsl-1.20"] {
        let dir = format!("{ROOT}/{version}/execution/built-in-functions");
        let Ok(entries) = std::fs::read_dir(&dir) else {
            eprintln!("skipping {dir}: not found");
            continue;
        };
        let mut files: Vec<_> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        files.sort();
        for f in files {
            if f.extension().and_then(|e| e.to_str()) != Some("shader_test") {
                continue;
            }
            let Ok(text) = std::fs::read_to_string(&f) else {
                continue;
            };
            total += 1;
            match run_test(&text) {
                Ok(()) => passed += 1,
                Err(e) => failures.push(format!("{}: {e}", f.display())),
            }
        }
    }
    for f in failures.iter().take(40) {
        eprintln!("FAIL {f}");
    }
    eprintln!("piglit built-in-functions: {passed}/{total} pass");
    assert_eq!(passed, total, "{} failures", failures.len());
}

/// Every shader of the 3138 execution tests (`/tmp/shader_tests.txt`):
/// compiled, linked, lowered and run once on zero inputs. Reports lowering
/// errors, loop-budget hits and panics (none expected).
#[test]
#[ignore = "needs the piglit files"]
fn piglit_execution_shaders_lower_and_run() {
    let base = "/work/main/.piglit/root/usr/lib/x86_64-linux-gnu/piglit";
    let Ok(list) = std::fs::read_to_string("/tmp/shader_tests.txt") else {
        eprintln!("skipping: no /tmp/shader_tests.txt");
        return;
    };
    let (mut files, mut linked, mut lowered, mut ran) = (0, 0, 0, 0);
    let mut problems = Vec::new();
    for line in list.lines() {
        let Some(start) = line
            .find("'tests/")
            .or_else(|| line.find("'generated_tests/"))
        else {
            continue;
        };
        let rest = &line[start + 1..];
        let Some(end) = rest.find('\'') else { continue };
        let path = format!("{base}/{}", &rest[..end]);
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        files += 1;
        let mut shaders: Vec<(Stage, String)> = Vec::new();
        let mut cur: Option<usize> = None;
        for l in text.lines() {
            if l.starts_with('[') {
                cur = None;
                let stage = match l.trim() {
                    "[vertex shader]" => Some(Stage::Vertex),
                    "[fragment shader]" => Some(Stage::Fragment),
                    "[vertex shader passthrough]" => {
                        shaders.push((
                            Stage::Vertex,
                            "attribute vec4 piglit_vertex; void main() { gl_Position = piglit_vertex; }".into(),
                        ));
                        None
                    }
                    _ => None,
                };
                if let Some(s) = stage {
                    shaders.push((s, String::new()));
                    cur = Some(shaders.len() - 1);
                }
                continue;
            }
            if let Some(i) = cur {
                shaders[i].1.push_str(l);
                shaders[i].1.push('\n');
            }
        }
        let v120 = text.contains("GLSL >= 1.20");
        let compiled: Vec<glsl::Shader> = shaders
            .iter()
            .map(|(stage, src)| {
                let mut o = CompileOptions::new(*stage);
                if v120 {
                    o.default_version = Some(glsl::Version::V120);
                }
                compile(&[src], &o)
            })
            .collect();
        let refs: Vec<&glsl::Shader> = compiled.iter().collect();
        let prog = glsl::link::link(&refs);
        if !prog.ok() {
            continue;
        }
        linked += 1;
        for st in &prog.stages {
            let r = std::panic::catch_unwind(|| {
                let mut k = Kernel::new(st)?;
                k.set_loop_budget(1 << 14);
                let mut b = Batch::for_kernel(&k, 0xffff);
                for (i, c) in b.inputs.iter_mut().enumerate() {
                    for (l, x) in c.iter_mut().enumerate() {
                        *x = (l as f32 - 6.5) * 0.37 + i as f32 * 0.11;
                    }
                }
                let u = vec![0u32; k.interface().uniform_words];
                run_both(&k, &mut b, &u).map(|_| true)
            });
            match r {
                Ok(Ok(_)) => {
                    lowered += 1;
                    ran += 1;
                }
                Ok(Err(e @ crate::ExecError::LoopBudget { .. })) => {
                    lowered += 1;
                    problems.push(format!("{path} ({}): {e}", st.stage.name()));
                }
                Ok(Err(e)) => problems.push(format!("{path} ({}): {e}", st.stage.name())),
                Err(_) => problems.push(format!("{path} ({}): PANIC", st.stage.name())),
            }
        }
    }
    for p in &problems {
        eprintln!("{p}");
    }
    eprintln!("{files} files, {linked} linked, {lowered} stages lowered, {ran} ran");
    assert!(!problems.iter().any(|p| p.ends_with("PANIC")));
}
