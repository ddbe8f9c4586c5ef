//! Runs the preprocessor over piglit's GLSL 1.10/1.20 compiler tests.
//!
//! Needs piglit extracted under /tmp/piglit and the test list in
//! /tmp/glslparser_list.txt, so it is ignored by default:
//! `cargo test -p shaderbox-glsl --test pp_piglit -- --ignored --nocapture`.
//!
//! Checks: no panic on any file; no preprocessor error in a test expected
//! to pass; and a preprocessor error in every test expected to fail whose
//! failure is a preprocessor matter.

use glsl::diag::Diagnostic;
use glsl::ir::Stage;
use glsl::pp::{preprocess, PpOptions};
use glsl::SourceMap;
use std::panic;

const PIGLIT: &str = "/tmp/piglit/usr/lib/x86_64-linux-gnu/piglit";
const LIST: &str = "/tmp/glslparser_list.txt";

/// Old glslparsertest files about the preprocessor (from piglit's
/// glslparser.xml), with their expected verdicts.
const EXTRA: &[(&str, &str)] = &[
    ("tests/glslparsertest/shaders/version3.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/version2.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess7.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess6.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess4.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess3.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess2.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess10.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess1.frag", "fail"),
    ("tests/glslparsertest/shaders/preprocess0.frag", "fail"),
    ("tests/glslparsertest/shaders/extension9.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension8.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension7.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension6.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension5.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension3.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/extension2.V110.frag", "fail"),
    ("tests/glslparsertest/shaders/comment.frag", "fail"),
    (
        "tests/glslparsertest/shaders/CorrectVersion1.V110.frag",
        "fail",
    ),
    (
        "tests/glslparsertest/shaders/CorrectVersion.V110.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectPreprocess9.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectPreprocess8.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectPreprocess5.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectExtension4.V110.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectExtension10.V110.frag",
        "pass",
    ),
    (
        "tests/glslparsertest/shaders/CorrectExtension1.V110.frag",
        "pass",
    ),
    ("tests/glslparsertest/glsl2/preprocessor-01.frag", "pass"),
    ("tests/glslparsertest/glsl2/pragma-08.frag", "pass"),
    ("tests/glslparsertest/glsl2/pragma-07.vert", "pass"),
    ("tests/glslparsertest/glsl2/pragma-06.vert", "fail"),
    ("tests/glslparsertest/glsl2/pragma-05.vert", "fail"),
    ("tests/glslparsertest/glsl2/pragma-04.vert", "fail"),
    ("tests/glslparsertest/glsl2/pragma-03.vert", "fail"),
    ("tests/glslparsertest/glsl2/pragma-02.vert", "pass"),
    ("tests/glslparsertest/glsl2/pragma-01.vert", "pass"),
    (
        "tests/glslparsertest/glsl2/glsl-pp-elif-no-expression-2.frag",
        "fail",
    ),
    ("tests/glslparsertest/glsl2/defined-02.vert", "pass"),
    ("tests/glslparsertest/glsl2/defined-01.vert", "pass"),
];

/// Tests whose expected failure is the preprocessor's (or the lexer's) to
/// report. Others that fail do so in the parser or semantic analysis.
fn is_pp_matter(path: &str) -> bool {
    let name = path.rsplit('/').next().unwrap_or(path);
    path.contains("/preprocessor/")
        || path.contains("/literals/")
        || name.starts_with("version")
        || name.starts_with("invalid-version")
        || name.starts_with("extension")
        || path.contains("glslparsertest/")
}

/// "Preprocessor matter" tests expected to fail whose failure comes later:
/// preprocess6 uses `&`, `|`, `>>`..., operators GLSL 1.10 reserves (§5.1),
/// which the parser rejects.
const FAIL_ELSEWHERE: &[&str] = &["preprocess6.frag"];

struct Outcome {
    panicked: bool,
    errors: Vec<String>,
}

fn run_file(path: &str) -> Option<Outcome> {
    let text = std::fs::read_to_string(format!("{PIGLIT}/{path}")).ok()?;
    let stage = if path.ends_with(".frag") {
        Stage::Fragment
    } else {
        Stage::Vertex
    };
    let result = panic::catch_unwind(|| {
        let mut map = SourceMap::new(path, text.clone());
        let out = preprocess(&mut map, &PpOptions::new(stage));
        let errors: Vec<String> = out
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(|d: &Diagnostic| {
                let loc = map.loc(d.span.map_or(0, |s| s.start));
                format!("{}:{}: {}", loc.source, loc.line, d.message)
            })
            .collect();
        errors
    });
    Some(match result {
        Ok(errors) => Outcome {
            panicked: false,
            errors,
        },
        Err(_) => Outcome {
            panicked: true,
            errors: Vec::new(),
        },
    })
}

fn parse_list() -> Vec<(String, String)> {
    let list = std::fs::read_to_string(LIST).unwrap_or_default();
    list.lines()
        .filter_map(|line| {
            let cmd = line.split('\t').nth(1)?;
            let parts: Vec<&str> = cmd
                .trim_matches(|c| c == '[' || c == ']')
                .split(", ")
                .map(|s| s.trim_matches('\''))
                .collect();
            Some((parts.get(1)?.to_string(), parts.get(2)?.to_string()))
        })
        .collect()
}

#[test]
#[ignore]
fn piglit_preprocessor_verdicts() {
    let mut tests = parse_list();
    let listed = tests.len();
    tests.extend(EXTRA.iter().map(|(p, v)| (p.to_string(), v.to_string())));
    let (mut run, mut missing, mut panics) = (0, 0, 0);
    let (mut pp_tests, mut agree) = (0, 0);
    let mut pass_with_errors = Vec::new();
    let mut disagreements = Vec::new();
    for (path, expected) in &tests {
        let Some(outcome) = run_file(path) else {
            missing += 1;
            continue;
        };
        run += 1;
        if outcome.panicked {
            panics += 1;
            println!("PANIC {path}");
            continue;
        }
        let failed = !outcome.errors.is_empty();
        if expected == "pass" && failed {
            pass_with_errors.push(format!("{path}: {:?}", outcome.errors));
        }
        if is_pp_matter(path) {
            pp_tests += 1;
            let elsewhere = FAIL_ELSEWHERE.iter().any(|n| path.ends_with(n));
            if (expected == "fail") == failed || (expected == "fail" && elsewhere) {
                agree += 1;
            } else {
                disagreements.push(format!(
                    "{path}: expected {expected}, pp errors {:?}",
                    outcome.errors
                ));
            }
            println!(
                "{expected:4} {:4} {path} {:?}",
                if failed { "fail" } else { "pass" },
                outcome.errors
            );
        }
    }
    println!(
        "listed {listed} + extra {}; ran {run}, missing {missing}, panics {panics}",
        EXTRA.len()
    );
    println!(
        "expected-pass tests with preprocessor errors: {}",
        pass_with_errors.len()
    );
    for p in &pass_with_errors {
        println!("  {p}");
    }
    println!("preprocessor-matter tests: {pp_tests}, verdict agrees: {agree}");
    for d in &disagreements {
        println!("  DISAGREE {d}");
    }
    assert_eq!(panics, 0);
    assert!(pass_with_errors.is_empty());
    assert!(disagreements.is_empty());
}
