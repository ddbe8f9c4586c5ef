//! Where things live in the vertex and fragment kernels' interfaces, and
//! how vertex outputs feed fragment inputs (matched by name, block members
//! as `Block.member` whatever their instance names; gl_Color from
//! gl_FrontColor / gl_BackColor, gl_SecondaryColor likewise).

use crate::ex::{Batch, Interface, Slot, LANES};
use crate::framebuffer::MAX_DRAW_BUFFERS;
use glsl::ir::Interpolation;
use glsl::types::ArraySize;

fn find<'a>(slots: &'a [Slot], name: &str) -> Option<&'a Slot> {
    slots.iter().find(|s| s.name == name)
}

/// The vertex kernel's outputs the pipeline itself reads.
pub(crate) struct VsLayout {
    pub outputs: usize,
    pub position: Option<usize>,
    pub point_size: Option<usize>,
    /// gl_ClipVertex when the shader writes it. GL 2.1 §2.12 leaves user
    /// clipping undefined otherwise; we then clip against gl_Position.
    pub clip_vertex: Option<usize>,
    /// gl_ClipDistance (first component, length) when the shader writes
    /// it: the enabled user clip planes then clip against its elements
    /// (GL 3.3 §2.20).
    pub clip_distance: Option<(usize, usize)>,
    /// gl_{Front,Back}{,Secondary}Color ranges (clamped per §2.14.6).
    pub colors: Vec<(usize, usize)>,
}

impl VsLayout {
    pub fn new(iface: &Interface) -> VsLayout {
        let out = &iface.outputs;
        let vec4 = |name: &str| {
            find(out, name)
                .filter(|s| s.components >= 4)
                .map(|s| s.offset)
        };
        VsLayout {
            outputs: out
                .iter()
                .map(|s| s.offset + s.components)
                .max()
                .unwrap_or(0),
            position: vec4("gl_Position"),
            point_size: find(out, "gl_PointSize")
                .filter(|s| s.written && s.components >= 1)
                .map(|s| s.offset),
            clip_vertex: find(out, "gl_ClipVertex")
                .filter(|s| s.written && s.components >= 4)
                .map(|s| s.offset),
            clip_distance: find(out, "gl_ClipDistance")
                .filter(|s| s.written && s.components >= 1)
                .map(|s| (s.offset, s.components)),
            colors: [
                "gl_FrontColor",
                "gl_BackColor",
                "gl_FrontSecondaryColor",
                "gl_BackSecondaryColor",
            ]
            .iter()
            .filter_map(|n| find(out, n).map(|s| (s.offset, s.components)))
            .collect(),
        }
    }

    pub fn position(&self, data: &[f32]) -> [f32; 4] {
        read4(data, self.position)
    }

    pub fn eye(&self, data: &[f32]) -> [f32; 4] {
        match self.clip_vertex {
            Some(_) => read4(data, self.clip_vertex),
            None => self.position(data),
        }
    }
}

fn read4(data: &[f32], at: Option<usize>) -> [f32; 4] {
    let mut v = [0.0; 4];
    if let Some(o) = at {
        for (i, c) in v.iter_mut().enumerate() {
            *c = data.get(o + i).copied().unwrap_or(0.0);
        }
    }
    v
}

/// One fragment-input component fed from the vertex stage.
#[derive(Clone, Debug)]
pub(crate) struct VaryingLink {
    pub fs_offset: usize,
    /// Vertex output component for front faces (None: undefined, reads 0).
    pub front: Option<usize>,
    /// For back faces with two-sided color on (gl_BackColor ...).
    pub back: Option<usize>,
    /// gl_Color / gl_SecondaryColor: flat-shaded under ShadeModel(FLAT)
    /// unless declared with an interpolation qualifier.
    pub color: bool,
    /// The declared interpolation qualifier (GLSL 1.30 §4.3.7), the
    /// fragment input's or else the vertex output's: `flat` is always
    /// the provoking vertex's value, `noperspective` linear in window
    /// space, `smooth` perspective-correct; any of them overrides the
    /// shade model. `None`: smooth, or the shade model's for colors.
    pub interpolation: Option<Interpolation>,
    /// `gl_TexCoord[set]`.component, for point-sprite coordinate replacement.
    pub texcoord: Option<(u32, usize)>,
    /// Whether the fragment program reads it (every link until
    /// [`FsLayout::with_reads`] says).
    pub read: bool,
}

