//! Numeric literals: the spelling of a preprocessing number to its value.
//!
//! Integer constants follow GLSL 1.30 §4.1.3 (decimal, octal with a leading
//! `0`, hexadecimal with `0x`/`0X`, each with an optional `u`/`U` suffix;
//! whether the suffix is allowed depends on the version, which the caller
//! checks). Floating constants follow
//! §4.1.4: `1.`, `.5`, `1e5`, `1.5e-3`; the `f`/`F` suffix exists only from
//! GLSL 1.20 on (the 1.10 grammar has no floating-suffix). Values are
//! converted exactly: integers with checked arithmetic, floats with Rust's
//! correctly rounded `f32` parser.

/// What a preprocessing number spells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Literal {
    /// An integer constant. `value` is exact when `fits_u64`; otherwise it
    /// holds the low 64 bits. `unsigned`: written with the `u`/`U` suffix.
    Int {
        value: u64,
        fits_u64: bool,
        unsigned: bool,
    },
    /// A floating constant; `suffix` is true when it ends in `f`/`F`.
    Float { value: f32, suffix: bool },
}

/// Parses the spelling of a preprocessing number. The error is a complete
/// sentence naming the literal.
pub(crate) fn parse_number(text: &str) -> Result<Literal, String> {
    let bytes = text.as_bytes();
    // The suffix is not part of the digits: `0x1u` is hexadecimal 1.
    let (body, unsigned) = match text.strip_suffix(['u', 'U']) {
        Some(b) => (b, true),
        None => (text, false),
    };
    let with_suffix = |r: Result<Literal, String>| {
        r.map(|l| match l {
            Literal::Int {
                value, fits_u64, ..
            } => Literal::Int {
                value,
                fits_u64,
                unsigned,
            },
            other => other,
        })
    };
    if bytes.len() >= 2 && bytes[0] == b'0' && (bytes[1] == b'x' || bytes[1] == b'X') {
        return with_suffix(parse_hex(body));
    }
    if !body.is_empty() && body.bytes().all(|b| b.is_ascii_digit()) {
        return with_suffix(parse_decimal_or_octal(body));
    }
    parse_float(text)
}

fn parse_hex(text: &str) -> Result<Literal, String> {
    let digits = &text[2..];
    if digits.is_empty() {
        return Err(format!(
            "invalid hexadecimal literal `{text}': `0x' must be followed by hexadecimal digits"
        ));
    }
    if let Some(bad) = digits.chars().find(|c| !c.is_ascii_hexdigit()) {
        return Err(format!(
            "invalid hexadecimal literal `{text}': `{bad}' is not a hexadecimal digit"
        ));
    }
    Ok(accumulate(digits, 16))
}

fn parse_decimal_or_octal(text: &str) -> Result<Literal, String> {
    if text.len() > 1 && text.starts_with('0') {
        if let Some(bad) = text.chars().find(|c| *c == '8' || *c == '9') {
            return Err(format!(
                "invalid octal literal `{text}': `{bad}' is not an octal digit (a leading 0 \
                 makes the constant octal, GLSL §4.1.3)"
            ));
        }
        return Ok(accumulate(&text[1..], 8));
    }
    Ok(accumulate(text, 10))
}

/// Digits (already validated for `radix`) to a value, noting overflow.
fn accumulate(digits: &str, radix: u32) -> Literal {
    let mut value: u64 = 0;
    let mut fits_u64 = true;
    for c in digits.chars() {
        let d = u64::from(c.to_digit(radix).unwrap_or(0));
        match value
            .checked_mul(u64::from(radix))
            .and_then(|v| v.checked_add(d))
        {
            Some(v) => value = v,
            None => {
                fits_u64 = false;
                value = value.wrapping_mul(u64::from(radix)).wrapping_add(d);
            }
        }
    }
    Literal::Int {
        value,
        fits_u64,
        unsigned: false,
    }
}

/// Validates the §4.1.4 grammar, then converts.
fn parse_float(text: &str) -> Result<Literal, String> {
    let bytes = text.as_bytes();
    let mut i = 0;
    let int_digits = count_digits(bytes, i);
    i += int_digits;
    let mut frac_digits = 0;
    let mut dot = false;
    if bytes.get(i) == Some(&b'.') {
        dot = true;
        i += 1;
        frac_digits = count_digits(bytes, i);
        i += frac_digits;
    }
    let mut exponent = false;
    if matches!(bytes.get(i), Some(b'e') | Some(b'E')) {
        exponent = true;
        i += 1;
        if matches!(bytes.get(i), Some(b'+') | Some(b'-')) {
            i += 1;
        }
        let exp_digits = count_digits(bytes, i);
        if exp_digits == 0 {
            return Err(format!(
                "invalid floating-point literal `{text}': the exponent has no digits"
            ));
        }
        i += exp_digits;
    }
    let mantissa_end = i;
    let suffix = matches!(bytes.get(i), Some(b'f') | Some(b'F'));
    if suffix {
        i += 1;
    }
    let well_formed = i == bytes.len() && int_digits + frac_digits > 0 && (dot || exponent);
    if !well_formed {
        return Err(describe_bad_number(text));
    }
    match text[..mantissa_end].parse::<f32>() {
        Ok(value) => Ok(Literal::Float { value, suffix }),
        Err(_) => Err(describe_bad_number(text)),
    }
}

