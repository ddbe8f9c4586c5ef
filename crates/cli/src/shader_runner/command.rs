//! The `[test]` commands.
//!
//! Each line is one command, recognised by its leading words as piglit's
//! `shader_runner` does (in the same order, so that `probe all rgba` wins
//! over `probe all rgb`); values are read with the C library's rules
//! ([`super::scan`]). Values after the ones a command needs are ignored, as
//! piglit ignores them (some tests put comments there). Where piglit would
//! read uninitialised memory because a value is missing, the line is
//! rejected instead.
//!
//! Beyond piglit (no piglit test uses them; `shaderbox debug`'s stencil
//! examples do): `clear stencil N`, `stencil func FUNC REF MASK`,
//! `stencil op FAIL ZFAIL ZPASS`.
//!
//! Commands of later GL versions and extensions (compute, SSBOs, transform
//! feedback, atomic counters, subroutines, framebuffer objects, ...) parse to
//! [`Command::NeedsLaterGl`]: running one makes the test a skip.

use super::scan::{self, Scanned};
use super::script::Cmp;
use gl::enums::*;

mod texture;
use texture::{parse_texparameter, parse_texture};
pub use texture::{TexParamValue, TextureCommand};

/// A `[test]` command.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    ClearColor([f32; 4]),
    ClearDepth(f32),
    ClearStencil(i32),
    /// `stencil func FUNC REF MASK` (a shaderbox extension).
    StencilFunc {
        func: u32,
        reference: i32,
        mask: u32,
    },
    /// `stencil op FAIL ZFAIL ZPASS` (a shaderbox extension).
    StencilOp([u32; 3]),
    Clear,
    ClipPlane {
        plane: u32,
        equation: [f64; 4],
    },
    Color([f32; 4]),
    /// `draw rect [ortho] X Y W H`, `draw rect tex X Y W H TX TY TW TH`
    /// and `draw instanced rect [ortho] N X Y W H` (N instances).
    DrawRect {
        rect: [f32; 4],
        ortho: bool,
        tex: Option<[f32; 4]>,
        instances: i32,
    },
    /// `draw arrays MODE FIRST COUNT`, and `draw arrays instanced MODE
    /// FIRST COUNT INSTANCES`.
    DrawArrays {
        mode: u32,
        first: i32,
        count: i32,
        instances: i32,
    },
    /// `polygon mode FACE MODE`.
    PolygonMode {
        face: u32,
        mode: u32,
    },
    /// `provoking vertex first|last`.
    ProvokingVertex(u32),
    Enable(u32),
    Disable(u32),
    /// `blend func SRC DST`.
    BlendFunc {
        src: u32,
        dst: u32,
    },
    Frustum([f32; 6]),
    Hint {
        target: u32,
        mode: u32,
    },
    /// `ortho` (window coordinates) or `ortho L R B T`.
    Ortho(Option<[f32; 4]>),
    /// `probe rgb`/`probe rgba`: one pixel.
    ProbePixel {
        x: i32,
        y: i32,
        expected: Vec<f32>,
    },
    /// `relative probe rgb`/`rgba`: one pixel at a fraction of the window.
    RelativeProbePixel {
        rx: f32,
        ry: f32,
        expected: Vec<f32>,
    },
    /// `probe rect rgb`/`rgba (x, y, w, h) (color)`.
    ProbeRect {
        rect: [i32; 4],
        expected: Vec<f32>,
    },
    /// `relative probe rect rgb`/`rgba`.
    RelativeProbeRect {
        rect: [f32; 4],
        expected: Vec<f32>,
    },
    /// `probe all rgb`/`rgba`; `warn`: `probe warn all rgba`.
    ProbeAll {
        expected: Vec<f32>,
        warn: bool,
    },
    ProbeDepth {
        x: i32,
        y: i32,
        expected: f32,
    },
    Tolerance([f32; 4]),
    ShadeModel(u32),
    Texture(TextureCommand),
    TexParameter {
        target: u32,
        pname: u32,
        value: TexParamValue,
    },
    /// `uniform TYPE NAME VALUES`. piglit leaves values missing from the
    /// line uninitialised (a few tests write `vec4` with 3 values); here they
    /// are 0, and `missing` counts them for a warning.
    Uniform {
        ty: UniformType,
        name: String,
        values: UniformValues,
        missing: usize,
    },
    LinkError,
    LinkSuccess,
    Light {
        light: u32,
        pname: u32,
        values: LightValues,
    },
    /// `active uniform NAME PNAME VALUE`: glGetActiveUniformsiv of the
    /// active uniform NAME (as glGetActiveUniform names it) gives VALUE.
    ActiveUniform {
        name: String,
        pname: u32,
        expected: i32,
    },
    /// `ubo array index N`: later `uniform` commands naming members of an
    /// array of uniform blocks write element N's buffer.
    UboArrayIndex(u32),
    /// `active shader program GL_VERTEX_SHADER` (or another stage's
    /// shader type): the stage's separable program becomes the pipeline's
    /// active program, which `uniform` commands then set
    /// (glActiveShaderProgram; `SSO ENABLED` scripts).
    ActiveShaderProgram(u32),
    /// `compute X Y Z`: glDispatchCompute, then glMemoryBarrier.
    Compute([u32; 3]),
    /// `ssbo N SIZE`: a buffer of SIZE zero bytes at storage binding N.
    SsboCreate {
        binding: u32,
        size: usize,
    },
    /// `ssbo N subdata TYPE OFFSET VALUES`: the values' bytes at OFFSET
    /// of binding N's buffer.
    SsboSubData {
        binding: u32,
        offset: usize,
        words: Vec<u32>,
    },
    /// `probe ssbo TYPE N OFFSET OP VALUE`: the word at OFFSET of binding
    /// N's buffer, as TYPE, compared with VALUE.
    ProbeSsbo {
        binding: u32,
        offset: usize,
        ty: SsboType,
        op: Cmp,
        expected: u32,
    },
    /// A command shaderbox does not provide because it needs a later GL.
    NeedsLaterGl(String),
}

