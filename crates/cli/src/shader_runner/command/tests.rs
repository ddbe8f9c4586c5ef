use super::*;

fn p(line: &str) -> Command {
    parse(line).unwrap().unwrap()
}

#[test]
fn uniform_block_commands() {
    assert_eq!(p("ubo array index 3"), Command::UboArrayIndex(3));
    assert!(parse("ubo array index x").is_err());
    assert_eq!(
        p("active uniform s.a[0] GL_UNIFORM_TYPE GL_FLOAT_MAT2x3"),
        Command::ActiveUniform {
            name: "s.a[0]".into(),
            pname: gl::enums::GL_UNIFORM_TYPE,
            expected: gl::enums::GL_FLOAT_MAT2x3 as i32,
        }
    );
    assert_eq!(
        p("active uniform m GL_UNIFORM_OFFSET 0x20"),
        Command::ActiveUniform {
            name: "m".into(),
            pname: gl::enums::GL_UNIFORM_OFFSET,
            expected: 32,
        }
    );
    assert!(parse("active uniform m GL_UNIFORM_BOGUS 0").is_err());
    assert!(parse("active uniform m GL_UNIFORM_TYPE GL_BOGUS").is_err());
    assert!(parse("active uniform m").is_err());
}

#[test]
fn blank_and_comments() {
    assert_eq!(parse("").unwrap(), None);
    assert_eq!(parse("   \t").unwrap(), None);
    assert_eq!(parse("# draw rect").unwrap(), None);
    assert_eq!(parse("  # x").unwrap(), None);
}

#[test]
fn draws() {
    assert_eq!(
        p("draw rect -1 -1 2 2"),
        Command::DrawRect {
            rect: [-1., -1., 2., 2.],
            ortho: false,
            tex: None,
            instances: 1,
        }
    );
    assert_eq!(
        p("draw rect ortho 0 0 10 10"),
        Command::DrawRect {
            rect: [0., 0., 10., 10.],
            ortho: true,
            tex: None,
            instances: 1,
        }
    );
    assert_eq!(
        p("draw instanced rect ortho 3 10 10 10 10"),
        Command::DrawRect {
            rect: [10., 10., 10., 10.],
            ortho: true,
            tex: None,
            instances: 3,
        }
    );
    assert_eq!(
        p("draw rect tex -1 -1 2 2 0 0 1 1"),
        Command::DrawRect {
            rect: [-1., -1., 2., 2.],
            ortho: false,
            tex: Some([0., 0., 1., 1.]),
            instances: 1,
        }
    );
    assert_eq!(
        p("draw arrays GL_TRIANGLE_FAN 0 4"),
        Command::DrawArrays {
            mode: GL_TRIANGLE_FAN,
            first: 0,
            count: 4,
            instances: 1,
        }
    );
    assert_eq!(
        p("draw arrays instanced GL_TRIANGLE_FAN 0 6 2"),
        Command::DrawArrays {
            mode: GL_TRIANGLE_FAN,
            first: 0,
            count: 6,
            instances: 2,
        }
    );
    assert_eq!(
        p("polygon mode GL_FRONT_AND_BACK GL_LINE"),
        Command::PolygonMode {
            face: gl::enums::GL_FRONT_AND_BACK,
            mode: gl::enums::GL_LINE,
        }
    );
    assert_eq!(
        p("provoking vertex first"),
        Command::ProvokingVertex(gl::enums::GL_FIRST_VERTEX_CONVENTION)
    );
    assert!(parse("polygon mode GL_FRONT GL_BOGUS").is_err());
    assert!(parse("provoking vertex middle").is_err());
    assert!(parse("draw rect 1 2 3").is_err());
    assert!(parse("draw arrays GL_BOGUS 0 4").is_err());
}

