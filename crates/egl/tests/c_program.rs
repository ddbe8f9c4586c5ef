//! C programs compiled with the system's C compiler and linked against
//! the built libEGL.so under its SONAME:
//!
//! - tests/c/triangle.c draws a triangle with a surfaceless context (into
//!   a framebuffer object) and with a pbuffer, on EGL_DEFAULT_DISPLAY and
//!   on the device platform, and checks the pixels it reads back;
//! - tests/c/errors.c makes bad EGL calls and prints each error code,
//!   compared with Mesa's codes for the same calls (recorded in
//!   tests/c/errors-mesa.txt) and the deliberate differences below.

use std::path::PathBuf;
use std::process::Command;

/// target/PROFILE, where cargo puts libEGL.so.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test path");
    exe.parent()
        .and_then(|p| p.parent())
        .expect("target/PROFILE/deps")
        .to_path_buf()
}

/// Compiles tests/c/NAME.c against the built library: (the program, the
/// directory holding it and `libEGL.so.1`, for LD_LIBRARY_PATH).
fn build(name: &str) -> (PathBuf, PathBuf) {
    let lib = profile_dir().join("libEGL.so");
    assert!(
        lib.exists(),
        "{} not built: `cargo test` does not write the cdylib in a fresh target \
         directory; run `cargo build -p shaderbox-egl` first (.ci/run does)",
        lib.display()
    );
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("egl-c-{name}"));
    std::fs::create_dir_all(&dir).unwrap();
    let so = dir.join("libEGL.so.1");
    let _ = std::fs::remove_file(&so);
    std::os::unix::fs::symlink(&lib, &so).unwrap();
    let exe = dir.join(name);
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("tests/c/{name}.c"));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let built = Command::new(&cc)
        .arg("-o")
        .arg(&exe)
        .arg(&src)
        .arg("-L")
        .arg(&dir)
        .arg("-l:libEGL.so.1")
        .arg("-lpthread")
        .status()
        .unwrap_or_else(|e| panic!("running {cc}: {e}"));
    assert!(built.success(), "compiling {}", src.display());
    (exe, dir)
}

#[test]
fn surfaceless_and_pbuffer_triangles() {
    let (exe, dir) = build("triangle");
    for platform in ["default", "device"] {
        let out = Command::new(&exe)
            .arg(platform)
            .env("LD_LIBRARY_PATH", &dir)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success() && stdout.contains("ok"),
            "{platform}: {stdout}{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(stdout.contains("GL_RENDERER: shaderbox"), "{stdout}");
    }
}

/// Where shaderbox's code differs from Mesa's on purpose: (check, what
/// shaderbox prints, why). EGL 1.5 is quoted by section.
const DIFFERENCES: &[(&str, &str, &str)] = &[
    (
        "platform-display-x11",
        "null 0x300c",
        "no X11 platform: \"An EGL_BAD_PARAMETER error is generated if platform \
         has an invalid value\" (EGL_EXT_platform_base); Mesa has one",
    ),
    (
        "query-api-initial",
        "0x3038 0x3000",
        "§3.7: \"The initial value of the current rendering API is \
         EGL_OPENGL_ES_API, unless OpenGL ES is not supported by an \
         implementation, in which case the initial value is EGL_NONE\"; \
         shaderbox has no OpenGL ES",
    ),
    (
        "thread-query-api-initial",
        "0x3038 0x3000",
        "the same rule on a new thread",
    ),
    (
        "query-api-after-release",
        "0x3038 0x3000",
        "§3.12: eglReleaseThread resets \"The current rendering API ... to its value at thread initialization\", EGL_NONE here",
    ),
    (
        "bind-api-opengl-es",
        "0 0x300c",
        "§3.7: \"if the client API specified by api is not supported by the \
         implementation, an EGL_BAD_PARAMETER error is generated\"",
    ),
    (
        "window-surface-pbuffer-config",
        "null 0x3009",
        "§3.5.1 names both EGL_BAD_MATCH (\"If config does not support \
         rendering to windows\") and EGL_BAD_NATIVE_WINDOW (an invalid native \
         window, which Mesa checks first); shaderbox has no window platform, \
         so no config has EGL_WINDOW_BIT",
    ),
];

/// `name rest` lines of a program's output or a record (comments skipped).
fn lines(text: &str) -> Vec<(String, String)> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| match l.split_once(' ') {
            Some((n, r)) => (n.to_string(), r.to_string()),
            None => (l.to_string(), String::new()),
        })
        .collect()
}

#[test]
fn error_codes_match_mesa_but_for_the_listed_differences() {
    let (exe, dir) = build("errors");
    let out = Command::new(&exe)
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let ours = lines(&stdout);
    let mesa = lines(include_str!("c/errors-mesa.txt"));
    let names = |v: &[(String, String)]| v.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&ours), names(&mesa), "the checks run differ");
    let mut wrong = Vec::new();
    for ((name, got), (_, theirs)) in ours.iter().zip(&mesa) {
        let want = DIFFERENCES
            .iter()
            .find(|(n, _, _)| n == name)
            .map_or(theirs.as_str(), |(_, ours, _)| *ours);
        if got != want {
            wrong.push(format!(
                "{name}: shaderbox {got}, expected {want} (Mesa {theirs})"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    for (name, _, _) in DIFFERENCES {
        let (_, theirs) = mesa.iter().find(|(n, _)| n == name).unwrap();
        let (_, got) = ours.iter().find(|(n, _)| n == name).unwrap();
        assert_ne!(
            got, theirs,
            "{name} no longer differs: drop it from DIFFERENCES"
        );
    }
}
