//! `debugPrintfEXT`: the format strings of shaderbox's debug extension.
//!
//! A shader that says `#extension GL_SHADERBOX_debug_printf : enable` may
//! call `debugPrintfEXT("format", args...)` as a statement. The format
//! follows C's `printf` for the conversions that make sense for GLSL values
//! (the same subset as Vulkan's `GL_EXT_debug_printf`):
//!
//! | conversion | argument |
//! |---|---|
//! | `%d` `%i` | `int` (a `bool` prints as 0 or 1) |
//! | `%u` `%x` `%X` `%o` | `uint`, or an `int` or `bool` printed as its 32-bit pattern |
//! | `%f` `%F` `%e` `%E` `%g` `%G` `%a` `%A` | `float` |
//! | `%vNc` (N = 2, 3, 4; c one of the above) | a vector of N components, printed `x, y, z` |
//! | `%%` | a literal `%` |
//!
//! Flags `-`, `+`, ` `, `0`, `#`, a width and a `.precision` are accepted
//! before the conversion as in C. Escapes in the string: `\n`, `\t`, `\\`,
//! `\"`. Formatting is done by [`format_values`], in Rust, so the text is the
//! same on every machine.
//!
//! A `uint` given to `%d`/`%i` is an error rather than a signed reading of
//! its bits (4294967295u would print as -1): `%u` prints it. The unsigned
//! conversions keep taking `int`s, which are all GLSL 1.10 and 1.20 have.

use crate::types::{Base, Scalar, Type};

/// One part of a parsed format string.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub enum Piece {
    Text(String),
    Arg(Conversion),
}

/// One `%` conversion.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Conversion {
    /// The conversion letter (`d`, `f`, `x`, ...).
    pub kind: char,
    /// Components: 1 for a scalar, 2–4 for `%vN`.
    pub components: u8,
    pub left: bool,
    pub plus: bool,
    pub space: bool,
    pub zero: bool,
    pub alt: bool,
    pub width: Option<u32>,
    pub precision: Option<u32>,
}

/// Largest width or precision accepted (keeps output bounded).
pub const MAX_FIELD: u32 = 64;

impl Conversion {
    /// Whether the conversion takes floats (else ints).
    pub fn is_float(&self) -> bool {
        matches!(self.kind, 'f' | 'F' | 'e' | 'E' | 'g' | 'G' | 'a' | 'A')
    }

    /// Whether the conversion prints the bits as unsigned (`%u`, `%x`,
    /// `%X`, `%o`): it takes `uint`s as well as `int`s.
    pub fn is_unsigned(&self) -> bool {
        matches!(self.kind, 'u' | 'x' | 'X' | 'o')
    }

    /// The GLSL type an argument must have, spelled for a message.
    pub fn expected(&self) -> String {
        let n = self.components;
        match (self.is_float(), self.is_unsigned(), n) {
            (true, _, 1) => "float".to_string(),
            (true, _, _) => format!("vec{n}"),
            (false, true, 1) => "uint or int".to_string(),
            (false, true, _) => format!("uvec{n} or ivec{n}"),
            (false, false, 1) => "int".to_string(),
            (false, false, _) => format!("ivec{n}"),
        }
    }

    /// Whether an argument of type `ty` fits this conversion.
    pub fn accepts(&self, ty: Type) -> bool {
        if ty.array.is_some() {
            return false;
        }
        let (scalar, n) = match ty.base {
            Base::Scalar(s) => (s, 1),
            Base::Vector(s, n) => (s, n),
            _ => return false,
        };
        if n != self.components {
            return false;
        }
        if self.is_float() {
            scalar == Scalar::Float
        } else if self.is_unsigned() {
            matches!(scalar, Scalar::Uint | Scalar::Int | Scalar::Bool)
        } else {
            matches!(scalar, Scalar::Int | Scalar::Bool)
        }
    }
}

