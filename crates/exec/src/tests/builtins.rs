//! Every overload of every built-in function that constant folding can
//! evaluate, run by the kernel on uniform arguments and compared bit for
//! bit with `glsl::builtins::eval_builtin` (the constant-folding oracle),
//! on every path: the reference interpreter, each supported interpreter
//! level and native code.

use super::{kernel, uniforms};
use crate::variant::supported_variants;
use crate::{Batch, NoTextures, LANES};
use glsl::builtins::{eval_builtin, prelude, BuiltinFn};
use glsl::ir::{ConstScalar, ConstValue, Stage};
use glsl::types::{Base, Scalar, Type};
use glsl::Version;

/// Parses `float`, `ivec3`, `mat2x4`, ... (no samplers).
fn parse_type(name: &str) -> Option<Type> {
    let digit = |s: &str| s.parse::<u8>().ok();
    Some(match name {
        "float" => Type::FLOAT,
        "int" => Type::INT,
        "uint" => Type::UINT,
        "bool" => Type::BOOL,
        _ if name.starts_with("vec") => Type::vec(Scalar::Float, digit(&name[3..])?),
        _ if name.starts_with("ivec") => Type::vec(Scalar::Int, digit(&name[4..])?),
        _ if name.starts_with("uvec") => Type::vec(Scalar::Uint, digit(&name[4..])?),
        _ if name.starts_with("bvec") => Type::vec(Scalar::Bool, digit(&name[4..])?),
        _ if name.starts_with("mat") => {
            let rest = &name[3..];
            match rest.split_once('x') {
                Some((c, r)) => Type::mat(digit(c)?, digit(r)?),
                None => {
                    let n = digit(rest)?;
                    Type::mat(n, n)
                }
            }
        }
        _ => return None,
    })
}

/// (function, argument types, result type) of every prototype in the
/// vertex-stage prelude of `lang` with non-sampler, `in` arguments.
fn overloads(lang: glsl::Language) -> Vec<(BuiltinFn, String, Vec<Type>, Type)> {
    let mut out = Vec::new();
    for line in prelude(lang, Stage::Vertex).lines() {
        let Some(line) = line.strip_suffix(");") else {
            continue;
        };
        let Some((head, params)) = line.split_once('(') else {
            continue;
        };
        let Some((ret, name)) = head.split_once(' ') else {
            continue;
        };
        let Some(f) = BuiltinFn::from_name(name) else {
            continue;
        };
        let Some(ret) = parse_type(ret) else { continue };
        let params: Option<Vec<Type>> = if params.trim().is_empty() {
            Some(Vec::new())
        } else {
            params.split(',').map(|p| parse_type(p.trim())).collect()
        };
        if let Some(params) = params {
            out.push((f, name.to_string(), params, ret));
        }
    }
    out
}

const FLOATS: [f32; 16] = [
    -2.5,
    -1.0,
    -0.75,
    -0.3,
    0.0,
    0.25,
    0.5,
    0.7,
    1.0,
    1.5,
    3.25,
    10.0,
    -0.0,
    0.9,
    f32::INFINITY,
    2.5,
];
const INTS: [i32; 6] = [-3, -1, 0, 1, 2, 5];
/// Small values, values past `i32::MAX` (where signed and unsigned
/// compares differ), and as float bits: 1.5, a subnormal, -0.0, NaNs.
const UINTS: [u32; 8] = [
    0,
    1,
    7,
    0x3fc0_0000,
    0x7fff_ffff,
    0x8000_0000,
    0x8000_0001,
    0xffff_ffff,
];

fn value(ty: Type, round: u32, arg: u32) -> ConstValue {
    let n = ty.component_count().unwrap_or(1);
    let components = (0..n)
        .map(|k| {
            let h = round
                .wrapping_mul(2_654_435_761)
                .wrapping_add(arg.wrapping_mul(40_503))
                .wrapping_add(k.wrapping_mul(97))
                >> 3;
            match ty.scalar() {
                Some(Scalar::Int) => ConstScalar::Int(INTS[h as usize % INTS.len()]),
                Some(Scalar::Uint) => ConstScalar::Uint(UINTS[h as usize % UINTS.len()]),
                Some(Scalar::Bool) => ConstScalar::Bool(h % 2 == 1),
                _ => ConstScalar::Float(FLOATS[h as usize % FLOATS.len()]),
            }
        })
        .collect();
    ConstValue { ty, components }
}

fn bits(c: &ConstScalar) -> u32 {
    match c {
        ConstScalar::Float(f) => f.to_bits(),
        ConstScalar::Int(i) => *i as u32,
        ConstScalar::Uint(u) => *u,
        ConstScalar::Bool(b) => *b as u32,
    }
}

