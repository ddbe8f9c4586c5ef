//! # shaderbox-debugger: why a pixel is what it is
//!
//! Turns the pipeline's pixel probe ([`raster::probe_draw`], collected per
//! draw by [`gl::Context::set_debug`]) into a report a person reads or a
//! tool parses: for each draw that touched the pixel, each fragment in
//! order with its primitive (the vertices after the vertex shader with
//! every output; with a geometry stage, the vertices it emitted and the
//! input primitive whose invocation emitted them), its interpolated inputs, each statement its shader
//! executed with the source line and the values it stored (loop
//! iterations appear as repeated statements), `debugPrintfEXT` output,
//! `discard`, its outputs, and what the per-fragment operations did (alpha,
//! stencil and depth tests with the values compared, blending, the stored
//! result). With a geometry stage, each invocation that emitted a
//! fragment's primitive is traced too: its input primitive (number,
//! `gl_PrimitiveIDIn`, input vertices), inputs, statements and stores,
//! prints, and every vertex it emitted with its strip, those of the
//! fragments' primitives marked.
//!
//! [`Report::from_records`] builds the report (`build`); [`Report::text`]
//! renders it with source lines (`text`), [`Report::json`] as JSON.
//!
//! ## Limitations
//! - Statements of a stage with several shader objects are shown against
//!   the first object's text (spans do not name their object yet).
//! - Fixed-function stages are generated GLSL: their statements are listed
//!   without source text.
//! - Values of struct members and arrays are named by flat component
//!   (`v[+3]`) beyond the first level.

mod build;
mod text;

use build::draw_report;
use gl::debug::DrawRecord;
use glsl::types::Scalar;
use raster::PixelState;
use serde::Serialize;

/// The debugger's answer for one pixel.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub pixel: (u32, u32),
    pub draws: Vec<DrawReport>,
}

#[derive(Clone, Debug, Serialize)]
pub struct DrawReport {
    pub draw: usize,
    pub mode: String,
    pub count: usize,
    pub program: u32,
    pub framebuffer: u32,
    /// The layer replayed, in a draw whose geometry shader writes
    /// `gl_Layer` into a layered framebuffer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub layer: Option<i32>,
    /// Why no fragment could reach the pixel, or the error that stopped the
    /// draw (what it recorded before is still reported).
    pub note: Option<String>,
    pub fragments: Vec<FragmentReport>,
    /// `debugPrintfEXT` output of the print rectangle (other pixels).
    pub prints: Vec<PrintReport>,
    /// `debugPrintfEXT` output of the vertex shader, per vertex index.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub vertex_prints: Vec<VertexPrint>,
    /// `debugPrintfEXT` output of the geometry shader, per input
    /// primitive (every invocation when a print rectangle is asked for).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub geometry_prints: Vec<GeometryPrint>,
    /// The pixel after the draw.
    pub after: Option<PixelReport>,
    /// The traced vertex, when one was asked for.
    pub vertex: Option<VertexTrace>,
    /// With a geometry stage: the invocations that emitted the fragments'
    /// primitives, by input primitive.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub geometry: Vec<GeometryTrace>,
    /// Every primitive's window-space corners, when asked for.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub outlines: Vec<Vec<[f64; 2]>>,
}

/// One vertex shader invocation.
#[derive(Clone, Debug, Serialize)]
pub struct VertexTrace {
    pub position: usize,
    pub index: u32,
    pub inputs: Vec<Named>,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub outputs: Vec<Named>,
    pub error: Option<String>,
}

/// One geometry shader invocation: the one of input primitive
/// `primitive`.
#[derive(Clone, Debug, Serialize)]
pub struct GeometryTrace {
    pub primitive: u32,
    /// `gl_PrimitiveIDIn`.
    pub primitive_id: u32,
    /// Its input vertices: positions in the draw's vertex list, and the
    /// vertex indices there.
    pub vertices: Vec<usize>,
    pub indices: Vec<u32>,
    pub inputs: Vec<Named>,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub emitted: Vec<EmittedReport>,
    pub error: Option<String>,
}

/// A vertex a geometry shader invocation emitted.
#[derive(Clone, Debug, Serialize)]
pub struct EmittedReport {
    /// Its number among the invocation's emitted vertices (from 0).
    pub vertex: u32,
    pub strip: u32,
    pub outputs: Vec<Named>,
    /// The fragments (numbered from 1, as the text report counts them)
    /// whose primitive it is a vertex of.
    pub fragments: Vec<usize>,
}

