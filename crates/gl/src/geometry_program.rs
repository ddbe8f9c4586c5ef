//! The geometry stage of program objects: which contexts have geometry
//! shaders, the program parameters of GL_EXT_geometry_shader4 and
//! GL_ARB_geometry_shader4 (glProgramParameteriEXT), the geometry
//! queries of glGetProgramiv, and whether a draw's mode feeds the
//! current geometry stage.
//!
//! Contract: GL 3.2 and later contexts create GL_GEOMETRY_SHADER objects
//! of GLSL 1.50; compatibility contexts (2.1 included) also advertise
//! the two extensions, whose shaders (GLSL 1.10-1.40 with `#extension`)
//! take the input type, output type and vertex count from the program's
//! parameters at link time (GLSL 1.50 shaders declare them and ignore
//! the parameters). glGetProgramiv's GL_GEOMETRY_*_EXT names return the
//! parameters as set (glProgramParameteri also takes GL 3.2's names for
//! them); GL 3.2's GL_GEOMETRY_* names the linked stage's
//! layouts (GL_INVALID_OPERATION without one, GL 3.3 §6.1.16). A draw
//! whose mode the linked geometry stage does not take is
//! GL_INVALID_OPERATION (GL 3.3 §2.12.1).

use crate::enums::*;
use crate::Context;
use glsl::ir::{InputPrimitive, OutputPrimitive};
use glsl::Stage;

/// The GL enum of an input primitive.
fn input_enum(p: InputPrimitive) -> u32 {
    match p {
        InputPrimitive::Points => GL_POINTS,
        InputPrimitive::Lines => GL_LINES,
        InputPrimitive::LinesAdjacency => GL_LINES_ADJACENCY,
        InputPrimitive::Triangles => GL_TRIANGLES,
        InputPrimitive::TrianglesAdjacency => GL_TRIANGLES_ADJACENCY,
    }
}

/// The GL enum of an output primitive.
fn output_enum(p: OutputPrimitive) -> u32 {
    match p {
        OutputPrimitive::Points => GL_POINTS,
        OutputPrimitive::LineStrip => GL_LINE_STRIP,
        OutputPrimitive::TriangleStrip => GL_TRIANGLE_STRIP,
    }
}

impl Context {
    /// Whether this context creates geometry shaders: GL 3.2 and later,
    /// and every compatibility context (GL_ARB/EXT_geometry_shader4).
    pub fn has_geometry_shaders(&self) -> bool {
        self.api.at_least(3, 2) || self.api.compatibility()
    }