/// What the test shader writes for a result component: floats as they
/// are, bools as 0.0/1.0, and integers in two halves (the bits above and
/// below bit 16, each exact as a float) so that every bit is compared.
fn as_floats(c: &ConstScalar) -> [f32; 2] {
    match c {
        ConstScalar::Float(f) => [*f, 0.0],
        ConstScalar::Int(i) => [(*i >> 16) as f32, (*i & 0xffff) as f32],
        ConstScalar::Uint(u) => [(*u >> 16) as f32, (*u & 0xffff) as f32],
        ConstScalar::Bool(b) => [*b as u8 as f32, 0.0],
    }
}

fn tname(ty: Type) -> String {
    ty.display(&|_| String::new()).to_string()
}

#[test]
fn every_overload_matches_constant_folding() {
    let mut checked = 0;
    let mut skipped = Vec::new();
    let v120 = glsl::Language::new(Version::V120, true);
    let v330 = glsl::Language::new(Version::V330, true);
    let older = overloads(v120);
    // 1.20's overloads, then those GLSL 1.30 to 3.30 add (compatibility
    // profile, so that the test's `varying` and `gl_Position` exist).
    let newer = overloads(v330)
        .into_iter()
        .filter(|(_, n, p, r)| {
            !older
                .iter()
                .any(|(_, n2, p2, r2)| n == n2 && p == p2 && r == r2)
        })
        .map(|o| (o, "330 compatibility"));
    let all: Vec<_> = older
        .iter()
        .cloned()
        .map(|o| (o, "120"))
        .chain(newer)
        .collect();
    for ((f, name, params, ret), version) in all {
        if matches!(
            f,
            BuiltinFn::Ftransform
                | BuiltinFn::Noise1
                | BuiltinFn::Noise2
                | BuiltinFn::Noise3
                | BuiltinFn::Noise4
        ) {
            continue;
        }
        let out_ty = match ret.base {
            Base::Scalar(_) => Type::FLOAT,
            Base::Vector(_, n) => Type::vec(Scalar::Float, n),
            _ => ret,
        };
        let decls: String = params
            .iter()
            .enumerate()
            .map(|(i, t)| format!("uniform {} a{i};\n", tname(*t)))
            .collect();
        let call_args: Vec<String> = (0..params.len()).map(|i| format!("a{i}")).collect();
        let call = format!("{name}({})", call_args.join(", "));
        let o = tname(out_ty);
        // Integer results (GLSL 1.30 on) in two halves: o the high bits
        // (arithmetic shift for ints), lo the low 16.
        let body = match ret.scalar() {
            Some(s @ (Scalar::Int | Scalar::Uint)) => {
                let u = if s == Scalar::Uint { "u" } else { "" };
                format!(
                    "{} r = {call}; o = {o}(r >> 16{u}); lo = {o}(r & 65535{u});",
                    tname(ret)
                )
            }
            _ => format!("o = {o}({call}); lo = {o}(0.0);"),
        };
        let src = format!(
            "#version {version}\n{decls}varying {o} o;\nvarying {o} lo;\n\
             void main() {{ gl_Position = vec4(0.0); {body} }}"
        );
        let k = kernel(Stage::Vertex, &src);
        for round in 0..12 {
            let args: Vec<ConstValue> = params
                .iter()
                .enumerate()
                .map(|(i, t)| value(*t, round, i as u32))
                .collect();
            let Some(want) = eval_builtin(f, &args, ret) else {
                skipped.push(format!("{name}{params:?}"));
                break;
            };
            let words: Vec<Vec<u32>> = args
                .iter()
                .map(|a| a.components.iter().map(bits).collect())
                .collect();
            let names: Vec<String> = (0..params.len()).map(|i| format!("a{i}")).collect();
            let unis: Vec<(&str, &[u32])> = names
                .iter()
                .map(|n| n.as_str())
                .zip(words.iter().map(|w| w.as_slice()))
                .collect();
            let u = uniforms(&k, &unis);
            let mut runs = vec![("run", Batch::for_kernel(&k, 0xffff))];
            k.run(&mut runs[0].1, &u, &NoTextures).expect("runs");
            let mut b = Batch::for_kernel(&k, 0xffff);
            k.run_reference(&mut b, &u, &NoTextures).expect("runs");
            runs.push(("reference", b));
            for v in supported_variants() {
                let mut b = Batch::for_kernel(&k, 0xffff);
                k.run_variant(v, &mut b, &u, &NoTextures).expect("runs");
                runs.push((v.name(), b));
            }
            let slots = [
                k.interface().output("o").expect("o").offset,
                k.interface().output("lo").expect("lo").offset,
            ];
            for (path, b) in &runs {
                for (i, c) in want.components.iter().enumerate() {
                    for (&slot, w) in slots.iter().zip(as_floats(c)) {
                        for lane in [0, LANES - 1] {
                            let g = b.outputs[slot + i][lane];
                            assert!(
                                g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()),
                                "{name}({}) component {i} ({path}): kernel {g} ({:#x}), \
                                 folding {w} ({:#x})",
                                args.iter()
                                    .map(|a| format!("{:?}", a.components))
                                    .collect::<Vec<_>>()
                                    .join(", "),
                                g.to_bits(),
                                w.to_bits()
                            );
                        }
                    }
                }
            }
            checked += 1;
        }
    }
    assert!(skipped.is_empty(), "not folded: {skipped:?}");
    assert!(checked > 2000, "only {checked} cases");
}

