//! End-to-end tests of the `shaderbox` binary: exit statuses and output
//! formats of `check`, and piglit's protocol for `glslparsertest`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn shaderbox(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .args(args)
        .env_remove("NO_COLOR")
        .output()
        .expect("the shaderbox binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn example(name: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/shaders")
        .join(name);
    p.to_string_lossy().into_owned()
}

/// Writes `text` to a fresh file named `name` and returns its path.
fn temp_shader(test: &str, name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli-tests")
        .join(test);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_string_lossy().into_owned()
}

const VALID_VERT: &str = "void main()\n{\n    gl_Position = ftransform();\n}\n";
const UNDECLARED_FRAG: &str = "void main()\n{\n    gl_FragColor = vec4(x);\n}\n";

// ---- check: exit statuses ------------------------------------------------

#[test]
fn check_valid_examples_exit_0() {
    let o = shaderbox(&[
        "check",
        &example("impostor.vert"),
        &example("impostor.frag"),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("ok: ") && out.contains("impostor.vert (vertex shader, GLSL 1.20)"),
        "{out}"
    );
    assert!(
        out.contains("impostor.frag (fragment shader, GLSL 1.20)"),
        "{out}"
    );
}

#[test]
fn check_errors_exit_1_and_reports_every_mistake() {
    let o = shaderbox(&["check", "--color", "never", &example("mistakes.frag")]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("failed: "), "{out}");
    // One error per deliberate mistake, on lines 9, 10 and 11.
    for line in [9, 10, 11] {
        assert!(
            out.contains(&format!("mistakes.frag:{line}:")),
            "line {line}:\n{out}"
        );
    }
}

#[test]
fn check_one_bad_file_among_good_ones_exits_1() {
    let bad = temp_shader("mixed", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&["check", &example("impostor.vert"), &bad]);
    assert_eq!(o.status.code(), Some(1));
}

#[test]
fn check_missing_file_exits_2_naming_it() {
    let o = shaderbox(&["check", "/no/such/dir/missing.frag"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`/no/such/dir/missing.frag'"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
}

#[test]
fn check_unknown_extension_needs_stage() {
    let p = temp_shader("stage", "shader.glsl", VALID_VERT);
    let o = shaderbox(&["check", &p]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--stage"), "{}", stderr(&o));
    let o = shaderbox(&["check", "--stage", "vertex", &p]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
}

#[test]
fn check_stage_flag_overrides_extension() {
    // gl_FragColor is not a vertex shader output.
    let p = temp_shader(
        "override",
        "s.vert",
        "void main() { gl_FragColor = vec4(1.0); }\n",
    );
    let o = shaderbox(&["check", &p]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let o = shaderbox(&["check", "--stage", "fragment", &p]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
}

#[test]
fn check_bad_arguments_exit_2() {
    assert_eq!(shaderbox(&["check"]).status.code(), Some(2));
    assert_eq!(
        shaderbox(&["check", "--format", "xml", "a.frag"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        shaderbox(&["check", "--glsl-version", "130", "a.frag"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        shaderbox(&["check", "--stage", "geometry", "a.frag"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(shaderbox(&["frobnicate"]).status.code(), Some(2));
}

#[test]
fn check_glsl_version_110_is_the_default() {
    let p = temp_shader("version", "v.vert", VALID_VERT);
    let o = shaderbox(&["check", "--glsl-version", "110", &p]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("GLSL 1.10"), "{}", stdout(&o));
}

#[test]
fn check_glsl_version_120_applies_without_version_directive() {
    // GLSL 1.20 converts int to float implicitly (§4.1.10); 1.10 does not.
    let p = temp_shader(
        "version120",
        "conv.frag",
        "void main()\n{\n    float x = 1;\n    gl_FragColor = vec4(x);\n}\n",
    );
    assert_eq!(shaderbox(&["check", &p]).status.code(), Some(1));
    let o = shaderbox(&["check", "--glsl-version", "120", &p]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("GLSL 1.20"), "{}", stdout(&o));
    // An explicit #version wins over the option.
    let q = temp_shader(
        "version120",
        "explicit.frag",
        "#version 110\nvoid main()\n{\n    float x = 1;\n    gl_FragColor = vec4(x);\n}\n",
    );
    assert_eq!(
        shaderbox(&["check", "--glsl-version", "120", &q])
            .status
            .code(),
        Some(1)
    );
}

#[test]
fn check_link_after_compile_failure_does_not_link() {
    let bad = temp_shader("link", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&[
        "check",
        "--link",
        "--color",
        "never",
        &example("impostor.vert"),
        &bad,
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("not linked: a shader failed to compile"),
        "{}",
        stdout(&o)
    );
}

const UNDEFINED_FUNCTION_VERT: &str =
    "void f();\nvoid main()\n{\n    f();\n    gl_Position = vec4(0.0);\n}\n";

#[test]
fn check_link_of_example_pair_exits_0() {
    let o = shaderbox(&[
        "check",
        "--link",
        &example("impostor.vert"),
        &example("impostor.frag"),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("ok: program linked"), "{}", stdout(&o));
}

#[test]
fn check_link_failure_exits_1() {
    let p = temp_shader("link-fail", "undef.vert", UNDEFINED_FUNCTION_VERT);
    // It compiles on its own...
    assert_eq!(shaderbox(&["check", &p]).status.code(), Some(0));
    // ...but does not link.
    let o = shaderbox(&["check", "--link", "--color", "never", &p]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("failed: program did not link"),
        "{}",
        stdout(&o)
    );
    let o = shaderbox(&["check", "--link", "--format", "json", &p]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("valid JSON");
    let codes: Vec<&str> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["code"].as_str().unwrap())
        .collect();
    assert!(codes.iter().any(|c| c.starts_with("E03")), "{codes:?}");
}

#[test]
fn check_link_takes_the_extension_geometry_program_parameters() {
    let shader = |name: &str| {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../shaders")
            .join(name)
            .to_string_lossy()
            .into_owned()
    };
    let files = [
        shader("sphere-point.vert"),
        shader("sphere.geom"),
        shader("sphere.frag"),
    ];
    let run = |extra: &[&str]| {
        let mut args = vec!["check", "--link", "--color", "never"];
        args.extend_from_slice(extra);
        args.extend(files.iter().map(String::as_str));
        shaderbox(&args)
    };
    // The initial parameters: no output vertex count, so no link.
    let o = run(&[]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("GEOMETRY_VERTICES_OUT"),
        "{}",
        stdout(&o)
    );
    // sphere.geom's own parameters.
    let o = run(&[
        "--geometry-input",
        "points",
        "--geometry-output",
        "triangle_strip",
        "--geometry-vertices-out",
        "4",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("ok: program linked"), "{}", stdout(&o));
    // Bad values and parameters without --link are misuse.
    for bad in [
        &["--link", "--geometry-input", "quads"][..],
        &["--geometry-vertices-out", "4"][..],
        &["--link", "--geometry-vertices-out", "-1"][..],
    ] {
        let mut args = vec!["check"];
        args.extend_from_slice(bad);
        args.push(&files[1]);
        let o = shaderbox(&args);
        assert_eq!(o.status.code(), Some(2), "{bad:?}: {}", stderr(&o));
    }
}

// ---- check: formats --------------------------------------------------------

#[test]
fn check_json_is_an_array_of_resolved_diagnostics() {
    let bad = temp_shader("json", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&["check", "--format", "json", &bad]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("valid JSON");
    let first = &v.as_array().expect("an array")[0];
    assert_eq!(first["file"], bad.as_str());
    assert_eq!(first["stage"], "fragment");
    assert_eq!(first["severity"], "error");
    assert_eq!(first["line"], 3);
    assert_eq!(first["column"], 25);
    assert!(first["code"].as_str().unwrap().starts_with('E'));
    assert!(
        first["message"].as_str().unwrap().contains("`x'"),
        "{first}"
    );
    assert!(first["notes"].is_array());
}

#[test]
fn check_json_of_valid_shader_is_empty_array() {
    let o = shaderbox(&["check", "--format", "json", &example("impostor.frag")]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("valid JSON");
    assert_eq!(v, serde_json::json!([]));
}

#[test]
fn check_infolog_uses_gl_layout() {
    let bad = temp_shader("infolog", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&["check", "--format", "infolog", &bad]);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(out.starts_with("0:3(25): error: "), "{out}");
}

#[test]
fn check_color_flag() {
    let bad = temp_shader("color", "bad.frag", UNDECLARED_FRAG);
    let always = stdout(&shaderbox(&["check", "--color", "always", &bad]));
    assert!(always.contains('\x1b'), "{always}");
    let never = stdout(&shaderbox(&["check", "--color", "never", &bad]));
    assert!(!never.contains('\x1b'), "{never}");
    // auto: stdout is a pipe here.
    let auto = stdout(&shaderbox(&["check", &bad]));
    assert!(!auto.contains('\x1b'), "{auto}");
}

// ---- glslparsertest: piglit's protocol -------------------------------------

fn piglit_result(o: &Output) -> String {
    let out = stdout(o);
    let line = out
        .lines()
        .rfind(|l| l.starts_with("PIGLIT: "))
        .unwrap_or_else(|| panic!("no PIGLIT line in {out}"));
    let v: serde_json::Value = serde_json::from_str(&line[8..]).expect("JSON after PIGLIT:");
    v["result"].as_str().unwrap().to_string()
}

#[test]
fn parsertest_expected_pass_compiles() {
    let p = temp_shader("pt-pass", "ok.vert", VALID_VERT);
    let o = shaderbox(&["glslparsertest", &p, "pass", "1.10"]);
    assert_eq!(piglit_result(&o), "pass");
    assert_eq!(o.status.code(), Some(0));
}

#[test]
fn parsertest_expected_fail_that_compiles_fails() {
    let p = temp_shader("pt-unexpected", "ok.vert", VALID_VERT);
    let o = shaderbox(&["glslparsertest", &p, "fail", "1.20"]);
    assert_eq!(piglit_result(&o), "fail");
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("Successfully compiled vertex shader"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn parsertest_expected_fail_that_fails_passes_and_shows_log() {
    let p = temp_shader("pt-fail", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&["glslparsertest", &p, "fail", "1.10"]);
    assert_eq!(piglit_result(&o), "pass");
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("0:3(25): error"), "{}", stdout(&o));
}

#[test]
fn parsertest_links_an_ext_geometry_shader_with_a_vertex_count() {
    // GL_ARB_geometry_shader4's form: the program's initial vertex count
    // (0) would fail the link; the runner's program sets 3.
    let src = "#version 110\n#extension GL_ARB_geometry_shader4: enable\nvoid main() {\n  for (int i = 0; i < 3; i++) {\n    gl_Position = gl_PositionIn[i];\n    EmitVertex();\n  }\n}\n";
    let p = temp_shader("pt-ext-gs", "sanity.geom", src);
    let o = shaderbox(&[
        "glslparsertest",
        &p,
        "pass",
        "1.10",
        "GL_ARB_geometry_shader4",
        "--check-link",
    ]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
    // Without the extension the same shader is GLSL 1.10 with no
    // geometry stage.
    let bare = temp_shader(
        "pt-ext-gs-bare",
        "bare.geom",
        &src.replace("#extension GL_ARB_geometry_shader4: enable\n", ""),
    );
    let o = shaderbox(&["glslparsertest", &bare, "fail", "1.10"]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
}

#[test]
fn parsertest_expected_pass_that_fails_fails() {
    let p = temp_shader("pt-fail2", "bad.frag", UNDECLARED_FRAG);
    let o = shaderbox(&["glslparsertest", &p, "pass", "1.10"]);
    assert_eq!(piglit_result(&o), "fail");
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("Failed to compile fragment shader"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn parsertest_skips() {
    let p = temp_shader("pt-skip", "ok.vert", VALID_VERT);
    for args in [
        vec!["glslparsertest", &p, "pass", "4.00"],
        vec!["glslparsertest", &p, "pass", "3.00 es"],
        vec!["glslparsertest", &p, "pass", "1.20", "GL_ARB_gpu_shader5"],
        // Offered from GLSL 1.40 only.
        vec![
            "glslparsertest",
            &p,
            "pass",
            "1.20",
            "GL_ARB_texture_rectangle",
        ],
    ] {
        let o = shaderbox(&args);
        assert_eq!(piglit_result(&o), "skip", "{args:?}");
        assert_eq!(o.status.code(), Some(0), "{args:?}");
    }
    // The texture extensions of the versions that have their built-ins.
    let r = temp_shader(
        "pt-skip",
        "rect.vert",
        "#version 140\n#extension GL_ARB_texture_rectangle : require\nuniform sampler2DRect s;\nvoid main() { gl_Position = texture2DRect(s, vec2(0.0)); }\n",
    );
    let o = shaderbox(&[
        "glslparsertest",
        &r,
        "pass",
        "1.40",
        "GL_ARB_texture_rectangle",
    ]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
}

#[test]
fn parsertest_links_a_geometry_shader_with_a_dummy_vertex_shader() {
    let g = temp_shader(
        "pt-geom",
        "pass.geom",
        "#version 150\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\nvoid main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }\n",
    );
    let o = shaderbox(&["glslparsertest", "--check-link", &g, "pass", "1.50"]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
    // Without an output layout the program does not link.
    let n = temp_shader(
        "pt-geom",
        "nolayout.geom",
        "#version 150\nlayout(points) in;\nvoid main() { EmitVertex(); }\n",
    );
    let o = shaderbox(&["glslparsertest", "--check-link", &n, "fail", "1.50"]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
}

#[test]
fn parsertest_check_link_counts_link_errors() {
    let p = temp_shader("pt-link", "undef.vert", UNDEFINED_FUNCTION_VERT);
    let o = shaderbox(&["glslparsertest", &p, "fail", "1.10"]);
    assert_eq!(
        piglit_result(&o),
        "fail",
        "compiles, so `fail' is wrong without --check-link"
    );
    let o = shaderbox(&["glslparsertest", &p, "fail", "1.10", "--check-link"]);
    assert_eq!(piglit_result(&o), "pass", "{}", stdout(&o));
    assert_eq!(o.status.code(), Some(0));
}

#[test]
fn parsertest_missing_file_fails() {
    let o = shaderbox(&["glslparsertest", "/no/such/file.vert", "pass", "1.10"]);
    assert_eq!(piglit_result(&o), "fail");
    assert_eq!(o.status.code(), Some(1));
}

#[test]
fn parsertest_bad_usage_is_nonzero() {
    // piglit turns any non-zero status without a PIGLIT line into "fail".
    let o = shaderbox(&["glslparsertest", "x.vert", "maybe", "1.10"]);
    assert_ne!(o.status.code(), Some(0));
}

#[test]
fn help_describes_the_command_as_it_is() {
    let o = shaderbox(&["--help"]);
    let first = stdout(&o).lines().next().unwrap_or("").to_string();
    assert_eq!(first, env!("CARGO_PKG_DESCRIPTION"));
    assert!(!first.contains("later"), "{first}");
    for command in ["check", "shader-runner", "render", "debug"] {
        assert!(
            stdout(&o).contains(&format!("  {command} ")),
            "{}",
            stdout(&o)
        );
    }
}

#[test]
fn check_refuses_a_source_over_the_size_limit() {
    // 40 MB of newlines: one error naming the limit, the file read only up
    // to it.
    let big = "\n".repeat(40 << 20) + "void main() {}\n";
    let path = temp_shader("too-big", "big.frag", &big);
    let o = shaderbox(&["check", "--format", "infolog", &path]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("the shader source is larger than 33554432 bytes, the limit"),
        "{}",
        stdout(&o)
    );
}
