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

#[test]
fn views_and_outlines_write_images() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/debug");
    let tmp = std::env::temp_dir().join(format!("shaderbox-debug-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("tmp dir");
    let (view, outl) = (tmp.join("view.png"), tmp.join("outlines.png"));
    let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .arg("debug")
        .arg(dir.join("vertex-trace.shader_test"))
        .args(["--pixel", "125,125", "--view", "tint", "--view-png"])
        .arg(&view)
        .arg("--outlines")
        .arg(&outl)
        .output()
        .expect("run shaderbox");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let legend = String::from_utf8_lossy(&out.stderr);
    // The quad spans the middle half: tint.x goes 0 → 1 across it (its
    // first pixel 0 to within the plane's rounding, llvmpipe's: the plane's
    // value is kept at pixel (0, 0), outside the quad).
    let x_range = legend
        .split("view `tint': x in [")
        .nth(1)
        .and_then(|r| r.split(']').next())
        .and_then(|r| r.split_once(", "))
        .and_then(|(a, b)| Some((a.parse::<f64>().ok()?, b.parse::<f64>().ok()?)));
    let (lo, hi) = x_range.unwrap_or_else(|| panic!("no tint.x range in {legend}"));
    assert!(lo.abs() < 1e-6 && (hi - 0.992).abs() < 1e-6, "{legend}");
    for png in [&view, &outl] {
        let bytes = std::fs::read(png).expect("png written");
        assert!(bytes.starts_with(b"\x89PNG"), "{}", png.display());
    }
    // An unknown name lists what there is.
    let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .arg("debug")
        .arg(dir.join("vertex-trace.shader_test"))
        .args(["--pixel", "1,1", "--view", "nope", "--view-png"])
        .arg(tmp.join("x.png"))
        .output()
        .expect("run shaderbox");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr)
        .contains("has no input or variable `nope' (it has: gl_FragColor, tint)"));
    let _ = std::fs::remove_dir_all(&tmp);
}

/// The seed's sphere impostors (`shaderbox render` of two overlapping
/// atoms, replayed from its exported scene): a pixel in a quad corner shows
/// the ray missing the sphere and the `discard`; a pixel on the rim the
/// ray-sphere values, the depth written and the depth test; a pixel where
/// the atoms overlap both fragments and the nearer one winning the depth
/// test.
#[test]
fn sphere_impostor_pixels_match_the_golden_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/debug");
    let tmp = std::env::temp_dir().join(format!("shaderbox-spheres-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("tmp dir");
    let scene = tmp.join("two-atoms.json");
    let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .arg("render")
        .arg(dir.join("two-atoms.pdb"))
        .args(["--size", "32x32", "-o"])
        .arg(tmp.join("two-atoms.png"))
        .arg("--export-scene")
        .arg(&scene)
        .output()
        .expect("run shaderbox render");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bless = std::env::var_os("BLESS").is_some();
    let mut failures = Vec::new();
    for (name, pixel, needles) in [
        ("sphere-corner", "5,5", &["discarded at line 108"][..]),
        (
            "sphere-rim",
            "6,6",
            &["position = 0.16", "gl_FragDepth = ", "depth test passed"][..],
        ),
        (
            "sphere-overlap",
            "16,16",
            &["2 fragments", "depth test passed"][..],
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
            .arg("debug")
            .arg(&scene)
            .args(["--pixel", pixel])
            .output()
            .expect("run shaderbox debug");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let got = String::from_utf8_lossy(&out.stdout).into_owned();
        for n in needles {
            assert!(got.contains(n), "{name}: no `{n}' in\n{got}");
        }
        let golden = dir.join(format!("{name}.out"));
        if bless {
            std::fs::write(&golden, &got).expect("write golden");
        } else if std::fs::read_to_string(&golden).unwrap_or_default() != got {
            failures.push(format!(
                "{name}: report differs from {}:\n{got}",
                golden.display()
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A draw with a geometry stage: the view shows a fragment-shader input
/// over the emitted primitives and the outlines are theirs.
#[test]
fn views_and_outlines_work_with_a_geometry_stage() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/debug");
    let tmp = std::env::temp_dir().join(format!("shaderbox-debug-gs-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("tmp dir");
    let (view, outl) = (tmp.join("view.png"), tmp.join("outlines.png"));
    let out = Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .arg("debug")
        .arg(dir.join("geometry-shrink.shader_test"))
        .args(["--pixel", "166,166", "--view", "color", "--view-png"])
        .arg(&view)
        .arg("--outlines")
        .arg(&outl)
        .output()
        .expect("run shaderbox");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The emitted vertices keep the corners' colours (x 0 or 1); the
    // pixel centres inside the shrunk triangles give x just inside that.
    let legend = String::from_utf8_lossy(&out.stderr);
    assert!(legend.contains("view `color': x in [0.006"), "{legend}");
    assert!(String::from_utf8_lossy(&out.stdout).contains("geometry shader, input primitive 1"));
    for png in [&view, &outl] {
        let bytes = std::fs::read(png).expect("png written");
        assert!(bytes.starts_with(b"\x89PNG"), "{}", png.display());
    }
    let _ = std::fs::remove_dir_all(&tmp);
}
