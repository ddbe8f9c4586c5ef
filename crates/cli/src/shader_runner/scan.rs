//! Number and word scanning with the C library's rules, as piglit's
//! `shader_runner` reads its scripts (`strtof`, `strtol(.., 0)`, `sscanf`).
//!
//! Every scanner takes the text and returns the value and the rest of the
//! text, or `None` when no number starts there (after white space). Values
//! that C would read are read the same way: `.5`, `1.`, `-1e-3`, `inf`,
//! `nan`; integers in base 0 (`0x1f` hexadecimal, `017` octal); piglit's
//! float lists also accept `0x` followed by the hexadecimal bit pattern of an
//! IEEE single (its `strtof_hex`).

/// C's `isspace` in the "C" locale.
pub fn is_c_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\n' | '\u{0b}' | '\u{0c}' | '\r')
}

/// Skips C white space.
pub fn skip_space(s: &str) -> &str {
    s.trim_start_matches(is_c_space)
}

/// Length of the longest prefix of `s` that C's `strtod` reads as a decimal
/// number (no leading white space), or 0.
fn decimal_float_len(s: &str) -> usize {
    let b = s.as_bytes();
    let mut i = 0;
    if matches!(b.first(), Some(b'+' | b'-')) {
        i += 1;
    }
    if matches!(b.get(i), Some(b'i' | b'I' | b'n' | b'N')) {
        let starts = |word: &str| {
            b.get(i..i + word.len())
                .is_some_and(|t| t.eq_ignore_ascii_case(word.as_bytes()))
        };
        if starts("infinity") {
            return i + 8;
        }
        if starts("inf") || starts("nan") {
            return i + 3;
        }
        return 0;
    }
    let int_start = i;
    while b.get(i).is_some_and(u8::is_ascii_digit) {
        i += 1;
    }
    let mut digits = i - int_start;
    if b.get(i) == Some(&b'.') {
        let frac_start = i + 1;
        let mut j = frac_start;
        while b.get(j).is_some_and(u8::is_ascii_digit) {
            j += 1;
        }
        digits += j - frac_start;
        if digits > 0 {
            i = j;
        }
    }
    if digits == 0 {
        return 0;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let mut j = i + 1;
        if matches!(b.get(j), Some(b'+' | b'-')) {
            j += 1;
        }
        let exp_start = j;
        while b.get(j).is_some_and(u8::is_ascii_digit) {
            j += 1;
        }
        if j > exp_start {
            i = j;
        }
    }
    i
}

/// C's `strtof`: a decimal float after white space.
pub fn scan_f32(s: &str) -> Option<(f32, &str)> {
    let s = skip_space(s);
    let n = decimal_float_len(s);
    if n == 0 {
        return None;
    }
    let text = &s[..n];
    let text = text.strip_prefix('+').unwrap_or(text);
    let v = text.parse::<f32>().ok()?;
    Some((v, &s[n..]))
}

/// C's `strtod`: a decimal double after white space.
pub fn scan_f64(s: &str) -> Option<(f64, &str)> {
    let s = skip_space(s);
    let n = decimal_float_len(s);
    if n == 0 {
        return None;
    }
    let text = &s[..n];
    let text = text.strip_prefix('+').unwrap_or(text);
    let v = text.parse::<f64>().ok()?;
    Some((v, &s[n..]))
}

/// piglit's `strtof_hex`: `0x` + the bit pattern of a single, else `strtof`.
pub fn scan_f32_or_bits(s: &str) -> Option<(f32, &str)> {
    let t = s.trim_start_matches([' ', '\t']);
    if let Some(hex) = t.strip_prefix("0x") {
        let n = hex.bytes().take_while(u8::is_ascii_hexdigit).count();
        if n == 0 {
            // strtoul reads the "0" and stops at the "x".
            return Some((0.0, &t[1..]));
        }
        let bits = u64::from_str_radix(&hex[..n.min(16)], 16).unwrap_or(u64::MAX);
        let bits = u32::try_from(bits).unwrap_or(u32::MAX);
        return Some((f32::from_bits(bits), &hex[n..]));
    }
    scan_f32(s)
}

/// C's `strtol(s, &end, 0)` converted to `int` (two's complement wrap, as
/// gcc does), after white space.
pub fn scan_i32_base0(s: &str) -> Option<(i32, &str)> {
    let (v, rest) = scan_i64_base(s, 0)?;
    Some((v as i32, rest))
}

