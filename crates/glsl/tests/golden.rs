//! Golden diagnostic tests.
//!
//! Each `tests/golden/NAME.vert` / `NAME.frag` is compiled alone; each
//! directory `tests/golden/NAME/` is a program: its shaders are compiled and
//! linked together. The diagnostics, in both renderings, must equal
//! `NAME.<ext>.out` / `NAME/expected.out` byte for byte. Run with
//! `BLESS=1 cargo test -p shaderbox-glsl --test golden` to rewrite the
//! expected files after an intended change, then review the diff.

use glsl::{compile, link::link, CompileOptions, Shader, Stage};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

fn stage_of(path: &Path) -> Option<Stage> {
    match path.extension()?.to_str()? {
        "vert" => Some(Stage::Vertex),
        "frag" => Some(Stage::Fragment),
        _ => None,
    }
}

fn compile_file(path: &Path) -> Option<Shader> {
    let stage = stage_of(path)?;
    let text = fs::read_to_string(path).ok()?;
    let mut opts = CompileOptions::new(stage);
    opts.name = path.file_name()?.to_string_lossy().into_owned();
    Some(compile(&[&text], &opts))
}

fn report(shaders: &[Shader], linked: bool) -> String {
    let mut out = String::new();
    for s in shaders {
        let _ = writeln!(
            out,
            "== {} ({}) ==",
            s.source.name,
            if s.ok() { "compiled" } else { "failed" }
        );
        out.push_str("-- info log --\n");
        out.push_str(&s.info_log());
        out.push_str("-- terminal --\n");
        out.push_str(&s.render(false));
    }
    if linked {
        let refs: Vec<&Shader> = shaders.iter().collect();
        let p = link(&refs);
        let _ = writeln!(
            out,
            "== link ({}) ==",
            if p.ok() { "linked" } else { "failed" }
        );
        out.push_str(p.info_log());
    }
    out
}

fn check(actual: &str, expected_path: &Path, failures: &mut Vec<String>) {
    if std::env::var_os("BLESS").is_some() {
        fs::write(expected_path, actual).expect("write golden");
        return;
    }
    match fs::read_to_string(expected_path) {
        Ok(exp) if exp == actual => {}
        Ok(exp) => failures.push(format!(
            "{}: output differs\n--- expected\n{exp}\n--- actual\n{actual}",
            expected_path.display()
        )),
        Err(_) => failures.push(format!(
            "{}: missing (run with BLESS=1)\n--- actual\n{actual}",
            expected_path.display()
        )),
    }
}

#[test]
fn golden_diagnostics() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut entries: Vec<PathBuf> = fs::read_dir(&dir)
        .expect("tests/golden")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    entries.sort();
    let mut failures = Vec::new();
    let mut count = 0;
    for path in entries {
        if path.is_dir() {
            let mut files: Vec<PathBuf> = fs::read_dir(&path)
                .expect("case dir")
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| stage_of(p).is_some())
                .collect();
            files.sort();
            let shaders: Vec<Shader> = files.iter().filter_map(|f| compile_file(f)).collect();
            check(
                &report(&shaders, true),
                &path.join("expected.out"),
                &mut failures,
            );
            count += 1;
        } else if stage_of(&path).is_some() {
            let Some(s) = compile_file(&path) else {
                continue;
            };
            let mut name = path.file_name().unwrap().to_os_string();
            name.push(".out");
            check(
                &report(&[s], false),
                &path.with_file_name(name),
                &mut failures,
            );
            count += 1;
        }
    }
    assert!(count > 0, "no golden cases found");
    assert!(
        failures.is_empty(),
        "{} golden mismatches:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
