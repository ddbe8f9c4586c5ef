//! The `texture ...` and `texparameter ...` commands: which image a test
//! asks for (piglit's generated patterns, sizes, formats, array layers)
//! and which sampler state.

use super::super::scan;
use super::{bad, floats, lit, scanned_f32, scanned_i32, sscanf_all, Command, CommandError};
use gl::enums::*;

/// The `texture ...` commands.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureCommand {
    /// `texture rgbw UNIT (W, H)`: quadrants red, green, blue, white.
    Rgbw2d { unit: u32, width: u32, height: u32 },
    /// `texture rgbw 1D UNIT`: texels red, green, blue, white.
    Rgbw1d { unit: u32 },
    /// `texture rgbw 3D UNIT`: 2x2x2 texels.
    Rgbw3d { unit: u32 },
    /// `texture miptree UNIT`: 8x8 with 4 solid levels.
    Miptree { unit: u32 },
    /// `texture checkerboard UNIT LEVEL (W, H) (black) (white)`.
    Checkerboard {
        unit: u32,
        level: i32,
        width: u32,
        height: u32,
        black: [f32; 4],
        white: [f32; 4],
    },
    /// `texture quads UNIT LEVEL (W, H) (SX, SY) (bl) (br) (tl) (tr)`.
    Quads {
        unit: u32,
        level: i32,
        width: u32,
        height: u32,
        square: [u32; 2],
        colors: [[f32; 4]; 4],
    },
    /// `texture shadow1D UNIT (W)` / `shadow2D UNIT (W, H)` / `shadowRect
    /// UNIT (W, H)`: depth gradients with compare mode on, compare func
    /// GREATER.
    Shadow {
        unit: u32,
        target: u32,
        width: u32,
        height: u32,
    },
    /// `texture rgbw 1DArray UNIT (W, L)` / `rgbw 2DArray UNIT (W, H, L)`:
    /// each layer one colour of red, green, blue, white in turn;
    /// `texture junk 2DArray UNIT (W, H, L)` (`junk`): contents undefined,
    /// no parameters set.
    Array {
        unit: u32,
        target: u32,
        width: u32,
        height: u32,
        layers: u32,
        junk: bool,
    },
    /// `texture shadow1DArray UNIT (W, L)` / `shadow2DArray UNIT (W, H,
    /// L)`: every layer the depth gradient of `Shadow`, compared GREATER.
    ShadowArray {
        unit: u32,
        target: u32,
        width: u32,
        height: u32,
        layers: u32,
    },
}

/// A `texparameter` value.
#[derive(Clone, Debug, PartialEq)]
pub enum TexParamValue {
    Enum(u32),
    Int(i32),
    Float(f32),
    Color([f32; 4]),
}

