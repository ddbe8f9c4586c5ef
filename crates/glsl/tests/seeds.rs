//! The shaders of the seed documents (`tests/seeds/`, extracted with their
//! verdicts in a header; see `tests/seeds/README.md`).
//!
//! Every shader meant to be valid must compile; every one with a
//! transcription error must fail, and its diagnostics are pinned in
//! `NAME.out` so a reviewer can see that they name the real problem (run
//! with `BLESS=1` to rewrite after an intended change). The programs of
//! `programs.txt` must link or fail as listed.
//!
//! The lecture (seed 001) targets GL 3.3 and loads its shaders behind a
//! first source string `"#version 150\n"`. `lecture.txt` lists the files
//! compiled that way too (`FILE | 150 | pass` or `fail: <why>`; `150
//! compatibility` puts `"#version 150 compatibility\n"` first); failures
//! pin their diagnostics in `NAME.150.out` (`NAME.150-compatibility.out`).

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
    let mut opts = case_options(case);
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

/// The lecture's way of compiling a shader: `first` as its own source
/// string, then the file.
fn compile_after(first: &str, case: &Case, text: &str) -> Shader {
    compile(&[first, text], &case_options(case))
}

/// The options of a seed file: its stage, named by its file name.
fn case_options(case: &Case) -> CompileOptions {
    let mut opts = CompileOptions::new(case.stage);
    opts.name = case
        .path
        .file_name()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    opts
}

#[test]
fn seed_shaders_as_the_lecture_loads_them() {
    let list = fs::read_to_string(dir().join("lecture.txt")).unwrap();
    let bless = std::env::var_os("BLESS").is_some();
    let mut failures = Vec::new();
    let mut count = 0;
    for line in list
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
    {
        let parts: Vec<&str> = line.split('|').map(str::trim).collect();
        assert_eq!(parts.len(), 3, "bad line: {line}");
        let (file, version, expect) = (parts[0], parts[1], parts[2]);
        let (case, text) = load(&dir().join(file)).expect("seed file");
        count += 1;
        let expect_pass = expect == "pass" || expect.starts_with("pass:");
        let shader = compile_after(&format!("#version {version}\n"), &case, &text);
        if shader.ok() != expect_pass {
            failures.push(format!(
                "{file} (#version {version}): expected {expect}, got {}\n{}",
                if shader.ok() { "pass" } else { "fail" },
                shader.info_log()
            ));
        }
        if expect_pass {
            continue;
        }
        let out = format!(
            "{}-- terminal --\n{}",
            shader.info_log(),
            shader.render(false)
        );
        let golden = dir().join(format!("{file}.{}.out", version.replace(' ', "-")));
        if bless {
            fs::write(&golden, &out).unwrap();
        } else if fs::read_to_string(&golden).ok().as_deref() != Some(out.as_str()) {
            failures.push(format!(
                "{file} (#version {version}): diagnostics differ from the golden\n{out}"
            ));
        }
    }
    assert!(count >= 8, "only {count} lecture cases found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The lecture's three-string example: `"#version 150\n"`, a shared
/// `common.glsl` and the stage's own file, as three source strings of one
/// shader. The two files are not in the lecture (it names them only);
/// `tests/lecture/` has a plausible pair.
#[test]
fn lecture_three_string_source() {
    let lecture = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/lecture");
    let common = fs::read_to_string(lecture.join("common.glsl")).unwrap();
    let mut program = Vec::new();
    for (file, stage) in [("mesh.vert", Stage::Vertex), ("mesh.frag", Stage::Fragment)] {
        let text = fs::read_to_string(lecture.join(file)).unwrap();
        let mut opts = CompileOptions::new(stage);
        opts.name = file.to_string();
        let shader = compile(&["#version 150\n", &common, &text], &opts);
        assert!(shader.ok(), "{file}: {}", shader.info_log());
        assert_eq!(shader.language.version, Version::V150);
        program.push(shader);
    }
    let linked = link(&program.iter().collect::<Vec<_>>());
    assert!(linked.ok(), "{}", linked.info_log());
    // An error in the second string is reported in source string 1, on
    // that string's own line numbers.
    let mut opts = CompileOptions::new(Stage::Vertex);
    opts.name = "mesh.vert".into();
    let broken = compile(
        &[
            "#version 150\n",
            "float shade(vec3 n) {\n  return n;\n}\n",
            "void main() {}\n",
        ],
        &opts,
    );
    assert!(!broken.ok());
    assert!(
        broken.info_log().starts_with("1:2("),
        "{}",
        broken.info_log()
    );
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
