//! Constant folding of built-in function calls.
//!
//! GLSL 1.30 §4.3.3 (and 1.20's, and every later version's): "a built-in function call whose arguments are all
//! constant expressions, with the exception of the texture lookup
//! functions, the noise functions, and ftransform" is a constant expression,
//! and dFdx, dFdy and fwidth "must return 0 when evaluated inside an
//! initializer with an argument that is a constant expression". GLSL 1.10
//! §4.3.2 allows no function calls in constant initializers at all; that
//! version rule is the analyzer's to enforce, this module folds whatever it
//! is given. Functions with an `out` parameter (`modf`) are not folded:
//! their call has an effect besides its value.
//!
//! Every function follows the formula its §8 entry gives, one `f32`
//! rounding per operation, with the deterministic scalar functions of
//! [`crate::math`]. Results the spec leaves undefined (`log(-1)`,
//! `clamp` with `minVal > maxVal`, `smoothstep` with equal edges) are
//! whatever those formulas give (NaN, ±inf), repeatably.
//!
//! The integer overloads of GLSL 1.30 compare as their type does: `min`,
//! `max`, `clamp` and the relational functions on `uint`/`uvec` are
//! unsigned (`min(0x80000000u, 1u)` is `1u`), on `int`/`ivec` signed.
//! `floatBitsToInt`/`floatBitsToUint` and `intBitsToFloat`/
//! `uintBitsToFloat` keep the bits (GLSL 3.30 §8.3), but a float is never
//! subnormal here or in the executor: a subnormal pattern gives the zero
//! of its sign (`uintBitsToFloat(1u)` is `0.0`,
//! `uintBitsToFloat(0x80000001u)` is `-0.0`), as every float result is
//! flushed, and NaN patterns keep their bits in folding (the spec leaves
//! the value of an inf or NaN pattern unspecified).

use crate::builtins::BuiltinFn;
use crate::ir::{ConstScalar, ConstValue};
use crate::math;
use crate::types::{Base, Type};

/// Folds `f(args)` to a constant of type `result` (the return type of the
/// overload the analyzer chose). Components are flattened as in
/// [`ConstValue`]: vectors in order, matrices column by column.
///
/// Returns `None` when the call is not constant-foldable (texture lookups,
/// `ftransform`, noise) or when the argument kinds or shapes do not match
/// an overload of `f` with result `result` (which a well-typed call never
/// produces).
pub fn eval_builtin(f: BuiltinFn, args: &[ConstValue], result: Type) -> Option<ConstValue> {
    if args.iter().any(|a| a.ty.component_count().is_none()) {
        return None;
    }
    let mut components = eval(f, args, result)?;
    // Subnormal results are flushed, as the executor does.
    for c in &mut components {
        if let ConstScalar::Float(x) = c {
            *x = math::flush_denormal(*x);
        }
    }
    if components.len() != result.component_count()? as usize {
        return None;
    }
    Some(ConstValue {
        ty: result,
        components,
    })
}