/// `texture ...` commands, or `None` when the line is not one.
pub(super) fn parse_texture(line: &str) -> Result<Option<TextureCommand>, CommandError> {
    use TextureCommand as T;
    let dim = |v: i32, line: &str| -> Result<u32, CommandError> {
        if (1..=16384).contains(&v) {
            Ok(v as u32)
        } else {
            Err(bad(&format!("texture size {v} out of range"), line))
        }
    };
    let unit = |v: i32, line: &str| -> Result<u32, CommandError> {
        if (0..32).contains(&v) {
            Ok(v as u32)
        } else {
            Err(bad(&format!("invalid texture index {v}"), line))
        }
    };
    if let Some(v) = sscanf_all(line, "texture rgbw 1D %d") {
        return Ok(Some(T::Rgbw1d {
            unit: unit(scanned_i32(&v)[0], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture rgbw 3D %d") {
        return Ok(Some(T::Rgbw3d {
            unit: unit(scanned_i32(&v)[0], line)?,
        }));
    }
    let (v, _) = scan::sscanf(line, "texture rgbw %d ( %d , %d )");
    if v.len() >= 2 {
        if v.len() < 3 {
            return Err(bad("invalid texture rgbw command", line));
        }
        // An internal format after the size would need sized formats.
        let rest_after = line.rfind(')').map_or("", |i| &line[i + 1..]);
        if let Some((fmt, _)) = scan::word(rest_after) {
            if fmt != "GL_RGBA" && fmt != "GL_RGBA8" {
                return Err(bad(
                    &format!("texture rgbw: unsupported internal format {fmt}"),
                    line,
                ));
            }
        }
        let v = scanned_i32(&v);
        return Ok(Some(T::Rgbw2d {
            unit: unit(v[0], line)?,
            width: dim(v[1], line)?,
            height: dim(v[2], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture miptree %d") {
        return Ok(Some(T::Miptree {
            unit: unit(scanned_i32(&v)[0], line)?,
        }));
    }
    if let Some(v) = sscanf_all(
        line,
        "texture checkerboard %d %d ( %d , %d ) ( %f , %f , %f , %f ) ( %f , %f , %f , %f )",
    ) {
        let i = scanned_i32(&v[..4]);
        let c = scanned_f32(&v[4..]);
        return Ok(Some(T::Checkerboard {
            unit: unit(i[0], line)?,
            level: i[1].clamp(0, 15),
            width: dim(i[2], line)?,
            height: dim(i[3], line)?,
            black: [c[0], c[1], c[2], c[3]],
            white: [c[4], c[5], c[6], c[7]],
        }));
    }
    if let Some(v) = sscanf_all(
        line,
        "texture quads %d %d ( %d , %d ) ( %d , %d ) ( %f , %f , %f , %f ) ( %f , %f , %f , %f ) ( %f , %f , %f , %f ) ( %f , %f , %f , %f )",
    ) {
        let i = scanned_i32(&v[..6]);
        let c = scanned_f32(&v[6..]);
        let color = |k: usize| [c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]];
        return Ok(Some(T::Quads {
            unit: unit(i[0], line)?,
            level: i[1].clamp(0, 15),
            width: dim(i[2], line)?,
            height: dim(i[3], line)?,
            square: [dim(i[4], line)?, dim(i[5], line)?],
            colors: [color(0), color(1), color(2), color(3)],
        }));
    }
    if let Some(v) = sscanf_all(line, "texture shadow2D %d ( %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Shadow {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_2D,
            width: dim(i[1], line)?,
            height: dim(i[2], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture rgbw 2DArray %d ( %d , %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Array {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_2D_ARRAY,
            width: dim(i[1], line)?,
            height: dim(i[2], line)?,
            layers: dim(i[3], line)?,
            junk: false,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture junk 2DArray %d ( %d , %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Array {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_2D_ARRAY,
            width: dim(i[1], line)?,
            height: dim(i[2], line)?,
            layers: dim(i[3], line)?,
            junk: true,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture rgbw 1DArray %d ( %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Array {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_1D_ARRAY,
            width: dim(i[1], line)?,
            height: 1,
            layers: dim(i[2], line)?,
            junk: false,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture shadow2DArray %d ( %d , %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::ShadowArray {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_2D_ARRAY,
            width: dim(i[1], line)?,
            height: dim(i[2], line)?,
            layers: dim(i[3], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture shadow1DArray %d ( %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::ShadowArray {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_1D_ARRAY,
            width: dim(i[1], line)?,
            height: 1,
            layers: dim(i[2], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture shadowRect %d ( %d , %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Shadow {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_RECTANGLE,
            width: dim(i[1], line)?,
            height: dim(i[2], line)?,
        }));
    }
    if let Some(v) = sscanf_all(line, "texture shadow1D %d ( %d )") {
        let i = scanned_i32(&v);
        return Ok(Some(T::Shadow {
            unit: unit(i[0], line)?,
            target: GL_TEXTURE_1D,
            width: dim(i[1], line)?,
            height: 1,
        }));
    }
    if lit(line, "texture ").is_some() {
        return Err(CommandError(format!("unknown command \"{line}\"")));
    }
    Ok(None)
}

pub(super) fn parse_texparameter(rest: &str, line: &str) -> Result<Command, CommandError> {
    let (t, rest) = scan::word(rest).ok_or_else(|| bad("Bad texture target", line))?;
    let target = match t {
        "1D" => GL_TEXTURE_1D,
        "2D" => GL_TEXTURE_2D,
        "3D" => GL_TEXTURE_3D,
        "Cube" => GL_TEXTURE_CUBE_MAP,
        "Rect" => GL_TEXTURE_RECTANGLE,
        "1DArray" => GL_TEXTURE_1D_ARRAY,
        "2DArray" => GL_TEXTURE_2D_ARRAY,
        "CubeArray" | "2DMS" | "2DMSArray" | "Buffer" => {
            return Ok(Command::NeedsLaterGl(format!(
                "{t} textures (OpenGL 3.0 or later)"
            )))
        }
        _ => return Err(bad("Bad texture target", line)),
    };
    let (param, rest) = scan::word(rest).ok_or_else(|| bad("unknown texture parameter", line))?;
    let table: &[(&str, u32)] = match param {
        "compare_func" => &[
            ("greater", GL_GREATER),
            ("gequal", GL_GEQUAL),
            ("less", GL_LESS),
            ("lequal", GL_LEQUAL),
            ("equal", GL_EQUAL),
            ("notequal", GL_NOTEQUAL),
            ("never", GL_NEVER),
            ("always", GL_ALWAYS),
        ],
        "depth_mode" => &[
            ("intensity", GL_INTENSITY),
            ("luminance", GL_LUMINANCE),
            ("alpha", GL_ALPHA),
            ("red", GL_RED),
        ],
        "min" => &[
            ("nearest_mipmap_nearest", GL_NEAREST_MIPMAP_NEAREST),
            ("linear_mipmap_nearest", GL_LINEAR_MIPMAP_NEAREST),
            ("nearest_mipmap_linear", GL_NEAREST_MIPMAP_LINEAR),
            ("linear_mipmap_linear", GL_LINEAR_MIPMAP_LINEAR),
            ("nearest", GL_NEAREST),
            ("linear", GL_LINEAR),
        ],
        "mag" => &[("nearest", GL_NEAREST), ("linear", GL_LINEAR)],
        "wrap_s" | "wrap_t" | "wrap_r" => &[
            ("repeat", GL_REPEAT),
            ("clamp_to_edge", GL_CLAMP_TO_EDGE),
            ("clamp_to_border", GL_CLAMP_TO_BORDER),
        ],
        "lod_bias" => {
            let (v, _) = scan::scan_f64(rest).ok_or_else(|| bad("Bad lod_bias", line))?;
            return Ok(Command::TexParameter {
                target,
                pname: GL_TEXTURE_LOD_BIAS,
                value: TexParamValue::Float(v as f32),
            });
        }
        "max_level" | "base_level" => {
            let (v, _) = scan::scan_i32_dec(rest).ok_or_else(|| bad("Bad level", line))?;
            let pname = if param == "max_level" {
                GL_TEXTURE_MAX_LEVEL
            } else {
                GL_TEXTURE_BASE_LEVEL
            };
            return Ok(Command::TexParameter {
                target,
                pname,
                value: TexParamValue::Int(v),
            });
        }
        "border_color" => {
            let c = floats::<4>(rest, "Could not parse border_color texture parameter", line)?;
            return Ok(Command::TexParameter {
                target,
                pname: GL_TEXTURE_BORDER_COLOR,
                value: TexParamValue::Color(c),
            });
        }
        "swizzle_r" | "swizzle_g" | "swizzle_b" | "swizzle_a" => &[
            ("red", GL_RED),
            ("green", GL_GREEN),
            ("blue", GL_BLUE),
            ("alpha", GL_ALPHA),
            ("zero", GL_ZERO),
            ("one", GL_ONE),
        ],
        _ => {
            return Err(CommandError(format!(
                "unknown texture parameter in `{line}'"
            )))
        }
    };
    let pname = match param {
        "compare_func" => GL_TEXTURE_COMPARE_FUNC,
        "depth_mode" => GL_DEPTH_TEXTURE_MODE,
        "min" => GL_TEXTURE_MIN_FILTER,
        "mag" => GL_TEXTURE_MAG_FILTER,
        "wrap_s" => GL_TEXTURE_WRAP_S,
        "wrap_t" => GL_TEXTURE_WRAP_T,
        "wrap_r" => GL_TEXTURE_WRAP_R,
        "swizzle_r" => GL_TEXTURE_SWIZZLE_R,
        "swizzle_g" => GL_TEXTURE_SWIZZLE_G,
        "swizzle_b" => GL_TEXTURE_SWIZZLE_B,
        _ => GL_TEXTURE_SWIZZLE_A,
    };
    let (v, _) = scan::word(rest).ok_or_else(|| bad(&format!("Bad {param}"), line))?;
    let value = table
        .iter()
        .find(|(n, _)| *n == v)
        .map(|&(_, e)| e)
        .ok_or_else(|| bad(&format!("Bad {param}"), line))?;
    Ok(Command::TexParameter {
        target,
        pname,
        value: TexParamValue::Enum(value),
    })
}