#[test]
fn probes() {
    assert_eq!(
        p("probe rgb 249 249 1.00 1.00 0"),
        Command::ProbePixel {
            x: 249,
            y: 249,
            expected: vec![1., 1., 0.]
        }
    );
    assert_eq!(
        p("probe rgba 1.9 2 0 0 0 1 # extra"),
        Command::ProbePixel {
            x: 1,
            y: 2,
            expected: vec![0., 0., 0., 1.]
        }
    );
    assert_eq!(
        p("relative probe rgb (.5, .5) (0.0, 1.0, 0.0)"),
        Command::RelativeProbePixel {
            rx: 0.5,
            ry: 0.5,
            expected: vec![0., 1., 0.]
        }
    );
    assert_eq!(
        p("probe rect rgba (0, 0, 10, 10) (0.0, 1.0, 0.0, 1.0)"),
        Command::ProbeRect {
            rect: [0, 0, 10, 10],
            expected: vec![0., 1., 0., 1.]
        }
    );
    assert_eq!(
        p("probe all rgb 0 1 0 0"),
        Command::ProbeAll {
            expected: vec![0., 1., 0.],
            warn: false
        }
    );
    assert_eq!(
        p("probe all rgba 0 1 0 0"),
        Command::ProbeAll {
            expected: vec![0., 1., 0., 0.],
            warn: false
        }
    );
    assert_eq!(
        p("probe warn all rgba 0 1 0 0"),
        Command::ProbeAll {
            expected: vec![0., 1., 0., 0.],
            warn: true
        }
    );
    assert_eq!(
        p("probe depth 1 2 0.5"),
        Command::ProbeDepth {
            x: 1,
            y: 2,
            expected: 0.5
        }
    );
    assert!(parse("relative probe rgb (.5, .5) (0.0, 1.0)").is_err());
    // Values after the last one read are ignored, as by sscanf.
    assert_eq!(
        p("relative probe rgb (0.0, 0.0) (1.0, 0.0, 0.0, 1.0)"),
        Command::RelativeProbePixel {
            rx: 0.0,
            ry: 0.0,
            expected: vec![1., 0., 0.]
        }
    );
}

#[test]
fn uniforms() {
    assert_eq!(
        p("uniform vec4 color 1 0 0.5 1"),
        Command::Uniform {
            ty: UniformType::Float(4),
            name: "color".into(),
            values: UniformValues::Floats(vec![1., 0., 0.5, 1.]),
            missing: 0
        }
    );
    assert_eq!(
        p("uniform ivec2 a[1] -1 0x10"),
        Command::Uniform {
            ty: UniformType::Int(2),
            name: "a[1]".into(),
            values: UniformValues::Ints(vec![-1, 16]),
            missing: 0
        }
    );
    match p("uniform mat2x3 m 1 2 3 4 5 6") {
        Command::Uniform { ty, values, .. } => {
            assert_eq!(ty, UniformType::Mat(2, 3));
            assert_eq!(values, UniformValues::Floats(vec![1., 2., 3., 4., 5., 6.]));
        }
        c => panic!("{c:?}"),
    }
    match p("uniform mat4 m 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1") {
        Command::Uniform { ty, .. } => assert_eq!(ty, UniformType::Mat(4, 4)),
        c => panic!("{c:?}"),
    }
    assert!(matches!(
        p("uniform uvec2 u 0xffffffff -1"),
        Command::Uniform {
            ty: UniformType::Uint(2),
            values: UniformValues::Uints(ref v),
            ..
        } if v == &[u32::MAX, u32::MAX]
    ));
    assert!(matches!(p("uniform dvec2 u 1 2"), Command::NeedsLaterGl(_)));
    assert_eq!(
        p("uniform vec4 v 0.5 -1.5 1.5, 0.0"),
        Command::Uniform {
            ty: UniformType::Float(4),
            name: "v".into(),
            values: UniformValues::Floats(vec![0.5, -1.5, 1.5, 0.0]),
            missing: 1
        }
    );
    assert!(parse("uniform vec3 v x").is_err());
    assert!(parse("uniform blob v 1").is_err());
    assert!(parse("uniform float").is_err());
}

