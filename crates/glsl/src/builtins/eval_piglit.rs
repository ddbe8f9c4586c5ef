//! Checks [`eval_builtin`] against the test vectors of piglit's generated
//! constant-folding tests (`generated_tests/spec/glsl-1.20/compiler/
//! built-in-functions/*.vert`, the `.frag` twins carry the same vectors).
//!
//! `testdata/piglit_builtin_vectors.txt` holds the vectors, one a line:
//! `call => expected ; tolerance`, the tolerance being the bound of the
//! test's check (`distance(call, expected) <= tol` for scalars and vectors,
//! the sum of the squared column distances for matrices) or `exact` for
//! boolean and integer results, or `lo..hi` when the test checks
//! `lo <= call && call <= hi` (the `distance` tests). It is extracted from the piglit files by the
//! ignored test [`regenerate`].

use super::{eval_builtin, BuiltinFn};
use crate::ir::{ConstScalar, ConstValue};
use crate::types::{Base, Scalar, Type};

const VECTORS: &str = include_str!("testdata/piglit_builtin_vectors.txt");

/// A parsed header value: a literal or a constructor of literals.
fn parse_value(text: &str) -> Option<ConstValue> {
    let text = text.trim();
    if let Some(open) = text.find('(') {
        let ty = type_from_name(&text[..open])?;
        let inner = text[open + 1..].strip_suffix(')')?;
        let scalars = inner
            .split(',')
            .map(|s| parse_scalar(s.trim()))
            .collect::<Option<Vec<_>>>()?;
        if scalars.len() != ty.component_count()? as usize {
            return None;
        }
        return Some(ConstValue {
            ty,
            components: scalars,
        });
    }
    let s = parse_scalar(text)?;
    let ty = match s {
        ConstScalar::Float(_) => Type::FLOAT,
        ConstScalar::Int(_) => Type::INT,
        ConstScalar::Uint(_) => Type::UINT,
        ConstScalar::Bool(_) => Type::BOOL,
    };
    Some(ConstValue {
        ty,
        components: vec![s],
    })
}

fn parse_scalar(s: &str) -> Option<ConstScalar> {
    match s {
        "true" => Some(ConstScalar::Bool(true)),
        "false" => Some(ConstScalar::Bool(false)),
        _ if s.contains(['.', 'e']) => s.parse().ok().map(ConstScalar::Float),
        _ => s.parse().ok().map(ConstScalar::Int),
    }
}

fn type_from_name(name: &str) -> Option<Type> {
    let digit = |c: char| c.to_digit(10).map(|d| d as u8);
    let mut chars = name.chars();
    let ty = match name {
        "float" => Type::FLOAT,
        "int" => Type::INT,
        "bool" => Type::BOOL,
        _ if name.starts_with("vec") => Type::vec(Scalar::Float, digit(name.chars().nth(3)?)?),
        _ if name.starts_with("ivec") => Type::vec(Scalar::Int, digit(name.chars().nth(4)?)?),
        _ if name.starts_with("bvec") => Type::vec(Scalar::Bool, digit(name.chars().nth(4)?)?),
        _ if name.starts_with("mat") => {
            let cols = digit(chars.nth(3)?)?;
            let rows = match chars.nth(1) {
                Some(c) => digit(c)?,
                None => cols,
            };
            Type::mat(cols, rows)
        }
        _ => return None,
    };
    Some(ty)
}