fn eval(f: BuiltinFn, args: &[ConstValue], result: Type) -> Option<Vec<ConstScalar>> {
    use BuiltinFn::*;
    match f {
        Radians => unary(args, math::radians),
        Degrees => unary(args, math::degrees),
        Sin => unary(args, math::sin),
        Cos => unary(args, math::cos),
        Tan => unary(args, math::tan),
        Asin => unary(args, math::asin),
        Acos => unary(args, math::acos),
        Atan if args.len() == 1 => unary(args, math::atan),
        Atan => binary(args, math::atan2),
        Sinh => unary(args, math::sinh),
        Cosh => unary(args, math::cosh),
        Tanh => unary(args, math::tanh),
        Asinh => unary(args, math::asinh),
        Acosh => unary(args, math::acosh),
        Atanh => unary(args, math::atanh),
        Trunc => unary(args, math::trunc),
        Round => unary(args, math::round),
        RoundEven => unary(args, math::round_even),
        Modf => None,
        IsNan => float_test(args, f32::is_nan),
        IsInf => float_test(args, f32::is_infinite),
        // The bits of the (flushed) float, and back.
        FloatBitsToInt => {
            let [x] = args else { return None };
            Some(
                floats(x)?
                    .iter()
                    .map(|f| ConstScalar::Int(f.to_bits() as i32))
                    .collect(),
            )
        }
        IntBitsToFloat => {
            let [x] = args else { return None };
            Some(
                ints(x)?
                    .iter()
                    .map(|&i| ConstScalar::Float(f32::from_bits(i as u32)))
                    .collect(),
            )
        }
        FloatBitsToUint => {
            let [x] = args else { return None };
            Some(
                floats(x)?
                    .iter()
                    .map(|f| ConstScalar::Uint(f.to_bits()))
                    .collect(),
            )
        }
        // Flushed with every other float result by `eval_builtin`.
        UintBitsToFloat => {
            let [x] = args else { return None };
            Some(
                uints(x)?
                    .iter()
                    .map(|&u| ConstScalar::Float(f32::from_bits(u)))
                    .collect(),
            )
        }
        PackUnorm2x16 => pack(args, 16, math::pack::pack_unorm),
        PackSnorm2x16 => pack(args, 16, math::pack::pack_snorm),
        PackUnorm4x8 => pack(args, 8, math::pack::pack_unorm),
        PackSnorm4x8 => pack(args, 8, math::pack::pack_snorm),
        PackHalf2x16 => pack(args, 16, |x, _| math::pack::half_from_float(x)),
        UnpackUnorm2x16 => unpack(args, 16, math::pack::unpack_unorm),
        UnpackSnorm2x16 => unpack(args, 16, math::pack::unpack_snorm),
        UnpackUnorm4x8 => unpack(args, 8, math::pack::unpack_unorm),
        UnpackSnorm4x8 => unpack(args, 8, math::pack::unpack_snorm),
        UnpackHalf2x16 => unpack(args, 16, |h, _| math::pack::float_from_half(h)),
        Min | Max | Clamp if is_uint_call(args) => uint_call(f, args),
        Abs | Sign | Min | Max | Clamp | Mix if is_int_or_bool_call(f, args) => int_call(f, args),
        Pow => binary(args, math::pow),
        Exp => unary(args, math::exp),
        Log => unary(args, math::log),
        Exp2 => unary(args, math::exp2),
        Log2 => unary(args, math::log2),
        Sqrt => unary(args, math::sqrt),
        InverseSqrt => unary(args, math::inversesqrt),
        Abs => unary(args, math::abs),
        Sign => unary(args, math::sign),
        Floor => unary(args, math::floor),
        Ceil => unary(args, math::ceil),
        Fract => unary(args, math::fract),
        Mod => binary(args, math::modulo),
        Min => binary(args, math::min),
        Max => binary(args, math::max),
        Clamp => ternary(args, math::clamp),
        Mix => ternary(args, math::mix),
        Step => binary(args, math::step),
        SmoothStep => ternary(args, math::smoothstep),
        Length => geometric(args, 1, |v| vec![math::length(&v[0])]),
        Distance => geometric(args, 2, |v| {
            let d: Vec<f32> = v[0].iter().zip(&v[1]).map(|(a, b)| a - b).collect();
            vec![math::length(&d)]
        }),
        Dot => geometric(args, 2, |v| vec![math::dot(&v[0], &v[1])]),
        Cross => geometric(args, 2, |v| cross(&v[0], &v[1])),
        Normalize => geometric(args, 1, |v| normalize(&v[0])),
        FaceForward => geometric(args, 3, |v| faceforward(&v[0], &v[1], &v[2])),
        Reflect => geometric(args, 2, |v| reflect(&v[0], &v[1])),
        Refract => refract(args),
        MatrixCompMult => {
            if args.len() != 2 || args[0].ty != args[1].ty || !args[0].ty.is_matrix() {
                return None;
            }
            binary(args, |a, b| a * b)
        }
        OuterProduct => outer_product(args),
        Transpose => transpose(args),
        Determinant => {
            let [m] = args else { return None };
            let n = square(m)?;
            Some(vec![ConstScalar::Float(
                math::matrix::determinant(&mut F32Arith, &floats(m)?, n)?.ok()?,
            )])
        }
        Inverse => {
            let [m] = args else { return None };
            let n = square(m)?;
            Some(float_result(
                math::matrix::inverse(&mut F32Arith, &floats(m)?, n)?.ok()?,
            ))
        }
        LessThan => compare(args, |a, b| a < b, |a, b| a < b, |a, b| a < b),
        LessThanEqual => compare(args, |a, b| a <= b, |a, b| a <= b, |a, b| a <= b),
        GreaterThan => compare(args, |a, b| a > b, |a, b| a > b, |a, b| a > b),
        GreaterThanEqual => compare(args, |a, b| a >= b, |a, b| a >= b, |a, b| a >= b),
        Equal => equality(args, true),
        NotEqual => equality(args, false),
        Any => reduce_bools(args, |b| b.iter().any(|&x| x)),
        All => reduce_bools(args, |b| b.iter().all(|&x| x)),
        Not => {
            let [x] = args else { return None };
            Some(bools(x)?.iter().map(|&b| ConstScalar::Bool(!b)).collect())
        }
        // §4.3.3 (1.20): derivatives of constant arguments are 0.
        DFdx | DFdy | Fwidth => {
            let [x] = args else { return None };
            floats(x)?;
            Some(vec![
                ConstScalar::Float(0.0);
                result.component_count()? as usize
            ])
        }
        Ftransform | Noise1 | Noise2 | Noise3 | Noise4 | EmitVertex | EndPrimitive => None,
        // Side effects on memory and on the other invocations.
        Barrier
        | MemoryBarrier
        | MemoryBarrierAtomicCounter
        | MemoryBarrierBuffer
        | MemoryBarrierImage
        | MemoryBarrierShared
        | GroupMemoryBarrier
        | AtomicAdd
        | AtomicMin
        | AtomicMax
        | AtomicAnd
        | AtomicOr
        | AtomicXor
        | AtomicExchange
        | AtomicCompSwap => None,
        Texture1D | Texture1DProj | Texture1DLod | Texture1DProjLod | Texture2D | Texture2DProj
        | Texture2DLod | Texture2DProjLod | Texture3D | Texture3DProj | Texture3DLod
        | Texture3DProjLod | TextureCube | TextureCubeLod | Shadow1D | Shadow2D | Shadow1DProj
        | Shadow2DProj | Shadow1DLod | Shadow2DLod | Shadow1DProjLod | Shadow2DProjLod
        | Texture2DRect | Texture2DRectProj | Shadow2DRect | Shadow2DRectProj | Texture1DArray
        | Texture1DArrayLod | Texture2DArray | Texture2DArrayLod | Shadow1DArray
        | Shadow1DArrayLod | Shadow2DArray => None,
        Texture1DGradARB
        | Texture1DProjGradARB
        | Texture2DGradARB
        | Texture2DProjGradARB
        | Texture3DGradARB
        | Texture3DProjGradARB
        | TextureCubeGradARB
        | Shadow1DGradARB
        | Shadow1DProjGradARB
        | Shadow2DGradARB
        | Shadow2DProjGradARB
        | Texture2DRectGradARB
        | Texture2DRectProjGradARB
        | Shadow2DRectGradARB
        | Shadow2DRectProjGradARB => None,
        TextureSize
        | Texture
        | TextureProj
        | TextureLod
        | TextureOffset
        | TexelFetch
        | TexelFetchOffset
        | TextureProjOffset
        | TextureLodOffset
        | TextureProjLod
        | TextureProjLodOffset
        | TextureGrad
        | TextureGradOffset
        | TextureProjGrad
        | TextureProjGradOffset => None,
    }
}

