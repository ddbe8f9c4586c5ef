//! Where a program's outputs go (GL 3.3 §3.9.2 "Shader Outputs"):
//! glBindFragDataLocation / glGetFragDataLocation, placing each user
//! fragment output (`out`) on its draw buffers at link time.
//!
//! Contract: at link, every user fragment output gets a location — its
//! `layout(location)`, else its glBindFragDataLocation binding (bindings
//! take effect at the next link; the shader's qualifier wins), else the
//! lowest free run of locations, in declaration order. An output whose
//! location, or an array whose last element, is past
//! GL_MAX_DRAW_BUFFERS, or two outputs on the same location, fail the
//! link. The locations are written into the fragment module's globals, so
//! the rasterizer's linkage ([`raster`]'s fragment layout) places the
//! outputs where glGetFragDataLocation says.

use crate::enums::*;
use crate::Context;
use glsl::ir::Storage;
use glsl::types::ArraySize;
use glsl::Stage;
use std::collections::BTreeMap;

/// Places the user fragment outputs of `program` (see the module docs);
/// the error is the link's message.
pub(crate) fn place_frag_outputs(
    program: &mut glsl::link::Program,
    bindings: &BTreeMap<String, u32>,
) -> Result<(), String> {
    let Some(fs) = program
        .stages
        .iter_mut()
        .find(|s| s.stage == Stage::Fragment)
    else {
        return Ok(());
    };
    let max = crate::MAX_DRAW_BUFFERS;
    let mut used = vec![false; max];
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
            let wanted = g.location.or_else(|| bindings.get(&g.name).copied());
            let start = match (pass, wanted) {
                (0, Some(l)) => l as usize,
                (1, None) => (0..=max.saturating_sub(n))
                    .find(|&s| used[s..s + n].iter().all(|u| !u))
                    .ok_or_else(|| format!("no room among the draw buffers for `{}'", g.name))?,
                _ => continue,
            };
            if start + n > max {
                return Err(format!(
                    "fragment output `{}' at location {start} does not fit: there are {max} draw buffers",
                    g.name
                ));
            }
            if used[start..start + n].iter().any(|&u| u) {
                return Err(format!(
                    "fragment output `{}' overlaps another at location {start}",
                    g.name
                ));
            }
            used[start..start + n].iter_mut().for_each(|u| *u = true);
            g.location = Some(start as u32);
        }
    }
    Ok(())
}

impl Context {
    /// glBindFragDataLocation: `name` goes to draw buffer `color` from
    /// the next link on. GL_INVALID_VALUE for `color` ≥
    /// GL_MAX_DRAW_BUFFERS; GL_INVALID_OPERATION for a `gl_` name.
    pub fn bind_frag_data_location(&mut self, program: u32, color: u32, name: &str) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        if color as usize >= crate::MAX_DRAW_BUFFERS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if name.starts_with("gl_") {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.frag_bindings.insert(name.to_string(), color);
        }
    }

    /// glGetFragDataLocation: the draw buffer of user output `name` (or
    /// of element `name[i]`) in the linked program; -1 for a name that is
    /// no user output. GL_INVALID_OPERATION for a program not linked.
    pub fn get_frag_data_location(&mut self, program: u32, name: &str) -> i32 {
        let Some(exe) = self.linked_exe(program) else {
            return -1;
        };
        let Some(fs) = exe.program.stage(Stage::Fragment) else {
            return -1;
        };
        let (base, index) = match name
            .trim_end()
            .strip_suffix(']')
            .and_then(|n| n.split_once('['))
        {
            Some((b, i)) => match i.trim().parse::<u32>() {
                Ok(i) => (b.trim_end(), Some(i)),
                Err(_) => return -1,
            },
            None => (name, None),
        };
        let Some(g) = fs
            .module
            .globals
            .iter()
            .find(|g| g.storage == Storage::FragOutput && !g.builtin && g.name == base)
        else {
            return -1;
        };
        let Some(loc) = g.location else { return -1 };
        match (index, g.ty.array) {
            (None, _) => loc as i32,
            (Some(i), Some(ArraySize::Sized(n))) if i < n => (loc + i) as i32,
            _ => -1,
        }
    }
}