/// Splits `f(a, vec2(b, c), d)` into `f` and its top-level arguments.
fn split_call(text: &str) -> Option<(&str, Vec<&str>)> {
    let open = text.find('(')?;
    let inner = text[open + 1..].strip_suffix(')')?;
    let mut args = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                args.push(inner[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    args.push(inner[start..].trim());
    Some((&text[..open], args))
}

enum Verdict {
    Pass,
    Fail(String),
}

fn check(line: &str) -> Verdict {
    let fail = |why: &str| Verdict::Fail(format!("{why}: {line}"));
    let Some((call, rest)) = line.split_once(" => ") else {
        return fail("malformed");
    };
    let Some((expected, tol)) = rest.rsplit_once(" ; ") else {
        return fail("malformed");
    };
    let (Some((name, args)), Some(expected)) = (split_call(call), parse_value(expected)) else {
        return fail("unparsed");
    };
    let (Some(f), Some(args)) = (
        BuiltinFn::from_name(name),
        args.iter()
            .map(|a| parse_value(a))
            .collect::<Option<Vec<_>>>(),
    ) else {
        return fail("unparsed");
    };
    let Some(got) = eval_builtin(f, &args, expected.ty) else {
        return fail("not folded");
    };
    if got.ty != expected.ty || got.components.len() != expected.components.len() {
        return fail("wrong shape");
    }
    if tol == "exact" {
        return if got.components == expected.components {
            Verdict::Pass
        } else {
            Verdict::Fail(format!("got {:?}: {line}", got.components))
        };
    }
    // The shader evaluates its check in `f32` with the same folding, so
    // the comparison here is done the same way.
    if let Some((lo, hi)) = tol.split_once("..") {
        let (Ok(lo), Ok(hi)) = (lo.parse::<f32>(), hi.parse::<f32>()) else {
            return fail("bad range");
        };
        return match got.components.as_slice() {
            [ConstScalar::Float(g)] if lo <= *g && *g <= hi => Verdict::Pass,
            _ => Verdict::Fail(format!("got {:?}: {line}", got.components)),
        };
    }
    let Ok(tol) = tol.parse::<f32>() else {
        return fail("bad tolerance");
    };
    let err = match expected.ty.base {
        // pow(distance(m[0], e[0]), 2) + pow(distance(m[1], e[1]), 2) + ...
        Base::Matrix { cols, rows } => (0..cols as usize).try_fold(0.0f32, |acc, c| {
            let col = |v: &ConstValue| ConstValue {
                ty: Type::vec(Scalar::Float, rows),
                components: v.components[c * rows as usize..(c + 1) * rows as usize].to_vec(),
            };
            let d = float_of(eval_builtin(
                BuiltinFn::Distance,
                &[col(&got), col(&expected)],
                Type::FLOAT,
            ))?;
            let two = float_value(2.0);
            let p = float_of(eval_builtin(
                BuiltinFn::Pow,
                &[float_value(d), two],
                Type::FLOAT,
            ))?;
            Some(acc + p)
        }),
        _ => float_of(eval_builtin(
            BuiltinFn::Distance,
            &[got.clone(), expected],
            Type::FLOAT,
        )),
    };
    match err {
        Some(err) if err <= tol => Verdict::Pass,
        _ => Verdict::Fail(format!("got {:?} (error {err:?}): {line}", got.components)),
    }
}

fn float_value(f: f32) -> ConstValue {
    ConstValue {
        ty: Type::FLOAT,
        components: vec![ConstScalar::Float(f)],
    }
}

fn float_of(v: Option<ConstValue>) -> Option<f32> {
    match v?.components.as_slice() {
        [ConstScalar::Float(f)] => Some(*f),
        _ => None,
    }
}

#[test]
fn piglit_constant_folding_vectors() {
    let mut passed = 0;
    let mut failures = Vec::new();
    for line in VECTORS
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
    {
        match check(line) {
            Verdict::Pass => passed += 1,
            Verdict::Fail(why) => failures.push(why),
        }
    }
    eprintln!(
        "piglit built-in vectors: {passed} passed, {} failed",
        failures.len()
    );
    assert!(
        passed > 1600,
        "only {passed} vectors in the data file passed"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn header_parser() {
    let v = parse_value("mat2x3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)").unwrap();
    assert_eq!(v.ty, Type::mat(2, 3));
    assert_eq!(
        parse_value("ivec2(-5, 2)").unwrap().ty,
        Type::vec(Scalar::Int, 2)
    );
    assert_eq!(parse_value("1e-10").unwrap().ty, Type::FLOAT);
    let (f, args) = split_call("atan(vec2(0.0, 1.0), vec2(1.0, 2.0))").unwrap();
    assert_eq!((f, args.len()), ("atan", 2));
    assert!(matches!(
        check("abs(-1.5) => 2.5 ; 1e-05"),
        Verdict::Fail(_)
    ));
}

/// Rewrites the data file from a piglit tree:
/// `PIGLIT_DIR=/path/to/piglit cargo test -p shaderbox-glsl regenerate -- --ignored`.
#[test]
#[ignore]
fn regenerate() {
    let root = std::env::var("PIGLIT_DIR")
        .unwrap_or_else(|_| "/tmp/piglit/usr/lib/x86_64-linux-gnu/piglit".into());
    let dir = format!("{root}/generated_tests/spec/glsl-1.20/compiler/built-in-functions");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".vert") && !n.starts_with("op-"))
        .collect();
    names.sort();
    let mut out = String::from(
        "# piglit generated_tests/spec/glsl-1.20/compiler/built-in-functions/*.vert\n\
         # (not op-*): call => expected ; tolerance (see eval_piglit.rs)\n",
    );
    for name in names {
        let text = std::fs::read_to_string(format!("{dir}/{name}")).unwrap();
        let vectors: Vec<&str> = text
            .lines()
            .filter_map(|l| l.strip_prefix(" * "))
            .filter(|l| l.contains(" => "))
            .collect();
        let checks: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with("  float[") && l.contains("? 1 : -1] array"))
            .collect();
        assert_eq!(vectors.len(), checks.len(), "{name}");
        for (v, c) in vectors.iter().zip(&checks) {
            // `lo <= f(..) && f(..) <= hi`, `distance(f(..), e) <= tol` or
            // `f(..) == e`.
            let bounds: Vec<&str> = c
                .split(" <= ")
                .map(|part| part.rsplit(['[', ' ']).next().unwrap())
                .collect();
            let tol = match bounds.as_slice() {
                [lo, _, hi] if c.contains(" && ") => {
                    let hi = c.rsplit(" <= ").next().unwrap().split(' ').next().unwrap();
                    format!("{lo}..{hi}")
                }
                [_, _] => c
                    .rsplit(" <= ")
                    .next()
                    .unwrap()
                    .split(' ')
                    .next()
                    .unwrap()
                    .to_string(),
                _ => "exact".to_string(),
            };
            out.push_str(&format!("{v} ; {tol}\n"));
        }
    }
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/src/builtins/testdata/piglit_builtin_vectors.txt"
    );
    std::fs::write(path, out).unwrap();
}
