//! End-to-end tests of `shaderbox render`: the PNG it writes, and its exit
//! statuses and messages for bad structure files and misuse.

use std::path::PathBuf;
use std::process::{Command, Output};

fn shaderbox(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .args(args)
        .output()
        .expect("the shaderbox binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn dir(test: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("render-tests")
        .join(test);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn write(test: &str, name: &str, bytes: &[u8]) -> String {
    let p = dir(test).join(name);
    std::fs::write(&p, bytes).unwrap();
    p.to_string_lossy().into_owned()
}

/// Width and height from a PNG's IHDR chunk.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    (be(16), be(20))
}

const ATOM: &str =
    "ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79           N\n";

#[test]
fn renders_embedded_molecule_to_png() {
    let out = dir("embedded").join("crambin.png");
    let o = shaderbox(&[
        "render",
        "-o",
        out.to_str().unwrap(),
        "--size",
        "48x32",
        "--fog",
        "exp2",
        "--projection",
        "perspective",
        "--rotate",
        "-30,45,10",
        "--lights",
        "0,1,4",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("327 atoms"), "{}", stderr(&o));
    let bytes = std::fs::read(&out).unwrap();
    assert_eq!(png_size(&bytes), (48, 32));
}

#[test]
fn renders_a_file_with_transparent_background() {
    let pdb = write("file", "one.pdb", ATOM.as_bytes());
    let out = dir("file").join("one.png");
    let o = shaderbox(&[
        "render",
        &pdb,
        "-o",
        out.to_str().unwrap(),
        "--size",
        "16x16",
        "--supersample",
        "2",
        "--background",
        "transparent",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bytes = std::fs::read(&out).unwrap();
    assert_eq!(png_size(&bytes), (16, 16));
    assert_eq!(bytes[25], 6, "colour type RGBA");
}

#[test]
fn truncated_file_names_file_and_line() {
    let text = format!("HEADER    T\n{ATOM}ATOM      2  CA  THR A   1      16.967  12.7");
    let pdb = write("truncated", "cut.pdb", text.as_bytes());
    let o = shaderbox(&["render", &pdb, "-o", "/nonexistent/x.png"]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("cut.pdb:3: ATOM record is 44 columns"), "{e}");
}

#[test]
fn malformed_number_names_line() {
    let bad = ATOM.replace("14.099", "14.0?9");
    let pdb = write(
        "malformed",
        "bad.pdb",
        format!("REMARK\n\n{bad}").as_bytes(),
    );
    let o = shaderbox(&["render", &pdb]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(
        e.contains("bad.pdb:3: y coordinate (columns 39-46) is not a number"),
        "{e}"
    );
}

#[test]
fn empty_and_binary_files() {
    let empty = write("empty", "empty.pdb", b"");
    let o = shaderbox(&["render", &empty]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("empty.pdb: has no atoms"),
        "{}",
        stderr(&o)
    );
    let bin = write(
        "empty",
        "noise.pdb",
        &[0x89, b'P', b'N', b'G', 0, 1, 2, 0xff],
    );
    let o = shaderbox(&["render", &bin]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("noise.pdb:1: control character"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn misuse_exits_2() {
    for args in [
        &["render", "/nonexistent/structure.pdb"][..],
        &["render", "--size", "0x10"],
        &["render", "--size", "wide"],
        &["render", "--lights", "0,9"],
        &["render", "--rotate", "1,2"],
        &["render", "--supersample", "0"],
        &["render", "--background", "mauve"],
        &["render", "--fog", "thick"],
        &["render", "--projection", "fisheye"],
        &["render", "--effect", "sepia"],
        &["render", "--size", "5000x5000", "--supersample", "2"],
    ] {
        let o = shaderbox(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{args:?}");
    }
}

#[test]
fn every_effect_renders_and_unknown_effect_is_named() {
    for effect in ["plain", "outline", "x", "x-red", "transparent"] {
        let out = dir("effects").join(format!("{effect}.png"));
        let o = shaderbox(&[
            "render",
            "-o",
            out.to_str().unwrap(),
            "--size",
            "24x24",
            "--effect",
            effect,
        ]);
        assert_eq!(o.status.code(), Some(0), "{effect}: {}", stderr(&o));
        assert_eq!(png_size(&std::fs::read(&out).unwrap()), (24, 24));
    }
    let o = shaderbox(&["render", "--effect", "sepia"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("`sepia` is not an effect: plain, outline, x, x-red, transparent"),
        "{e}"
    );
}

#[test]
fn points_draw_the_same_png_as_quads_and_unknown_atoms_is_named() {
    let mut pngs = Vec::new();
    for atoms in ["quads", "points"] {
        let out = dir("atoms").join(format!("{atoms}.png"));
        let scene = dir("atoms").join(format!("{atoms}.json"));
        let o = shaderbox(&[
            "render",
            "-o",
            out.to_str().unwrap(),
            "--size",
            "40x40",
            "--projection",
            "perspective",
            "--fog",
            "linear",
            "--atoms",
            atoms,
            "--export-scene",
            scene.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{atoms}: {}", stderr(&o));
        pngs.push(std::fs::read(&out).unwrap());
        let json = std::fs::read_to_string(&scene).unwrap();
        assert!(json.contains(&format!("--atoms {atoms}")));
        assert_eq!(json.contains("GL_EXT_geometry_shader4"), atoms == "points");
    }
    assert_eq!(pngs[0], pngs[1]);
    let o = shaderbox(&["render", "--atoms", "lines"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("`lines` is not a way to draw atoms: quads, points"),
        "{e}"
    );
}

#[test]
fn unwritable_output_exits_1() {
    let pdb = write("unwritable", "one.pdb", ATOM.as_bytes());
    let o = shaderbox(&[
        "render",
        &pdb,
        "--size",
        "8x8",
        "-o",
        "/nonexistent/dir/x.png",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("/nonexistent/dir/x.png"),
        "{}",
        stderr(&o)
    );
}

const CIF: &str = "data_T\nloop_\n_atom_site.id\n_atom_site.type_symbol\n_atom_site.Cartn_x\n_atom_site.Cartn_y\n_atom_site.Cartn_z\n1 C 0 0 0\n2 O 1.4 0 0\n";

#[test]
fn ballstick_mmcif_several_files_and_turntable() {
    let d = dir("several");
    let cif = write("several", "co.cif", CIF.as_bytes());
    let pdb = write("several", "one.pdb", ATOM.as_bytes());
    let out = d.join("m.png");
    let o = shaderbox(&[
        "render",
        &cif,
        &pdb,
        "--style",
        "ballstick",
        "--turntable",
        "3",
        "--size",
        "16x16",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("wrote 6 images"), "{}", stderr(&o));
    for n in 1..=6 {
        let f = d.join(format!("m-{n:04}.png"));
        assert_eq!(png_size(&std::fs::read(&f).unwrap()), (16, 16), "{f:?}");
    }
    assert!(!d.join("m-0007.png").exists());
    assert!(!out.exists(), "numbered outputs only");
}

#[test]
fn bad_mmcif_names_file_and_line_and_others_still_render() {
    let d = dir("badcif");
    let bad = write("badcif", "cut.cif", &CIF.as_bytes()[..CIF.len() - 4]);
    let good = write("badcif", "one.pdb", ATOM.as_bytes());
    let out = d.join("m.png");
    let o = shaderbox(&[
        "render",
        &bad,
        &good,
        "--size",
        "8x8",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("cut.cif:9: the loop_ of line 2 has 8 values"),
        "{}",
        stderr(&o)
    );
    assert!(
        d.join("m-0002.png").exists(),
        "the good file is still drawn"
    );
    assert!(!stderr(&o).contains("panicked"));
}

#[test]
fn export_scene_writes_the_gl_calls() {
    let d = dir("export");
    let json = d.join("scene.json");
    let out = d.join("m.png");
    let o = shaderbox(&[
        "render",
        "--size",
        "8x8",
        "--style",
        "ballstick",
        "-o",
        out.to_str().unwrap(),
        "--export-scene",
        json.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&json).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["width"], 8);
    let calls = v["calls"].as_array().unwrap();
    let draws = calls.iter().filter(|c| c["call"] == "Draw").count();
    assert_eq!(draws, 2, "atoms and bonds");
    assert!(calls.iter().any(|c| c["call"] == "Program"));
    // One image only.
    let o = shaderbox(&[
        "render",
        "--turntable",
        "2",
        "--export-scene",
        json.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
}

/// RGB(A) pixels of a PNG.
fn png_pixels(path: &std::path::Path) -> Vec<[u8; 3]> {
    let file = std::fs::File::open(path).unwrap();
    let mut r = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    let n = info.color_type.samples();
    buf[..info.buffer_size()]
        .chunks(n)
        .map(|c| [c[0], c[1], c[2]])
        .collect()
}

#[test]
fn gallery_writes_every_picture_and_the_page() {
    let d = dir("gallery");
    let o = shaderbox(&["gallery", "-o", d.to_str().unwrap(), "--size", "48"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let html = std::fs::read_to_string(d.join("index.html")).unwrap();
    let pictures: Vec<&str> = html
        .split("src=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .collect();
    // One picture per library program, six for single-texture's modes.
    assert_eq!(pictures.len(), 24, "{pictures:?}");
    for name in [
        "sphere",
        "sphere-points",
        "cylinder",
        "volume",
        "wireframe",
        "wireframe-geom",
        "normals",
        "toon",
        "single-texture-blend",
    ] {
        assert!(pictures.contains(&format!("{name}.png").as_str()), "{name}");
    }
    for p in &pictures {
        let px = png_pixels(&d.join(p));
        assert_eq!(px.len(), 48 * 48, "{p}");
        // Not blank: a tenth of the pixels differ from the corner
        // (background) and there are several colours.
        let bg = px[0];
        let drawn = px.iter().filter(|c| **c != bg).count();
        assert!(drawn > 48 * 48 / 10, "{p}: {drawn} drawn pixels");
        let mut colours = px.clone();
        colours.sort_unstable();
        colours.dedup();
        assert!(colours.len() > 8, "{p}: {} colours", colours.len());
    }
}
