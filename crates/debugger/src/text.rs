//! The report as text: each draw, its fragments with their statements
//! beside the source lines, the geometry invocations and vertex traces,
//! prints, the per-fragment operations and the pixel after the draw.

use crate::*;
use std::fmt::Write;

/// [`Report::text`].
pub(crate) fn report(r: &Report) -> String {
    let mut s = String::new();
    let (x, y) = r.pixel;
    if r.draws.is_empty() {
        let _ = writeln!(s, "pixel ({x}, {y}): no draw was debugged");
    }
    for d in &r.draws {
        let layer = d.layer.map_or(String::new(), |l| format!(" of layer {l}"));
        let _ = writeln!(
            s,
            "draw {} ({}, {} indices, program {}, framebuffer {}) at pixel ({x}, {y}){layer}: {} fragment{}",
            d.draw,
            d.mode,
            d.count,
            d.program,
            d.framebuffer,
            d.fragments.len(),
            if d.fragments.len() == 1 { "" } else { "s" }
        );
        if let Some(n) = &d.note {
            let _ = writeln!(s, "  {n}");
        }
        for (i, f) in d.fragments.iter().enumerate() {
            write_fragment(&mut s, i + 1, f);
        }
        for g in &d.geometry {
            write_geometry(&mut s, g);
        }
        for p in &d.vertex_prints {
            write_print(&mut s, &format!("vertex {}", p.vertex), p.line, &p.text);
        }
        for p in &d.geometry_prints {
            let from = format!("geometry, input primitive {}", p.primitive);
            write_print(&mut s, &from, p.line, &p.text);
        }
        for p in &d.prints {
            let from = format!("({}, {}) primitive {}", p.x, p.y, p.primitive);
            write_print(&mut s, &from, p.line, &p.text);
        }
        if let Some(v) = &d.vertex {
            write_vertex(&mut s, v);
        }
        if let Some(a) = &d.after {
            let _ = writeln!(s, "  pixel after the draw: {}", pixel_text(a));
        }
    }
    s
}

/// One `debugPrintfEXT` line of the print rectangle: where it came from
/// (`from`), its source line and its text.
fn write_print(s: &mut String, from: &str, line: Option<u32>, text: &str) {
    let line = line.map_or(String::new(), |l| format!(" line {l}"));
    let _ = writeln!(s, "  printf {from}{line}: {}", text.trim_end());
}