#[derive(Clone, Debug, Serialize)]
pub struct VertexPrint {
    pub vertex: u32,
    pub line: Option<u32>,
    pub text: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct GeometryPrint {
    /// The input primitive whose invocation printed.
    pub primitive: u32,
    pub line: Option<u32>,
    pub text: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct PrintReport {
    pub x: u32,
    pub y: u32,
    pub primitive: u32,
    pub line: Option<u32>,
    pub text: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct FragmentReport {
    pub primitive: u32,
    /// With a geometry stage: the input primitive whose invocation
    /// emitted this primitive (`DrawReport::geometry`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub input_primitive: Option<u32>,
    pub facing: &'static str,
    /// The primitive's vertices: index position in the draw and the vertex
    /// shader's outputs (with a geometry stage: position in the list of
    /// emitted vertices and the geometry shader's outputs).
    pub vertices: Vec<VertexReport>,
    pub window_z: f64,
    pub inputs: Vec<Named>,
    pub early_rejected: bool,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub discarded: Option<Step>,
    pub error: Option<String>,
    pub outputs: Vec<Named>,
    pub operations: Option<OpsReport>,
}

#[derive(Clone, Debug, Serialize)]
pub struct VertexReport {
    pub position: usize,
    /// With a geometry stage: its number among the emitted vertices of
    /// its invocation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub emitted_vertex: Option<u32>,
    pub outputs: Vec<Named>,
}

/// A variable's value: `values` are numbers (floats, ints, bools as 0/1).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Named {
    pub name: String,
    pub values: Vec<Number>,
}

/// A value as its type says: float, int, uint or bool.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Number {
    Float(f32),
    Int(i32),
    Uint(u32),
    Bool(bool),
}

impl Number {
    fn from_bits(kind: Scalar, bits: u32) -> Number {
        match kind {
            Scalar::Float => Number::Float(f32::from_bits(bits)),
            Scalar::Int => Number::Int(bits as i32),
            Scalar::Uint => Number::Uint(bits),
            Scalar::Bool => Number::Bool(bits != 0),
        }
    }

    /// An interface component: integers carry their bits when
    /// `integer_bits` (every stage's inputs, the varyings a vertex shader
    /// outputs: `exec::Batch`), else their values as floats (fragment
    /// outputs).
    fn from_slot(kind: Scalar, v: f32, integer_bits: bool) -> Number {
        match kind {
            Scalar::Int if integer_bits => Number::Int(v.to_bits() as i32),
            Scalar::Uint if integer_bits => Number::Uint(v.to_bits()),
            _ => Number::from_f32(kind, v),
        }
    }

    fn from_f32(kind: Scalar, v: f32) -> Number {
        match kind {
            Scalar::Float => Number::Float(v),
            Scalar::Int => Number::Int(v as i32),
            Scalar::Uint => Number::Uint(v as u32),
            Scalar::Bool => Number::Bool(v != 0.0),
        }
    }
}

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Number::Float(v) if *v != 0.0 && (v.abs() < 1e-4 || v.abs() >= 1e7) => {
                write!(f, "{v:e}")
            }
            Number::Float(v) => write!(f, "{v}"),
            Number::Int(v) => write!(f, "{v}"),
            Number::Uint(v) => write!(f, "{v}u"),
            Number::Bool(v) => write!(f, "{v}"),
        }
    }
}