/// The scalar types of the `ssbo` and `probe ssbo` commands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SsboType {
    Int,
    Uint,
    Float,
}

impl SsboType {
    fn parse(word: &str) -> Option<SsboType> {
        Some(match word {
            "int" => SsboType::Int,
            "uint" => SsboType::Uint,
            "float" => SsboType::Float,
            _ => return None,
        })
    }

    /// A value as its word (ints in decimal or hex, as piglit reads them).
    fn word(self, text: &str) -> Option<u32> {
        match self {
            SsboType::Float => text.parse::<f32>().ok().map(f32::to_bits),
            SsboType::Int => scan::scan_i32_base0(text).map(|v| v.0 as u32),
            SsboType::Uint => parse_u32(text),
        }
    }

    /// `value CMP expected` of two words of this type.
    pub fn holds(self, op: Cmp, expected: u32, value: u32) -> bool {
        match self {
            SsboType::Int => op.holds(expected as i32, value as i32),
            SsboType::Uint => op.holds(expected, value),
            SsboType::Float => op.holds(f32::from_bits(expected), f32::from_bits(value)),
        }
    }

    /// A word as the type's value, for messages.
    pub fn show(self, w: u32) -> String {
        match self {
            SsboType::Int => (w as i32).to_string(),
            SsboType::Uint => w.to_string(),
            SsboType::Float => f32::from_bits(w).to_string(),
        }
    }
}

/// `light` values: `float ...` or `int ...`.
#[derive(Clone, Debug, PartialEq)]
pub enum LightValues {
    Float(Vec<f32>),
    Int(Vec<i32>),
}

/// The GLSL type a `uniform` command names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UniformType {
    /// float, vec2..vec4 (components).
    Float(u8),
    /// int, ivec2..4.
    Int(u8),
    /// uint, uvec2..4 (glUniform*uiv, GL 3.0).
    Uint(u8),
    /// bool, bvec2..4 (not in piglit; set with glUniform*iv).
    Bool(u8),
    /// matCxR: columns, rows.
    Mat(u8, u8),
}

