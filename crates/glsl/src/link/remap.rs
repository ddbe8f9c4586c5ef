//! Moving one shader object's IR into the merged module of its stage: the
//! object's struct, global and function ids mapped onto the merged ones.

use crate::ir::{self, Block, ConstValue, Expr, ExprKind, FunctionId, GlobalId};
use crate::types::{Base, StructId, Type};

/// How one object's ids map into the merged module.
pub(super) struct Remap {
    pub(super) structs: Vec<StructId>,
    pub(super) globals: Vec<GlobalId>,
    pub(super) functions: Vec<FunctionId>,
}

pub(super) fn remap_type(ty: Type, map: &Remap) -> Type {
    match ty.base {
        Base::Struct(id) => Type {
            base: Base::Struct(map.structs.get(id.0 as usize).copied().unwrap_or(id)),
            ..ty
        },
        _ => ty,
    }
}

pub(super) fn remap_const(v: &mut ConstValue, map: &Remap) {
    v.ty = remap_type(v.ty, map);
}

pub(super) fn remap_expr(e: &mut Expr, map: &Remap) {
    e.ty = remap_type(e.ty, map);
    match &mut e.kind {
        ExprKind::Const(v) => remap_const(v, map),
        ExprKind::Global(g) => *g = map.globals.get(g.0 as usize).copied().unwrap_or(*g),
        ExprKind::Call { function, .. } => {
            *function = map
                .functions
                .get(function.0 as usize)
                .copied()
                .unwrap_or(*function)
        }
        _ => {}
    }
    e.for_each_child_mut(|c| remap_expr(c, map));
}

pub(super) fn remap_block(b: &mut Block, map: &Remap) {
    ir::for_each_block_expr_mut(b, &mut |e| remap_expr(e, map));
}
