//! The shaders of the seed documents (`tests/seeds/`, extracted with their
//! verdicts in a header; see `tests/seeds/README.md`).
//!
//! Every shader meant to be valid must compile; every one with a
//! transcription error must fail, and its diagnostics are pinned in
//! `NAME.out` so a reviewer can see that they name the real problem (run
//! with `BLESS=1` to rewrite after an intended change). The programs of
//! `programs.txt` must link or fail as listed.

use glsl::{compile, link::link, CompileOptions, Shader, Stage, Version};
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

struct Case {
    path: PathBuf,
    expect_pass: bool,
    version: Option<Version>,
    stage: Stage,
}

fn header(text: &str, key: &str) -> Option<String> {
    text.lines()
        .take_while(|l| l.starts_with("//"))
        .find_map(|l| {
            l.strip_prefix(&format!("// {key}:"))
                .map(|v| v.trim().to_string())
        })
}

fn load(path: &Path) -> Option<(Case, String)> {
    let text = fs::read_to_string(path).ok()?;
    let expect = header(&text, "expect")?;
    let stage = match path.extension()?.to_str()? {
        "vert" => Stage::Vertex,
        "frag" => Stage::Fragment,
        _ => return None,
    };
    let version = header(&text, "version")
        .and_then(|v| v.parse().ok())
        .and_then(Version::from_number);
    let case = Case {
        path: path.to_path_buf(),
        expect_pass: expect == "pass",
        version,
        stage,
    };
    Some((case, text))
}

fn compile_case(case: &Case, text: &str) -> Shader {
    let mut opts = CompileOptions::new(case.stage);
    opts.name = case
        .path
        .file_name()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    opts.default_version = case.version;
    compile(&[text], &opts)
}

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/seeds")
}

#[test]
fn seed_shaders() {
    let mut paths: Vec<PathBuf> = fs::read_dir(dir())
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    paths.sort();
    let bless = std::env::var_os("BLESS").is_some();
    let mut failures = Vec::new();
    let mut count = 0;
    for path in paths {
        let Some((case, text)) = load(&path) else {
            continue;
        };
        count += 1;
        let shader = compile_case(&case, &text);
        if shader.ok() != case.expect_pass {
            failures.push(format!(
                "{}: expected {}, got {}\n{}",
                path.display(),
                if case.expect_pass { "pass" } else { "fail" },
                if shader.ok() { "pass" } else { "fail" },
                shader.info_log()
            ));
        }
        if !case.expect_pass {
            let out = format!(
                "{}-- terminal --\n{}",
                shader.info_log(),
                shader.render(false)
            );
            let mut name = path.file_name().unwrap().to_os_string();
            name.push(".out");
            let golden = path.with_file_name(name);
            if bless {
                fs::write(&golden, &out).unwrap();
            } else if fs::read_to_string(&golden).ok().as_deref() != Some(out.as_str()) {
                failures.push(format!(
                    "{}: diagnostics differ from the golden\n{out}",
                    path.display()
                ));
            }
        }
    }
    assert!(count >= 30, "only {count} seed shaders found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn seed_programs() {
    let list = fs::read_to_string(dir().join("programs.txt")).unwrap();
    let mut cache: BTreeMap<String, Shader> = BTreeMap::new();
    let mut failures = Vec::new();
    for line in list
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
    {
        let parts: Vec<&str> = line.split('|').collect();
        assert_eq!(parts.len(), 3, "bad line: {line}");
        let files: Vec<&str> = parts[0]
            .split_whitespace()
            .chain(parts[1].split_whitespace())
            .collect();
        let expect_pass = parts[2].trim() == "pass";
        for f in &files {
            if !cache.contains_key(*f) {
                let (case, text) = load(&dir().join(f)).expect("seed file");
                cache.insert(f.to_string(), compile_case(&case, &text));
            }
        }
        let shaders: Vec<&Shader> = files.iter().map(|f| &cache[*f]).collect();
        let program = link(&shaders);
        if program.ok() != expect_pass {
            failures.push(format!(
                "{line}: link {}\n{}",
                if program.ok() { "succeeded" } else { "failed" },
                program.info_log()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
