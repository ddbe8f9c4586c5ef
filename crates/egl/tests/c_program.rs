//! The C program tests/c/triangle.c, compiled with the system's C compiler
//! and linked against the built libEGL.so under its SONAME, draws a
//! triangle with a surfaceless context (into a framebuffer object) and
//! with a pbuffer, on EGL_DEFAULT_DISPLAY and on the device platform, and
//! checks the pixels it reads back.

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

#[test]
fn surfaceless_and_pbuffer_triangles() {
    let lib = profile_dir().join("libEGL.so");
    assert!(
        lib.exists(),
        "{} not built: `cargo test` does not write the cdylib in a fresh target \
         directory; run `cargo build -p shaderbox-egl` first (.ci/run does)",
        lib.display()
    );
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("egl-c-program");
    std::fs::create_dir_all(&dir).unwrap();
    let so = dir.join("libEGL.so.1");
    let _ = std::fs::remove_file(&so);
    std::os::unix::fs::symlink(&lib, &so).unwrap();
    let exe = dir.join("triangle");
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/c/triangle.c");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let built = Command::new(&cc)
        .arg("-o")
        .arg(&exe)
        .arg(&src)
        .arg("-L")
        .arg(&dir)
        .arg("-l:libEGL.so.1")
        .status()
        .unwrap_or_else(|e| panic!("running {cc}: {e}"));
    assert!(built.success(), "compiling {}", src.display());
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