/// C's `strtoul(s, &end, 0)` converted to `unsigned` (`-1` wraps to
/// 0xffffffff, as in C).
pub fn scan_u32_base0(s: &str) -> Option<(u32, &str)> {
    let (v, rest) = scan_i64_base(s, 0)?;
    Some((v as u32, rest))
}

/// C's `strtol(s, &end, 10)` converted to `int`.
pub fn scan_i32_dec(s: &str) -> Option<(i32, &str)> {
    let (v, rest) = scan_i64_base(s, 10)?;
    Some((v as i32, rest))
}

/// `strtol`/`strtoul` digits: base 0 picks 16 (`0x`), 8 (`0`) or 10.
/// Saturates like `strtol` on overflow.
fn scan_i64_base(s: &str, base: u32) -> Option<(i64, &str)> {
    let s = skip_space(s);
    let b = s.as_bytes();
    let mut i = 0;
    let mut negative = false;
    if let Some(&c) = b.first() {
        if c == b'+' || c == b'-' {
            negative = c == b'-';
            i = 1;
        }
    }
    let mut radix = if base == 0 { 10 } else { base };
    let hex_prefix = b.get(i) == Some(&b'0')
        && matches!(b.get(i + 1), Some(b'x' | b'X'))
        && b.get(i + 2).is_some_and(u8::is_ascii_hexdigit);
    if (base == 0 || base == 16) && hex_prefix {
        radix = 16;
        i += 2;
    } else if base == 0 && b.get(i) == Some(&b'0') {
        radix = 8;
    }
    let start = i;
    let mut value: i64 = 0;
    let mut overflow = false;
    while let Some(d) = b.get(i).and_then(|&c| (c as char).to_digit(radix)) {
        match value
            .checked_mul(i64::from(radix))
            .and_then(|v| v.checked_add(i64::from(d)))
        {
            Some(v) => value = v,
            None => overflow = true,
        }
        i += 1;
    }
    if i == start {
        return None;
    }
    let v = if overflow {
        if negative {
            i64::MIN
        } else {
            i64::MAX
        }
    } else if negative {
        -value
    } else {
        value
    };
    Some((v, &s[i..]))
}

/// Up to `n` values with `scan`, as piglit's `parse_floats`/`parse_ints`:
/// stops at the first text that is not a number.
pub fn scan_list<T>(
    mut s: &str,
    n: usize,
    scan: impl Fn(&str) -> Option<(T, &str)>,
) -> (Vec<T>, &str) {
    let mut out = Vec::new();
    while out.len() < n {
        match scan(s) {
            Some((v, rest)) => {
                out.push(v);
                s = rest;
            }
            None => break,
        }
    }
    (out, s)
}

/// The next white-space-delimited word and the rest.
pub fn word(s: &str) -> Option<(&str, &str)> {
    let s = skip_space(s);
    if s.is_empty() {
        return None;
    }
    let end = s.find(is_c_space).unwrap_or(s.len());
    Some((&s[..end], &s[end..]))
}

/// `sscanf` literal matching: white space in the pattern matches any amount
/// (also none) of white space; other characters must match exactly;
/// `%f`/`%lf`/`%d` read a value (recorded in order).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scanned {
    F(f32),
    D(f64),
    I(i32),
}

