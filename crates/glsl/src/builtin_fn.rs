//! The names of the built-in functions (GLSL 1.10 to 3.30 §8): the IR calls them
//! by [`BuiltinFn`], and [`crate::builtins`] declares, types and folds them.
//! Overloads of one name share a variant; the argument types in the IR tell
//! them apart (`atan(y)` / `atan(y, x)`, `texture2D(s, p)` /
//! `texture2D(s, p, bias)`). Its own module so that the IR depends on the
//! names alone, not on the tables that depend on the IR.

macro_rules! builtin_fns {
    ($($variant:ident = $name:literal;)*) => {
        /// A built-in function (GLSL 1.10 to 3.30 §8).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
        pub enum BuiltinFn { $($variant),* }

        impl BuiltinFn {
            pub const ALL: &'static [BuiltinFn] = &[$(BuiltinFn::$variant),*];

            pub fn name(self) -> &'static str {
                match self { $(BuiltinFn::$variant => $name),* }
            }

            pub fn from_name(name: &str) -> Option<BuiltinFn> {
                match name { $($name => Some(BuiltinFn::$variant),)* _ => None }
            }
        }
    };
}

builtin_fns! {
    // §8.1 angle and trigonometry
    Radians = "radians";
    Degrees = "degrees";
    Sin = "sin";
    Cos = "cos";
    Tan = "tan";
    Asin = "asin";
    Acos = "acos";
    Atan = "atan";
    Sinh = "sinh";
    Cosh = "cosh";
    Tanh = "tanh";
    Asinh = "asinh";
    Acosh = "acosh";
    Atanh = "atanh";
    // §8.2 exponential
    Pow = "pow";
    Exp = "exp";
    Log = "log";
    Exp2 = "exp2";
    Log2 = "log2";
    Sqrt = "sqrt";
    InverseSqrt = "inversesqrt";
    // §8.3 common
    Abs = "abs";
    Sign = "sign";
    Floor = "floor";
    Trunc = "trunc";
    Round = "round";
    RoundEven = "roundEven";
    Ceil = "ceil";
    Fract = "fract";
    Mod = "mod";
    Modf = "modf";
    Min = "min";
    Max = "max";
    Clamp = "clamp";
    Mix = "mix";
    Step = "step";
    SmoothStep = "smoothstep";
    IsNan = "isnan";
    IsInf = "isinf";
    FloatBitsToInt = "floatBitsToInt";
    IntBitsToFloat = "intBitsToFloat";
    FloatBitsToUint = "floatBitsToUint";
    UintBitsToFloat = "uintBitsToFloat";
    // GL_ARB_shading_language_packing (GLSL 4.20 §8.4 in core).
    PackUnorm2x16 = "packUnorm2x16";
    PackSnorm2x16 = "packSnorm2x16";
    PackUnorm4x8 = "packUnorm4x8";
    PackSnorm4x8 = "packSnorm4x8";
    UnpackUnorm2x16 = "unpackUnorm2x16";
    UnpackSnorm2x16 = "unpackSnorm2x16";
    UnpackUnorm4x8 = "unpackUnorm4x8";
    UnpackSnorm4x8 = "unpackSnorm4x8";
    PackHalf2x16 = "packHalf2x16";
    UnpackHalf2x16 = "unpackHalf2x16";
    // §8.4 geometric
    Length = "length";
    Distance = "distance";
    Dot = "dot";
    Cross = "cross";
    Normalize = "normalize";
    Ftransform = "ftransform";
    FaceForward = "faceforward";
    Reflect = "reflect";
    Refract = "refract";
    // §8.5 matrix
    MatrixCompMult = "matrixCompMult";
    OuterProduct = "outerProduct";
    Transpose = "transpose";
    Determinant = "determinant";
    Inverse = "inverse";
    // §8.6 vector relational
    LessThan = "lessThan";
    LessThanEqual = "lessThanEqual";
    GreaterThan = "greaterThan";
    GreaterThanEqual = "greaterThanEqual";
    Equal = "equal";
    NotEqual = "notEqual";
    Any = "any";
    All = "all";
    Not = "not";
    // §8.7 texture lookup
    Texture1D = "texture1D";
    Texture1DProj = "texture1DProj";
    Texture1DLod = "texture1DLod";
    Texture1DProjLod = "texture1DProjLod";
    Texture2D = "texture2D";
    Texture2DProj = "texture2DProj";
    Texture2DLod = "texture2DLod";
    Texture2DProjLod = "texture2DProjLod";
    Texture3D = "texture3D";
    Texture3DProj = "texture3DProj";
    Texture3DLod = "texture3DLod";
    Texture3DProjLod = "texture3DProjLod";
    TextureCube = "textureCube";
    TextureCubeLod = "textureCubeLod";
    Shadow1D = "shadow1D";
    Shadow2D = "shadow2D";
    Shadow1DProj = "shadow1DProj";
    Shadow2DProj = "shadow2DProj";
    Shadow1DLod = "shadow1DLod";
    Shadow2DLod = "shadow2DLod";
    Shadow1DProjLod = "shadow1DProjLod";
    Shadow2DProjLod = "shadow2DProjLod";
    // GL_ARB_texture_rectangle's lookups (GLSL 1.40 has the sampler
    // types).
    Texture2DRect = "texture2DRect";
    Texture2DRectProj = "texture2DRectProj";
    Shadow2DRect = "shadow2DRect";
    Shadow2DRectProj = "shadow2DRectProj";
    // GL_EXT_texture_array's lookups.
    Texture1DArray = "texture1DArray";
    Texture1DArrayLod = "texture1DArrayLod";
    Texture2DArray = "texture2DArray";
    Texture2DArrayLod = "texture2DArrayLod";
    Shadow1DArray = "shadow1DArray";
    Shadow1DArrayLod = "shadow1DArrayLod";
    Shadow2DArray = "shadow2DArray";
    // GL_ARB_shader_texture_lod's lookups with explicit derivatives.
    Texture1DGradARB = "texture1DGradARB";
    Texture1DProjGradARB = "texture1DProjGradARB";
    Texture2DGradARB = "texture2DGradARB";
    Texture2DProjGradARB = "texture2DProjGradARB";
    Texture3DGradARB = "texture3DGradARB";
    Texture3DProjGradARB = "texture3DProjGradARB";
    TextureCubeGradARB = "textureCubeGradARB";
    Shadow1DGradARB = "shadow1DGradARB";
    Shadow1DProjGradARB = "shadow1DProjGradARB";
    Shadow2DGradARB = "shadow2DGradARB";
    Shadow2DProjGradARB = "shadow2DProjGradARB";
    Texture2DRectGradARB = "texture2DRectGradARB";
    Texture2DRectProjGradARB = "texture2DRectProjGradARB";
    Shadow2DRectGradARB = "shadow2DRectGradARB";
    Shadow2DRectProjGradARB = "shadow2DRectProjGradARB";
    // §8.7 (1.30 and later): one name per kind of lookup, the sampler
    // type telling the target apart.
    TextureSize = "textureSize";
    Texture = "texture";
    TextureProj = "textureProj";
    TextureLod = "textureLod";
    TextureOffset = "textureOffset";
    TexelFetch = "texelFetch";
    TexelFetchOffset = "texelFetchOffset";
    TextureProjOffset = "textureProjOffset";
    TextureLodOffset = "textureLodOffset";
    TextureProjLod = "textureProjLod";
    TextureProjLodOffset = "textureProjLodOffset";
    TextureGrad = "textureGrad";
    TextureGradOffset = "textureGradOffset";
    TextureProjGrad = "textureProjGrad";
    TextureProjGradOffset = "textureProjGradOffset";
    // §8.8 fragment processing
    DFdx = "dFdx";
    DFdy = "dFdy";
    Fwidth = "fwidth";
    // §8.9 noise
    Noise1 = "noise1";
    Noise2 = "noise2";
    Noise3 = "noise3";
    Noise4 = "noise4";
    // §8.10 geometry shader functions (1.50, GL_EXT_geometry_shader4)
    EmitVertex = "EmitVertex";
    EndPrimitive = "EndPrimitive";
    // GL_ARB_compute_shader (GLSL 4.30 §8.15, §8.16): barriers and the
    // atomic memory functions on `shared` variables.
    Barrier = "barrier";
    MemoryBarrier = "memoryBarrier";
    MemoryBarrierAtomicCounter = "memoryBarrierAtomicCounter";
    MemoryBarrierBuffer = "memoryBarrierBuffer";
    MemoryBarrierImage = "memoryBarrierImage";
    MemoryBarrierShared = "memoryBarrierShared";
    GroupMemoryBarrier = "groupMemoryBarrier";
    AtomicAdd = "atomicAdd";
    AtomicMin = "atomicMin";
    AtomicMax = "atomicMax";
    AtomicAnd = "atomicAnd";
    AtomicOr = "atomicOr";
    AtomicXor = "atomicXor";
    AtomicExchange = "atomicExchange";
    AtomicCompSwap = "atomicCompSwap";
}

impl BuiltinFn {
    /// The atomic memory functions, whose first argument is the memory
    /// they update.
    pub fn is_atomic(self) -> bool {
        use BuiltinFn as B;
        matches!(
            self,
            B::AtomicAdd
                | B::AtomicMin
                | B::AtomicMax
                | B::AtomicAnd
                | B::AtomicOr
                | B::AtomicXor
                | B::AtomicExchange
                | B::AtomicCompSwap
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for f in BuiltinFn::ALL {
            assert_eq!(BuiltinFn::from_name(f.name()), Some(*f));
        }
    }
}