fn describe_bad_number(text: &str) -> String {
    let has_float_marks = text.contains('.') || text.contains('e') || text.contains('E');
    if !has_float_marks && text.starts_with(|c: char| c.is_ascii_digit()) {
        let suffix: String = text.chars().skip_while(char::is_ascii_digit).collect();
        return format!("invalid integer literal `{text}': unexpected `{suffix}' after the digits");
    }
    format!("invalid floating-point literal `{text}'")
}

fn count_digits(bytes: &[u8], start: usize) -> usize {
    bytes.get(start..).map_or(0, |rest| {
        rest.iter().take_while(|b| b.is_ascii_digit()).count()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(text: &str) -> u64 {
        match parse_number(text) {
            Ok(Literal::Int {
                value,
                fits_u64: true,
                unsigned: false,
            }) => value,
            other => panic!("{text}: {other:?}"),
        }
    }

    fn float(text: &str) -> (f32, bool) {
        match parse_number(text) {
            Ok(Literal::Float { value, suffix }) => (value, suffix),
            other => panic!("{text}: {other:?}"),
        }
    }

    #[test]
    fn integers() {
        assert_eq!(int("0"), 0);
        assert_eq!(int("42"), 42);
        assert_eq!(int("07"), 7);
        assert_eq!(int("010"), 8);
        assert_eq!(int("0xff"), 255);
        assert_eq!(int("0XaB"), 0xab);
        assert_eq!(int("4294967295"), 4_294_967_295);
        assert_eq!(int("18446744073709551615"), u64::MAX);
        assert_eq!(
            parse_number("18446744073709551616"),
            Ok(Literal::Int {
                value: 0,
                fits_u64: false,
                unsigned: false,
            })
        );
    }

    #[test]
    fn unsigned_suffix() {
        let uint = |t: &str| match parse_number(t) {
            Ok(Literal::Int {
                value,
                fits_u64: true,
                unsigned: true,
            }) => value,
            other => panic!("{t}: {other:?}"),
        };
        assert_eq!(uint("1u"), 1);
        assert_eq!(uint("0U"), 0);
        assert_eq!(uint("017u"), 15);
        assert_eq!(uint("0xffffffffu"), 0xffff_ffff);
        assert_eq!(uint("0x1ffffffffU"), 0x1_ffff_ffff);
        assert!(parse_number("u").is_err());
        assert!(parse_number("1uu").is_err());
        assert!(parse_number("0xu").is_err());
        assert!(parse_number("1.0u").is_err());
        assert!(parse_number("09u").unwrap_err().contains("octal"));
    }

    #[test]
    fn bad_integers() {
        assert!(parse_number("08").unwrap_err().contains("octal"));
        assert!(parse_number("0779").unwrap_err().contains("`9'"));
        assert!(parse_number("0xg").unwrap_err().contains("hexadecimal"));
        assert!(parse_number("0x").unwrap_err().contains("hexadecimal"));
        assert!(parse_number("12abc").is_err());
        assert!(parse_number("1f").is_err());
    }

    #[test]
    fn floats() {
        assert_eq!(float("1."), (1.0, false));
        assert_eq!(float(".5"), (0.5, false));
        assert_eq!(float("1e5"), (1e5, false));
        assert_eq!(float("1.5e-3"), (1.5e-3, false));
        assert_eq!(float("1E+2"), (100.0, false));
        assert_eq!(float("2.5f"), (2.5, true));
        assert_eq!(float("1e5F"), (1e5, true));
        assert_eq!(float("0.1"), (0.1f32, false));
        assert!(float("1e60").0.is_infinite());
    }

    #[test]
    fn bad_floats() {
        assert!(parse_number("1e").is_err());
        assert!(parse_number("1.5e+").is_err());
        assert!(parse_number("1..2").is_err());
        assert!(parse_number("1.0ff").is_err());
        assert!(parse_number("1.0x").is_err());
        assert!(parse_number("1.0.x").is_err());
    }
}
