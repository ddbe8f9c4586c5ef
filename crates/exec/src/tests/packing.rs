//! GL_ARB_shading_language_packing run lane by lane on every path
//! (`frag_colors`: engine, reference, native code, subroutines), compared
//! with hand-computed words and with constant folding.

use super::*;
use glsl::builtins::{eval_builtin, BuiltinFn};
use glsl::math::pack;

/// Per lane: zeros of both signs, the ends of the ranges, halves (ties of
/// the snorm and unorm products), NaN, infinities, out of range, the
/// binary16 overflow boundary, its subnormals and a tie between them.
const X: [f32; LANES] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    -0.5,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    2.0,
    65520.0,
    65519.996,
    5.960_464_5e-8,
    2.980_232_2e-8,
    1.000_488_3,
    0.2,
];

fn y(l: usize) -> f32 {
    X[LANES - 1 - l]
}

/// `expr` (a `uint` of `x[i]`, `y[i]`) per lane.
fn packed(expr: &str) -> Vec<u32> {
    let src = format!(
        "#version 130\n#extension GL_ARB_shading_language_packing : enable\n\
         uniform float x[16]; uniform float y[16];\n\
         void main() {{ int i = int(gl_FragCoord.x); uint r = {expr};\n\
         gl_FragColor = vec4(float(r & 0xffffu), float(r >> 16), 0.0, 1.0); }}"
    );
    let ys: Vec<u32> = (0..LANES).map(|l| y(l).to_bits()).collect();
    let (c, _) = frag_colors(&src, &[("x", &X.map(f32::to_bits)), ("y", &ys)]);
    c.iter()
        .map(|p| p[0] as u32 | (p[1] as u32) << 16)
        .collect()
}

fn fold_pack(f: BuiltinFn, v: &[f32]) -> u32 {
    let arg = ConstValue {
        ty: Type::vec(Scalar::Float, v.len() as u8),
        components: v.iter().map(|&x| ConstScalar::Float(x)).collect(),
    };
    match eval_builtin(f, &[arg], Type::UINT)
        .expect("folds")
        .components[..]
    {
        [ConstScalar::Uint(u)] => u,
        ref c => panic!("{c:?}"),
    }
}

#[test]
fn pack_2x16_words_per_lane() {
    let halves = packed("packHalf2x16(vec2(x[i], y[i]))");
    let unorm = packed("packUnorm2x16(vec2(x[i], y[i]))");
    let snorm = packed("packSnorm2x16(vec2(x[i], y[i]))");
    // The low field of each lane, worked out by hand from the spec's
    // formulas (ties to even) and binary16's layout.
    let want_half: [u32; LANES] = [
        0x0000, 0x8000, 0x3c00, 0xbc00, 0x3800, 0xb800, 0x7e00, 0x7c00, 0xfc00, 0x4000, 0x7c00,
        0x7bff, 0x0001, 0x0000, 0x3c00, 0x3266,
    ];
    let want_unorm: [u32; LANES] = [
        0, 0, 0xffff, 0, 0x8000, 0, 0, 0xffff, 0, 0xffff, 0xffff, 0xffff, 0, 0, 0xffff, 0x3333,
    ];
    let want_snorm: [u32; LANES] = [
        0, 0, 0x7fff, 0x8001, 0x4000, 0xc000, 0x8001, 0x7fff, 0x8001, 0x7fff, 0x7fff, 0x7fff, 0, 0,
        0x7fff, 0x1999,
    ];
    for l in 0..LANES {
        let r = LANES - 1 - l;
        let pair = |w: &[u32; LANES]| w[l] | w[r] << 16;
        assert_eq!(halves[l], pair(&want_half), "packHalf2x16 lane {l}");
        assert_eq!(unorm[l], pair(&want_unorm), "packUnorm2x16 lane {l}");
        assert_eq!(snorm[l], pair(&want_snorm), "packSnorm2x16 lane {l}");
        let v = [X[l], y(l)];
        assert_eq!(halves[l], fold_pack(BuiltinFn::PackHalf2x16, &v));
        assert_eq!(unorm[l], fold_pack(BuiltinFn::PackUnorm2x16, &v));
        assert_eq!(snorm[l], fold_pack(BuiltinFn::PackSnorm2x16, &v));
    }
}

#[test]
fn pack_4x8_words_per_lane() {
    let args = "vec4(x[i], y[i], x[(i + 5) & 15], 0.25 * y[(i + 3) & 15])";
    let unorm = packed(&format!("packUnorm4x8({args})"));
    let snorm = packed(&format!("packSnorm4x8({args})"));
    for l in 0..LANES {
        let v = [X[l], y(l), X[(l + 5) & 15], 0.25 * y((l + 3) & 15)];
        let by_fields = |f: fn(f32, u32) -> u32| {
            v.iter()
                .enumerate()
                .fold(0, |w, (k, &c)| w | f(c, 8) << (8 * k))
        };
        assert_eq!(unorm[l], by_fields(pack::pack_unorm), "packUnorm4x8 {v:?}");
        assert_eq!(snorm[l], by_fields(pack::pack_snorm), "packSnorm4x8 {v:?}");
        assert_eq!(unorm[l], fold_pack(BuiltinFn::PackUnorm4x8, &v));
        assert_eq!(snorm[l], fold_pack(BuiltinFn::PackSnorm4x8, &v));
    }
    // By hand, lane 4: (0.5, 65519.996, 2.0, 0.25·−inf): unorm 128 (127.5
    // to even), 255, 255, 0; snorm 64 (63.5 to even), 127, 127, −127.
    assert_eq!(unorm[4], 0x00ff_ff80);
    assert_eq!(snorm[4], 0x817f_7f40);
    // Lane 15: (0.2, 0.0, 0.5, 0.25·2^-25): unorm 51 (51.000001), 0,
    // 128, 0; snorm 25 (25.4), 0, 64, 0.
    assert_eq!(unorm[15], 0x0080_0033);
    assert_eq!(snorm[15], 0x0040_0019);
}

