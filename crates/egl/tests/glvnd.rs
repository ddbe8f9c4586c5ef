//! The GLVND route: tests/c/triangle.c linked against the SYSTEM's
//! `libEGL.so.1` (libglvnd), run with `__EGL_VENDOR_LIBRARY_FILENAMES`
//! naming a vendor JSON whose library is the built libEGL.so, draws its
//! triangles through shaderbox (EGL_VENDOR and GL_RENDERER say so, pixels
//! checked by the program) on EGL_DEFAULT_DISPLAY and on the device
//! platform (eglQueryDevicesEXT in libglvnd, eglQueryDeviceStringEXT
//! through our dispatch stub). Without the JSON the same binary finds no
//! display, so the drawing did go through the vendor.
//!
//! Skipped, with the reason printed, when the C compiler finds no
//! `libEGL.so.1` or the one it finds is not libglvnd's.

use std::path::{Path, PathBuf};
use std::process::Command;

/// target/PROFILE, where cargo puts libEGL.so.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test path");
    exe.parent()
        .and_then(|p| p.parent())
        .expect("target/PROFILE/deps")
        .to_path_buf()
}

/// The system libEGL.so.1 the C compiler links against, if it is
/// libglvnd's (which reads the vendor-list variable); otherwise why not.
fn system_glvnd_egl(cc: &str) -> Result<PathBuf, String> {
    let out = Command::new(cc)
        .arg("-print-file-name=libEGL.so.1")
        .output()
        .map_err(|e| format!("running {cc}: {e}"))?;
    let path = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    if !path.is_absolute() {
        return Err(format!(
            "{cc} finds no libEGL.so.1 (Debian: apt-get install libegl1)"
        ));
    }
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let marker = b"__EGL_VENDOR_LIBRARY_FILENAMES";
    if !bytes.windows(marker.len()).any(|w| w == marker) {
        return Err(format!("{} is not libglvnd's libEGL", path.display()));
    }
    Ok(path)
}

fn run(exe: &Path, platform: &str, vendor_json: &Path) -> (bool, String) {
    let out = Command::new(exe)
        .arg(platform)
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("LD_PRELOAD")
        .env_remove("EGL_PLATFORM")
        .env("__EGL_VENDOR_LIBRARY_FILENAMES", vendor_json)
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.success(), text)
}

#[test]
fn triangles_through_system_libglvnd() {
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let system = match system_glvnd_egl(&cc) {
        Ok(p) => p,
        Err(why) => {
            println!("skipped: {why}");
            return;
        }
    };
    let lib = profile_dir().join("libEGL.so");
    assert!(
        lib.exists(),
        "{} not built: run `cargo build -p shaderbox-egl` first (.ci/run does)",
        lib.display()
    );
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("egl-glvnd");
    std::fs::create_dir_all(&dir).unwrap();
    let json = dir.join("50_shaderbox.json");
    std::fs::write(
        &json,
        format!(
            "{{\"file_format_version\": \"1.0.0\", \"ICD\": {{\"library_path\": \"{}\"}}}}\n",
            lib.display()
        ),
    )
    .unwrap();
    let exe = dir.join("triangle");
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/c/triangle.c");
    // No -L: the system's libEGL.so.1.
    let built = Command::new(&cc)
        .arg("-o")
        .arg(&exe)
        .arg(&src)
        .arg("-l:libEGL.so.1")
        .status()
        .unwrap_or_else(|e| panic!("running {cc}: {e}"));
    assert!(
        built.success(),
        "compiling {} against {}",
        src.display(),
        system.display()
    );
    for platform in ["default", "device"] {
        let (ok, text) = run(&exe, platform, &json);
        assert!(ok && text.contains("\nok"), "{platform}: {text}");
        assert!(text.contains("EGL_VENDOR: shaderbox\n"), "{text}");
        assert!(text.contains("GL_RENDERER: shaderbox"), "{text}");
        let (ok, text) = run(&exe, platform, &dir.join("absent.json"));
        assert!(
            !ok && text.contains("FAILED"),
            "{platform} without the vendor: {text}"
        );
    }
}