/// One executed statement and what it stored or printed.
#[derive(Clone, Debug, Serialize)]
pub struct Step {
    pub line: Option<u32>,
    pub column: Option<u32>,
    pub source: String,
    pub stores: Vec<Named>,
    pub prints: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct OpsReport {
    pub fragment_depth: f32,
    pub alpha_test: Option<bool>,
    pub stencil_test: Option<bool>,
    pub depth_test: Option<bool>,
    pub blended: bool,
    pub color_mask: [bool; 4],
    pub before: PixelReport,
    pub after: PixelReport,
    /// The fragment changed the pixel.
    pub written: bool,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelReport {
    pub color: Option<[f32; 4]>,
    pub color_bytes: Option<[u8; 4]>,
    pub depth: Option<f32>,
    pub stencil: Option<u8>,
}

impl PixelReport {
    fn new(p: &PixelState) -> PixelReport {
        PixelReport {
            color: p.colors.first().copied(),
            color_bytes: p.color_bytes.first().copied().flatten(),
            depth: p.depth.map(raster::fixed_to_depth),
            stencil: p.stencil,
        }
    }
}

impl Report {
    /// The report of the records of one debugging session (all for the
    /// same pixel).
    pub fn from_records(pixel: (u32, u32), records: &[DrawRecord]) -> Report {
        Report {
            pixel,
            draws: records.iter().map(draw_report).collect(),
        }
    }

    /// The report as JSON.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The report as text, source lines beside the values.
    pub fn text(&self) -> String {
        text::report(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gl::enums::*;

    /// A vertex shader's integer input is reported as the integer the
    /// attribute held (its bits), not as the float those bits make.
    #[test]
    fn integer_vertex_inputs_show_their_values() {
        let mut ctx = gl::Context::new(4, 4);
        let p = ctx.create_program();
        for (kind, src) in [
            (
                GL_VERTEX_SHADER,
                "#version 130\nin vec2 pos;\nin ivec2 code;\nflat out int k;\n\
                 void main() { gl_Position = vec4(pos, 0.0, 1.0); k = code.x; }",
            ),
            (
                GL_FRAGMENT_SHADER,
                "#version 130\nflat in int k;\nout vec4 c;\n\
                 void main() { c = vec4(k < 0 ? 1.0 : 0.0); }",
            ),
        ] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        ctx.use_program(p);
        let pos = ctx.get_attrib_location(p, "pos") as u32;
        let code = ctx.get_attrib_location(p, "code") as u32;
        let quad = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
        ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, gl::ArrayData::from_f32(&quad));
        ctx.enable_vertex_attrib_array(pos);
        ctx.vertex_attrib_i4i(code, [-123456789, 7, 0, 1]);
        let mut request = gl::debug::DebugRequest::pixel(1, 1);
        request.vertex = Some(0);
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        let records = ctx.take_debug_records();
        let report = Report::from_records((1, 1), &records);
        let text = report.text();
        assert!(text.contains("-123456789"), "{text}");
        // No geometry stage: none of its keys in the JSON.
        let json = report.json();
        for key in ["\"geometry\"", "input_primitive", "emitted_vertex"] {
            assert!(!json.contains(key), "{key} in {json}");
        }
    }

    /// A 3.3 compatibility context drawing with `gs` between a
    /// pass-through vertex stage and a constant fragment stage; `pos`
    /// holds the points given.
    fn geometry_context(gs: &str, points: &[f32]) -> gl::Context {
        let mut ctx = gl::Context::with_api(8, 8, gl::Api::GL33_COMPAT);
        let p = ctx.create_program();
        for (kind, src) in [
            (
                GL_VERTEX_SHADER,
                "#version 150\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }",
            ),
            (GL_GEOMETRY_SHADER, gs),
            (
                GL_FRAGMENT_SHADER,
                "#version 150\nout vec4 c;\nvoid main() { c = vec4(1.0); }",
            ),
        ] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            assert_eq!(ctx.get_shaderiv(s, GL_COMPILE_STATUS), 1, "{src}");
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 1);
        ctx.use_program(p);
        let pos = ctx.get_attrib_location(p, "pos") as u32;
        ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, gl::ArrayData::from_f32(points));
        ctx.enable_vertex_attrib_array(pos);
        ctx
    }

    /// The JSON report of a draw with a geometry stage names the input
    /// primitive of each fragment, the emitted number of each of its
    /// vertices, and the invocation with its per-vertex inputs one element
    /// at a time and its emitted vertices marked with the fragment.
    #[test]
    fn geometry_invocations_are_in_the_json_report() {
        let gs = "#version 150
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
void main() {
    for (int i = 0; i < 4; i++) {
        gl_Position = gl_in[0].gl_Position + vec4(vec2(i % 2, i / 2) * 0.5 - 0.25, 0.0, 0.0);
        EmitVertex();
    }
}";
        let mut ctx = geometry_context(gs, &[-0.5, -0.5, 0.5, 0.5]);
        let mut request = gl::debug::DebugRequest::pixel(6, 6);
        request.vertex = Some(1);
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_POINTS, 0, 2);
        let records = ctx.take_debug_records();
        let report = Report::from_records((6, 6), &records);
        let d = &report.draws[0];
        assert_eq!(d.fragments.len(), 1, "{}", report.text());
        let f = &d.fragments[0];
        assert_eq!(f.input_primitive, Some(1));
        assert!(f.vertices.iter().all(|v| v.emitted_vertex.is_some()));
        // The vertices are named by the geometry shader's outputs.
        assert!(f.vertices[0]
            .outputs
            .iter()
            .any(|o| o.name == "gl_Position"));
        assert_eq!(d.geometry.len(), 1);
        let g = &d.geometry[0];
        assert_eq!((g.primitive, g.primitive_id), (1, 1));
        assert_eq!((&g.vertices[..], &g.indices[..]), (&[1][..], &[1][..]));
        assert_eq!(g.inputs[0].name, "gl_in[0].gl_Position");
        assert_eq!(g.emitted.len(), 4);
        let marked = g.emitted.iter().filter(|e| e.fragments == [1]).count();
        assert_eq!(marked, 3);
        assert!(d.vertex.as_ref().is_some_and(|v| v.index == 1));
        let json = report.json();
        for key in ["\"geometry\"", "\"input_primitive\": 1", "emitted_vertex"] {
            assert!(json.contains(key), "no {key} in {json}");
        }
    }