/// GL_ARB_shading_language_packing's `pack*`: the fields of a vector's
/// components, `bits` wide each, the first component in the lowest bits.
fn pack(args: &[ConstValue], bits: u32, field: fn(f32, u32) -> u32) -> Option<Vec<ConstScalar>> {
    let [v] = args else { return None };
    let v = floats(v)?;
    if v.len() * bits as usize != 32 {
        return None;
    }
    let word = v
        .iter()
        .enumerate()
        .fold(0u32, |w, (i, &x)| w | field(x, bits) << (i as u32 * bits));
    Some(vec![ConstScalar::Uint(word)])
}

/// The `unpack*` of [`pack`]: one float per `bits`-wide field of a `uint`
/// (`float_of` sees the word shifted down to the field, and masks it).
fn unpack(
    args: &[ConstValue],
    bits: u32,
    float_of: fn(u32, u32) -> f32,
) -> Option<Vec<ConstScalar>> {
    let [u] = args else { return None };
    let [word] = uints(u)?[..] else { return None };
    Some(
        (0..32 / bits)
            .map(|i| ConstScalar::Float(float_of(word >> (i * bits), bits)))
            .collect(),
    )
}

/// `f32` arithmetic, each operation rounded and flushed as the executor
/// does it, for [`math::matrix`].
struct F32Arith;

impl math::matrix::Arith for F32Arith {
    type V = f32;
    type E = ();
    fn mul(&mut self, a: f32, b: f32) -> Result<f32, ()> {
        Ok(math::flush_denormal(a * b))
    }
    fn add(&mut self, a: f32, b: f32) -> Result<f32, ()> {
        Ok(math::flush_denormal(a + b))
    }
    fn sub(&mut self, a: f32, b: f32) -> Result<f32, ()> {
        Ok(math::flush_denormal(a - b))
    }
    fn div(&mut self, a: f32, b: f32) -> Result<f32, ()> {
        Ok(math::flush_denormal(a / b))
    }
    fn neg(&mut self, a: f32) -> Result<f32, ()> {
        Ok(-a)
    }
}

/// The size of a square matrix.
fn square(m: &ConstValue) -> Option<usize> {
    match m.ty.base {
        Base::Matrix { cols, rows } if cols == rows && !m.ty.is_array() => Some(cols as usize),
        _ => None,
    }
}

/// `isnan`/`isinf`: a bool per float component.
fn float_test(args: &[ConstValue], f: fn(f32) -> bool) -> Option<Vec<ConstScalar>> {
    let [x] = args else { return None };
    Some(
        floats(x)?
            .into_iter()
            .map(|v| ConstScalar::Bool(f(v)))
            .collect(),
    )
}

/// The integer forms of `abs`, `sign`, `min`, `max`, `clamp` and the
/// bool-selector form of `mix` (GLSL 1.30 §8.3).
fn is_int_or_bool_call(f: BuiltinFn, args: &[ConstValue]) -> bool {
    let kind = |a: &ConstValue| a.ty.scalar();
    match f {
        BuiltinFn::Mix => args.get(2).and_then(kind) == Some(crate::types::Scalar::Bool),
        _ => args.first().and_then(kind) == Some(crate::types::Scalar::Int),
    }
}

/// The unsigned forms of `min`, `max` and `clamp` (GLSL 1.30 §8.3).
fn is_uint_call(args: &[ConstValue]) -> bool {
    args.first().and_then(|a| a.ty.scalar()) == Some(crate::types::Scalar::Uint)
}

/// `min`, `max`, `clamp` on `uint`s, compared unsigned, a scalar argument
/// standing for every component (`uvec min(uvec, uint)`).
fn uint_call(f: BuiltinFn, args: &[ConstValue]) -> Option<Vec<ConstScalar>> {
    let vals = args.iter().map(uints).collect::<Option<Vec<_>>>()?;
    let n = vals.iter().map(Vec::len).max()?;
    if vals.iter().any(|v| v.len() != n && v.len() != 1) {
        return None;
    }
    let at = |k: usize, i: usize| vals[k][if vals[k].len() == 1 { 0 } else { i }];
    let one = |i: usize| -> Option<u32> {
        Some(match (f, vals.len()) {
            (BuiltinFn::Min, 2) => at(0, i).min(at(1, i)),
            (BuiltinFn::Max, 2) => at(0, i).max(at(1, i)),
            // min(max(x, lo), hi), whatever the order of lo and hi, as
            // the signed form.
            (BuiltinFn::Clamp, 3) => at(0, i).max(at(1, i)).min(at(2, i)),
            _ => return None,
        })
    };
    (0..n).map(|i| one(i).map(ConstScalar::Uint)).collect()
}