impl UniformType {
    /// Values the command reads.
    pub fn components(self) -> usize {
        match self {
            UniformType::Float(n)
            | UniformType::Int(n)
            | UniformType::Uint(n)
            | UniformType::Bool(n) => usize::from(n),
            UniformType::Mat(c, r) => usize::from(c) * usize::from(r),
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum UniformValues {
    Floats(Vec<f32>),
    Ints(Vec<i32>),
    Uints(Vec<u32>),
}

/// A line piglit's `shader_runner` would reject.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct CommandError(pub String);

/// The glGetActiveUniformsiv pnames `active uniform` names.
fn active_uniform_pname(name: &str) -> Option<u32> {
    use gl::enums as e;
    Some(match name {
        "GL_UNIFORM_TYPE" => e::GL_UNIFORM_TYPE,
        "GL_UNIFORM_SIZE" => e::GL_UNIFORM_SIZE,
        "GL_UNIFORM_NAME_LENGTH" => e::GL_UNIFORM_NAME_LENGTH,
        "GL_UNIFORM_BLOCK_INDEX" => e::GL_UNIFORM_BLOCK_INDEX,
        "GL_UNIFORM_OFFSET" => e::GL_UNIFORM_OFFSET,
        "GL_UNIFORM_ARRAY_STRIDE" => e::GL_UNIFORM_ARRAY_STRIDE,
        "GL_UNIFORM_MATRIX_STRIDE" => e::GL_UNIFORM_MATRIX_STRIDE,
        "GL_UNIFORM_IS_ROW_MAJOR" => e::GL_UNIFORM_IS_ROW_MAJOR,
        _ => return None,
    })
}

/// The uniform type enums (and GL_TRUE/GL_FALSE) `active uniform` may
/// expect, by name.
fn uniform_type_enum(name: &str) -> Option<u32> {
    use gl::enums as e;
    Some(match name {
        "GL_FALSE" => 0,
        "GL_TRUE" => 1,
        "GL_FLOAT" => e::GL_FLOAT,
        "GL_FLOAT_VEC2" => e::GL_FLOAT_VEC2,
        "GL_FLOAT_VEC3" => e::GL_FLOAT_VEC3,
        "GL_FLOAT_VEC4" => e::GL_FLOAT_VEC4,
        "GL_INT" => e::GL_INT,
        "GL_INT_VEC2" => e::GL_INT_VEC2,
        "GL_INT_VEC3" => e::GL_INT_VEC3,
        "GL_INT_VEC4" => e::GL_INT_VEC4,
        "GL_UNSIGNED_INT" => e::GL_UNSIGNED_INT,
        "GL_UNSIGNED_INT_VEC2" => e::GL_UNSIGNED_INT_VEC2,
        "GL_UNSIGNED_INT_VEC3" => e::GL_UNSIGNED_INT_VEC3,
        "GL_UNSIGNED_INT_VEC4" => e::GL_UNSIGNED_INT_VEC4,
        "GL_BOOL" => e::GL_BOOL,
        "GL_BOOL_VEC2" => e::GL_BOOL_VEC2,
        "GL_BOOL_VEC3" => e::GL_BOOL_VEC3,
        "GL_BOOL_VEC4" => e::GL_BOOL_VEC4,
        "GL_FLOAT_MAT2" => e::GL_FLOAT_MAT2,
        "GL_FLOAT_MAT3" => e::GL_FLOAT_MAT3,
        "GL_FLOAT_MAT4" => e::GL_FLOAT_MAT4,
        "GL_FLOAT_MAT2x3" => e::GL_FLOAT_MAT2x3,
        "GL_FLOAT_MAT2x4" => e::GL_FLOAT_MAT2x4,
        "GL_FLOAT_MAT3x2" => e::GL_FLOAT_MAT3x2,
        "GL_FLOAT_MAT3x4" => e::GL_FLOAT_MAT3x4,
        "GL_FLOAT_MAT4x2" => e::GL_FLOAT_MAT4x2,
        "GL_FLOAT_MAT4x3" => e::GL_FLOAT_MAT4x3,
        "GL_SAMPLER_2D" => e::GL_SAMPLER_2D,
        _ => return None,
    })
}

fn bad(what: &str, line: &str) -> CommandError {
    CommandError(format!("{what} at: {line}"))
}

/// `parse_str`: optional white space, then the literal.
fn lit<'a>(s: &'a str, literal: &str) -> Option<&'a str> {
    s.trim_start_matches(|c| c != '\n' && scan::is_c_space(c))
        .strip_prefix(literal)
}

/// Exactly `n` floats (piglit's `parse_floats` with `strtof_hex`).
fn floats<const N: usize>(s: &str, what: &str, line: &str) -> Result<[f32; N], CommandError> {
    let (v, _) = scan::scan_list(s, N, scan::scan_f32_or_bits);
    v.try_into().map_err(|v: Vec<f32>| {
        bad(
            &format!("{what}: expected {N} numbers, found {}", v.len()),
            line,
        )
    })
}

fn scanned_f32(v: &[Scanned]) -> Vec<f32> {
    v.iter()
        .map(|s| match *s {
            Scanned::F(f) => f,
            Scanned::D(d) => d as f32,
            Scanned::I(i) => i as f32,
        })
        .collect()
}

fn scanned_i32(v: &[Scanned]) -> Vec<i32> {
    v.iter()
        .map(|s| match *s {
            Scanned::I(i) => i,
            Scanned::F(f) => f as i32,
            Scanned::D(d) => d as i32,
        })
        .collect()
}

/// `sscanf(line, pattern) == conversions`: every conversion of the pattern
/// read a value (literals after the last conversion need not match, as in
/// C: `relative probe rgb (0, 0) (1, 0, 0, 1)` reads its five values).
fn sscanf_all(line: &str, pattern: &str) -> Option<Vec<Scanned>> {
    let (v, _) = scan::sscanf(line, pattern);
    (v.len() == pattern.matches('%').count()).then_some(v)
}

/// Parses one `[test]` line; `Ok(None)` for blank lines and comments.
pub fn parse(line: &str) -> Result<Option<Command>, CommandError> {
    let line = line.trim_start_matches(|c| c != '\n' && scan::is_c_space(c));
    if line.is_empty() || line.starts_with('#') {
        return Ok(None);
    }
    parse_command(line).map(Some)
}

fn parse_command(line: &str) -> Result<Command, CommandError> {
    use Command as C;
    // Commands of later GL versions, by their leading words.
    for (prefix, what) in LATER_GL {
        if lit(line, prefix).is_some() {
            return Ok(C::NeedsLaterGl((*what).to_string()));
        }
    }
    if let Some(rest) = lit(line, "active shader program ") {
        let (stage, _) = scan::word(rest).ok_or_else(|| bad("Bad shader type", line))?;
        let kind = match stage {
            "GL_VERTEX_SHADER" => GL_VERTEX_SHADER,
            "GL_GEOMETRY_SHADER" => GL_GEOMETRY_SHADER,
            "GL_FRAGMENT_SHADER" => GL_FRAGMENT_SHADER,
            "GL_TESS_CONTROL_SHADER" | "GL_TESS_EVALUATION_SHADER" | "GL_COMPUTE_SHADER" => {
                return Ok(C::NeedsLaterGl(format!(
                    "{stage} (a stage shaderbox does not have)"
                )))
            }
            _ => return Err(bad(&format!("Bad shader type {stage}"), line)),
        };
        return Ok(C::ActiveShaderProgram(kind));
    }
    if let Some(rest) = lit(line, "active uniform ") {
        let (name, rest) = scan::word(rest).ok_or_else(|| bad("Bad active uniform", line))?;
        let (pname, rest) = scan::word(rest).ok_or_else(|| bad("Bad active uniform", line))?;
        let (value, _) = scan::word(rest).ok_or_else(|| bad("Bad active uniform", line))?;
        let pname = active_uniform_pname(pname)
            .ok_or_else(|| bad(&format!("Bad glGetUniformsiv pname {pname}"), line))?;
        let expected = if value.starts_with(|c: char| c.is_ascii_digit() || c == '-') {
            scan::scan_i32_base0(value).map(|v| v.0)
        } else {
            uniform_type_enum(value).map(|e| e as i32)
        }
        .ok_or_else(|| bad(&format!("Bad active uniform value {value}"), line))?;
        return Ok(C::ActiveUniform {
            name: name.to_string(),
            pname,
            expected,
        });
    }
    if let Some(rest) = lit(line, "compute ") {
        let v: Option<Vec<u32>> = rest.split_whitespace().take(3).map(parse_u32).collect();
        return match v.as_deref() {
            Some(&[x, y, z]) => Ok(C::Compute([x, y, z])),
            _ => Err(bad("compute needs X Y Z work group counts", line)),
        };
    }
    if let Some(rest) = lit(line, "probe ssbo ") {
        let words: Vec<&str> = rest.split_whitespace().collect();
        let [ty, binding, offset, op, value, ..] = words.as_slice() else {
            return Err(bad("probe ssbo needs TYPE BINDING OFFSET OP VALUE", line));
        };
        let ty = SsboType::parse(ty).ok_or_else(|| {
            CommandError(format!("probe ssbo: type {ty} is not int, uint or float"))
        })?;
        let op = Cmp::parse(op).ok_or_else(|| bad("probe ssbo: bad comparison", line))?;
        return Ok(C::ProbeSsbo {
            binding: parse_u32(binding).ok_or_else(|| bad("Bad ssbo binding", line))?,
            offset: parse_u32(offset).ok_or_else(|| bad("Bad ssbo offset", line))? as usize,
            ty,
            op,
            expected: ty
                .word(value)
                .ok_or_else(|| bad("Bad probe ssbo value", line))?,
        });
    }
    if let Some(rest) = lit(line, "ssbo ") {
        let words: Vec<&str> = rest
            .split_whitespace()
            .take_while(|w| !w.starts_with('#'))
            .collect();
        let binding = words
            .first()
            .and_then(|w| parse_u32(w))
            .ok_or_else(|| bad("Bad ssbo binding", line))?;
        if words.get(1) == Some(&"subdata") {
            let (Some(ty), Some(offset)) = (words.get(2), words.get(3)) else {
                return Err(bad("ssbo subdata needs TYPE OFFSET VALUES", line));
            };
            let ty = SsboType::parse(ty).ok_or_else(|| {
                CommandError(format!("ssbo subdata: type {ty} is not int, uint or float"))
            })?;
            let offset = parse_u32(offset).ok_or_else(|| bad("Bad ssbo offset", line))? as usize;
            let words: Option<Vec<u32>> = words[4..].iter().map(|w| ty.word(w)).collect();
            let words = words.ok_or_else(|| bad("Bad ssbo subdata value", line))?;
            return Ok(C::SsboSubData {
                binding,
                offset,
                words,
            });
        }
        let size = words
            .get(1)
            .and_then(|w| parse_u32(w))
            .ok_or_else(|| bad("ssbo needs BINDING SIZE", line))?;
        return Ok(C::SsboCreate {
            binding,
            size: size as usize,
        });
    }
    if let Some(rest) = lit(line, "ubo array index ") {
        let (w, _) = scan::word(rest).ok_or_else(|| bad("Bad ubo array index", line))?;
        let v = w
            .parse::<u32>()
            .map_err(|_| bad("Bad ubo array index", line))?;
        return Ok(C::UboArrayIndex(v));
    }
    if let Some(rest) = lit(line, "clear color ") {
        return Ok(C::ClearColor(floats::<4>(rest, "clear color", line)?));
    }
    if let Some(rest) = lit(line, "clear depth ") {
        return Ok(C::ClearDepth(floats::<1>(rest, "clear depth", line)?[0]));
    }
    if let Some(rest) = lit(line, "clear stencil ") {
        let (w, _) = scan::word(rest).ok_or_else(|| bad("Bad clear stencil value", line))?;
        let v = w
            .parse()
            .map_err(|_| bad("Bad clear stencil value", line))?;
        return Ok(C::ClearStencil(v));
    }
    if lit(line, "clear").is_some() {
        return Ok(C::Clear);
    }
    if let Some(rest) = lit(line, "stencil func ") {
        let words: Vec<&str> = rest.split_whitespace().collect();
        let [f, r, m, ..] = words.as_slice() else {
            return Err(bad("stencil func needs FUNC REF MASK", line));
        };
        let func = compare_func(f).ok_or_else(|| bad("Bad stencil function", line))?;
        let reference = r.parse().map_err(|_| bad("Bad stencil reference", line))?;
        let mask = parse_u32(m).ok_or_else(|| bad("Bad stencil mask", line))?;
        return Ok(C::StencilFunc {
            func,
            reference,
            mask,
        });
    }
    if let Some(rest) = lit(line, "stencil op ") {
        let ops: Option<Vec<u32>> = rest.split_whitespace().take(3).map(stencil_op).collect();
        return match ops.as_deref() {
            Some([a, b, c]) => Ok(C::StencilOp([*a, *b, *c])),
            _ => Err(bad("stencil op needs three of GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP", line)),
        };
    }
    if let Some(v) = sscanf_all(line, "clip plane %d %lf %lf %lf %lf") {
        let plane = scanned_i32(&v[..1])[0];
        let eq: Vec<f64> = v[1..]
            .iter()
            .map(|s| match *s {
                Scanned::D(d) => d,
                _ => 0.0,
            })
            .collect();
        if !(0..8).contains(&plane) {
            return Err(CommandError(format!("clip plane id {plane} out of range")));
        }
        return Ok(C::ClipPlane {
            plane: plane as u32,
            equation: [eq[0], eq[1], eq[2], eq[3]],
        });
    }
    if let Some(rest) = lit(line, "color ") {
        return Ok(C::Color(floats::<4>(rest, "color", line)?));
    }
    if let Some(rest) = lit(line, "draw rect tex ") {
        let v = floats::<8>(rest, "draw rect tex", line)?;
        return Ok(C::DrawRect {
            rect: [v[0], v[1], v[2], v[3]],
            ortho: false,
            tex: Some([v[4], v[5], v[6], v[7]]),
            instances: 1,
        });
    }
    if lit(line, "draw rect ortho patch ").is_some() || lit(line, "draw rect patch ").is_some() {
        return Ok(C::NeedsLaterGl("tessellation patches (OpenGL 4.0)".into()));
    }
    if let Some(rest) = lit(line, "draw rect ortho ") {
        return Ok(C::DrawRect {
            rect: floats::<4>(rest, "draw rect ortho", line)?,
            ortho: true,
            tex: None,
            instances: 1,
        });
    }
    if let Some(rest) = lit(line, "draw rect ") {
        return Ok(C::DrawRect {
            rect: floats::<4>(rest, "draw rect", line)?,
            ortho: false,
            tex: None,
            instances: 1,
        });
    }
    if let Some(rest) = lit(line, "draw instanced rect ") {
        let (ortho, rest) = match lit(rest, "ortho ") {
            Some(r) => (true, r),
            None => (false, rest),
        };
        let v = floats::<5>(rest, "draw instanced rect", line)?;
        if v[0].fract() != 0.0 || v[0] < 0.0 {
            return Err(bad(
                "draw instanced rect: the instance count must be a whole number",
                line,
            ));
        }
        return Ok(C::DrawRect {
            rect: [v[1], v[2], v[3], v[4]],
            ortho,
            tex: None,
            instances: v[0] as i32,
        });
    }
    if let Some(rest) = lit(line, "draw arrays instanced ") {
        let (mode_name, rest) =
            scan::word(rest).ok_or_else(|| bad("draw arrays instanced: no mode", line))?;
        let (v, _) = scan::scan_list(rest, 3, scan::scan_i32_dec);
        let [first, count, instances] = v[..] else {
            return Err(bad(
                "draw arrays instanced: expected MODE FIRST COUNT INSTANCES",
                line,
            ));
        };
        let mode = draw_mode(mode_name)?;
        return Ok(C::DrawArrays {
            mode,
            first,
            count,
            instances,
        });
    }
    if let Some(rest) = lit(line, "draw arrays ") {
        let (mode_name, rest) =
            scan::word(rest).ok_or_else(|| bad("draw arrays: no mode", line))?;
        let (v, _) = scan::scan_list(rest, 2, scan::scan_i32_dec);
        let [first, count] = v[..] else {
            return Err(bad("draw arrays: expected MODE FIRST COUNT", line));
        };
        let mode = draw_mode(mode_name)?;
        return Ok(C::DrawArrays {
            mode,
            first,
            count,
            instances: 1,
        });
    }
    if let Some(rest) = lit(line, "polygon mode ") {
        let words: Vec<&str> = rest.split_whitespace().collect();
        let face = match words.first().copied() {
            Some("GL_FRONT") => GL_FRONT,
            Some("GL_BACK") => GL_BACK,
            Some("GL_FRONT_AND_BACK") => GL_FRONT_AND_BACK,
            _ => return Err(bad("polygon mode: expected FACE MODE", line)),
        };
        let mode = match words.get(1).copied() {
            Some("GL_POINT") => GL_POINT,
            Some("GL_LINE") => GL_LINE,
            Some("GL_FILL") => GL_FILL,
            _ => return Err(bad("polygon mode: expected FACE MODE", line)),
        };
        return Ok(C::PolygonMode { face, mode });
    }
    if let Some(rest) = lit(line, "provoking vertex ") {
        return Ok(C::ProvokingVertex(match rest.trim() {
            "first" => GL_FIRST_VERTEX_CONVENTION,
            "last" => GL_LAST_VERTEX_CONVENTION,
            _ => return Err(bad("provoking vertex: expected first or last", line)),
        }));
    }
    if lit(line, "draw elements ").is_some() || lit(line, "multidraw arrays ").is_some() {
        return Ok(C::NeedsLaterGl("[elements] / multidraw".into()));
    }
    if let Some(rest) = lit(line, "blend func ") {
        let factor = |rest: &mut &str| -> Result<u32, CommandError> {
            let (w, r) = scan::word(rest).ok_or_else(|| bad("Bad blend factor", line))?;
            *rest = r;
            Ok(match w {
                "GL_ZERO" => GL_ZERO,
                "GL_ONE" => GL_ONE,
                "GL_SRC_COLOR" => GL_SRC_COLOR,
                "GL_ONE_MINUS_SRC_COLOR" => GL_ONE_MINUS_SRC_COLOR,
                "GL_SRC_ALPHA" => GL_SRC_ALPHA,
                "GL_ONE_MINUS_SRC_ALPHA" => GL_ONE_MINUS_SRC_ALPHA,
                "GL_DST_ALPHA" => GL_DST_ALPHA,
                "GL_ONE_MINUS_DST_ALPHA" => GL_ONE_MINUS_DST_ALPHA,
                "GL_DST_COLOR" => GL_DST_COLOR,
                "GL_ONE_MINUS_DST_COLOR" => GL_ONE_MINUS_DST_COLOR,
                _ => return Err(bad("Bad blend factor", line)),
            })
        };
        let mut r = rest;
        let src = factor(&mut r)?;
        let dst = factor(&mut r)?;
        return Ok(C::BlendFunc { src, dst });
    }
    if let Some(rest) = lit(line, "disable ") {
        return Ok(C::Disable(enable_cap(rest, line)?));
    }
    if let Some(rest) = lit(line, "enable ") {
        return Ok(C::Enable(enable_cap(rest, line)?));
    }
    if let Some(rest) = lit(line, "frustum") {
        return Ok(C::Frustum(floats::<6>(rest, "frustum", line)?));
    }
    if let Some(rest) = lit(line, "hint") {
        let (t, rest) = scan::word(rest).ok_or_else(|| bad("Bad hint target", line))?;
        let target = match t {
            "GL_LINE_SMOOTH_HINT" => GL_LINE_SMOOTH_HINT,
            "GL_POLYGON_SMOOTH_HINT" => GL_POLYGON_SMOOTH_HINT,
            "GL_TEXTURE_COMPRESSION_HINT" => GL_TEXTURE_COMPRESSION_HINT,
            "GL_FRAGMENT_SHADER_DERIVATIVE_HINT" => GL_FRAGMENT_SHADER_DERIVATIVE_HINT,
            _ => return Err(bad("Bad hint target", line)),
        };
        let (m, _) = scan::word(rest).ok_or_else(|| bad("Bad hint param", line))?;
        let mode = match m {
            "GL_FASTEST" => GL_FASTEST,
            "GL_NICEST" => GL_NICEST,
            "GL_DONT_CARE" => GL_DONT_CARE,
            _ => return Err(bad("Bad hint param", line)),
        };
        return Ok(C::Hint { target, mode });
    }
    if let Some(v) = sscanf_all(line, "ortho %f %f %f %f") {
        let v = scanned_f32(&v);
        return Ok(C::Ortho(Some([v[0], v[1], v[2], v[3]])));
    }
    if lit(line, "ortho").is_some() {
        return Ok(C::Ortho(None));
    }
    if let Some(rest) = lit(line, "probe rgba ") {
        let v = floats::<6>(rest, "probe rgba", line)?;
        return Ok(C::ProbePixel {
            x: v[0] as i32,
            y: v[1] as i32,
            expected: v[2..].to_vec(),
        });
    }
    if let Some(rest) = lit(line, "probe depth ") {
        let v = floats::<3>(rest, "probe depth", line)?;
        return Ok(C::ProbeDepth {
            x: v[0] as i32,
            y: v[1] as i32,
            expected: v[2],
        });
    }
    if let Some(v) = sscanf_all(
        line,
        "relative probe rgba ( %f , %f ) ( %f , %f , %f , %f )",
    ) {
        let v = scanned_f32(&v);
        return Ok(C::RelativeProbePixel {
            rx: v[0],
            ry: v[1],
            expected: v[2..].to_vec(),
        });
    }
    if let Some(rest) = lit(line, "probe rgb ") {
        let v = floats::<5>(rest, "probe rgb", line)?;
        return Ok(C::ProbePixel {
            x: v[0] as i32,
            y: v[1] as i32,
            expected: v[2..].to_vec(),
        });
    }
    if let Some(v) = sscanf_all(line, "relative probe rgb ( %f , %f ) ( %f , %f , %f )") {
        let v = scanned_f32(&v);
        return Ok(C::RelativeProbePixel {
            rx: v[0],
            ry: v[1],
            expected: v[2..].to_vec(),
        });
    }
    if let Some(v) = sscanf_all(
        line,
        "probe rect rgba ( %d , %d , %d , %d ) ( %f , %f , %f , %f )",
    ) {
        let r = scanned_i32(&v[..4]);
        return Ok(C::ProbeRect {
            rect: [r[0], r[1], r[2], r[3]],
            expected: scanned_f32(&v[4..]),
        });
    }
    if let Some(v) = sscanf_all(
        line,
        "probe rect rgb ( %d , %d , %d , %d ) ( %f , %f , %f )",
    ) {
        let r = scanned_i32(&v[..4]);
        return Ok(C::ProbeRect {
            rect: [r[0], r[1], r[2], r[3]],
            expected: scanned_f32(&v[4..]),
        });
    }
    if let Some(v) = sscanf_all(
        line,
        "relative probe rect rgb ( %f , %f , %f , %f ) ( %f , %f , %f )",
    ) {
        let v = scanned_f32(&v);
        return Ok(C::RelativeProbeRect {
            rect: [v[0], v[1], v[2], v[3]],
            expected: v[4..].to_vec(),
        });
    }
    if let Some(v) = sscanf_all(
        line,
        "relative probe rect rgba ( %f , %f , %f , %f ) ( %f , %f , %f , %f )",
    ) {
        let v = scanned_f32(&v);
        return Ok(C::RelativeProbeRect {
            rect: [v[0], v[1], v[2], v[3]],
            expected: v[4..].to_vec(),
        });
    }
    if lit(line, "relative probe rect rgba int ").is_some() {
        return Ok(C::NeedsLaterGl("integer color buffers (OpenGL 3.0)".into()));
    }
    if lit(line, "polygon mode ").is_some() {
        return Ok(C::NeedsLaterGl("the `polygon mode' command".into()));
    }
    if let Some(rest) = lit(line, "probe all rgba ") {
        return Ok(C::ProbeAll {
            expected: floats::<4>(rest, "probe all rgba", line)?.to_vec(),
            warn: false,
        });
    }
    if let Some(rest) = lit(line, "probe warn all rgba ") {
        return Ok(C::ProbeAll {
            expected: floats::<4>(rest, "probe warn all rgba", line)?.to_vec(),
            warn: true,
        });
    }
    if let Some(rest) = lit(line, "probe all rgb") {
        return Ok(C::ProbeAll {
            expected: floats::<3>(rest, "probe all rgb", line)?.to_vec(),
            warn: false,
        });
    }
    if let Some(rest) = lit(line, "tolerance") {
        return Ok(C::Tolerance(floats::<4>(rest, "tolerance", line)?));
    }
    if lit(line, "shade model smooth").is_some() {
        return Ok(C::ShadeModel(GL_SMOOTH));
    }
    if lit(line, "shade model flat").is_some() {
        return Ok(C::ShadeModel(GL_FLAT));
    }
    if let Some(t) = parse_texture(line)? {
        return Ok(C::Texture(t));
    }
    if let Some(rest) = lit(line, "texparameter ") {
        return parse_texparameter(rest, line);
    }
    if let Some(rest) = lit(line, "uniform ") {
        return parse_uniform(rest, line);
    }
    if lit(line, "link error").is_some() {
        return Ok(C::LinkError);
    }
    if lit(line, "link success").is_some() {
        return Ok(C::LinkSuccess);
    }
    if let Some(rest) = lit(line, "light ") {
        return parse_light(rest, line);
    }
    Err(CommandError(format!("unknown command \"{line}\"")))
}

/// Leading words of commands that need a later GL or an extension.
const LATER_GL: &[(&str, &str)] = &[
    ("atomic counter", "atomic counters (OpenGL 4.2)"),
    ("subuniform ", "shader subroutines (OpenGL 4.0)"),
    ("probe atomic counter", "atomic counters (OpenGL 4.2)"),
    ("xfb ", "transform feedback (OpenGL 3.0)"),
    ("probe xfb ", "transform feedback (OpenGL 3.0)"),
    ("fb ", "framebuffer objects (OpenGL 3.0)"),
    ("blit ", "framebuffer objects (OpenGL 3.0)"),
    ("image texture ", "image load/store (OpenGL 4.2)"),
    ("memory barrier ", "image load/store (OpenGL 4.2)"),
    ("blend barrier", "GL_KHR_blend_equation_advanced"),
    ("fbfetch barrier", "GL_EXT_shader_framebuffer_fetch"),
    ("viewport indexed ", "viewport arrays (OpenGL 4.1)"),
    ("viewport swizzle ", "GL_NV_viewport_swizzle"),
    ("resident ", "GL_ARB_bindless_texture"),
    ("texture integer ", "integer textures (OpenGL 3.0)"),
    ("texture storage ", "texture storage (OpenGL 4.2)"),
    ("texcoord ", "the `texcoord' command"),
    ("parameter ", "ARB assembly programs"),
    ("patch parameter ", "tessellation (OpenGL 4.0)"),
    (
        "program binary save restore",
        "program binaries (OpenGL 4.1)",
    ),
    ("block ", "uniform blocks (OpenGL 3.1)"),
    ("verify program_query", "program queries"),
    (
        "verify program_interface_query ",
        "program interface queries (OpenGL 4.3)",
    ),
    ("verify query_object", "query objects"),
    ("vertex attrib ", "64-bit vertex attributes"),
    ("newlist ", "display lists"),
    ("endlist", "display lists"),
    ("calllist", "display lists"),
    ("deletelist", "display lists"),
    ("depthfunc ", "the `depthfunc' command"),
];

pub(super) fn draw_mode(name: &str) -> Result<u32, CommandError> {
    Ok(match name {
        "GL_POINTS" => GL_POINTS,
        "GL_LINES" => GL_LINES,
        "GL_LINE_LOOP" => GL_LINE_LOOP,
        "GL_LINE_STRIP" => GL_LINE_STRIP,
        "GL_TRIANGLES" => GL_TRIANGLES,
        "GL_TRIANGLE_STRIP" => GL_TRIANGLE_STRIP,
        "GL_TRIANGLE_FAN" => GL_TRIANGLE_FAN,
        "GL_QUADS" => GL_QUADS,
        "GL_QUAD_STRIP" => GL_QUAD_STRIP,
        "GL_POLYGON" => GL_POLYGON,
        "GL_LINES_ADJACENCY" => GL_LINES_ADJACENCY,
        "GL_LINE_STRIP_ADJACENCY" => GL_LINE_STRIP_ADJACENCY,
        "GL_TRIANGLES_ADJACENCY" => GL_TRIANGLES_ADJACENCY,
        "GL_TRIANGLE_STRIP_ADJACENCY" => GL_TRIANGLE_STRIP_ADJACENCY,
        _ => return Err(CommandError(format!("unknown drawing mode \"{name}\""))),
    })
}

fn compare_func(name: &str) -> Option<u32> {
    Some(match name {
        "GL_NEVER" => GL_NEVER,
        "GL_LESS" => GL_LESS,
        "GL_EQUAL" => GL_EQUAL,
        "GL_LEQUAL" => GL_LEQUAL,
        "GL_GREATER" => GL_GREATER,
        "GL_NOTEQUAL" => GL_NOTEQUAL,
        "GL_GEQUAL" => GL_GEQUAL,
        "GL_ALWAYS" => GL_ALWAYS,
        _ => return None,
    })
}

fn stencil_op(name: &str) -> Option<u32> {
    Some(match name {
        "GL_KEEP" => GL_KEEP,
        "GL_ZERO" => GL_ZERO,
        "GL_REPLACE" => GL_REPLACE,
        "GL_INCR" => GL_INCR,
        "GL_DECR" => GL_DECR,
        "GL_INVERT" => GL_INVERT,
        "GL_INCR_WRAP" => GL_INCR_WRAP,
        "GL_DECR_WRAP" => GL_DECR_WRAP,
        _ => return None,
    })
}

/// A decimal or `0x` hexadecimal unsigned number.
fn parse_u32(s: &str) -> Option<u32> {
    match s.strip_prefix("0x").or_else(|| s.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok(),
        None => s.parse().ok(),
    }
}

fn enable_cap(rest: &str, line: &str) -> Result<u32, CommandError> {
    let (name, _) = scan::word(rest).ok_or_else(|| bad("Bad enable/disable enum", line))?;
    if let Some(n) = name.strip_prefix("GL_CLIP_PLANE") {
        if let Ok(i @ 0..=7) = n.parse::<u32>() {
            return Ok(GL_CLIP_PLANE0 + i);
        }
    }
    Ok(match name {
        "GL_VERTEX_PROGRAM_TWO_SIDE" => GL_VERTEX_PROGRAM_TWO_SIDE,
        "GL_PROGRAM_POINT_SIZE" => GL_VERTEX_PROGRAM_POINT_SIZE,
        "GL_DEPTH_TEST" => GL_DEPTH_TEST,
        "GL_BLEND" => GL_BLEND,
        "GL_STENCIL_TEST" => GL_STENCIL_TEST,
        "GL_CULL_FACE" => GL_CULL_FACE,
        _ => return Err(bad("Bad enable/disable enum", line)),
    })
}

/// Parses a uniform type name; `Err` with a reason when it needs a later GL.
pub fn uniform_type(name: &str) -> Result<Option<UniformType>, String> {
    let vec_n = |s: &str| match s {
        "2" => Some(2u8),
        "3" => Some(3),
        "4" => Some(4),
        _ => None,
    };
    Ok(Some(match name {
        "float" => UniformType::Float(1),
        "int" => UniformType::Int(1),
        "bool" => UniformType::Bool(1),
        _ => {
            if let Some(n) = name.strip_prefix("vec").and_then(vec_n) {
                UniformType::Float(n)
            } else if let Some(n) = name.strip_prefix("ivec").and_then(vec_n) {
                UniformType::Int(n)
            } else if let Some(n) = name.strip_prefix("bvec").and_then(vec_n) {
                UniformType::Bool(n)
            } else if let Some(m) = name.strip_prefix("mat") {
                let (c, r) = match m.split_once('x') {
                    Some((c, r)) => (vec_n(c), vec_n(r)),
                    None => (vec_n(m), vec_n(m)),
                };
                match (c, r) {
                    (Some(c), Some(r)) => UniformType::Mat(c, r),
                    _ => return Ok(None),
                }
            } else if name == "uint" {
                UniformType::Uint(1)
            } else if let Some(n) = name.strip_prefix("uvec").and_then(vec_n) {
                UniformType::Uint(n)
            } else if name == "double" || name.starts_with("dvec") || name.starts_with("dmat") {
                return Err("double uniforms (OpenGL 4.0)".into());
            } else if name.contains("64") {
                return Err("64-bit integer uniforms (GL_ARB_gpu_shader_int64)".into());
            } else if name == "handle" {
                return Err("bindless textures (GL_ARB_bindless_texture)".into());
            } else {
                return Ok(None);
            }
        }
    }))
}

fn parse_uniform(rest: &str, line: &str) -> Result<Command, CommandError> {
    let (ty_name, rest) =
        scan::word(rest).ok_or_else(|| bad("Invalid set uniform command", line))?;
    let (name, rest) = scan::word(rest).ok_or_else(|| bad("Invalid set uniform command", line))?;
    let ty = match uniform_type(ty_name) {
        Ok(Some(t)) => t,
        Ok(None) => {
            return Err(CommandError(format!(
                "unknown uniform type \"{ty_name}\" for \"{name}\""
            )))
        }
        Err(why) => return Ok(Command::NeedsLaterGl(why)),
    };
    let n = ty.components();
    let missing;
    let values = match ty {
        UniformType::Float(_) | UniformType::Mat(..) => {
            let (mut v, _) = scan::scan_list(rest, n, scan::scan_f32_or_bits);
            missing = n - v.len();
            v.resize(n, 0.0);
            UniformValues::Floats(v)
        }
        UniformType::Int(_) | UniformType::Bool(_) => {
            let (mut v, _) = scan::scan_list(rest, n, scan::scan_i32_base0);
            missing = n - v.len();
            v.resize(n, 0);
            UniformValues::Ints(v)
        }
        UniformType::Uint(_) => {
            let (mut v, _) = scan::scan_list(rest, n, scan::scan_u32_base0);
            missing = n - v.len();
            v.resize(n, 0);
            UniformValues::Uints(v)
        }
    };
    if missing == n {
        return Err(bad(&format!("uniform {ty_name} {name}: no values"), line));
    }
    Ok(Command::Uniform {
        ty,
        name: name.to_string(),
        values,
        missing,
    })
}

fn parse_light(rest: &str, line: &str) -> Result<Command, CommandError> {
    let (index, rest) = scan::scan_i32_base0(rest).ok_or_else(|| bad("Bad light index", line))?;
    if !(0..8).contains(&index) {
        return Err(bad("Bad light index", line));
    }
    let (name, rest) = scan::word(rest).ok_or_else(|| bad("Bad light enum", line))?;
    let pname = match name {
        "GL_AMBIENT" => GL_AMBIENT,
        "GL_DIFFUSE" => GL_DIFFUSE,
        "GL_SPECULAR" => GL_SPECULAR,
        "GL_POSITION" => GL_POSITION,
        "GL_SPOT_DIRECTION" => GL_SPOT_DIRECTION,
        "GL_SPOT_EXPONENT" => GL_SPOT_EXPONENT,
        "GL_SPOT_CUTOFF" => GL_SPOT_CUTOFF,
        "GL_CONSTANT_ATTENUATION" => GL_CONSTANT_ATTENUATION,
        "GL_LINEAR_ATTENUATION" => GL_LINEAR_ATTENUATION,
        "GL_QUADRATIC_ATTENUATION" => GL_QUADRATIC_ATTENUATION,
        _ => return Err(bad("Bad light enum", line)),
    };
    let values = if let Some(r) = lit(rest, "float") {
        let (v, _) = scan::scan_list(r, 16, scan::scan_f32_or_bits);
        if v.is_empty() {
            return Err(bad("No float found for light", line));
        }
        LightValues::Float(v)
    } else if let Some(r) = lit(rest, "int") {
        let (v, _) = scan::scan_list(r, 16, scan::scan_i32_base0);
        if v.is_empty() {
            return Err(bad("No int found for light", line));
        }
        LightValues::Int(v)
    } else {
        return Err(CommandError(format!(
            "Invalid light value type \"{}\"",
            rest.trim()
        )));
    };
    Ok(Command::Light {
        light: GL_LIGHT0 + index as u32,
        pname,
        values,
    })
}

#[cfg(test)]
mod tests;