#[test]
fn state_commands() {
    assert_eq!(
        p("clear color 0.2 0.2 0.2 0.2"),
        Command::ClearColor([0.2; 4])
    );
    assert_eq!(p("clear"), Command::Clear);
    assert_eq!(p("ortho"), Command::Ortho(None));
    assert_eq!(p("ortho 0 1 0 1"), Command::Ortho(Some([0., 1., 0., 1.])));
    assert_eq!(
        p("frustum -1.0 1.0 -1.0 1.0 1.0 10.0"),
        Command::Frustum([-1., 1., -1., 1., 1., 10.])
    );
    assert_eq!(
        p("enable GL_CLIP_PLANE3"),
        Command::Enable(GL_CLIP_PLANE0 + 3)
    );
    assert_eq!(
        p("clip plane 0 0.0 1.0 0.0 -0.5 # accept points"),
        Command::ClipPlane {
            plane: 0,
            equation: [0., 1., 0., -0.5]
        }
    );
    assert_eq!(p("shade model flat"), Command::ShadeModel(GL_FLAT));
    assert_eq!(
        p("light 0 GL_POSITION float 0 0 1 0"),
        Command::Light {
            light: GL_LIGHT0,
            pname: GL_POSITION,
            values: LightValues::Float(vec![0., 0., 1., 0.])
        }
    );
    assert_eq!(
        p("hint GL_FRAGMENT_SHADER_DERIVATIVE_HINT GL_NICEST"),
        Command::Hint {
            target: GL_FRAGMENT_SHADER_DERIVATIVE_HINT,
            mode: GL_NICEST
        }
    );
    assert!(parse("enable GL_BLEND_X").is_err());
    // shaderbox's stencil commands.
    assert_eq!(p("clear stencil 3"), Command::ClearStencil(3));
    assert_eq!(
        p("stencil func GL_EQUAL 1 0xff"),
        Command::StencilFunc {
            func: GL_EQUAL,
            reference: 1,
            mask: 255
        }
    );
    assert_eq!(
        p("stencil op GL_KEEP GL_INCR GL_REPLACE"),
        Command::StencilOp([GL_KEEP, GL_INCR, GL_REPLACE])
    );
    assert!(parse("stencil op GL_KEEP GL_KEEP").is_err());
    assert!(parse("stencil func GL_SOMETIMES 1 1").is_err());
    assert!(parse("frobnicate").is_err());
}

#[test]
fn textures() {
    assert_eq!(
        p("texture rgbw 0 (8, 8)"),
        Command::Texture(TextureCommand::Rgbw2d {
            unit: 0,
            width: 8,
            height: 8
        })
    );
    assert_eq!(
        p("texture rgbw 1D 1"),
        Command::Texture(TextureCommand::Rgbw1d { unit: 1 })
    );
    assert_eq!(
        p("texture shadow1D 0 (32)"),
        Command::Texture(TextureCommand::Shadow {
            unit: 0,
            target: GL_TEXTURE_1D,
            width: 32,
            height: 1
        })
    );
    assert_eq!(
        p("texture shadowRect 2 (32, 16)"),
        Command::Texture(TextureCommand::Shadow {
            unit: 2,
            target: GL_TEXTURE_RECTANGLE,
            width: 32,
            height: 16
        })
    );
    assert!(matches!(
        p("texture checkerboard 0 0 (32, 32) (0.5, 0.0, 0.0, 0.0) (1.0, 1.0, 1.0, 1.0)"),
        Command::Texture(TextureCommand::Checkerboard { width: 32, .. })
    ));
    assert_eq!(
        p("texparameter 2D compare_func greater"),
        Command::TexParameter {
            target: GL_TEXTURE_2D,
            pname: GL_TEXTURE_COMPARE_FUNC,
            value: TexParamValue::Enum(GL_GREATER)
        }
    );
    assert_eq!(
        p("texparameter Rect swizzle_g one"),
        Command::TexParameter {
            target: GL_TEXTURE_RECTANGLE,
            pname: GL_TEXTURE_SWIZZLE_G,
            value: TexParamValue::Enum(GL_ONE)
        }
    );
    assert_eq!(
        p("texture rgbw 1DArray 1 (16, 3)"),
        Command::Texture(TextureCommand::Array {
            unit: 1,
            target: GL_TEXTURE_1D_ARRAY,
            width: 16,
            height: 1,
            layers: 3,
            junk: false
        })
    );
    assert_eq!(
        p("texture shadow2DArray 0 (8, 4, 2)"),
        Command::Texture(TextureCommand::ShadowArray {
            unit: 0,
            target: GL_TEXTURE_2D_ARRAY,
            width: 8,
            height: 4,
            layers: 2
        })
    );
    assert!(parse("texture rgbw 0 (8)").is_err());
    assert!(parse("texparameter 2D depth_mode purple").is_err());
    assert!(parse("texparameter 2D swizzle_a purple").is_err());
}

#[test]
fn active_shader_program_names_a_stage() {
    assert_eq!(
        p("active shader program GL_FRAGMENT_SHADER"),
        Command::ActiveShaderProgram(gl::enums::GL_FRAGMENT_SHADER)
    );
    assert!(matches!(
        p("active shader program GL_TESS_CONTROL_SHADER"),
        Command::NeedsLaterGl(_)
    ));
    assert!(parse("active shader program GL_FOO").is_err());
}