fn int_call(f: BuiltinFn, args: &[ConstValue]) -> Option<Vec<ConstScalar>> {
    if f == BuiltinFn::Mix {
        // mix(x, y, a): y where a is true, else x.
        let [x, y, a] = args else { return None };
        let a = bools(a)?;
        if x.components.len() != a.len() || y.components.len() != a.len() {
            return None;
        }
        return Some(
            a.iter()
                .zip(x.components.iter().zip(&y.components))
                .map(|(&a, (x, y))| if a { *y } else { *x })
                .collect(),
        );
    }
    let vals = args.iter().map(ints).collect::<Option<Vec<_>>>()?;
    let n = vals.iter().map(Vec::len).max()?;
    if vals.iter().any(|v| v.len() != n && v.len() != 1) {
        return None;
    }
    let at = |k: usize, i: usize| vals[k][if vals[k].len() == 1 { 0 } else { i }];
    let one = |i: usize| -> Option<i32> {
        Some(match (f, vals.len()) {
            (BuiltinFn::Abs, 1) => at(0, i).wrapping_abs(),
            (BuiltinFn::Sign, 1) => at(0, i).signum(),
            (BuiltinFn::Min, 2) => at(0, i).min(at(1, i)),
            (BuiltinFn::Max, 2) => at(0, i).max(at(1, i)),
            // min(max(x, lo), hi), whatever the order of lo and hi.
            (BuiltinFn::Clamp, 3) => at(0, i).max(at(1, i)).min(at(2, i)),
            _ => return None,
        })
    };
    (0..n).map(|i| one(i).map(ConstScalar::Int)).collect()
}

/// The components of a float scalar, vector or matrix.
fn floats(v: &ConstValue) -> Option<Vec<f32>> {
    if v.ty.scalar()? != crate::types::Scalar::Float {
        return None;
    }
    v.components
        .iter()
        .map(|c| match c {
            ConstScalar::Float(f) => Some(*f),
            _ => None,
        })
        .collect()
}

fn ints(v: &ConstValue) -> Option<Vec<i32>> {
    v.components
        .iter()
        .map(|c| match c {
            ConstScalar::Int(i) => Some(*i),
            _ => None,
        })
        .collect()
}

fn uints(v: &ConstValue) -> Option<Vec<u32>> {
    v.components
        .iter()
        .map(|c| match c {
            ConstScalar::Uint(u) => Some(*u),
            _ => None,
        })
        .collect()
}

fn bools(v: &ConstValue) -> Option<Vec<bool>> {
    v.components
        .iter()
        .map(|c| match c {
            ConstScalar::Bool(b) => Some(*b),
            _ => None,
        })
        .collect()
}

fn float_result(v: Vec<f32>) -> Vec<ConstScalar> {
    v.into_iter().map(ConstScalar::Float).collect()
}

/// Applies `f` component-wise to float arguments of equal length, a
/// length-1 (scalar) argument standing for every component (the
/// `genType f(genType, float)` overloads of §8.3).
fn component_wise<const N: usize>(
    args: &[ConstValue],
    f: impl Fn([f32; N]) -> f32,
) -> Option<Vec<ConstScalar>> {
    if args.len() != N {
        return None;
    }
    let vals = args.iter().map(floats).collect::<Option<Vec<_>>>()?;
    let n = vals.iter().map(Vec::len).max()?;
    if vals.iter().any(|v| v.len() != n && v.len() != 1) {
        return None;
    }
    let at = |v: &Vec<f32>, i: usize| if v.len() == 1 { v[0] } else { v[i] };
    Some(
        (0..n)
            .map(|i| ConstScalar::Float(f(std::array::from_fn(|k| at(&vals[k], i)))))
            .collect(),
    )
}

fn unary(args: &[ConstValue], f: fn(f32) -> f32) -> Option<Vec<ConstScalar>> {
    component_wise(args, |[x]| f(x))
}

fn binary(args: &[ConstValue], f: impl Fn(f32, f32) -> f32) -> Option<Vec<ConstScalar>> {
    component_wise(args, |[x, y]| f(x, y))
}

fn ternary(args: &[ConstValue], f: fn(f32, f32, f32) -> f32) -> Option<Vec<ConstScalar>> {
    component_wise(args, |[x, y, z]| f(x, y, z))
}

/// §8.4 functions on `n` float vectors of one size.
fn geometric(
    args: &[ConstValue],
    n: usize,
    f: impl Fn(&[Vec<f32>]) -> Vec<f32>,
) -> Option<Vec<ConstScalar>> {
    if args.len() != n || args.iter().any(|a| a.ty.vector_size().is_none()) {
        return None;
    }
    let vals = args.iter().map(floats).collect::<Option<Vec<_>>>()?;
    if vals.iter().any(|v| v.len() != vals[0].len()) {
        return None;
    }
    Some(float_result(f(&vals)))
}

fn cross(x: &[f32], y: &[f32]) -> Vec<f32> {
    if x.len() != 3 {
        return Vec::new();
    }
    vec![
        x[1] * y[2] - y[1] * x[2],
        x[2] * y[0] - y[2] * x[0],
        x[0] * y[1] - y[0] * x[1],
    ]
}

