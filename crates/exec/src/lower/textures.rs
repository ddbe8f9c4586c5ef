//! Texture lookups: the `texture*`/`shadow*` built-ins lowered to one
//! texture op with its coordinates, projection, bias or explicit LOD, the
//! per-lane requests made by the executor's texture callback.

use super::{unsupported, Lowerer, Val, R};
use crate::program::{Op, Reg, TexLod, TexOp};
use glsl::builtins::BuiltinFn;
use glsl::ir::{Expr, Stage};
use glsl::types::{Base, SamplerKind};

pub(super) fn is_texture(f: BuiltinFn) -> bool {
    use BuiltinFn as B;
    matches!(
        f,
        B::Texture1D
            | B::Texture1DProj
            | B::Texture1DLod
            | B::Texture1DProjLod
            | B::Texture2D
            | B::Texture2DProj
            | B::Texture2DLod
            | B::Texture2DProjLod
            | B::Texture3D
            | B::Texture3DProj
            | B::Texture3DLod
            | B::Texture3DProjLod
            | B::TextureCube
            | B::TextureCubeLod
            | B::Shadow1D
            | B::Shadow2D
            | B::Shadow1DProj
            | B::Shadow2DProj
            | B::Shadow1DLod
            | B::Shadow2DLod
            | B::Shadow1DProjLod
            | B::Shadow2DProjLod
            | B::TextureSize
            | B::Texture
            | B::TextureProj
            | B::TextureLod
            | B::TextureOffset
            | B::TexelFetch
            | B::TexelFetchOffset
            | B::TextureProjOffset
            | B::TextureLodOffset
            | B::TextureProjLod
            | B::TextureProjLodOffset
            | B::TextureGrad
            | B::TextureGradOffset
            | B::TextureProjGrad
            | B::TextureProjGradOffset
    )
}

impl<'m> Lowerer<'m> {
    pub(super) fn texture(&mut self, f: BuiltinFn, args: &[Expr]) -> R<Val> {
        use BuiltinFn as B;
        let refs: Vec<&Expr> = args.iter().collect();
        let v = self.operands(&refs)?;
        let Some(Base::Sampler(target)) = args.first().map(|a| a.ty.base) else {
            return unsupported("texture lookup without a sampler");
        };
        let (Some(&unit), Some(coord)) = (v.first().and_then(|u| u.first()), v.get(1)) else {
            return unsupported("texture lookup without coordinates");
        };
        let coord = coord.clone();
        let extra = v.get(2).and_then(|x| x.first()).copied();
        // The lookups of GLSL 1.30 the texture op has no form for yet.
        if matches!(
            f,
            B::TextureSize
                | B::TextureOffset
                | B::TexelFetch
                | B::TexelFetchOffset
                | B::TextureProjOffset
                | B::TextureLodOffset
                | B::TextureProjLodOffset
                | B::TextureGrad
                | B::TextureGradOffset
                | B::TextureProjGrad
                | B::TextureProjGradOffset
        ) {
            return unsupported(format!(
                "`{}' is not implemented by the pipeline yet",
                f.name()
            ));
        }
        let proj = matches!(
            f,
            B::TextureProj
                | B::TextureProjLod
                | B::Texture1DProj
                | B::Texture1DProjLod
                | B::Texture2DProj
                | B::Texture2DProjLod
                | B::Texture3DProj
                | B::Texture3DProjLod
                | B::Shadow1DProj
                | B::Shadow2DProj
                | B::Shadow1DProjLod
                | B::Shadow2DProjLod
        );
        let explicit = matches!(
            f,
            B::TextureLod
                | B::TextureProjLod
                | B::Texture1DLod
                | B::Texture1DProjLod
                | B::Texture2DLod
                | B::Texture2DProjLod
                | B::Texture3DLod
                | B::Texture3DProjLod
                | B::TextureCubeLod
                | B::Shadow1DLod
                | B::Shadow2DLod
                | B::Shadow1DProjLod
                | B::Shadow2DProjLod
        );
        let (dims, shadow) = match target {
            SamplerKind::Sampler1D => (1usize, false),
            SamplerKind::Sampler2D => (2, false),
            SamplerKind::Sampler3D | SamplerKind::SamplerCube => (3, false),
            SamplerKind::Sampler1DShadow => (1, true),
            SamplerKind::Sampler2DShadow => (2, true),
            // Arrays, rectangles, buffers, multisample, cube shadows and
            // integer results: the texture units have no such targets.
            other => {
                return unsupported(format!(
                    "lookups on `{}' samplers are not implemented by the pipeline yet",
                    other.name()
                ))
            }
        };
        let need = if shadow { 3 } else { dims };
        if coord.len() < need || (proj && coord.len() < need + 1) {
            return unsupported("texture coordinates too short");
        }
        let q = if proj { coord.last().copied() } else { None };
        let div = |s: &mut Self, c: Reg| -> R<Reg> {
            match q {
                Some(q) => s.fbin(|d, a, b| Op::FDiv { d, a, b }, c, q),
                None => Ok(c),
            }
        };
        let zero = self.fconst(0.0)?;
        let one = self.fconst(1.0)?;
        let mut c = [zero, zero, zero, one];
        for (k, slot) in c.iter_mut().enumerate().take(dims) {
            *slot = div(self, coord[k])?;
        }
        // Shadow lookups compare against the third coordinate (r), divided
        // by q in the Proj forms (GLSL 1.20 §8.7).
        let compare = if shadow {
            Some(div(self, coord[2])?)
        } else {
            None
        };
        let lod = if explicit {
            TexLod::Explicit(extra)
        } else if self.stage == Stage::Fragment {
            TexLod::Implicit { bias: extra }
        } else {
            TexLod::Explicit(extra)
        };
        let d = self.temps(4)?;
        let index = self.p.textures.len() as u32;
        self.p.textures.push(TexOp {
            target,
            unit,
            coord: c,
            dims: dims as u8,
            compare,
            lod,
            d: d[0],
        });
        self.emit(Op::Texture { index })?;
        // The lookups of 1.30 and later return the comparison alone from a
        // shadow sampler (`float`), the older ones a `vec4`.
        if shadow && !f.name().starts_with("shadow") {
            return Ok(vec![d[0]]);
        }
        Ok(d)
    }
}
