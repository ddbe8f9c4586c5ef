//! Where a program's outputs go (GL 3.3 §3.9.2 "Shader Outputs"):
//! glBindFragDataLocation(Indexed) / glGetFragDataLocation /
//! glGetFragDataIndex, placing each user fragment output (`out`) on its
//! draw buffers, and its source-colour index, at link time.
//!
//! Contract: at link, every user fragment output gets a location and an
//! index (0, or 1 for the second source colour of dual-source blending) —
//! its `layout(location, index)`, else its glBindFragDataLocation(Indexed)
//! binding (bindings take effect at the next link; the shader's qualifier
//! wins), else index 0 and the lowest free run of locations, in
//! declaration order. An output whose location, or an array whose last
//! element, is past GL_MAX_DRAW_BUFFERS, an index-1 output past
//! GL_MAX_DUAL_SOURCE_DRAW_BUFFERS (1), or two outputs on the same
//! location and index, fail the link. The locations and indices are
//! written into the fragment module's globals, so the rasterizer's linkage
//! ([`raster`]'s fragment layout) places the outputs where
//! glGetFragDataLocation and glGetFragDataIndex say.

use crate::enums::*;
use crate::Context;
use glsl::ir::Storage;
use glsl::types::ArraySize;
use glsl::Stage;
use std::collections::BTreeMap;

/// GL_MAX_DUAL_SOURCE_DRAW_BUFFERS: the draw buffers that take a second
/// source colour (index 1).
pub const MAX_DUAL_SOURCE_DRAW_BUFFERS: usize = 1;

/// Places the user fragment outputs of `program` (see the module docs);
/// `bindings` maps a name to its bound (location, index). The error is
/// the link's message.
pub(crate) fn place_frag_outputs(
    program: &mut glsl::link::Program,
    bindings: &BTreeMap<String, (u32, u32)>,
) -> Result<(), String> {
    let Some(fs) = program
        .stages
        .iter_mut()
        .find(|s| s.stage == Stage::Fragment)
    else {
        return Ok(());
    };
    let max = crate::MAX_DRAW_BUFFERS;
    // Locations taken, per index.
    let mut used = [vec![false; max], vec![false; max]];
    let len = |ty: glsl::types::Type| match ty.array {
        Some(ArraySize::Sized(n)) => n as usize,
        _ => 1,
    };
    let outputs: Vec<usize> = (0..fs.module.globals.len())
        .filter(|&i| {
            let g = &fs.module.globals[i];
            g.storage == Storage::FragOutput && !g.builtin
        })
        .collect();
    // Explicit locations and bindings first, then the rest.
    for pass in 0..2 {
        for &i in &outputs {
            let g = &mut fs.module.globals[i];
            let n = len(g.ty);
            let wanted = match g.location {
                Some(l) => Some((l, g.index.unwrap_or(0))),
                None => bindings.get(&g.name).copied(),
            };
            let (start, index) = match (pass, wanted) {
                (0, Some((l, index))) => (l as usize, index.min(1) as usize),
                (1, None) => (
                    (0..=max.saturating_sub(n))
                        .find(|&s| used[0][s..s + n].iter().all(|u| !u))
                        .ok_or_else(|| {
                            format!("no room among the draw buffers for `{}'", g.name)
                        })?,
                    0,
                ),
                _ => continue,
            };
            let limit = if index == 1 {
                MAX_DUAL_SOURCE_DRAW_BUFFERS
            } else {
                max
            };
            if start + n > limit {
                return Err(if index == 1 {
                    format!(
                        "fragment output `{}' at location {start}, index 1 does not fit: {limit} draw buffer takes a second source colour",
                        g.name
                    )
                } else {
                    format!(
                        "fragment output `{}' at location {start} does not fit: there are {max} draw buffers",
                        g.name
                    )
                });
            }
            let used = &mut used[index];
            if used[start..start + n].iter().any(|&u| u) {
                return Err(format!(
                    "fragment output `{}' overlaps another at location {start}",
                    g.name
                ));
            }
            used[start..start + n].iter_mut().for_each(|u| *u = true);
            g.location = Some(start as u32);
            g.index = Some(index as u32);
        }
    }
    Ok(())
}

impl Context {
    /// glBindFragDataLocation: `name` goes to draw buffer `color` from
    /// the next link on. GL_INVALID_VALUE for `color` ≥
    /// GL_MAX_DRAW_BUFFERS; GL_INVALID_OPERATION for a `gl_` name.
    pub fn bind_frag_data_location(&mut self, program: u32, color: u32, name: &str) {
        self.bind_frag_data_location_indexed(program, color, 0, name);
    }

    /// glBindFragDataLocationIndexed: `name` goes to source colour
    /// `index` of draw buffer `color` from the next link on.
    /// GL_INVALID_VALUE for `index` > 1, for `color` ≥ GL_MAX_DRAW_BUFFERS
    /// (index 0) or ≥ GL_MAX_DUAL_SOURCE_DRAW_BUFFERS (index 1);
    /// GL_INVALID_OPERATION for a `gl_` name.
    pub fn bind_frag_data_location_indexed(
        &mut self,
        program: u32,
        color: u32,
        index: u32,
        name: &str,
    ) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        let limit = if index == 1 {
            MAX_DUAL_SOURCE_DRAW_BUFFERS
        } else {
            crate::MAX_DRAW_BUFFERS
        };
        if index > 1 || color as usize >= limit {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if name.starts_with("gl_") {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.frag_bindings.insert(name.to_string(), (color, index));
        }
    }

    /// glGetFragDataIndex: the source-colour index of user output `name`
    /// (or of element `name[i]`) in the linked program; -1 for a name
    /// that is no user output. GL_INVALID_OPERATION for a program not
    /// linked.
    pub fn get_frag_data_index(&mut self, program: u32, name: &str) -> i32 {
        match self.frag_output(program, name) {
            Some((_, index)) => index as i32,
            None => -1,
        }
    }

    /// glGetFragDataLocation: the draw buffer of user output `name` (or
    /// of element `name[i]`) in the linked program; -1 for a name that is
    /// no user output. GL_INVALID_OPERATION for a program not linked.
    pub fn get_frag_data_location(&mut self, program: u32, name: &str) -> i32 {
        match self.frag_output(program, name) {
            Some((location, _)) => location as i32,
            None => -1,
        }
    }

    /// The (location, index) of user fragment output `name` (or element
    /// `name[i]`) of linked program `program`; GL_INVALID_OPERATION when
    /// it is not linked.
    fn frag_output(&mut self, program: u32, name: &str) -> Option<(u32, u32)> {
        let exe = self.linked_exe(program)?;
        let fs = exe.program.stage(Stage::Fragment)?;
        let (base, element) = match name
            .trim_end()
            .strip_suffix(']')
            .and_then(|n| n.split_once('['))
        {
            Some((b, i)) => (b.trim_end(), Some(i.trim().parse::<u32>().ok()?)),
            None => (name, None),
        };
        let g = fs
            .module
            .globals
            .iter()
            .find(|g| g.storage == Storage::FragOutput && !g.builtin && g.name == base)?;
        let loc = g.location?;
        let index = g.index.unwrap_or(0);
        match (element, g.ty.array) {
            (None, _) => Some((loc, index)),
            (Some(i), Some(ArraySize::Sized(n))) if i < n => Some((loc + i, index)),
            _ => None,
        }
    }
}