pub(crate) struct FsLayout {
    pub inputs: usize,
    pub outputs: usize,
    pub links: Vec<VaryingLink>,
    pub frag_coord: Option<usize>,
    pub front_facing: Option<usize>,
    pub point_coord: Option<usize>,
    /// gl_PrimitiveID (an int: its bits, `exec::Batch::inputs`).
    pub primitive_id: Option<usize>,
    /// Output offset of the color for each fragment output index.
    pub color_out: [Option<usize>; MAX_DRAW_BUFFERS],
    /// The output offset of the second source colour of draw buffer 0
    /// (the user output at `layout(location = 0, index = 1)`), read by
    /// the SRC1 blend factors (dual-source blending).
    pub src1_out: Option<usize>,
    pub frag_depth: Option<usize>,
    /// Whether the fragment program reads gl_FragCoord's z and w (both
    /// until [`FsLayout::with_reads`] says).
    pub frag_coord_zw: [bool; 2],
}

impl FsLayout {
    /// This layout knowing which input components the fragment program
    /// reads (`reads`, component by component: `ShaderStage::reads_input`).
    pub fn with_reads(mut self, reads: impl Fn(usize) -> bool) -> FsLayout {
        for link in &mut self.links {
            link.read = reads(link.fs_offset);
        }
        self.frag_coord_zw = self
            .frag_coord
            .map_or([false; 2], |o| [reads(o + 2), reads(o + 3)]);
        self
    }