/// `x / length(x)`.
/// `x · inversesqrt(dot(x, x))`, as Mesa's compiler writes `normalize`
/// (the executor's order).
fn normalize(x: &[f32]) -> Vec<f32> {
    let inv = math::inversesqrt(math::dot(x, x));
    x.iter().map(|c| c * inv).collect()
}

/// `dot(Nref, I) < 0 ? N : -N`.
fn faceforward(n: &[f32], i: &[f32], nref: &[f32]) -> Vec<f32> {
    if math::dot(nref, i) < 0.0 {
        n.to_vec()
    } else {
        n.iter().map(|c| -c).collect()
    }
}

/// `I - 2 * dot(N, I) * N`.
fn reflect(i: &[f32], n: &[f32]) -> Vec<f32> {
    let d = 2.0 * math::dot(n, i);
    i.iter().zip(n).map(|(ic, nc)| ic - d * nc).collect()
}

/// `k = 1 - eta² (1 - dot(N, I)²)`; 0 if `k < 0`, else
/// `eta I - (eta dot(N, I) + sqrt(k)) N`.
fn refract(args: &[ConstValue]) -> Option<Vec<ConstScalar>> {
    let [i, n, eta] = args else { return None };
    if i.ty != n.ty || i.ty.vector_size().is_none() || !eta.ty.is_scalar() {
        return None;
    }
    let (i, n, eta) = (floats(i)?, floats(n)?, floats(eta)?[0]);
    let d = math::dot(&n, &i);
    let k = 1.0 - eta * eta * (1.0 - d * d);
    let r = if k < 0.0 {
        vec![0.0; i.len()]
    } else {
        let s = eta * d + math::sqrt(k);
        i.iter().zip(&n).map(|(ic, nc)| eta * ic - s * nc).collect()
    };
    Some(float_result(r))
}

/// `outerProduct(c, r)`: a matrix of `r.len()` columns, column `j` being
/// `c * r[j]` (§8.5).
fn outer_product(args: &[ConstValue]) -> Option<Vec<ConstScalar>> {
    let [c, r] = args else { return None };
    if !c.ty.is_vector() || !r.ty.is_vector() {
        return None;
    }
    let (c, r) = (floats(c)?, floats(r)?);
    Some(float_result(
        r.iter()
            .flat_map(|rj| c.iter().map(move |ci| ci * rj))
            .collect(),
    ))
}

fn transpose(args: &[ConstValue]) -> Option<Vec<ConstScalar>> {
    let [m] = args else { return None };
    let Base::Matrix { cols, rows } = m.ty.base else {
        return None;
    };
    let (cols, rows) = (cols as usize, rows as usize);
    let v = floats(m)?;
    if m.ty.is_array() || v.len() != cols * rows {
        return None;
    }
    // Result column j is input row j.
    Some(float_result(
        (0..rows)
            .flat_map(|j| (0..cols).map(move |i| (i, j)))
            .map(|(i, j)| v[i * rows + j])
            .collect(),
    ))
}

/// Component-wise ordering of two `vec`s, `ivec`s or `uvec`s (§8.6),
/// each compared as its type (`uvec`s unsigned).
fn compare(
    args: &[ConstValue],
    on_floats: fn(f32, f32) -> bool,
    on_ints: fn(i32, i32) -> bool,
    on_uints: fn(u32, u32) -> bool,
) -> Option<Vec<ConstScalar>> {
    let [x, y] = args else { return None };
    if x.ty != y.ty || !x.ty.is_vector() {
        return None;
    }
    let out: Vec<bool> = if let (Some(a), Some(b)) = (floats(x), floats(y)) {
        a.iter().zip(&b).map(|(&p, &q)| on_floats(p, q)).collect()
    } else if let (Some(a), Some(b)) = (uints(x), uints(y)) {
        a.iter().zip(&b).map(|(&p, &q)| on_uints(p, q)).collect()
    } else {
        let (a, b) = (ints(x)?, ints(y)?);
        a.iter().zip(&b).map(|(&p, &q)| on_ints(p, q)).collect()
    };
    Some(out.into_iter().map(ConstScalar::Bool).collect())
}

/// `equal` (`want_equal`) or `notEqual` of two vectors of any kind.
fn equality(args: &[ConstValue], want_equal: bool) -> Option<Vec<ConstScalar>> {
    let [x, y] = args else { return None };
    if x.ty != y.ty || !x.ty.is_vector() {
        return None;
    }
    let eq = |a: &ConstScalar, b: &ConstScalar| match (a, b) {
        (ConstScalar::Float(p), ConstScalar::Float(q)) => Some(p == q),
        (ConstScalar::Int(p), ConstScalar::Int(q)) => Some(p == q),
        (ConstScalar::Uint(p), ConstScalar::Uint(q)) => Some(p == q),
        (ConstScalar::Bool(p), ConstScalar::Bool(q)) => Some(p == q),
        _ => None,
    };
    x.components
        .iter()
        .zip(&y.components)
        .map(|(a, b)| Some(ConstScalar::Bool(eq(a, b)? == want_equal)))
        .collect()
}