/// Parses the text between the quotes of a format string.
pub fn parse(text: &str) -> Result<Vec<Piece>, String> {
    let mut pieces = Vec::new();
    let mut lit = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => match chars.next() {
                Some('n') => lit.push('\n'),
                Some('t') => lit.push('\t'),
                Some('\\') => lit.push('\\'),
                Some('"') => lit.push('"'),
                Some(o) => {
                    return Err(format!(
                        "unknown escape `\\{o}' (use \\n, \\t, \\\\ or \\\")"
                    ))
                }
                None => return Err("the format ends with a lone `\\'".into()),
            },
            '%' => {
                if chars.peek() == Some(&'%') {
                    chars.next();
                    lit.push('%');
                    continue;
                }
                let mut conv = Conversion {
                    kind: 'd',
                    components: 1,
                    left: false,
                    plus: false,
                    space: false,
                    zero: false,
                    alt: false,
                    width: None,
                    precision: None,
                };
                while let Some(&f) = chars.peek() {
                    match f {
                        '-' => conv.left = true,
                        '+' => conv.plus = true,
                        ' ' => conv.space = true,
                        '0' => conv.zero = true,
                        '#' => conv.alt = true,
                        _ => break,
                    }
                    chars.next();
                }
                conv.width = number(&mut chars)?;
                if chars.peek() == Some(&'.') {
                    chars.next();
                    conv.precision = Some(number(&mut chars)?.unwrap_or(0));
                }
                if chars.peek() == Some(&'v') {
                    chars.next();
                    conv.components = match chars.next() {
                        Some(d @ '2'..='4') => d as u8 - b'0',
                        other => {
                            return Err(format!(
                                "`%v' must be followed by 2, 3 or 4 (found {})",
                                other.map_or("the end".to_string(), |c| format!("`{c}'"))
                            ))
                        }
                    };
                }
                conv.kind = match chars.next() {
                    Some(
                        k @ ('d' | 'i' | 'u' | 'x' | 'X' | 'o' | 'f' | 'F' | 'e' | 'E' | 'g' | 'G'
                        | 'a' | 'A'),
                    ) => k,
                    Some(k) => {
                        return Err(format!(
                            "unsupported conversion `%{k}' (use %d %i for int, %u %x %o for uint \
                             or int, %f %e %g %a for float, %v3f for a vec3, %% for a percent sign)"
                        ))
                    }
                    None => return Err("the format ends inside a `%' conversion".into()),
                };
                if !lit.is_empty() {
                    pieces.push(Piece::Text(std::mem::take(&mut lit)));
                }
                pieces.push(Piece::Arg(conv));
            }
            c => lit.push(c),
        }
    }
    if !lit.is_empty() {
        pieces.push(Piece::Text(lit));
    }
    Ok(pieces)
}

fn number(chars: &mut std::iter::Peekable<std::str::Chars>) -> Result<Option<u32>, String> {
    let mut v: Option<u32> = None;
    while let Some(d) = chars.peek().and_then(|c| c.to_digit(10)) {
        chars.next();
        let n = v.unwrap_or(0).saturating_mul(10).saturating_add(d);
        if n > MAX_FIELD {
            return Err(format!(
                "a width or precision above {MAX_FIELD} is not supported"
            ));
        }
        v = Some(n);
    }
    Ok(v)
}

/// The conversions of a parsed format, in order.
pub fn conversions(pieces: &[Piece]) -> impl Iterator<Item = &Conversion> {
    pieces.iter().filter_map(|p| match p {
        Piece::Arg(c) => Some(c),
        Piece::Text(_) => None,
    })
}

/// Formats `values`: for each conversion in order, its components' raw
/// bits (floats as `f32` bits, ints as `i32` bits, uints as they are).
/// Missing values print as 0.
pub fn format_values(pieces: &[Piece], values: &[u32]) -> String {
    let mut out = String::new();
    let mut next = values.iter().copied();
    for p in pieces {
        match p {
            Piece::Text(t) => out.push_str(t),
            Piece::Arg(c) => {
                for i in 0..c.components {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    let bits = next.next().unwrap_or(0);
                    out.push_str(&format_one(c, bits));
                }
            }
        }
    }
    out
}

