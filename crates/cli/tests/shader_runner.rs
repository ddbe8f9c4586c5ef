//! End-to-end tests of `shaderbox shader-runner`: piglit's protocol (the
//! `PIGLIT:` line and exit statuses), its command line, and the reports of
//! malformed scripts. Tests that render need the GL pipeline (feature
//! `gl-context`).

use std::path::PathBuf;
use std::process::{Command, Output};

fn shaderbox(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shaderbox"))
        .args(args)
        .output()
        .expect("the shaderbox binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Writes `text` to a fresh file and returns its path.
fn script(test: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("shader-runner-tests")
        .join(test);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{test}.shader_test"));
    std::fs::write(&path, text).unwrap();
    path.to_string_lossy().into_owned()
}

fn last_line(o: &Output) -> String {
    stdout(o).lines().last().unwrap_or("").to_string()
}

const GREEN: &str = "\
[require]
GLSL >= 1.10

[vertex shader passthrough]

[fragment shader]
void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }

[test]
clear color 0.0 0.0 0.0 0.0
clear
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
relative probe rgb (0.5, 0.5) (0.0, 1.0, 0.0)
";

#[test]
fn missing_file_fails_like_piglit() {
    let o = shaderbox(&[
        "shader-runner",
        "/nonexistent/t.shader_test",
        "-auto",
        "-fbo",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "fail" }"#);
    assert!(stdout(&o).contains("could not read file"), "{}", stdout(&o));
}

#[test]
fn malformed_lines_name_file_and_line() {
    let path = script(
        "malformed",
        "[require]\nGLSL >= 1.10\n[fragment shader]\nvoid main(){}\n[test]\ndraw rect 0 0\n",
    );
    let o = shaderbox(&["shader-runner", &path, "--parse-only"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "fail" }"#);
    assert!(
        stdout(&o).contains(&format!("{path}:6: draw rect: expected 4 numbers, found 2")),
        "{}",
        stdout(&o)
    );

    let path = script("bad-section", "[require]\nGLSL >= 1.10\n[fragment shadr]\n");
    let o = shaderbox(&["shader-runner", &path, "-auto"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains(":3: unknown section"), "{}", stdout(&o));
}

#[test]
fn parse_only_passes_well_formed_scripts() {
    let path = script("green-parse", GREEN);
    let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo", "--parse-only"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
    assert!(stdout(&o).starts_with("5 commands"), "{}", stdout(&o));
}

#[test]
fn command_line_errors_fail() {
    let o = shaderbox(&["shader-runner", "t.shader_test", "-bogus"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "fail" }"#);
    assert!(
        stderr(&o).contains("unknown option `-bogus'"),
        "{}",
        stderr(&o)
    );
    let o = shaderbox(&["shader-runner", "a.shader_test", "b.shader_test"]);
    assert_eq!(o.status.code(), Some(1));
}

mod rendering {
    use super::*;

    /// Uniform blocks: `uniform` commands on block members fill each
    /// block's buffer (piglit's `set_ubo_uniform`), `ubo array index`
    /// picks an element of an array of blocks, and `active uniform`
    /// checks the std140 layout.
    const UBO: &str = "\
[require]
GLSL >= 1.10

[vertex shader]
#version 150
in vec4 piglit_vertex;
void main() { gl_Position = piglit_vertex; }

[fragment shader]
#version 150
layout(std140) uniform Block {
    float f[2];
    layout(row_major) mat2 m;
};
uniform Pal { vec4 c; } pal[2];
out vec4 o;
void main() { o = vec4(f[1], (m * vec2(1.0, 0.0)).y, 0.0, 1.0) + pal[1].c; }

[test]
active uniform f[0] GL_UNIFORM_OFFSET 0
active uniform f[0] GL_UNIFORM_ARRAY_STRIDE 16
active uniform f[0] GL_UNIFORM_TYPE GL_FLOAT
active uniform m GL_UNIFORM_OFFSET 32
active uniform m GL_UNIFORM_IS_ROW_MAJOR 1
active uniform Pal.c GL_UNIFORM_TYPE GL_FLOAT_VEC4
uniform float f[1] 0.25
uniform mat2 m 0.0 0.5 0.9 0.0
ubo array index 1
uniform vec4 Pal.c 0.0 0.0 0.75 0.0
draw rect -1 -1 2 2
probe all rgba 0.25 0.5 0.75 1.0
";

    #[test]
    fn uniform_blocks_are_filled_from_uniform_commands() {
        let path = script("ubo", UBO);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
        assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
    }

    #[test]
    fn a_wrong_active_uniform_value_fails() {
        let text = UBO.replace("GL_UNIFORM_OFFSET 32", "GL_UNIFORM_OFFSET 24");
        let path = script("ubo-wrong-offset", &text);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1));
        assert!(
            stderr(&o).contains("expected 24 (0x0018), got 32 (0x0020)"),
            "{}{}",
            stdout(&o),
            stderr(&o)
        );
        let text = UBO.replace(
            "active uniform m GL_UNIFORM_OFFSET",
            "active uniform n GL_UNIFORM_OFFSET",
        );
        let path = script("ubo-no-such-uniform", &text);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1));
        assert!(
            stderr(&o).contains("No active uniform named \"n\""),
            "{}",
            stderr(&o)
        );
    }

    /// Array textures made by `texture rgbw 2DArray`/`1DArray` (a colour
    /// per layer) and `texture shadow2DArray` (the depth gradient in
    /// every layer, compared GREATER), read through the GLSL 1.30
    /// lookups.
    const ARRAYS: &str = "\
[require]
GLSL >= 1.30

[vertex shader]
#version 130
in vec4 piglit_vertex;
out vec2 tc;
void main() { gl_Position = piglit_vertex; tc = piglit_vertex.xy * 0.5 + 0.5; }

[fragment shader]
#version 130
uniform sampler2DArray a;
uniform sampler1DArray b;
uniform sampler2DArrayShadow s;
uniform int layer;
in vec2 tc;
out vec4 o;
void main() {
    o = texture(a, vec3(tc, float(layer))) * 0.5 + texture(b, vec2(tc.x, 3.0)) * 0.25
        + vec4(0.0, 0.0, 0.0, texture(s, vec4(tc, 1.0, 0.5)) * 0.25);
}

[test]
uniform int a 0
uniform int b 1
uniform int s 2
texture rgbw 2DArray 0 (4, 4, 3)
texture rgbw 1DArray 1 (4, 5)
texture shadow2DArray 2 (16, 16, 2)
uniform int layer 2
draw rect -1 -1 2 2
relative probe rgba (0.1, 0.5) (0.25, 0.25, 0.75, 1.0)
relative probe rgba (0.9, 0.5) (0.25, 0.25, 0.75, 0.75)
";

    /// GL_ARB_shading_language_packing required by name, its functions in
    /// both stages: the vertex stage packs, the fragment stage unpacks
    /// and compares with uniform words.
    const PACKING: &str = "\
[require]
GLSL >= 1.30
GL_ARB_shading_language_packing

[vertex shader]
#version 130
#extension GL_ARB_shading_language_packing : require
in vec4 piglit_vertex;
uniform vec2 v;
flat out uint word;
void main() { gl_Position = piglit_vertex; word = packHalf2x16(v); }

[fragment shader]
#version 130
#extension GL_ARB_shading_language_packing : require
flat in uint word;
uniform uint expect;
uniform uint snorm;
out vec4 o;
void main() {
    bool ok = word == expect && unpackHalf2x16(word) == vec2(-2.0, 65504.0)
        && packSnorm4x8(unpackSnorm4x8(snorm)) == snorm;
    o = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
}

[test]
uniform vec2 v -2.0 65504.0
uniform uint expect 2080358400
uniform uint snorm 2181005951
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
";

    #[test]
    fn packing_functions_run_where_the_extension_is_required() {
        let path = script("packing", PACKING);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
        assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
        // A wrong expectation fails the probe.
        let path = script(
            "packing-wrong",
            &PACKING.replace("2080358400", "2080358401"),
        );
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    }

    #[test]
    fn array_textures_are_made_and_sampled() {
        let path = script("arrays", ARRAYS);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
        assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
        // Another layer, another colour (the probes can fail).
        let path = script("arrays-layer", &ARRAYS.replace("layer 2", "layer 1"));
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    }

    #[test]
    fn green_quad_passes() {
        let path = script("green", GREEN);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
        assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
    }

    #[test]
    fn wrong_color_fails_with_probe_report() {
        let text = GREEN.replace(
            "probe all rgba 0.0 1.0 0.0 1.0",
            "probe all rgba 1.0 0.0 0.0 1.0",
        );
        let path = script("red-expected", &text);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1));
        let out = stdout(&o);
        assert!(out.contains("Probe color at (0,0)"), "{out}");
        assert!(out.contains("Test failure on line 13"), "{out}");
    }

    #[test]
    fn huge_rectangles_cover_every_pixel() {
        // Clipped in f32, the cut of a rectangle reaching 10⁶ moved its
        // left edge by pixels; a cut is now placed exactly on the plane.
        for m in ["1e5", "1e6", "1e9", "1e20"] {
            let text = GREEN
                .replace(
                    "draw rect -1 -1 2 2",
                    &format!("draw rect -{m} -{m} 2{} 2{}", &m[1..], &m[1..]),
                )
                .replace("clear color 0.0 0.0 0.0 0.0", "clear color 1.0 0.0 0.0 1.0");
            let path = script(&format!("huge-{m}"), &text);
            let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
            assert_eq!(
                last_line(&o),
                r#"PIGLIT: {"result": "pass" }"#,
                "{m}: {}",
                stdout(&o)
            );
        }
    }

    /// `SSO ENABLED`: each stage a separable program in a pipeline, the
    /// fragment input matched by location, a uniform of each stage set
    /// through `active shader program`.
    const SSO: &str = "\
[require]
GLSL >= 1.50
SSO ENABLED