    /// glProgramParameteriEXT / glProgramParameteriARB (and the GL 4.1
    /// entry point glProgramParameteri for the same names): a geometry
    /// parameter, or GL_PROGRAM_SEPARABLE, for the program's next link.
    pub fn program_parameteri(&mut self, program: u32, pname: u32, value: i32) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        // GL_ARB_separate_shader_objects' parameter, on every context.
        if pname == GL_PROGRAM_SEPARABLE {
            if value != GL_TRUE as i32 && value != GL_FALSE as i32 {
                self.set_error(GL_INVALID_VALUE);
            } else if let Some(p) = self.programs.get_mut(&program) {
                p.separable = value != 0;
            }
            return;
        }
        // The geometry parameters: compatibility contexts only.
        if !self.api.compatibility() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(p) = self.programs.get(&program) else {
            return;
        };
        let mut g = p.geometry;
        // GL 3.2's names of the three parameters (query names there) are
        // taken for the extension's, as programs written against both
        // headers pass them (the seed lecture's does).
        let pname = match pname {
            GL_GEOMETRY_INPUT_TYPE => GL_GEOMETRY_INPUT_TYPE_EXT,
            GL_GEOMETRY_OUTPUT_TYPE => GL_GEOMETRY_OUTPUT_TYPE_EXT,
            GL_GEOMETRY_VERTICES_OUT => GL_GEOMETRY_VERTICES_OUT_EXT,
            other => other,
        };
        let ok = match pname {
            GL_GEOMETRY_INPUT_TYPE_EXT => {
                match InputPrimitive::ALL
                    .into_iter()
                    .find(|&i| input_enum(i) as i32 == value)
                {
                    Some(i) => {
                        g.input = i;
                        true
                    }
                    None => false,
                }
            }
            GL_GEOMETRY_OUTPUT_TYPE_EXT => {
                let o = [
                    OutputPrimitive::Points,
                    OutputPrimitive::LineStrip,
                    OutputPrimitive::TriangleStrip,
                ]
                .into_iter()
                .find(|&o| output_enum(o) as i32 == value);
                match o {
                    Some(o) => {
                        g.output = o;
                        true
                    }
                    None => false,
                }
            }
            GL_GEOMETRY_VERTICES_OUT_EXT => {
                let max = glsl::limits::MAX_GEOMETRY_OUTPUT_VERTICES as i32;
                if (0..=max).contains(&value) {
                    g.vertices_out = value as u32;
                    true
                } else {
                    false
                }
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        if !ok {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.geometry = g;
        }
    }

    /// glGetProgramiv's geometry names, `None` for the others: the EXT
    /// parameters as set, or GL 3.2's linked layouts (see the module
    /// docs).
    pub(crate) fn geometry_programiv(&mut self, program: u32, pname: u32) -> Option<i32> {
        if !self.has_geometry_shaders() {
            return None;
        }
        match pname {
            GL_GEOMETRY_VERTICES_OUT_EXT
            | GL_GEOMETRY_INPUT_TYPE_EXT
            | GL_GEOMETRY_OUTPUT_TYPE_EXT
                if self.api.compatibility() =>
            {
                let g = self.program_query(program, |p| p.geometry)?;
                Some(match pname {
                    GL_GEOMETRY_VERTICES_OUT_EXT => g.vertices_out as i32,
                    GL_GEOMETRY_INPUT_TYPE_EXT => input_enum(g.input) as i32,
                    _ => output_enum(g.output) as i32,
                })
            }
            GL_GEOMETRY_VERTICES_OUT | GL_GEOMETRY_INPUT_TYPE | GL_GEOMETRY_OUTPUT_TYPE
                if self.api.at_least(3, 2) =>
            {
                let layout = match self.linked_exe(program) {
                    Some(e) => e.program.stage(Stage::Geometry).map(|g| g.module.geometry),
                    None => return Some(0),
                };
                let Some(g) = layout else {
                    self.set_error(GL_INVALID_OPERATION);
                    return Some(0);
                };
                Some(match pname {
                    GL_GEOMETRY_VERTICES_OUT => g.max_vertices.unwrap_or(0) as i32,
                    GL_GEOMETRY_INPUT_TYPE => g.input.map_or(GL_TRIANGLES, input_enum) as i32,
                    _ => g.output.map_or(GL_TRIANGLE_STRIP, output_enum) as i32,
                })
            }
            _ => None,
        }
    }

    /// Whether the current program's geometry stage, if it has one,
    /// takes the primitives of `mode` (GL 3.3 §2.12.1, "Primitive Type
    /// Mismatches and Drawing Commands").
    pub(crate) fn geometry_takes(&self, mode: u32) -> bool {
        let Some(input) = self.current_geometry().map(|g| g.input) else {
            return true;
        };
        match input {
            Some(InputPrimitive::Points) => mode == GL_POINTS,
            Some(InputPrimitive::Lines) => {
                matches!(mode, GL_LINES | GL_LINE_STRIP | GL_LINE_LOOP)
            }
            Some(InputPrimitive::LinesAdjacency) => {
                matches!(mode, GL_LINES_ADJACENCY | GL_LINE_STRIP_ADJACENCY)
            }
            Some(InputPrimitive::Triangles) => {
                matches!(mode, GL_TRIANGLES | GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN)
            }
            Some(InputPrimitive::TrianglesAdjacency) => {
                matches!(mode, GL_TRIANGLES_ADJACENCY | GL_TRIANGLE_STRIP_ADJACENCY)
            }
            None => false,
        }
    }

    /// The primitive the current program's geometry stage emits, as the
    /// transform feedback mode that captures it (GL_POINTS, GL_LINES or
    /// GL_TRIANGLES), if it has a geometry stage.
    pub(crate) fn geometry_feedback_mode(&self) -> Option<u32> {
        let output = self.current_geometry()?.output?;
        Some(crate::transform_feedback::feedback_mode(output_enum(
            output,
        )))
    }

    /// The layouts of the current program's linked geometry stage, if it
    /// has one.
    fn current_geometry(&self) -> Option<glsl::ir::GeometryLayout> {
        self.stage_executable(Stage::Geometry)?
            .program
            .stage(Stage::Geometry)
            .map(|g| g.module.geometry)
    }
}