fn format_one(c: &Conversion, bits: u32) -> String {
    let (sign, body) = match c.kind {
        'd' | 'i' => {
            let v = bits as i32;
            let sign = if v < 0 {
                "-"
            } else if c.plus {
                "+"
            } else if c.space {
                " "
            } else {
                ""
            };
            let mut digits = v.unsigned_abs().to_string();
            pad_precision(&mut digits, c.precision);
            (sign, digits)
        }
        'u' => ("", with_precision(bits.to_string(), c.precision)),
        'x' => (
            if c.alt && bits != 0 { "0x" } else { "" },
            with_precision(format!("{bits:x}"), c.precision),
        ),
        'X' => (
            if c.alt && bits != 0 { "0X" } else { "" },
            with_precision(format!("{bits:X}"), c.precision),
        ),
        'o' => (
            if c.alt { "0" } else { "" },
            with_precision(format!("{bits:o}"), c.precision),
        ),
        _ => {
            let v = f32::from_bits(bits);
            let sign = if v.is_sign_negative() && !v.is_nan() {
                "-"
            } else if c.plus {
                "+"
            } else if c.space {
                " "
            } else {
                ""
            };
            (sign, format_float(c, v.abs()))
        }
    };
    let len = sign.len() + body.len();
    let width = c.width.unwrap_or(0) as usize;
    if len >= width {
        return format!("{sign}{body}");
    }
    let fill = width - len;
    let numeric_zero = c.zero
        && !c.left
        && (c.is_float() && f32::from_bits(bits).is_finite()
            || !c.is_float() && c.precision.is_none());
    if c.left {
        format!("{sign}{body}{}", " ".repeat(fill))
    } else if numeric_zero {
        format!("{sign}{}{body}", "0".repeat(fill))
    } else {
        format!("{}{sign}{body}", " ".repeat(fill))
    }
}

fn with_precision(mut s: String, precision: Option<u32>) -> String {
    pad_precision(&mut s, precision);
    s
}

fn pad_precision(digits: &mut String, precision: Option<u32>) {
    if let Some(p) = precision {
        let p = p as usize;
        if digits == "0" && p == 0 {
            digits.clear();
        } else if digits.len() < p {
            digits.insert_str(0, &"0".repeat(p - digits.len()));
        }
    }
}

/// A non-negative float in C's notation for the conversion.
fn format_float(c: &Conversion, v: f32) -> String {
    let upper = c.kind.is_ascii_uppercase();
    let s = if v.is_nan() {
        "nan".to_string()
    } else if v.is_infinite() {
        "inf".to_string()
    } else {
        let p = c.precision.unwrap_or(6) as usize;
        match c.kind.to_ascii_lowercase() {
            'f' => format!("{v:.p$}"),
            'e' => exponent(v, p),
            'a' => hex_float(v),
            _ => general(v, p.max(1), c.alt),
        }
    };
    if upper {
        s.to_uppercase()
    } else {
        s
    }
}

/// `%e`: d.ddde±XX (at least two exponent digits, as C).
fn exponent(v: f32, p: usize) -> String {
    let s = format!("{v:.p$e}");
    let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
    let e: i32 = exp.parse().unwrap_or(0);
    format!(
        "{mantissa}e{}{:02}",
        if e < 0 { '-' } else { '+' },
        e.unsigned_abs()
    )
}

/// `%g`: the shorter of `%e` and `%f` with `p` significant digits, trailing
/// zeros removed unless `alt`.
fn general(v: f32, p: usize, alt: bool) -> String {
    let x = if v == 0.0 {
        0
    } else {
        let s = format!("{v:.*e}", p - 1);
        s.split_once('e')
            .and_then(|(_, e)| e.parse::<i32>().ok())
            .unwrap_or(0)
    };
    let mut s = if x < -4 || x >= p as i32 {
        exponent(v, p - 1)
    } else {
        let decimals = (p as i32 - 1 - x).max(0) as usize;
        format!("{v:.decimals$}")
    };
    if !alt {
        let (mantissa, exp) = match s.find('e') {
            Some(i) => (s[..i].to_string(), s[i..].to_string()),
            None => (s.clone(), String::new()),
        };
        if mantissa.contains('.') {
            let m = mantissa.trim_end_matches('0').trim_end_matches('.');
            s = format!("{m}{exp}");
        }
    }
    s
}

