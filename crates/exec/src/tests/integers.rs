//! GLSL 1.30's unsigned integers, integer operators and `switch`, run
//! through every path (`frag_colors`: engine, reference, native code,
//! subroutines) and compared with constant folding.

use super::*;
use glsl::ir::{BinaryOp, Expr, ExprKind, UnaryOp};
use glsl::Span;

/// Operand pairs per lane: zeros, signs, extremes, shift amounts at and
/// past 32, negative amounts.
const A: [u32; LANES] = [
    0,
    1,
    7,
    0xffff_fff9, // -7
    0x8000_0000,
    0xffff_ffff,
    12345678,
    0x7fff_ffff,
    100,
    0xdead_beef,
    3,
    0x8000_0000,
    5,
    0xffff_ff00,
    42,
    9,
];
const B: [u32; LANES] = [
    3,
    0,
    2,
    3,
    0xffff_ffff, // -1
    31,
    32,
    33,
    0xffff_ffff,
    0xffff_fffe, // -2
    0x8000_0001,
    1,
    0xffff_fffd, // -3
    4,
    17,
    9,
];

fn konst(ty: Type, c: ConstScalar) -> Expr {
    Expr {
        kind: ExprKind::Const(ConstValue {
            ty,
            components: vec![c],
        }),
        ty,
        span: Span::default(),
    }
}

fn scalar(s: Scalar, bits: u32) -> ConstScalar {
    match s {
        Scalar::Uint => ConstScalar::Uint(bits),
        _ => ConstScalar::Int(bits as i32),
    }
}

fn bits(c: &ConstScalar) -> u32 {
    match *c {
        ConstScalar::Int(i) => i as u32,
        ConstScalar::Uint(u) => u,
        ConstScalar::Bool(b) => b as u32,
        ConstScalar::Float(f) => f.to_bits(),
    }
}

/// What constant folding gives for `a op b`; 0 where it does not fold
/// (a division or remainder by zero: the executor's 0).
fn folded(op: BinaryOp, ls: Scalar, rs: Scalar, ty: Type, a: u32, b: u32) -> u32 {
    let e = Expr {
        kind: ExprKind::Binary {
            op,
            left: Box::new(konst(Type::vec(ls, 1), scalar(ls, a))),
            right: Box::new(konst(Type::vec(rs, 1), scalar(rs, b))),
        },
        ty,
        span: Span::default(),
    };
    glsl::consteval::fold(&e, &[]).map_or(0, |v| v.components.first().map_or(0, bits))
}

/// Runs `expr` (of the uniforms `a[i]`, `b[i]` with `i` the lane) and
/// returns its 32 bits per lane (`b` is read even where `expr` does not
/// use it, so that both uniforms exist).
fn run_u32(decl_a: &str, decl_b: &str, expr: &str) -> Vec<u32> {
    let src = format!(
        "#version 130\nuniform {decl_a} a[16]; uniform {decl_b} b[16];\n\
         void main() {{ int i = int(gl_FragCoord.x); uint r = uint({expr}) + uint(b[0]) * 0u;\n\
         gl_FragColor = vec4(float(r & 0xffffu), float(r >> 16), 0.0, 1.0); }}"
    );
    let (c, _) = frag_colors(&src, &[("a", &A), ("b", &B)]);
    c.iter()
        .map(|p| p[0] as u32 | (p[1] as u32) << 16)
        .collect()
}

#[test]
fn integer_operators_match_constant_folding() {
    use Scalar::{Int, Uint};
    let ops = [
        ("+", BinaryOp::Add),
        ("-", BinaryOp::Sub),
        ("*", BinaryOp::Mul),
        ("/", BinaryOp::Div),
        ("%", BinaryOp::Mod),
        ("&", BinaryOp::BitAnd),
        ("|", BinaryOp::BitOr),
        ("^", BinaryOp::BitXor),
        ("<<", BinaryOp::Shl),
        (">>", BinaryOp::Shr),
    ];
    for (text, op) in ops {
        let shift = matches!(op, BinaryOp::Shl | BinaryOp::Shr);
        let mut kinds = vec![(Int, Int), (Uint, Uint)];
        if shift {
            kinds.extend([(Int, Uint), (Uint, Int)]);
        }
        for (ls, rs) in kinds {
            let got = run_u32(ls.name(), rs.name(), &format!("a[i] {text} b[i]"));
            for l in 0..LANES {
                let want = folded(op, ls, rs, Type::vec(ls, 1), A[l], B[l]);
                assert_eq!(
                    got[l],
                    want,
                    "{} {text} {}: {:#x} {text} {:#x}",
                    ls.name(),
                    rs.name(),
                    A[l],
                    B[l]
                );
            }
        }
    }
}

#[test]
fn unsigned_comparisons_and_unary_operators() {
    let got = run_u32(
        "uint",
        "uint",
        "(a[i] < b[i] ? 1u : 0u) | (a[i] <= b[i] ? 2u : 0u) | (a[i] > b[i] ? 4u : 0u) \
         | (a[i] >= b[i] ? 8u : 0u) | (lessThan(uvec2(a[i]), uvec2(b[i])).x ? 16u : 0u)",
    );
    for l in 0..LANES {
        let (x, y) = (A[l], B[l]);
        let want = (x < y) as u32
            | ((x <= y) as u32) << 1
            | ((x > y) as u32) << 2
            | ((x >= y) as u32) << 3
            | ((x < y) as u32) << 4;
        assert_eq!(got[l], want, "{x:#x} vs {y:#x}");
    }
    for (text, op) in [("~", UnaryOp::BitNot), ("-", UnaryOp::Neg)] {
        for s in [Scalar::Int, Scalar::Uint] {
            let got = run_u32(s.name(), s.name(), &format!("{text}a[i]"));
            for l in 0..LANES {
                let ty = Type::vec(s, 1);
                let e = Expr {
                    kind: ExprKind::Unary {
                        op,
                        operand: Box::new(konst(ty, scalar(s, A[l]))),
                    },
                    ty,
                    span: Span::default(),
                };
                let want = glsl::consteval::fold(&e, &[]).map(|v| bits(&v.components[0]));
                assert_eq!(Some(got[l]), want, "{text}{:#x}", A[l]);
            }
        }
    }
}

