//! The GLVND route: tests/c/triangle.c linked against the SYSTEM's
//! `libEGL.so.1` (libglvnd), run with `__EGL_VENDOR_LIBRARY_FILENAMES`
//! naming a vendor JSON whose library is the built libEGL.so, draws its
//! triangles through shaderbox (EGL_VENDOR and GL_RENDERER say so, pixels
//! checked by the program) on EGL_DEFAULT_DISPLAY and on the device
//! platform (eglQueryDevicesEXT in libglvnd, eglQueryDeviceStringEXT
//! through our dispatch stub). Without the JSON the same binary finds no
//! display, so the drawing did go through the vendor.
//!
//! A Python script on PyOpenGL's EGL platform does the same through the
//! system's libEGL.so.1 and libOpenGL.so.0 (GL calls through libGLdispatch's
//! exported stubs rather than eglGetProcAddress).
//!
//! Skipped, with the reason printed, when the C compiler finds no
//! `libEGL.so.1` or the one it finds is not libglvnd's (and the Python
//! test when `python3` cannot import PyOpenGL).

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

/// A directory for test `name` with a vendor JSON naming the built
/// library: (directory, JSON path).
fn vendor_json(name: &str) -> (PathBuf, PathBuf) {
    let lib = profile_dir().join("libEGL.so");
    assert!(
        lib.exists(),
        "{} not built: run `cargo build -p shaderbox-egl` first (.ci/run does)",
        lib.display()
    );
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
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
    (dir, json)
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
    let (dir, json) = vendor_json("egl-glvnd");
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

/// A full-viewport red triangle on a green clear in a 16x16 pbuffer, with
/// the fixed-function pipeline (of the compatibility context a default
/// request gets); prints the vendor strings and the
/// corner and centre pixels, then "ok".
const PYOPENGL_TRIANGLE: &str = r#"
import ctypes
from OpenGL import EGL, GL
dpy = EGL.eglGetDisplay(EGL.EGL_DEFAULT_DISPLAY)
assert EGL.eglInitialize(dpy, None, None)
attribs = (EGL.EGLint * 5)(EGL.EGL_SURFACE_TYPE, EGL.EGL_PBUFFER_BIT,
                           EGL.EGL_RENDERABLE_TYPE, EGL.EGL_OPENGL_BIT, EGL.EGL_NONE)
configs = (EGL.EGLConfig * 1)()
n = EGL.EGLint()
assert EGL.eglChooseConfig(dpy, attribs, configs, 1, ctypes.pointer(n)) and n.value == 1
assert EGL.eglBindAPI(EGL.EGL_OPENGL_API)
ctx = EGL.eglCreateContext(dpy, configs[0], EGL.EGL_NO_CONTEXT, None)
size = (EGL.EGLint * 5)(EGL.EGL_WIDTH, 16, EGL.EGL_HEIGHT, 16, EGL.EGL_NONE)
pb = EGL.eglCreatePbufferSurface(dpy, configs[0], size)
assert EGL.eglMakeCurrent(dpy, pb, pb, ctx)
print("EGL_VENDOR:", EGL.eglQueryString(dpy, EGL.EGL_VENDOR).decode())
print("GL_RENDERER:", GL.glGetString(GL.GL_RENDERER).decode())
GL.glClearColor(0, 1, 0, 1)
GL.glClear(GL.GL_COLOR_BUFFER_BIT)
GL.glColor3f(1, 0, 0)
GL.glBegin(GL.GL_TRIANGLES)
GL.glVertex2f(-1, -1)
GL.glVertex2f(1, -1)
GL.glVertex2f(-1, 1)
GL.glEnd()
px = bytes(GL.glReadPixels(0, 0, 16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
at = lambda x, y: tuple(px[(y * 16 + x) * 4:(y * 16 + x) * 4 + 4])
assert at(2, 2) == (255, 0, 0, 255), at(2, 2)
assert at(14, 14) == (0, 255, 0, 255), at(14, 14)
assert EGL.eglMakeCurrent(dpy, EGL.EGL_NO_SURFACE, EGL.EGL_NO_SURFACE, EGL.EGL_NO_CONTEXT)
assert EGL.eglTerminate(dpy)
print("ok")
"#;

#[test]
fn pyopengl_through_system_libglvnd() {
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    if let Err(why) = system_glvnd_egl(&cc) {
        println!("skipped: {why}");
        return;
    }
    let python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".into());
    let has_pyopengl = Command::new(&python)
        .args(["-c", "import OpenGL"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_pyopengl {
        println!(
            "skipped: {python} cannot import PyOpenGL (Debian: apt-get install python3-opengl)"
        );
        return;
    }
    let (_, json) = vendor_json("egl-glvnd-python");
    let out = Command::new(&python)
        .args(["-c", PYOPENGL_TRIANGLE])
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("LD_PRELOAD")
        .env_remove("EGL_PLATFORM")
        .env("PYOPENGL_PLATFORM", "egl")
        .env("__EGL_VENDOR_LIBRARY_FILENAMES", &json)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let text = format!("{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success() && stdout.ends_with("ok\n"), "{text}");
    assert!(stdout.contains("EGL_VENDOR: shaderbox\n"), "{text}");
    assert!(stdout.contains("GL_RENDERER: shaderbox"), "{text}");
}