/// `%a`: hexadecimal floating point, as C prints a `double` holding `v`.
fn hex_float(v: f32) -> String {
    if v == 0.0 {
        return "0x0p+0".into();
    }
    let d = v as f64;
    let bits = d.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let frac = bits & ((1u64 << 52) - 1);
    let mut hex = format!("{frac:013x}");
    while hex.ends_with('0') {
        hex.pop();
    }
    let dot = if hex.is_empty() { "" } else { "." };
    format!(
        "0x1{dot}{hex}p{}{}",
        if exp < 0 { '-' } else { '+' },
        exp.abs()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(f: &str, vals: &[u32]) -> String {
        format_values(&parse(f).unwrap(), vals)
    }

    #[test]
    fn parses_conversions_and_text() {
        let p = parse("x=%d y=%5.2f %v3f %%\\n").unwrap();
        let convs: Vec<_> = conversions(&p).map(|c| (c.kind, c.components)).collect();
        assert_eq!(convs, vec![('d', 1), ('f', 1), ('f', 3)]);
        assert_eq!(p.last(), Some(&Piece::Text(" %\n".into())));
    }

    #[test]
    fn formats_like_c() {
        assert_eq!(
            fmt("%d|%5d|%-5d|%05d", &[7, (-3i32) as u32, 42, 9]),
            "7|   -3|42   |00009"
        );
        assert_eq!(
            fmt("%u %x %#X %o", &[u32::MAX, 255, 255, 8]),
            "4294967295 ff 0XFF 10"
        );
        let f = |v: f32| v.to_bits();
        assert_eq!(fmt("%f", &[f(1.5)]), "1.500000");
        assert_eq!(
            fmt("%.2f|%8.3f|%+.1f", &[f(3.25159), f(-2.5), f(2.0)]),
            "3.25|  -2.500|+2.0"
        );
        assert_eq!(fmt("%e", &[f(12345.678)]), "1.234568e+04");
        assert_eq!(
            fmt("%g %g %g", &[f(0.0001), f(100000.0), f(1e-5)]),
            "0.0001 100000 1e-05"
        );
        assert_eq!(fmt("%a", &[f(1.0)]), "0x1p+0");
        assert_eq!(
            fmt("%f %f", &[f(f32::NAN), f(f32::NEG_INFINITY)]),
            "nan -inf"
        );
        assert_eq!(
            fmt("%v3f", &[f(1.0), f(0.5), f(-0.25)]),
            "1.000000, 0.500000, -0.250000"
        );
        assert_eq!(fmt("%.1v2f!", &[f(1.0), f(2.0)]), "1.0, 2.0!");
    }

    #[test]
    fn rejects_bad_formats_with_a_reason() {
        assert!(parse("%s")
            .unwrap_err()
            .contains("unsupported conversion `%s'"));
        assert!(parse("%v5f").unwrap_err().contains("2, 3 or 4"));
        assert!(parse("%").unwrap_err().contains("ends inside"));
        assert!(parse("\\q").unwrap_err().contains("unknown escape"));
        assert!(parse("%999d").unwrap_err().contains("above 64"));
    }

    #[test]
    fn type_checks() {
        let p = parse("%d %v3f").unwrap();
        let c: Vec<_> = conversions(&p).copied().collect();
        assert!(c[0].accepts(Type::INT));
        assert!(!c[0].accepts(Type::FLOAT));
        assert!(c[1].accepts(Type::new(Base::Vector(Scalar::Float, 3))));
        assert!(!c[1].accepts(Type::new(Base::Vector(Scalar::Float, 4))));
        assert_eq!(c[1].expected(), "vec3");
    }

    #[test]
    fn unsigned_conversions_take_uints_and_signed_ones_do_not() {
        let uvec3 = Type::new(Base::Vector(Scalar::Uint, 3));
        let p = parse("%d %i %u %x %X %o %v3u %v3d").unwrap();
        let c: Vec<_> = conversions(&p).copied().collect();
        for signed in &c[..2] {
            assert!(!signed.accepts(Type::UINT) && signed.accepts(Type::INT));
            assert_eq!(signed.expected(), "int");
        }
        for unsigned in &c[2..6] {
            assert!(unsigned.accepts(Type::UINT) && unsigned.accepts(Type::INT));
            assert!(unsigned.accepts(Type::BOOL) && !unsigned.accepts(Type::FLOAT));
            assert_eq!(unsigned.expected(), "uint or int");
        }
        assert!(c[6].accepts(uvec3) && c[6].expected() == "uvec3 or ivec3");
        assert!(!c[7].accepts(uvec3));
        assert_eq!(
            fmt("%u %v2u", &[u32::MAX, 0x8000_0000, 7]),
            "4294967295 2147483648, 7"
        );
    }
}