    /// A geometry shader sending each triangle to the layer its primitive
    /// ID names, into a two-layer array texture: the debugger replays the
    /// layer asked for, with its primitives only, on its images, and says
    /// so; a layer the framebuffer lacks is named; the geometry shader's
    /// prints of every invocation come with a print rectangle.
    #[test]
    fn layered_draws_replay_the_requested_layer() {
        let gs = "#version 150
#extension GL_SHADERBOX_debug_printf : enable
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
    debugPrintfEXT(\"layer %d\\n\", gl_PrimitiveIDIn);
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        gl_Layer = gl_PrimitiveIDIn;
        EmitVertex();
    }
}";
        // Two triangles over the whole window: primitive 0 to layer 0,
        // primitive 1 to layer 1.
        let big = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
        let points: Vec<f32> = big.iter().chain(&big).copied().collect();
        let mut ctx = geometry_context(gs, &points);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D_ARRAY, t);
        let zeros = vec![0u8; 8 * 8 * 4 * 2];
        ctx.tex_image(
            GL_TEXTURE_2D_ARRAY,
            0,
            GL_RGBA8 as i32,
            [8, 8, 2],
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&zeros),
        );
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0);
        let mut request = gl::debug::DebugRequest::pixel(2, 2);
        request.view = Some("c".into());
        request.layer = 1;
        request.print_rect = Some((0, 0, 1, 1));
        ctx.set_debug(Some(request.clone()));
        ctx.draw_arrays(GL_TRIANGLES, 0, 6);
        let records = ctx.take_debug_records();
        let view = records[0].view.as_ref().unwrap().as_ref().unwrap();
        assert!(view.image.pixels[2 * 8 + 2].is_some());
        let report = Report::from_records((2, 2), &records);
        let text = report.text();
        let d = &report.draws[0];
        assert_eq!(d.layer, Some(1), "{text}");
        assert!(text.contains("at pixel (2, 2) of layer 1"), "{text}");
        // Only layer 1's triangle reaches the pixel: the second input
        // primitive's.
        assert_eq!(d.fragments.len(), 1, "{text}");
        assert_eq!(d.fragments[0].input_primitive, Some(1), "{text}");
        assert_eq!(d.after.as_ref().and_then(|a| a.color_bytes), Some([255; 4]));
        // Both invocations printed.
        let printed: Vec<u32> = d.geometry_prints.iter().map(|p| p.primitive).collect();
        assert_eq!(printed, [0, 1], "{text}");
        assert!(
            text.contains("printf geometry, input primitive 0 line 6: layer 0"),
            "{text}"
        );
        // A layer the framebuffer does not have.
        request.layer = 5;
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_TRIANGLES, 0, 6);
        let records = ctx.take_debug_records();
        assert!(matches!(&records[0].view, Some(Err(e)) if e.contains("no layer 5")));
        let report = Report::from_records((2, 2), &records);
        let text = report.text();
        assert!(report.draws[0].fragments.is_empty(), "{text}");
        assert!(text.contains("has 2 layers: there is no layer 5"), "{text}");
    }
}