fn values_text(v: &[Number]) -> String {
    match v {
        [one] => one.to_string(),
        many => format!(
            "({})",
            many.iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

fn pixel_text(p: &PixelReport) -> String {
    let mut parts = Vec::new();
    if let Some(b) = p.color_bytes {
        parts.push(format!("colour ({}, {}, {}, {})", b[0], b[1], b[2], b[3]));
    } else if let Some(c) = p.color {
        parts.push(format!("colour ({}, {}, {}, {})", c[0], c[1], c[2], c[3]));
    }
    if let Some(d) = p.depth {
        parts.push(format!("depth {d}"));
    }
    if let Some(st) = p.stencil {
        parts.push(format!("stencil {st}"));
    }
    parts.join(", ")
}

/// Executed statements, source beside the values they stored.
fn write_truncated(s: &mut String, truncated: bool) {
    if truncated {
        let _ = writeln!(
            s,
            "    trace truncated: the draw recorded its limit of {} statements, stores and prints; the shader ran on",
            raster::MAX_TRACE_EVENTS
        );
    }
}

fn write_steps(s: &mut String, steps: &[Step]) {
    for st in steps {
        let at = st.line.map_or("     ".to_string(), |l| format!("{l:>4} |"));
        let stores: Vec<String> = st
            .stores
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let mut line = format!("    {at} {}", st.source);
        if !stores.is_empty() {
            let pad = 48usize.saturating_sub(line.chars().count()).max(2);
            line.push_str(&" ".repeat(pad));
            line.push_str(&format!("→ {}", stores.join(", ")));
        }
        let _ = writeln!(s, "{line}");
        for p in &st.prints {
            let _ = writeln!(s, "         printf: {}", p.trim_end());
        }
    }
}

fn named_text(v: &[Named]) -> String {
    v.iter()
        .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
        .collect::<Vec<_>>()
        .join("; ")
}

fn write_vertex(s: &mut String, v: &VertexTrace) {
    let _ = writeln!(
        s,
        "  vertex shader, vertex {} (index {}):",
        v.position, v.index
    );
    if !v.inputs.is_empty() {
        let _ = writeln!(s, "    inputs: {}", named_text(&v.inputs));
    }
    write_steps(s, &v.steps);
    write_truncated(s, v.truncated);
    if let Some(e) = &v.error {
        let _ = writeln!(s, "    {e}");
    } else {
        let _ = writeln!(s, "    outputs: {}", named_text(&v.outputs));
    }
}

fn write_geometry(s: &mut String, g: &GeometryTrace) {
    let list = |v: &[String]| v.join(", ");
    let (vertices, indices) = if g.vertices.len() == 1 {
        ("vertex", "index")
    } else {
        ("vertices", "indices")
    };
    let _ = writeln!(
        s,
        "  geometry shader, input primitive {} (gl_PrimitiveIDIn {}), {vertices} {} ({indices} {}):",
        g.primitive,
        g.primitive_id,
        list(&g.vertices.iter().map(|v| v.to_string()).collect::<Vec<_>>()),
        list(&g.indices.iter().map(|v| v.to_string()).collect::<Vec<_>>()),
    );
    if !g.inputs.is_empty() {
        let _ = writeln!(s, "    inputs: {}", named_text(&g.inputs));
    }
    write_steps(s, &g.steps);
    write_truncated(s, g.truncated);
    if let Some(e) = &g.error {
        let _ = writeln!(s, "    {e}");
    }
    if g.emitted.is_empty() {
        let _ = writeln!(s, "    emitted no vertex");
    }
    for e in &g.emitted {
        let of = match e.fragments.as_slice() {
            [] => String::new(),
            [one] => format!(", of fragment {one}'s primitive"),
            many => format!(
                ", of fragments {}'s primitives",
                list(&many.iter().map(|v| v.to_string()).collect::<Vec<_>>())
            ),
        };
        let _ = writeln!(
            s,
            "    emitted vertex {} (strip {}{of}): {}",
            e.vertex,
            e.strip,
            named_text(&e.outputs)
        );
    }
}

fn write_fragment(s: &mut String, n: usize, f: &FragmentReport) {
    let verts: Vec<String> = f.vertices.iter().map(|v| v.position.to_string()).collect();
    let _ = writeln!(
        s,
        "  fragment {n}: primitive {} (vertices {}), {}-facing, window z {}",
        f.primitive,
        verts.join(", "),
        f.facing,
        f.window_z
    );
    if let Some(k) = f.input_primitive {
        let _ = writeln!(
            s,
            "    emitted by the geometry shader of input primitive {k}"
        );
    }
    for v in &f.vertices {
        let outs: Vec<String> = v
            .outputs
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let emitted = v
            .emitted_vertex
            .map_or(String::new(), |e| format!(" (emitted vertex {e})"));
        let _ = writeln!(s, "    vertex {}{emitted}: {}", v.position, outs.join("; "));
    }
    let ins: Vec<String> = f
        .inputs
        .iter()
        .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
        .collect();
    if !ins.is_empty() {
        let _ = writeln!(s, "    inputs: {}", ins.join("; "));
    }
    if f.early_rejected {
        let _ = writeln!(
            s,
            "    rejected by the early depth/stencil test before shading"
        );
    }
    write_steps(s, &f.steps);
    write_truncated(s, f.truncated);
    if let Some(d) = &f.discarded {
        let at = d.line.map_or(String::new(), |l| format!(" at line {l}"));
        let _ = writeln!(s, "    discarded{at}: {}", d.source);
    }
    if let Some(e) = &f.error {
        let _ = writeln!(s, "    shader error: {e}");
    }
    if !f.outputs.is_empty() && f.discarded.is_none() {
        let outs: Vec<String> = f
            .outputs
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let _ = writeln!(s, "    outputs: {}", outs.join("; "));
    }
    if let Some(o) = &f.operations {
        let mut tests = Vec::new();
        let word = |b: bool| if b { "passed" } else { "failed" };
        if let Some(a) = o.alpha_test {
            tests.push(format!("alpha test {}", word(a)));
        }
        if let Some(st) = o.stencil_test {
            tests.push(format!(
                "stencil test {} (stored {})",
                word(st),
                o.before.stencil.unwrap_or(0)
            ));
        }
        if let Some(dt) = o.depth_test {
            tests.push(format!(
                "depth test {}: fragment {} against stored {}",
                word(dt),
                o.fragment_depth,
                o.before.depth.unwrap_or(1.0)
            ));
        }
        if o.blended {
            tests.push(format!("blended with {}", pixel_text(&o.before)));
        }
        if o.color_mask != [true; 4] {
            tests.push(format!("colour mask {:?}", o.color_mask));
        }
        if tests.is_empty() {
            tests.push("no test enabled".into());
        }
        let _ = writeln!(s, "    per-fragment operations: {}", tests.join("; "));
        let _ = writeln!(
            s,
            "    {}: {}",
            if o.written {
                "wrote"
            } else {
                "left the pixel as"
            },
            pixel_text(&o.after)
        );
    }
}
