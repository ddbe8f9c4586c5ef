//! Golden reports of `shaderbox debug`: each `tests/debug/*.shader_test`
//! names its arguments on its first line (`# args: --pixel X,Y ...`); the
//! report must equal `<name>.out` byte for byte. `BLESS=1` rewrites the
//! expected files.

use std::path::Path;
use std::process::Command;

#[test]
fn debug_reports_match_the_golden_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/debug");
    let mut cases: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/debug")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "shader_test"))
        .collect();
    cases.sort();
    assert!(
        cases.len() >= 8,
        "expected the golden cases, found {}",
        cases.len()
    );
    let bless = std::env::var_os("BLESS").is_some();
    let mut failures = Vec::new();
    for case in &cases {
        let text = std::fs::read_to_string(case).expect("read case");
        let args: Vec<&str> = text
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("# args:"))
            .expect("first line `# args: ...`")
            .split_whitespace()
            .collect();
        let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
            .arg("debug")
            .arg(case)
            .args(&args)
            .env("SHADERBOX_THREADS", "2")
            .output()
            .expect("run shaderbox");
        assert!(
            out.status.success(),
            "{}: {}",
            case.display(),
            String::from_utf8_lossy(&out.stderr)
        );
        let got = String::from_utf8_lossy(&out.stdout).into_owned();
        let golden = case.with_extension("out");
        if bless {
            std::fs::write(&golden, &got).expect("write golden");
            continue;
        }
        let want = std::fs::read_to_string(&golden).unwrap_or_default();
        if got != want {
            failures.push(format!(
                "{}:\n--- expected\n{want}\n--- got\n{got}",
                case.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn bad_arguments_are_clear_errors() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/debug");
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_shaderbox"))
            .arg("debug")
            .args(args)
            .output()
            .expect("run shaderbox")
    };
    let case = dir.join("discard.shader_test");
    let case = case.to_str().expect("path");
    let out = run(&[case, "--pixel", "3"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("two non-negative integers"));
    let out = run(&["/nonexistent.shader_test", "--pixel", "1,1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("could not read"));
    // A pixel outside the window: the report says why nothing reached it.
    let out = run(&[case, "--pixel", "9999,1"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("outside the"));
}