fn reduce_bools(args: &[ConstValue], f: fn(&[bool]) -> bool) -> Option<Vec<ConstScalar>> {
    let [x] = args else { return None };
    if !x.ty.is_vector() {
        return None;
    }
    Some(vec![ConstScalar::Bool(f(&bools(x)?))])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::types::Scalar;

    fn vec(v: &[f32]) -> ConstValue {
        ConstValue {
            ty: Type::vec(Scalar::Float, v.len() as u8),
            components: v.iter().map(|&f| ConstScalar::Float(f)).collect(),
        }
    }

    fn ivec(v: &[i32]) -> ConstValue {
        ConstValue {
            ty: Type::vec(Scalar::Int, v.len() as u8),
            components: v.iter().map(|&i| ConstScalar::Int(i)).collect(),
        }
    }

    fn uvec(v: &[u32]) -> ConstValue {
        ConstValue {
            ty: Type::vec(Scalar::Uint, v.len() as u8),
            components: v.iter().map(|&u| ConstScalar::Uint(u)).collect(),
        }
    }

    fn uints_of(v: Option<ConstValue>) -> Vec<u32> {
        uints(&v.expect("folds")).expect("uints")
    }

    fn bools_of(v: Option<ConstValue>) -> Vec<bool> {
        bools(&v.expect("folds")).expect("bools")
    }

    fn floats_of(v: Option<ConstValue>) -> Vec<f32> {
        floats(&v.expect("folds")).expect("floats")
    }

    #[test]
    fn not_foldable() {
        let p = vec(&[0.5, 0.5]);
        assert_eq!(
            eval_builtin(BuiltinFn::Noise1, std::slice::from_ref(&p), Type::FLOAT),
            None
        );
        assert_eq!(
            eval_builtin(BuiltinFn::Ftransform, &[], Type::vec(Scalar::Float, 4)),
            None
        );
        assert_eq!(
            eval_builtin(BuiltinFn::Texture2D, &[p], Type::vec(Scalar::Float, 4)),
            None
        );
    }

    #[test]
    fn derivatives_of_constants_are_zero() {
        let v = vec(&[1.0, 2.0, 3.0]);
        let r = eval_builtin(BuiltinFn::Fwidth, &[v], Type::vec(Scalar::Float, 3));
        assert_eq!(floats_of(r), vec![0.0; 3]);
    }

    #[test]
    fn scalar_broadcast_and_shapes() {
        let r = eval_builtin(
            BuiltinFn::Clamp,
            &[vec(&[-2.0, 0.5, 3.0]), vec(&[0.0]), vec(&[1.0])],
            Type::vec(Scalar::Float, 3),
        );
        assert_eq!(floats_of(r), vec![0.0, 0.5, 1.0]);
        let r = eval_builtin(
            BuiltinFn::Step,
            &[vec(&[1.0]), vec(&[0.0, 2.0])],
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(floats_of(r), vec![0.0, 1.0]);
        // Mismatched sizes do not fold.
        let bad = eval_builtin(
            BuiltinFn::Min,
            &[vec(&[1.0, 2.0]), vec(&[1.0, 2.0, 3.0])],
            Type::vec(Scalar::Float, 3),
        );
        assert_eq!(bad, None);
        // Nor does a wrong result type.
        assert_eq!(
            eval_builtin(BuiltinFn::Sin, &[vec(&[1.0, 2.0])], Type::FLOAT),
            None
        );
        // Nor int arguments to a float function.
        assert_eq!(
            eval_builtin(BuiltinFn::Sin, &[ivec(&[1, 2])], Type::vec(Scalar::Int, 2)),
            None
        );
    }

    #[test]
    fn matrices() {
        // mat2x3: 2 columns of 3.
        let m = ConstValue {
            ty: Type::mat(2, 3),
            components: [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
                .iter()
                .map(|&f| ConstScalar::Float(f))
                .collect(),
        };
        let t = eval_builtin(BuiltinFn::Transpose, &[m], Type::mat(3, 2));
        assert_eq!(floats_of(t), vec![1.0, 4.0, 2.0, 5.0, 3.0, 6.0]);
        let o = eval_builtin(
            BuiltinFn::OuterProduct,
            &[vec(&[1.0, 2.0, 3.0]), vec(&[10.0, 20.0])],
            Type::mat(2, 3),
        );
        assert_eq!(floats_of(o), vec![10.0, 20.0, 30.0, 20.0, 40.0, 60.0]);
    }

    #[test]
    fn relational() {
        let r = eval_builtin(
            BuiltinFn::LessThan,
            &[ivec(&[1, 5]), ivec(&[2, 2])],
            Type::vec(Scalar::Bool, 2),
        )
        .unwrap();
        assert_eq!(
            r.components,
            vec![ConstScalar::Bool(true), ConstScalar::Bool(false)]
        );
        let any = eval_builtin(BuiltinFn::Any, &[r], Type::BOOL).unwrap();
        assert_eq!(any.components, vec![ConstScalar::Bool(true)]);
    }

    #[test]
    fn geometric() {
        let r = eval_builtin(
            BuiltinFn::Cross,
            &[vec(&[1.0, 0.0, 0.0]), vec(&[0.0, 1.0, 0.0])],
            Type::vec(Scalar::Float, 3),
        );
        assert_eq!(floats_of(r), vec![0.0, 0.0, 1.0]);
        let r = eval_builtin(
            BuiltinFn::Normalize,
            &[vec(&[3.0, 4.0])],
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(floats_of(r), vec![0.6, 0.8]);
        // Total internal reflection gives the zero vector.
        let r = eval_builtin(
            BuiltinFn::Refract,
            &[vec(&[0.6, -0.8]), vec(&[0.0, 1.0]), vec(&[2.0])],
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(floats_of(r), vec![0.0, 0.0]);
    }

    #[test]
    fn glsl130_common_functions() {
        let v4 = Type::vec(Scalar::Float, 4);
        let x = vec(&[-2.5, -0.5, 0.5, 3.5]);
        let r = |f| floats_of(eval_builtin(f, std::slice::from_ref(&x), v4));
        assert_eq!(r(BuiltinFn::Trunc), vec![-2.0, -0.0, 0.0, 3.0]);
        assert_eq!(r(BuiltinFn::Round), vec![-3.0, -1.0, 1.0, 4.0]);
        assert_eq!(r(BuiltinFn::RoundEven), vec![-2.0, -0.0, 0.0, 4.0]);
        assert_eq!(r(BuiltinFn::Sinh)[2], math::sinh(0.5));
        assert_eq!(r(BuiltinFn::Atanh)[1], math::atanh(-0.5));
        let b = eval_builtin(
            BuiltinFn::IsInf,
            &[vec(&[f32::INFINITY, 1.0])],
            Type::vec(Scalar::Bool, 2),
        )
        .unwrap();
        assert_eq!(
            b.components,
            vec![ConstScalar::Bool(true), ConstScalar::Bool(false)]
        );
        let b = eval_builtin(BuiltinFn::IsNan, &[vec(&[f32::NAN])], Type::BOOL).unwrap();
        assert_eq!(b.components, vec![ConstScalar::Bool(true)]);
        // Integer overloads.
        let i2 = Type::vec(Scalar::Int, 2);
        let c = eval_builtin(
            BuiltinFn::Clamp,
            &[ivec(&[-5, 9]), ivec(&[0]), ivec(&[4])],
            i2,
        )
        .unwrap();
        assert_eq!(c.components, vec![ConstScalar::Int(0), ConstScalar::Int(4)]);
        let a = eval_builtin(BuiltinFn::Abs, &[ivec(&[i32::MIN, -3])], i2).unwrap();
        assert_eq!(
            a.components,
            vec![ConstScalar::Int(i32::MIN), ConstScalar::Int(3)]
        );
        // mix with a bool selector.
        let sel = ConstValue {
            ty: Type::vec(Scalar::Bool, 2),
            components: vec![ConstScalar::Bool(true), ConstScalar::Bool(false)],
        };
        let m = eval_builtin(
            BuiltinFn::Mix,
            &[vec(&[1.0, 2.0]), vec(&[3.0, 4.0]), sel],
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(floats_of(m), vec![3.0, 2.0]);
        // Bits, both ways; modf is not folded (it writes its argument).
        let bits = eval_builtin(BuiltinFn::FloatBitsToInt, &[vec(&[1.0])], Type::INT).unwrap();
        assert_eq!(bits.components, vec![ConstScalar::Int(0x3f80_0000)]);
        let back = eval_builtin(
            BuiltinFn::IntBitsToFloat,
            &[ivec(&[0x3f80_0000])],
            Type::FLOAT,
        );
        assert_eq!(floats_of(back), vec![1.0]);
        let sub = eval_builtin(BuiltinFn::IntBitsToFloat, &[ivec(&[1])], Type::FLOAT);
        assert_eq!(floats_of(sub), vec![0.0]);
        assert_eq!(
            eval_builtin(BuiltinFn::Modf, &[vec(&[1.5]), vec(&[0.0])], Type::FLOAT),
            None
        );
    }

    #[test]
    fn unsigned_min_max_clamp_compare_unsigned() {
        let u2 = Type::vec(Scalar::Uint, 2);
        let big = 0x8000_0000;
        let min = eval_builtin(BuiltinFn::Min, &[uvec(&[big, 3]), uvec(&[1, u32::MAX])], u2);
        assert_eq!(uints_of(min), vec![1, 3]);
        let max = eval_builtin(BuiltinFn::Max, &[uvec(&[big, 3]), uvec(&[1])], u2);
        assert_eq!(uints_of(max), vec![big, 3]);
        let c = eval_builtin(
            BuiltinFn::Clamp,
            &[uvec(&[u32::MAX, 0]), uvec(&[2]), uvec(&[big])],
            u2,
        );
        assert_eq!(uints_of(c), vec![big, 2]);
        // Scalar forms, and lo > hi giving hi as for ints.
        let c = eval_builtin(
            BuiltinFn::Clamp,
            &[uvec(&[5]), uvec(&[9]), uvec(&[4])],
            Type::UINT,
        );
        assert_eq!(uints_of(c), vec![4]);
        // No unsigned abs or sign: not an overload, not folded.
        assert_eq!(
            eval_builtin(BuiltinFn::Abs, &[uvec(&[1])], Type::UINT),
            None
        );
        // Mixed signedness is no overload either.
        assert_eq!(
            eval_builtin(BuiltinFn::Min, &[uvec(&[1, 2]), ivec(&[1])], u2),
            None
        );
    }

    #[test]
    fn unsigned_relational_functions() {
        let b3 = Type::vec(Scalar::Bool, 3);
        let x = uvec(&[0x8000_0000, 1, 7]);
        let y = uvec(&[1, 0xffff_ffff, 7]);
        let r = |f| bools_of(eval_builtin(f, &[x.clone(), y.clone()], b3));
        assert_eq!(r(BuiltinFn::LessThan), vec![false, true, false]);
        assert_eq!(r(BuiltinFn::LessThanEqual), vec![false, true, true]);
        assert_eq!(r(BuiltinFn::GreaterThan), vec![true, false, false]);
        assert_eq!(r(BuiltinFn::GreaterThanEqual), vec![true, false, true]);
        assert_eq!(r(BuiltinFn::Equal), vec![false, false, true]);
        assert_eq!(r(BuiltinFn::NotEqual), vec![true, true, false]);
        // The same bits as ivecs compare signed.
        let (xi, yi) = (ivec(&[i32::MIN, 1, 7]), ivec(&[1, -1, 7]));
        assert_eq!(
            bools_of(eval_builtin(BuiltinFn::LessThan, &[xi, yi], b3)),
            vec![true, false, false]
        );
    }

    #[test]
    fn unsigned_bit_casts() {
        let u2 = Type::vec(Scalar::Uint, 2);
        let v2 = Type::vec(Scalar::Float, 2);
        let bits = eval_builtin(BuiltinFn::FloatBitsToUint, &[vec(&[1.0, -2.0])], u2);
        assert_eq!(uints_of(bits), vec![0x3f80_0000, 0xc000_0000]);
        let back = eval_builtin(
            BuiltinFn::UintBitsToFloat,
            &[uvec(&[0x3f80_0000, 0xc000_0000])],
            v2,
        );
        assert_eq!(floats_of(back), vec![1.0, -2.0]);
        // Subnormal patterns are the zero of their sign.
        let to_bits = |v: Vec<f32>| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
        let sub = to_bits(floats_of(eval_builtin(
            BuiltinFn::UintBitsToFloat,
            &[uvec(&[1, 0x8000_0001])],
            v2,
        )));
        assert_eq!(sub, vec![0, 0x8000_0000]);
        // Infinities and NaN patterns keep their bits.
        let special = to_bits(floats_of(eval_builtin(
            BuiltinFn::UintBitsToFloat,
            &[uvec(&[0x7f80_0000, 0x7fc0_0001])],
            v2,
        )));
        assert_eq!(special, vec![0x7f80_0000, 0x7fc0_0001]);
        // Scalars, and an int argument is no overload.
        let one = eval_builtin(BuiltinFn::FloatBitsToUint, &[vec(&[0.5])], Type::UINT);
        assert_eq!(uints_of(one), vec![0x3f00_0000]);
        assert_eq!(
            eval_builtin(BuiltinFn::UintBitsToFloat, &[ivec(&[1])], Type::FLOAT),
            None
        );
    }

    #[test]
    fn determinant_and_inverse() {
        let m = ConstValue {
            ty: Type::mat(2, 2),
            components: [2.0, 0.0, 1.0, 4.0]
                .iter()
                .map(|&f| ConstScalar::Float(f))
                .collect(),
        };
        let d = eval_builtin(
            BuiltinFn::Determinant,
            std::slice::from_ref(&m),
            Type::FLOAT,
        );
        assert_eq!(floats_of(d), vec![8.0]);
        let i = eval_builtin(BuiltinFn::Inverse, &[m], Type::mat(2, 2));
        assert_eq!(floats_of(i), vec![0.5, 0.0, -0.125, 0.25]);
    }

    #[test]
    fn packing_functions() {
        let v2 = Type::vec(Scalar::Float, 2);
        let v4 = Type::vec(Scalar::Float, 4);
        let p = |f, v: &[f32]| uints_of(eval_builtin(f, &[vec(v)], Type::UINT))[0];
        assert_eq!(p(BuiltinFn::PackUnorm2x16, &[0.5, 1.0]), 0xffff_8000);
        assert_eq!(p(BuiltinFn::PackSnorm2x16, &[-1.0, f32::NAN]), 0x8001_8001);
        assert_eq!(
            p(BuiltinFn::PackUnorm4x8, &[0.0, 0.2, 2.0, f32::NAN]),
            0x00ff_3300
        );
        assert_eq!(
            p(BuiltinFn::PackSnorm4x8, &[-0.5, 0.5, -0.0, 1.0]),
            0x7f00_40c0
        );
        assert_eq!(
            p(BuiltinFn::PackHalf2x16, &[f32::NEG_INFINITY, -0.0]),
            0x8000_fc00
        );
        let u = |f, w: u32, ty| floats_of(eval_builtin(f, &[uvec(&[w])], ty));
        assert_eq!(
            u(BuiltinFn::UnpackUnorm2x16, 0xffff_0000, v2),
            vec![0.0, 1.0]
        );
        assert_eq!(
            u(BuiltinFn::UnpackSnorm2x16, 0x8000_7fff, v2),
            vec![1.0, -1.0]
        );
        assert_eq!(
            u(BuiltinFn::UnpackUnorm4x8, 0x3300_ff00, v4),
            vec![0.0, 1.0, 0.0, 0.2]
        );
        assert_eq!(
            u(BuiltinFn::UnpackSnorm4x8, 0x8081_7f00, v4),
            vec![0.0, 1.0, -1.0, -1.0]
        );
        assert_eq!(
            u(BuiltinFn::UnpackHalf2x16, 0x7c00_bc00, v2),
            vec![-1.0, f32::INFINITY]
        );
        // A vec2 is no argument of the 4x8 forms.
        assert_eq!(
            eval_builtin(BuiltinFn::PackUnorm4x8, &[vec(&[0.0, 1.0])], Type::UINT),
            None
        );
    }
}
