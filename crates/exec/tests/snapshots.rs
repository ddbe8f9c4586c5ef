//! Snapshot tests of the front end's IR, of lowering (inlining, unrolling,
//! masks) and of the executor's rewrite (hoisting, dead code, store
//! fusion): for each shader below, `tests/snapshots/<name>.ir` is the
//! linked stage's `glsl::ir::Module` as text, `<name>.lowered` is
//! `Kernel::print_lowered` and `<name>.rewritten` is
//! `Kernel::print_rewritten`; each must equal the current output byte for
//! byte.
//!
//! `BLESS=1 cargo test -p shaderbox-exec --test snapshots` rewrites the
//! expected files (and deletes those no case makes). Without `BLESS`, a
//! difference, a missing expected file or a stray one fails, with the
//! first differing lines.
//!
//! The shaders: seed shaders of `shaders/` (sphere impostors, the lit
//! materials shader, the Phong library linked with a main) and small ones
//! in `tests/snapshots/` for what lowering treats specially (counted loops
//! unrolled or not, inlined calls, the light loop, texture lookups and
//! `discard`, a vertex stage with `ftransform`).

use glsl::ir::Stage;
use glsl::{compile, CompileOptions};
use std::path::{Path, PathBuf};

/// A snapshot case: its name (the prefix of its expected files), its
/// stage and its shader objects (paths from the workspace root).
struct Case {
    name: &'static str,
    stage: Stage,
    sources: &'static [&'static str],
}

const CASES: &[Case] = &[
    Case {
        name: "sphere.vert",
        stage: Stage::Vertex,
        sources: &["shaders/sphere.vert"],
    },
    Case {
        name: "sphere.frag",
        stage: Stage::Fragment,
        sources: &["shaders/sphere.frag"],
    },
    Case {
        name: "materials.frag",
        stage: Stage::Fragment,
        sources: &["shaders/materials.frag"],
    },
    Case {
        name: "one-sided-lighting.frag",
        stage: Stage::Fragment,
        sources: &[
            "shaders/one-sided-lighting.frag",
            "shaders/phong-lighting-lib.frag",
        ],
    },
    Case {
        name: "counted-loop.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/counted-loop.frag"],
    },
    Case {
        name: "dynamic-loops.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/dynamic-loops.frag"],
    },
    Case {
        name: "calls.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/calls.frag"],
    },
    Case {
        name: "light-loop.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/light-loop.frag"],
    },
    Case {
        name: "texture-discard.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/texture-discard.frag"],
    },
    Case {
        name: "texel-fetch.frag",
        stage: Stage::Fragment,
        sources: &["crates/exec/tests/snapshots/texel-fetch.frag"],
    },
    Case {
        name: "ftransform.vert",
        stage: Stage::Vertex,
        sources: &["crates/exec/tests/snapshots/ftransform.vert"],
    },
];

/// The kinds of snapshot, by file extension.
const KINDS: [&str; 3] = ["ir", "lowered", "rewritten"];

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn snapshot_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots")
}

/// The three texts of a case, in the order of [`KINDS`].
fn texts(case: &Case) -> [String; 3] {
    let root = workspace_root();
    let sources: Vec<String> = case
        .sources
        .iter()
        .map(|p| std::fs::read_to_string(root.join(p)).unwrap_or_else(|e| panic!("read {p}: {e}")))
        .collect();
    let shaders: Vec<glsl::Shader> = sources
        .iter()
        .zip(case.sources)
        .map(|(src, path)| {
            let mut opts = CompileOptions::new(case.stage);
            opts.name = path.to_string();
            let sh = compile(&[src], &opts);
            assert!(sh.ok(), "{path} does not compile:\n{}", sh.info_log());
            sh
        })
        .collect();
    let refs: Vec<&glsl::Shader> = shaders.iter().collect();
    let program = glsl::link::link(&refs);
    assert!(
        program.ok(),
        "{} does not link:\n{}",
        case.name,
        program.info_log()
    );
    let stage = program.stage(case.stage).expect("the linked stage");
    let kernel =
        exec::Kernel::new(stage).unwrap_or_else(|e| panic!("{}: lowering failed: {e}", case.name));
    [
        stage.module.to_string(),
        kernel.print_lowered(),
        kernel.print_rewritten(),
    ]
}

/// The first difference of two texts: its line number and a few lines of
/// context from each.
fn first_difference(want: &str, got: &str) -> String {
    let w: Vec<&str> = want.lines().collect();
    let g: Vec<&str> = got.lines().collect();
    let at = (0..w.len().max(g.len()))
        .find(|&i| w.get(i) != g.get(i))
        .unwrap_or(w.len().min(g.len()));
    let from = at.saturating_sub(2);
    let show = |lines: &[&str]| -> String {
        let mut s = String::new();
        for (i, line) in lines.iter().enumerate().skip(from).take(at - from + 4) {
            let marker = if i == at { '>' } else { ' ' };
            s.push_str(&format!("{marker}{:>5} | {line}\n", i + 1));
        }
        if at >= lines.len() {
            s.push_str(&format!(">{:>5} | <end of text>\n", lines.len() + 1));
        }
        s
    };
    format!(
        "first difference at line {} ({} lines expected, {} got)\n--- expected\n{}--- got\n{}",
        at + 1,
        w.len(),
        g.len(),
        show(&w),
        show(&g)
    )
}

#[test]
fn snapshots_match() {
    let bless = std::env::var_os("BLESS").is_some();
    let dir = snapshot_dir();
    let mut failures = Vec::new();
    let mut expected_files = Vec::new();
    for case in CASES {
        for (kind, got) in KINDS.iter().zip(texts(case)) {
            let file = format!("{}.{kind}", case.name);
            let path = dir.join(&file);
            expected_files.push(file.clone());
            if bless {
                std::fs::write(&path, &got).unwrap_or_else(|e| panic!("write {file}: {e}"));
                continue;
            }
            match std::fs::read_to_string(&path) {
                Err(e) => failures.push(format!("{file}: cannot read the expected file ({e})")),
                Ok(want) if want != got => {
                    failures.push(format!("{file}: {}", first_difference(&want, &got)))
                }
                Ok(_) => {}
            }
        }
    }
    // Expected files no case makes any more.
    for entry in std::fs::read_dir(&dir).expect("tests/snapshots") {
        let path = entry.expect("directory entry").path();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_string();
        let is_snapshot = KINDS
            .iter()
            .any(|k| path.extension().is_some_and(|e| e == *k));
        if is_snapshot && !expected_files.contains(&name) {
            if bless {
                std::fs::remove_file(&path).unwrap_or_else(|e| panic!("remove {name}: {e}"));
            } else {
                failures.push(format!("{name}: no case makes this file"));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} snapshot(s) differ (rerun with BLESS=1 to accept the new output):\n\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn output_is_deterministic() {
    // Two compilations of the same shader give the same texts.
    let case = &CASES[1];
    assert_eq!(texts(case), texts(case));
}

#[test]
fn differences_are_reported_by_line() {
    let d = first_difference("a\nb\nc\n", "a\nx\nc\n");
    assert!(
        d.starts_with("first difference at line 2 (3 lines expected, 3 got)"),
        "{d}"
    );
    assert!(d.contains(">    2 | b\n"), "{d}");
    assert!(d.contains(">    2 | x\n"), "{d}");
    let d = first_difference("a\n", "a\nb\n");
    assert!(d.contains(">    2 | <end of text>"), "{d}");
}