#[test]
fn conversions_match_constant_folding() {
    let floats: [f32; LANES] = [
        0.0,
        -0.0,
        1.5,
        -1.5,
        4_294_967_040.0,
        4_294_967_296.0,
        1e20,
        -1e20,
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        2_147_483_648.0,
        0.999,
        16_777_217.0,
        3e9,
        -3e9,
    ];
    let src = "#version 130\nuniform float f[16]; uniform uint u[16]; uniform int k[16];\n\
        void main() { int i = int(gl_FragCoord.x); uint a = uint(f[i]); \
        gl_FragColor = vec4(float(a & 0xffffu), float(a >> 16), float(u[i]), \
        float(uint(k[i]) >> 16) + float(int(u[i]) < 0) * 65536.0); }";
    let fb = fbits(&floats);
    let (c, _) = frag_colors(src, &[("f", &fb), ("u", &A), ("k", &B)]);
    for l in 0..LANES {
        let want = glsl::consteval::float_to_uint(floats[l]);
        let got = c[l][0] as u32 | (c[l][1] as u32) << 16;
        assert_eq!(got, want, "uint({})", floats[l]);
        assert_eq!(
            c[l][2].to_bits(),
            (A[l] as f32).to_bits(),
            "float({}u)",
            A[l]
        );
        let bit_pattern = (B[l] >> 16) as f32 + if (A[l] as i32) < 0 { 65536.0 } else { 0.0 };
        assert_eq!(c[l][3], bit_pattern, "int↔uint of {:#x}", A[l]);
    }
}

/// The switch of [`switch_falls_through_and_breaks`] in Rust.
fn switch_reference(x: i32) -> f32 {
    let mut r = 0i32;
    for k in 0..2 {
        let mut case = match x % 6 {
            0 => 0,
            1 => 1,
            2 => 2,
            3 => 3,
            5 => 5,
            _ => 4,
        };
        let mut continued = false;
        loop {
            match case {
                0 => r += 1,
                1 => {
                    r += 10;
                    break;
                }
                2 => {
                    if k == 0 {
                        continued = true;
                        break;
                    }
                    r += 100;
                    break;
                }
                3 => {
                    r += 1000;
                    if x > 8 {
                        break;
                    }
                    r += 1000;
                }
                4 => r += 10_000,
                _ => {
                    r += 100_000;
                    break;
                }
            }
            case += 1;
        }
        if continued {
            continue;
        }
        r += 1_000_000;
    }
    r as f32
}

#[test]
fn switch_falls_through_and_breaks() {
    let src = "#version 130\n\
        void main() {\n\
          int x = int(gl_FragCoord.x);\n\
          int r = 0;\n\
          for (int k = 0; k < 2; k++) {\n\
            switch (x % 6) {\n\
              case 0: r += 1;\n\
              case 1: r += 10; break;\n\
              case 2: if (k == 0) continue; r += 100; break;\n\
              case 3: { r += 1000; if (x > 8) break; r += 1000; }\n\
              default: r += 10000;\n\
              case 5: r += 100000; break;\n\
            }\n\
            r += 1000000;\n\
          }\n\
          uint u = uint(x);\n\
          float s = 0.0;\n\
          switch (u & 3u) { case 1u: s = 1.0; break; case 2u: case 3u: s = 2.0; }\n\
          switch (x) { case 14: discard; case 15: return; }\n\
          gl_FragColor = vec4(float(r), s, 0.0, 1.0);\n\
        }";
    let (c, discarded) = frag_colors(src, &[]);
    assert_eq!(discarded, 1 << 14);
    for l in 0..LANES {
        if l >= 14 {
            continue;
        }
        assert_eq!(c[l][0], switch_reference(l as i32), "lane {l}");
        let s = match l & 3 {
            1 => 1.0,
            2 | 3 => 2.0,
            _ => 0.0,
        };
        assert_eq!(c[l][1], s, "lane {l}");
    }
}

#[test]
fn uint_indices_clamp_like_int_ones() {
    // Lane l indexes with a[l]: in range, or past it (huge values select
    // the last element, as out-of-range int indices do).
    let src = "#version 130\nuniform uint a[16];\n\
        void main() { int i = int(gl_FragCoord.x); float t[4] = float[4](1.0, 2.0, 3.0, 4.0); \
        vec4 v = vec4(5.0, 6.0, 7.0, 8.0); \
        gl_FragColor = vec4(t[a[i]], v[a[i]], t[a[i] & 3u], 0.0); }";
    let (c, _) = frag_colors(src, &[("a", &A)]);
    for l in 0..LANES {
        let k = (A[l] as usize).min(3);
        assert_eq!(c[l][0], k as f32 + 1.0, "t[{:#x}]", A[l]);
        assert_eq!(c[l][1], k as f32 + 5.0, "v[{:#x}]", A[l]);
        assert_eq!(c[l][2], (A[l] & 3) as f32 + 1.0, "t[{:#x} & 3]", A[l]);
    }
}