/// A small `sscanf`: returns the values read before the first mismatch (like
/// `sscanf`'s count) and whether the whole pattern matched.
pub fn sscanf(mut s: &str, pattern: &str) -> (Vec<Scanned>, bool) {
    let mut out = Vec::new();
    let mut p = pattern;
    while let Some(c) = p.chars().next() {
        if is_c_space(c) {
            p = skip_space(p);
            s = skip_space(s);
            continue;
        }
        if let Some(rest) = p.strip_prefix("%lf") {
            match scan_f64(s) {
                Some((v, r)) => {
                    out.push(Scanned::D(v));
                    s = r;
                    p = rest;
                }
                None => return (out, false),
            }
        } else if let Some(rest) = p.strip_prefix("%f") {
            match scan_f32(s) {
                Some((v, r)) => {
                    out.push(Scanned::F(v));
                    s = r;
                    p = rest;
                }
                None => return (out, false),
            }
        } else if let Some(rest) = p.strip_prefix("%d") {
            match scan_i32_dec(s) {
                Some((v, r)) => {
                    out.push(Scanned::I(v));
                    s = r;
                    p = rest;
                }
                None => return (out, false),
            }
        } else {
            // Conversions skip leading white space; literals do not.
            match s.strip_prefix(c) {
                Some(r) => {
                    s = r;
                    p = &p[c.len_utf8()..];
                }
                None => return (out, false),
            }
        }
    }
    (out, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_like_strtof() {
        assert_eq!(scan_f32(" 1.5 x"), Some((1.5, " x")));
        assert_eq!(scan_f32(".5"), Some((0.5, "")));
        assert_eq!(scan_f32("1."), Some((1.0, "")));
        assert_eq!(scan_f32("-2e3,"), Some((-2000.0, ",")));
        assert_eq!(scan_f32("+3"), Some((3.0, "")));
        assert_eq!(scan_f32("1e"), Some((1.0, "e")));
        assert_eq!(scan_f32("1e+"), Some((1.0, "e+")));
        assert_eq!(scan_f32("."), None);
        assert_eq!(scan_f32("-"), None);
        assert_eq!(scan_f32("x1"), None);
        assert_eq!(scan_f32("(1"), None);
        assert!(scan_f32("inf").is_some_and(|(v, _)| v.is_infinite()));
        assert!(scan_f32("-Infinity").is_some_and(|(v, r)| v == f32::NEG_INFINITY && r.is_empty()));
        assert!(scan_f32("NaN").is_some_and(|(v, _)| v.is_nan()));
        // Correct rounding of long decimals.
        assert_eq!(
            scan_f32("1.03935908892461").map(|p| p.0),
            Some(1.039_359_1_f32)
        );
    }

    #[test]
    fn hex_bits() {
        assert_eq!(scan_f32_or_bits("0x3f800000"), Some((1.0, "")));
        assert_eq!(scan_f32_or_bits(" 0x40000000 1"), Some((2.0, " 1")));
        assert_eq!(scan_f32_or_bits("0.25"), Some((0.25, "")));
    }

    #[test]
    fn integers_like_strtol_base0() {
        assert_eq!(scan_i32_base0(" 42 "), Some((42, " ")));
        assert_eq!(scan_i32_base0("-7"), Some((-7, "")));
        assert_eq!(scan_i32_base0("0x1f"), Some((31, "")));
        assert_eq!(scan_i32_base0("017"), Some((15, "")));
        assert_eq!(scan_i32_base0("0"), Some((0, "")));
        assert_eq!(scan_i32_base0("08"), Some((0, "8")));
        assert_eq!(scan_i32_base0("0x"), Some((0, "x")));
        assert_eq!(scan_i32_base0("-2147483648"), Some((i32::MIN, "")));
        assert_eq!(scan_i32_base0("4294967295"), Some((-1, "")));
        assert_eq!(scan_i32_base0("a"), None);
        assert_eq!(scan_i32_dec("012"), Some((12, "")));
        assert_eq!(scan_i32_dec("1.5"), Some((1, ".5")));
    }

    #[test]
    fn lists_stop_at_non_numbers() {
        let (v, rest) = scan_list("1 2 3 # c", 5, scan_f32);
        assert_eq!(v, vec![1.0, 2.0, 3.0]);
        assert_eq!(rest, " # c");
        let (v, _) = scan_list("1 2 3", 2, scan_i32_base0);
        assert_eq!(v, vec![1, 2]);
    }

    #[test]
    fn sscanf_patterns() {
        let (v, ok) = sscanf("(.5, .5) (0.0, 1.0, 0.0)", "( %f , %f ) ( %f , %f , %f )");
        assert!(ok);
        assert_eq!(v.len(), 5);
        assert_eq!(v[0], Scanned::F(0.5));
        let (v, ok) = sscanf(
            "(0,0,10,10)(1,0,0,1)",
            "( %d , %d , %d , %d ) ( %f , %f , %f , %f )",
        );
        assert!(ok);
        assert_eq!(v[2], Scanned::I(10));
        let (v, ok) = sscanf("( 1 , 2 ) x", "( %d , %d ) ( %f )");
        assert!(!ok);
        assert_eq!(v.len(), 2);
        let (v, ok) = sscanf("0 1 2 3 4", "%d %lf %lf %lf %lf");
        assert!(ok);
        assert_eq!(v[1], Scanned::D(1.0));
    }

    #[test]
    fn words() {
        assert_eq!(word("  vec4 color 1"), Some(("vec4", " color 1")));
        assert_eq!(word("   "), None);
    }
}