/// Words whose fields cover every case of each unpacking: zeros of both
/// signs, the extremes of unorm and snorm (−128 and −127 both −1.0),
/// binary16 subnormals, normals, infinities and NaNs.
const W: [u32; LANES] = [
    0x0000_0000,
    0xffff_ffff,
    0x8000_7fff,
    0x3c00_bc00,
    0x7c00_fc00,
    0x7e01_fe00,
    0x0001_03ff,
    0x0400_8001,
    0x1234_5678,
    0x8081_8283,
    0x7f7f_0101,
    0xdead_beef,
    0x3266_c000,
    0x00ff_00ff,
    0x7bff_fbff,
    0x0000_8000,
];

/// What the test shader writes for a NaN result: NaN would compare
/// unequal to itself where the paths' outputs are compared.
const NAN_MARK: f32 = 7.0e30;

fn unpacked(f: &str) -> Vec<[f32; 4]> {
    let src = format!(
        "#version 130\n#extension GL_ARB_shading_language_packing : enable\n\
         uniform uint w[16];\n\
         void main() {{ int i = int(gl_FragCoord.x); vec4 v = vec4({f}(w[i]){pad});\n\
         bvec4 n = isnan(v);\n\
         gl_FragColor = vec4(n.x ? {NAN_MARK:e} : v.x, n.y ? {NAN_MARK:e} : v.y, n.z ? {NAN_MARK:e} : v.z, n.w ? {NAN_MARK:e} : v.w); }}",
        pad = if f.ends_with("4x8") { "" } else { ", 0.0, 0.0" }
    );
    frag_colors(&src, &[("w", &W)]).0
}

#[test]
fn unpack_fields_per_lane() {
    type Field = fn(u32, u32) -> f32;
    let half: Field = |h, _| pack::float_from_half(h);
    let cases: [(&str, BuiltinFn, u32, Field); 5] = [
        ("unpackHalf2x16", BuiltinFn::UnpackHalf2x16, 16, half),
        (
            "unpackUnorm2x16",
            BuiltinFn::UnpackUnorm2x16,
            16,
            pack::unpack_unorm,
        ),
        (
            "unpackSnorm2x16",
            BuiltinFn::UnpackSnorm2x16,
            16,
            pack::unpack_snorm,
        ),
        (
            "unpackUnorm4x8",
            BuiltinFn::UnpackUnorm4x8,
            8,
            pack::unpack_unorm,
        ),
        (
            "unpackSnorm4x8",
            BuiltinFn::UnpackSnorm4x8,
            8,
            pack::unpack_snorm,
        ),
    ];
    let same = |g: f32, w: f32| g.to_bits() == w.to_bits() || (g == NAN_MARK && w.is_nan());
    for (name, f, bits, field) in cases {
        let got = unpacked(name);
        let n = (32 / bits) as usize;
        for l in 0..LANES {
            let ty = Type::vec(Scalar::Float, n as u8);
            let folded = eval_builtin(
                f,
                &[ConstValue {
                    ty: Type::UINT,
                    components: vec![ConstScalar::Uint(W[l])],
                }],
                ty,
            )
            .expect("folds");
            for k in 0..n {
                let want = field(W[l] >> (k as u32 * bits), bits);
                let g = got[l][k];
                assert!(same(g, want), "{name}({:#x})[{k}]: {g} vs {want}", W[l]);
                let ConstScalar::Float(c) = folded.components[k] else {
                    panic!("float")
                };
                assert!(same(g, c), "{name}({:#x})[{k}] folded {c}", W[l]);
            }
        }
    }
    // By hand: binary16 ±1, ±inf, the largest finite, the smallest
    // subnormal and the largest one; unorm 1.0, snorm −1.0 from both −128
    // and −127, 0x7f → 1.0.
    let h = unpacked("unpackHalf2x16");
    assert_eq!(h[3][..2], [-1.0, 1.0]);
    assert_eq!(h[4][..2], [f32::NEG_INFINITY, f32::INFINITY]);
    assert_eq!(h[14][..2], [-65504.0, 65504.0]);
    assert_eq!(h[6][..2], [1023.0 / 16_777_216.0, 5.960_464_5e-8]);
    assert_eq!(h[15][0].to_bits(), 0x8000_0000);
    assert_eq!(h[5][..2], [NAN_MARK, NAN_MARK]);
    let u = unpacked("unpackUnorm2x16");
    assert_eq!(u[1][..2], [1.0, 1.0]);
    let s = unpacked("unpackSnorm4x8");
    assert_eq!(s[9], [-125.0 / 127.0, -126.0 / 127.0, -1.0, -1.0]);
    assert_eq!(s[10], [1.0 / 127.0, 1.0 / 127.0, 1.0, 1.0]);
}