    pub fn new(vs: &Interface, fs: &Interface, two_sided: bool) -> FsLayout {
        let mut links = Vec::new();
        let mut frag_coord = None;
        let mut front_facing = None;
        let mut point_coord = None;
        let mut primitive_id = None;
        // A geometry shader's gl_PrimitiveID output feeds the fragment
        // shader's (GL 3.3 §3.12.2), as a flat varying; else the
        // pipeline numbers the primitives.
        let upstream_id = find(&vs.outputs, "gl_PrimitiveID").is_some_and(|s| s.written);
        for slot in &fs.inputs {
            let link_name = slot.link_name();
            match link_name.as_ref() {
                "gl_FragCoord" => frag_coord = Some(slot.offset),
                "gl_PrimitiveID" if !upstream_id => primitive_id = Some(slot.offset),
                "gl_FrontFacing" => front_facing = Some(slot.offset),
                "gl_PointCoord" => point_coord = Some(slot.offset),
                name => {
                    let (front_name, back_name, color) = match name {
                        "gl_Color" => ("gl_FrontColor", Some("gl_BackColor"), true),
                        "gl_SecondaryColor" => (
                            "gl_FrontSecondaryColor",
                            Some("gl_BackSecondaryColor"),
                            true,
                        ),
                        other => (other, None, false),
                    };
                    // By location for a user input with one, else by
                    // name (`Interface::output_for`).
                    let front = vs.output_for(front_name, slot.location);
                    let back = back_name
                        .filter(|_| two_sided)
                        .and_then(|n| vs.output_for(n, None));
                    let interpolation = if name == "gl_PrimitiveID" {
                        Some(Interpolation::Flat)
                    } else {
                        slot.interpolation
                            .or_else(|| front.and_then(|(s, _)| s.interpolation))
                            .or_else(|| back.and_then(|(s, _)| s.interpolation))
                    };
                    for c in 0..slot.components {
                        let pick = |s: Option<(&Slot, usize)>| {
                            s.filter(|(s, at)| at + c < s.components)
                                .map(|(s, at)| s.offset + at + c)
                        };
                        let front = pick(front);
                        links.push(VaryingLink {
                            fs_offset: slot.offset + c,
                            front,
                            back: pick(back).or(front),
                            color,
                            interpolation,
                            texcoord: (name == "gl_TexCoord").then_some(((c / 4) as u32, c % 4)),
                            read: true,
                        });
                    }
                }
            }
        }
        let out = &fs.outputs;
        let mut color_out = [None; MAX_DRAW_BUFFERS];
        let data = find(out, "gl_FragData").filter(|s| s.written);
        let color = find(out, "gl_FragColor").filter(|s| s.components >= 4);
        for (i, o) in color_out.iter_mut().enumerate() {
            *o = match data {
                Some(d) => (d.components >= 4 * (i + 1)).then_some(d.offset + 4 * i),
                None => color.map(|s| s.offset),
            };
        }
        // User outputs (GLSL 1.30 `out`): each at its location, or, without
        // one, at the next free draw buffers in declaration order.
        // An output of index 1 is a second source colour, placed apart
        // (only location 0 has one).
        let src1_out = out
            .iter()
            .find(|s| !s.name.starts_with("gl_") && s.index == Some(1) && s.location == Some(0))
            .map(|s| s.offset);
        let user: Vec<&Slot> = out
            .iter()
            .filter(|s| !s.name.starts_with("gl_") && s.index != Some(1))
            .collect();
        let has_user = !user.is_empty() || src1_out.is_some();
        if has_user {
            color_out = [None; MAX_DRAW_BUFFERS];
            let mut next = 0usize;
            let placed = user.iter().filter(|s| s.location.is_some());
            let unplaced = user.iter().filter(|s| s.location.is_none());
            for s in placed.chain(unplaced) {
                let elems = match s.ty.array {
                    Some(ArraySize::Sized(n)) => n as usize,
                    _ => 1,
                };
                let per = s.components / elems.max(1);
                let start = match s.location {
                    Some(l) => l as usize,
                    None => {
                        while color_out.get(next).is_some_and(|c| c.is_some()) {
                            next += 1;
                        }
                        next
                    }
                };
                for e in 0..elems {
                    if let Some(c) = color_out.get_mut(start + e) {
                        *c = Some(s.offset + e * per);
                    }
                }
            }
        }
        FsLayout {
            inputs: fs
                .inputs
                .iter()
                .map(|s| s.offset + s.components)
                .max()
                .unwrap_or(0),
            // A draw buffer reads four components from an output's offset;
            // a user output may have fewer (`out float c;'), whose missing
            // components are undefined (GLSL 1.30 §4.3.6): three spare
            // components keep the read in the batch.
            outputs: out
                .iter()
                .map(|s| s.offset + s.components)
                .max()
                .unwrap_or(0)
                + if has_user { 3 } else { 0 },
            links,
            frag_coord,
            front_facing,
            point_coord,
            primitive_id,
            color_out,
            src1_out,
            frag_depth: find(out, "gl_FragDepth")
                .filter(|s| s.written)
                .map(|s| s.offset),
            frag_coord_zw: [true; 2],
        }
    }
}

impl FsLayout {
    /// The vertex-output components feeding `noperspective` fragment
    /// inputs (front and back), ascending: what clipping interpolates
    /// linearly in window space.
    pub fn noperspective_outputs(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self
            .links
            .iter()
            .filter(|l| l.interpolation == Some(Interpolation::NoPerspective))
            .flat_map(|l| [l.front, l.back])
            .flatten()
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// A fresh batch of `inputs` input and `outputs` output components
/// (all zero, no lane active), laid out as a stage interface says.
pub(crate) fn new_batch(inputs: usize, outputs: usize) -> Batch {
    Batch {
        inputs: vec![[0.0; LANES]; inputs],
        outputs: vec![[0.0; LANES]; outputs],
        active: 0,
        discarded: 0,
        helper: 0,
    }
}