[vertex shader]
#version 150
#extension GL_ARB_separate_shader_objects : require
in vec4 piglit_vertex;
uniform float green;
layout(location = 3) out vec4 v;
void main() { gl_Position = piglit_vertex; v = vec4(0.0, green, 0.0, 1.0); }

[fragment shader]
#version 150
#extension GL_ARB_separate_shader_objects : require
uniform float blue;
layout(location = 3) in vec4 f;
out vec4 o;
void main() { o = f + vec4(0.0, 0.0, blue, 0.0); }

[test]
active shader program GL_VERTEX_SHADER
uniform float green 0.5
active shader program GL_FRAGMENT_SHADER
uniform float blue 0.25
draw rect -1 -1 2 2
probe all rgba 0.0 0.5 0.25 1.0
";

    #[test]
    fn separate_shader_objects_run_in_a_pipeline() {
        let path = script("sso", SSO);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
        assert_eq!(last_line(&o), r#"PIGLIT: {"result": "pass" }"#);
        // The fragment stage's uniform is not the vertex program's.
        let text = SSO.replace("active shader program GL_FRAGMENT_SHADER\n", "");
        let path = script("sso-wrong-program", &text);
        let o = shaderbox(&["shader-runner", &path, "-auto", "-fbo"]);
        assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
        assert!(stdout(&o).contains("cannot get location of uniform \"blue\""));
    }

    #[test]
    fn later_gl_is_a_skip() {
        for (name, req) in [
            ("glsl400", "GLSL >= 4.00"),
            ("gl40", "GLSL >= 1.50\nGL >= 4.0"),
        ] {
            let path = script(name, &format!("[require]\n{req}\n[test]\n"));
            let o = shaderbox(&["shader-runner", &path, "-auto"]);
            assert_eq!(o.status.code(), Some(0));
            assert_eq!(last_line(&o), r#"PIGLIT: {"result": "skip" }"#, "{req}");
        }
    }
}

/// A fragment shader whose `main` calls a chain of `n` functions.
fn call_chain_script(n: usize) -> String {
    let mut fs = String::from("float f0(float x) { return x + 0.25; }\n");
    for i in 1..n {
        fs += &format!("float f{i}(float x) {{ return f{}(x); }}\n", i - 1);
    }
    fs += &format!("void main() {{ gl_FragColor = vec4(f{}(0.0)); }}\n", n - 1);
    format!(
        "[require]\nGLSL >= 1.10\n\n[vertex shader passthrough]\n\n[fragment shader]\n{fs}\n\
         [test]\ndraw rect -1 -1 2 2\nprobe all rgba 0.25 0.25 0.25 0.25\n"
    )
}

#[test]
fn a_loop_that_never_ends_stops_its_draw_with_an_error() {
    let path = script(
        "endless-loop",
        "[require]\nGLSL >= 1.10\nSIZE 16 16\n\n[vertex shader passthrough]\n\n[fragment shader]\n\
         void main() { for (int i = 1; i < 8; 0.0) {} gl_FragColor = vec4(1.0); }\n\n\
         [test]\ndraw rect -1 -1 2 2\nprobe all rgba 1.0 1.0 1.0 1.0\n",
    );
    let o = shaderbox(&["shader-runner", &path, "-auto"]);
    let out = stdout(&o) + &stderr(&o);
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "fail" }"#, "{out}");
    assert!(
        out.contains("shader exceeded 1048577 loop iterations in one invocation"),
        "{out}"
    );
}

#[test]
fn deep_call_chains_fail_to_compile_naming_the_call_depth() {
    // 4,000 nested calls: refused at compile time with the limit named
    // (they used to run as subroutines, seconds per draw, or be reported
    // as loop iterations), in well under a second.
    let path = script("deep-call-chain", &call_chain_script(4000));
    let t = std::time::Instant::now();
    let o = shaderbox(&["shader-runner", &path, "-auto"]);
    let out = stdout(&o) + &stderr(&o);
    assert_eq!(last_line(&o), r#"PIGLIT: {"result": "fail" }"#, "{out}");
    assert!(out.contains("function calls nested too deeply"), "{out}");
    assert!(!out.contains("loop iterations"), "{out}");
    assert!(t.elapsed().as_secs() < 10, "{:?}", t.elapsed());
    // The deepest chain allowed draws the right colour.
    let path = script("call-chain-at-limit", &call_chain_script(127));
    let o = shaderbox(&["shader-runner", &path, "-auto"]);
    assert_eq!(
        last_line(&o),
        r#"PIGLIT: {"result": "pass" }"#,
        "{}{}",
        stdout(&o),
        stderr(&o)
    );
}