#[test]
fn noise_matches_glsl_math() {
    let k = kernel(
        Stage::Vertex,
        "uniform vec3 p; varying vec4 o; varying float n1;
         void main() { gl_Position = vec4(0.0); o = noise4(p); n1 = noise1(p.xy); }",
    );
    let p = [1.25f32, -3.5, 0.3];
    let u = uniforms(&k, &[("p", &p.map(f32::to_bits))]);
    let mut b = Batch::for_kernel(&k, 1);
    k.run(&mut b, &u, &NoTextures).unwrap();
    let o = k.interface().output("o").unwrap().offset;
    let want = glsl::math::noise4(&p);
    for (c, w) in want.iter().enumerate() {
        assert_eq!(b.outputs[o + c][0].to_bits(), w.to_bits());
    }
    let n1 = k.interface().output("n1").unwrap().offset;
    assert_eq!(b.outputs[n1][0], glsl::math::noise1(&p[..2]));
}

#[test]
fn modf_writes_the_whole_part_and_returns_the_fraction() {
    let k = kernel(
        Stage::Vertex,
        "#version 130
uniform vec2 x;
varying vec2 whole;
varying vec2 fraction;
void main() { gl_Position = vec4(0.0); fraction = modf(x, whole); }",
    );
    let x = [-2.75f32, 3.5];
    let u = uniforms(&k, &[("x", &x.map(f32::to_bits))]);
    let mut b = Batch::for_kernel(&k, 1);
    k.run(&mut b, &u, &NoTextures).expect("runs");
    let w = k.interface().output("whole").expect("whole").offset;
    let f = k.interface().output("fraction").expect("fraction").offset;
    for (i, &v) in x.iter().enumerate() {
        assert_eq!(b.outputs[w + i][0], glsl::math::trunc(v));
        assert_eq!(b.outputs[f + i][0], glsl::math::modf_fract(v));
    }
    assert_eq!(b.outputs[f][0], -0.75);
}

#[test]
fn what_the_pipeline_cannot_run_is_refused_when_lowered() {
    for (stage, src, what) in [
        (
            Stage::Fragment,
            "#version 150\nuniform sampler2DMS s;\nout vec4 c;\nvoid main() { c = texelFetch(s, ivec2(0), 0); }",
            "sampler2DMS",
        ),
        (
            Stage::Fragment,
            "#version 150\nuniform isampler2DMSArray s;\nout vec4 c;\nvoid main() { c = vec4(textureSize(s), 1.0); }",
            "isampler2DMSArray",
        ),
    ] {
        let s = super::link_one(stage, src).unwrap_or_else(|e| panic!("{e}"));
        match crate::Kernel::new(&s) {
            Err(crate::ExecError::Unsupported(m)) => assert!(m.contains(what), "{m}"),
            Err(e) => panic!("{what}: {e}"),
            Ok(_) => panic!("{what}: lowered"),
        }
    }
}

#[test]
fn glsl130_lookups_lower_like_their_120_forms() {
    // The same program, apart from the header line and the statements'
    // source spans.
    let body = |stage: Stage, v: u32, lookups: &str| {
        let (input, output) = match stage {
            Stage::Vertex => ("attribute", "gl_Position"),
            _ => ("varying", "gl_FragColor"),
        };
        let k = kernel(
            stage,
            &format!(
                "#version {v}\nuniform sampler2D s;\nuniform sampler2DShadow z;\n{input} vec4 p;\nvoid main() {{ {output} = {lookups}; }}"
            ),
        );
        let text = k.print_lowered();
        text.lines()
            .skip(1)
            .filter(|l| !l.starts_with("; stmt"))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(
        body(
            Stage::Fragment,
            120,
            "texture2D(s, p.xy) + texture2DProj(s, p, 1.5) + shadow2D(z, p.xyz).xxxx"
        ),
        body(
            Stage::Fragment,
            130,
            "texture(s, p.xy) + textureProj(s, p, 1.5) + vec4(texture(z, p.xyz))"
        )
    );
    assert_eq!(
        body(
            Stage::Vertex,
            120,
            "texture2DLod(s, p.xy, 2.0) + texture2DProjLod(s, p.xyw, 1.0)"
        ),
        body(
            Stage::Vertex,
            130,
            "textureLod(s, p.xy, 2.0) + textureProjLod(s, p.xyw, 1.0)"
        )
    );
}
