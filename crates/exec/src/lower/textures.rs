//! Texture lookups: the `texture*`/`shadow*` built-ins lowered to one
//! texture op with its coordinates, projection, bias or explicit LOD, the
//! per-lane requests made by the executor's texture callback.

use super::{unsupported, Lowerer, Val, R};
use crate::program::{Op, Reg, TexKind, TexLod, TexOp};
use glsl::builtins::BuiltinFn;
use glsl::ir::{Expr, Stage};
use glsl::types::{Base, SamplerDim};

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
            | B::Texture2DRect
            | B::Texture2DRectProj
            | B::Shadow2DRect
            | B::Shadow2DRectProj
            | B::Texture1DArray
            | B::Texture1DArrayLod
            | B::Texture2DArray
            | B::Texture2DArrayLod
            | B::Shadow1DArray
            | B::Shadow1DArrayLod
            | B::Shadow2DArray
            | B::Texture1DGradARB
            | B::Texture1DProjGradARB
            | B::Texture2DGradARB
            | B::Texture2DProjGradARB
            | B::Texture3DGradARB
            | B::Texture3DProjGradARB
            | B::TextureCubeGradARB
            | B::Shadow1DGradARB
            | B::Shadow1DProjGradARB
            | B::Shadow2DGradARB
            | B::Shadow2DProjGradARB
            | B::Texture2DRectGradARB
            | B::Texture2DRectProjGradARB
            | B::Shadow2DRectGradARB
            | B::Shadow2DRectProjGradARB
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
        let Some(&unit) = v.first().and_then(|u| u.first()) else {
            return unsupported("texture lookup without a sampler");
        };
        // The coordinates a lookup's derivatives are taken of, and
        // whether an array layer follows them.
        let dims = match target.dim() {
            SamplerDim::D1 | SamplerDim::Buffer => 1usize,
            SamplerDim::D2 | SamplerDim::Rect => 2,
            SamplerDim::D3 | SamplerDim::Cube => 3,
            SamplerDim::Ms => {
                return unsupported(format!(
                    "lookups on `{}' samplers are not implemented by the pipeline yet",
                    target.name()
                ))
            }
        };
        let layered = target.is_array();
        let shadow = target.is_shadow();
        let arg = |k: usize| v.get(k).cloned();
        let one_reg = |k: usize| v.get(k).and_then(|x| x.first()).copied();
        let index = self.p.textures.len() as u32;
        // Levels: every target but rectangles and buffers has them.
        let has_levels = !matches!(target.dim(), SamplerDim::Rect | SamplerDim::Buffer);
        if f == B::TextureSize {
            let lod = if has_levels { one_reg(1) } else { None };
            let d = self.temps(4)?;
            let zero_i = self.konst(0)?;
            self.p.textures.push(TexOp {
                kind: TexKind::Size,
                target,
                unit,
                coord: [zero_i; 4],
                dims: dims as u8,
                compare: None,
                lod: TexLod::Explicit(lod),
                offset: None,
                compare_only: false,
                d: d[0],
            });
            self.emit(Op::Texture { index })?;
            let n =
                dims.min(2) + usize::from(layered) + usize::from(target.dim() == SamplerDim::D3);
            return Ok(d[..n].to_vec());
        }
        let Some(coord) = arg(1) else {
            return unsupported("texture lookup without coordinates");
        };
        // Unused offset components are 0.
        let offset3 = |s: &mut Self, o: Option<Val>| -> R<Option<[Reg; 3]>> {
            let Some(o) = o else { return Ok(None) };
            let zero_i = s.konst(0)?;
            let mut r = [zero_i; 3];
            for (slot, &x) in r.iter_mut().zip(&o) {
                *slot = x;
            }
            Ok(Some(r))
        };
        if matches!(f, B::TexelFetch | B::TexelFetchOffset) {
            if shadow {
                return unsupported("texelFetch on a shadow sampler");
            }
            let (lod, off) = if has_levels {
                (
                    one_reg(2),
                    if f == B::TexelFetchOffset {
                        arg(3)
                    } else {
                        None
                    },
                )
            } else {
                (
                    None,
                    if f == B::TexelFetchOffset {
                        arg(2)
                    } else {
                        None
                    },
                )
            };
            let d = self.temps(4)?;
            let zero_i = self.konst(0)?;
            let mut c = [zero_i; 4];
            for (slot, &x) in c.iter_mut().zip(&coord) {
                *slot = x;
            }
            let offset = offset3(self, off)?;
            self.p.textures.push(TexOp {
                kind: TexKind::Fetch,
                target,
                unit,
                coord: c,
                dims: dims as u8,
                compare: None,
                lod: TexLod::Explicit(lod),
                offset,
                compare_only: false,
                d: d[0],
            });
            self.emit(Op::Texture { index })?;
            return Ok(d);
        }
        if target.dim() == SamplerDim::Buffer {
            return unsupported("buffer textures have texelFetch and textureSize only");
        }
        let proj = matches!(
            f,
            B::TextureProj
                | B::TextureProjLod
                | B::TextureProjOffset
                | B::TextureProjLodOffset
                | B::TextureProjGrad
                | B::TextureProjGradOffset
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
                | B::Texture2DRectProj
                | B::Shadow2DRectProj
                | B::Texture1DProjGradARB
                | B::Texture2DProjGradARB
                | B::Texture3DProjGradARB
                | B::Shadow1DProjGradARB
                | B::Shadow2DProjGradARB
                | B::Texture2DRectProjGradARB
                | B::Shadow2DRectProjGradARB
        );
        let explicit = matches!(
            f,
            B::TextureLod
                | B::TextureProjLod
                | B::TextureLodOffset
                | B::TextureProjLodOffset
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
                | B::Texture1DArrayLod
                | B::Texture2DArrayLod
                | B::Shadow1DArrayLod
        );
        let grad = matches!(
            f,
            B::TextureGrad | B::TextureGradOffset | B::TextureProjGrad | B::TextureProjGradOffset
        ) || f.name().ends_with("GradARB");
        // The arguments after the coordinates: (lod or bias, offset), or
        // the derivatives and an offset.
        let (extra, off, grads) = match f {
            B::TextureOffset | B::TextureProjOffset => (one_reg(3), arg(2), None),
            B::TextureLodOffset | B::TextureProjLodOffset => (one_reg(2), arg(3), None),
            B::TextureGrad | B::TextureProjGrad => (None, None, Some((arg(2), arg(3)))),
            _ if grad => (None, None, Some((arg(2), arg(3)))),
            B::TextureGradOffset | B::TextureProjGradOffset => {
                (None, arg(4), Some((arg(2), arg(3))))
            }
            _ => (one_reg(2), None, None),
        };
        // Shadow lookups compare against the coordinate after the
        // target's and the layer (r of 1D and 2D, q of cube maps and 2D
        // arrays: GLSL 1.30 §8.7), divided by q in the Proj forms; a cube
        // map array's, which has no room for it, is the argument after
        // the coordinates (GL_ARB_texture_cube_map_array).
        let compare_arg = shadow && dims + usize::from(layered) == 4;
        let (extra, compare_arg) = if compare_arg {
            (None, one_reg(2))
        } else {
            (extra, None)
        };
        let compare_at =
            (shadow && compare_arg.is_none()).then_some((dims + usize::from(layered)).max(2));
        let need = compare_at.map_or(dims + usize::from(layered), |c| c + 1);
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
        if layered {
            c[dims] = coord[dims];
        }
        let compare = match compare_at {
            Some(i) => Some(div(self, coord[i])?),
            None => compare_arg,
        };
        let lod = if grad {
            let Some((Some(dx), Some(dy))) = grads else {
                return unsupported("textureGrad without derivatives");
            };
            let mut ddx = [zero; 3];
            let mut ddy = [zero; 3];
            for k in 0..dims {
                ddx[k] = dx.get(k).copied().unwrap_or(zero);
                ddy[k] = dy.get(k).copied().unwrap_or(zero);
            }
            TexLod::Grad { ddx, ddy }
        } else if explicit {
            TexLod::Explicit(extra)
        } else if self.stage == Stage::Fragment {
            TexLod::Implicit { bias: extra }
        } else {
            TexLod::Explicit(extra)
        };
        let offset = offset3(self, off)?;
        // The lookups of 1.30 and later return the comparison alone from a
        // shadow sampler (`float`), the older ones a `vec4`.
        let compare_only = shadow && !f.name().starts_with("shadow");
        let d = self.temps(4)?;
        let index = self.p.textures.len() as u32;
        self.p.textures.push(TexOp {
            kind: TexKind::Sample,
            target,
            unit,
            coord: c,
            dims: dims as u8,
            compare,
            lod,
            offset,
            compare_only,
            d: d[0],
        });
        self.emit(Op::Texture { index })?;
        if compare_only {
            return Ok(vec![d[0]]);
        }
        Ok(d)
    }
}
