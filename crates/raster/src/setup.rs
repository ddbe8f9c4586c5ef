//! Primitive set-up: assembled primitives to [`Prim`]s ready for
//! rasterization.
//!
//! Takes the vertex stage's outputs and, per primitive of a set-up chunk,
//! its vertices ([`Setup::chunk`], which assembles them with
//! `crate::assembly`); clips them in clip space against the view volume
//! and the user clip planes (`crate::clip`, GL 2.1 §2.12), divides and maps
//! them to window space (§2.11), decides facing from the window-space area
//! (§3.5.1), culls, applies polygon offset (§3.5.5) and the polygon mode,
//! and gives the chunk's [`Prim`]s with the planes of their fragment
//! varyings ([`Out`]). Triangles and quads inside every clip plane skip
//! the clipper; with shared vertices each vertex's outcode and window
//! position ([`Corner`]) are computed once per draw.

use std::ops::Range;

use glsl::ir::Interpolation;

use crate::assembly::{first_vertex_provoking, primitive, small_polygon, Assembled, Fan, Mode};
use crate::clip::{ClipVertex, Planes};
use crate::framebuffer::{DepthFormat, Framebuffer, DEPTH_MAX};
use crate::interpolate::{Bases, Basis, Plane, PrimPlanes, TriangleSetup};
use crate::linkage::{FsLayout, VaryingLink, VsLayout};
use crate::prim::Prim;
use crate::probe::Probe;
use crate::rasterize::{max_depth_slope, snap, vertex_depths, PixelRect, Shape, WinVertex};
use crate::simd::Level;
use crate::state::{CullFace, FrontFace, PipelineState, PolygonMode};

/// Largest point size used (points are clamped to [1, MAX_POINT_SIZE]).
pub const MAX_POINT_SIZE: f32 = 2048.0;

/// Viewport coordinates are clamped to ±2^19 so window positions fit the
/// rasterizer's fixed-point range.
const VIEWPORT_LIMIT: i64 = 1 << 19;

/// Quadrilaterals set up as one primitive ([`Setup::one_quadrilateral`]),
/// for the tests to see that a scene exercises it.
#[cfg(test)]
pub(crate) static QUADRILATERALS: std::sync::atomic::AtomicU64 =
    std::sync::atomic::AtomicU64::new(0);

/// Turns assembled primitives into set-up [`Prim`]s.
pub(crate) struct Setup<'a> {
    state: &'a PipelineState,
    vs: &'a VsLayout,
    fs: &'a FsLayout,
    outputs: &'a [f32],
    planes: Planes,
    clip_rect: PixelRect,
    /// 1 / r of §3.5.5 (r: the smallest resolvable difference of window
    /// z in the target's depth buffer, one step of its fixed point).
    depth_steps: f64,
    /// Viewport transform (px/2, ox, py/2, oy, (f-n)/2, n+(f-n)/2).
    vp: [f64; 6],
    /// The framebuffer's height when its planes take rows from the top
    /// ([`PipelineState::top_down`]).
    rows: Option<f32>,
    /// Whether a pixel's values depend on its primitive's 1/w plane:
    /// the fragment stage reads gl_FragCoord.w or a smooth varying (a
    /// perspective one is multiplied by 1 over it).
    reads_w: bool,
    probe: Option<&'a Probe>,
    /// Per vertex (when vertices are shared enough to be worth it, else
    /// empty): its clip-plane outcode and window position, what
    /// [`Setup::polygon`] computes for each primitive's vertices.
    corners: &'a [Corner],
}

/// A vertex's [`Planes::outcode_of`], [`Setup::window`] and that
/// position in fixed point ([`snap`]).
#[derive(Clone, Copy)]
pub(crate) struct Corner {
    outcode: u32,
    win: Option<(WinVertex, (i64, i64))>,
}

impl Corner {
    /// A placeholder, before a table's entries are computed.
    pub const BLANK: Corner = Corner {
        outcode: 0,
        win: None,
    };
}

/// Below this many primitive vertices per vertex the set-up computes each
/// vertex's outcode and window position where it is used (no table).
pub(crate) const CORNER_REUSE: usize = 2;

/// Where set-up primitives go: the primitives of one chunk, their
/// fragment varyings' planes (`Prim::index` × links locates a primitive's in `planes`), and the index of
/// the assembled primitive being set up.
pub(crate) struct Out {
    pub prims: Vec<Prim>,
    pub planes: Vec<Plane>,
    pub source: u32,
    /// The set-up chunk (its index in the draw's chunks).
    pub chunk: u32,
}

const NO_WIN: WinVertex = WinVertex {
    x: 0.0,
    y: 0.0,
    z: 0.0,
    inv_w: 0.0,
};

impl<'a> Setup<'a> {
    /// The set-up of a draw into `fb` with `state`: the vertex stage's
    /// `outputs` (laid out as `vs` says), linked to the fragment stage
    /// by `fs`; no per-vertex table yet ([`Setup::with_corners`]).
    pub fn new(
        state: &'a PipelineState,
        (vs, fs): (&'a VsLayout, &'a FsLayout),
        outputs: &'a [f32],
        fb: &Framebuffer,
        probe: Option<&'a Probe>,
    ) -> Setup<'a> {
        let vp = state.viewport;
        let lim = |v: i32| (v as i64).clamp(-VIEWPORT_LIMIT, VIEWPORT_LIMIT) as f64;
        let (vw, vh) = (lim(vp.w.max(0)), lim(vp.h.max(0)));
        let (n, f) = (state.depth_range.0 as f64, state.depth_range.1 as f64);
        let mut clip_rect = (0, 0, fb.width as i64, fb.height as i64);
        if let Some(s) = state.scissor {
            let (x0, y0) = (s.x as i64, s.y as i64);
            clip_rect = (
                clip_rect.0.max(x0),
                clip_rect.1.max(y0),
                clip_rect.2.min(x0 + s.w.max(0) as i64),
                clip_rect.3.min(y0 + s.h.max(0) as i64),
            );
        }
        Setup {
            state,
            vs,
            fs,
            outputs,
            planes: Planes::new(
                &state.clip_planes,
                vs.clip_distance,
                fs.noperspective_outputs(),
            )
            .with_depth_clamp(state.depth_clamp),
            clip_rect,
            depth_steps: match fb.depth_format {
                DepthFormat::Bits24 => DEPTH_MAX as f64,
                DepthFormat::Bits16 => 65535.0,
            },
            vp: [
                vw / 2.0,
                lim(vp.x) + vw / 2.0,
                vh / 2.0,
                lim(vp.y) + vh / 2.0,
                (f - n) / 2.0,
                n + (f - n) / 2.0,
            ],
            rows: state.top_down.then_some(fb.height as f32),
            reads_w: fs.frag_coord_zw[1]
                || fs
                    .links
                    .iter()
                    .any(|l| l.read && interpolation(state, l) == Interpolation::Smooth),
            probe,
            corners: &[],
        }
    }

    /// This set-up reading each vertex's outcode and window position
    /// from `corners` (entry `v` is [`Setup::compute_corner`] of `v`).
    pub fn with_corners(self, corners: &'a [Corner]) -> Setup<'a> {
        Setup { corners, ..self }
    }
}

impl Setup<'_> {
    /// Assembles and sets up primitives `range` of the draw (`vertex_of`:
    /// the vertex at each position of the index list) into `out`, in
    /// order. Triangles and quads take [`Setup::polygon_at`] (the copy of
    /// `level`), except under the debugger's probe, which
    /// notes each assembled primitive.
    #[inline(always)]
    pub fn chunk(
        &self,
        out: &mut Out,
        mode: Mode,
        vertex_of: &[u32],
        range: Range<usize>,
        level: Level,
    ) {
        let probe = self.probe;
        let count = vertex_of.len();
        let v = |i: usize| vertex_of.get(i).map_or(0, |&v| v as usize);
        let first = self.state.provoking_first;
        let pairs = matches!(
            mode,
            Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
        );
        let end = range.end;
        // The second triangle of a pair set up as one quadrilateral.
        let mut paired = false;
        for k in range {
            if std::mem::take(&mut paired) {
                continue;
            }
            out.source = k as u32;
            // The assembly names the last-vertex convention's provoking
            // vertex; the first-vertex convention picks another.
            let provoking = |last: usize| {
                if first {
                    first_vertex_provoking(mode, k)
                } else {
                    last
                }
            };
            if probe.is_none() {
                if pairs && k + 1 < end {
                    let triangle = |k: usize| small_polygon(mode, k).map(|(vs, _, _)| vs.map(v));
                    if let (Some([a, b, c, _]), Some([d, e, f, _])) = (triangle(k), triangle(k + 1))
                    {
                        paired = self.triangle_pair(out, [a, b, c], [d, e, f]);
                        if paired {
                            continue;
                        }
                    }
                }
                if let Some((vs, n, prov)) = small_polygon(mode, k) {
                    let vs = vs.map(v);
                    self.polygon_at(level, out, &vs[..n], (v(provoking(prov)), mode.fan()));
                    continue;
                }
            }
            let p = primitive(mode, count, k);
            if let Some(probe) = probe {
                probe.note_primitive(out.source, &p);
            }
            match p {
                Assembled::Point(i) => {
                    let cv = self.clip_vertex(v(i));
                    self.point(out, &cv, false, 0.0, self.data(v(i)));
                }
                Assembled::Line(a, b) => {
                    let (ca, cb) = (self.clip_vertex(v(a)), self.clip_vertex(v(b)));
                    self.line(out, &ca, &cb, false, 0.0, self.data(v(provoking(b))));
                }
                Assembled::Polygon(vs, prov) => {
                    let vs: Vec<usize> = vs.into_iter().map(v).collect();
                    self.polygon(out, &vs, (v(provoking(prov)), mode.fan()));
                }
            }
        }
    }

    fn data(&self, v: usize) -> &[f32] {
        let s = self.vs.outputs;
        self.outputs.get(v * s..(v + 1) * s).unwrap_or(&[])
    }

    fn clip_vertex(&self, v: usize) -> ClipVertex {
        let data = self.data(v);
        ClipVertex {
            pos: self.vs.position(data),
            eye: self.vs.eye(data),
            data: data.to_vec(),
        }
    }

    /// Perspective division and viewport transform (GL 2.1 §2.11) of a
    /// clip-space position. x, y and 1/w are llvmpipe's f32 values (its
    /// draw module's): 1/w rounded, then `fma(x · (1/w), scale,
    /// translate)`, so that the planes built from them round as its do
    /// (`crate::interpolate`); in a top-down framebuffer y is computed
    /// from the top (scale −h/2, translate `rows − oy`) and turned back
    /// exactly. Window z the same way, with Mesa's translate `n + (f −
    /// n)/2`.
    fn window(&self, pos: [f32; 4]) -> Option<WinVertex> {
        let w = pos[3];
        if w.is_nan() || w <= 0.0 {
            return None;
        }
        let [sx, ox, sy, oy, sz, oz] = self.vp;
        let inv_w = 1.0 / w;
        let yw = pos[1] * inv_w;
        let y = match self.rows {
            Some(h) => h as f64 - yw.mul_add(-(sy as f32), h - oy as f32) as f64,
            None => yw.mul_add(sy as f32, oy as f32) as f64,
        };
        let win = WinVertex {
            x: (pos[0] * inv_w).mul_add(sx as f32, ox as f32) as f64,
            y,
            z: (pos[2] * inv_w).mul_add(sz as f32, oz as f32) as f64,
            inv_w: inv_w as f64,
        };
        (win.x.is_finite() && win.y.is_finite() && win.z.is_finite() && win.inv_w.is_finite())
            .then_some(win)
    }

    /// Appends the planes of the fragment varyings of `shape` (`win` and
    /// `vertices`: the window positions and the data of its vertices) to
    /// `out.planes`, flat-shaded colours constant at `provoking`'s;
    /// returns the primitive's own planes (window z, 1/w).
    #[inline(always)]
    fn planes(
        &self,
        out: &mut Out,
        (shape, win): (&Shape, &[WinVertex]),
        vertices: &[&[f32]],
        (back, provoking): (bool, &[f32]),
    ) -> PrimPlanes {
        // A triangle's planes come from its vertices' window positions
        // (llvmpipe's set-up where it has an area), over rows from the top
        // in a top-down framebuffer (exact); coverage from the snapped
        // positions.
        let row = |y: f64| self.rows.map_or(y, |h| h as f64 - y);
        let top = self.rows.map(|h| h - 1.0);
        let triangle = match (shape, win) {
            (Shape::Triangle { .. } | Shape::Quadrilateral { .. }, [a, b, c]) => {
                let xy = [a, b, c].map(|w| (w.x, row(w.y)));
                TriangleSetup::new(xy.map(|(x, y)| (x as f32, y as f32)))
                    .map(|(t, order)| Bases::Triangle(t, order))
                    .or_else(|| Basis::of_triangle(xy).map(Bases::General))
            }
            _ => None,
        };
        let bases = triangle.unwrap_or_else(|| {
            Bases::General(match top {
                Some(t) => shape.basis().top_down(t as f64),
                None => shape.basis(),
            })
        });
        let (z, inv_w) = vertex_depths(win);
        let (z, inv_w) = (z.map(|z| z as f32), inv_w.map(|w| w as f32));
        let prim = PrimPlanes::new(&bases, z, inv_w, top);
        // A line's or a point's missing vertices repeat its last.
        let data = |j: usize| vertices.get(j).or(vertices.last()).copied().unwrap_or(&[]);
        let (d0, d1, d2) = (data(0), data(1), data(2));
        for link in &self.fs.links {
            let get = |d: &[f32]| link_value(link, back, d);
            out.planes.push(match self.interpolation(link) {
                Interpolation::Flat => Plane::constant(get(provoking)),
                Interpolation::Smooth => prim.varying(&bases, [get(d0), get(d1), get(d2)], inv_w),
                Interpolation::NoPerspective => {
                    prim.screen_linear(&bases, [get(d0), get(d1), get(d2)])
                }
            });
        }
        prim
    }

    /// How `link` is interpolated: GLSL 1.30 §4.3.7, a qualifier
    /// overrides the shade model.
    fn interpolation(&self, link: &VaryingLink) -> Interpolation {
        interpolation(self.state, link)
    }

    /// Whether a polygon of window vertices `win` (in its order) faces
    /// back: GL 2.1 §3.5.1 eq. 3.6, the sign of its window-space area.
    fn back_facing(&self, win: &[WinVertex]) -> bool {
        let mut area = 0.0f64;
        for i in 0..win.len() {
            let j = (i + 1) % win.len();
            area += win[i].x * win[j].y - win[j].x * win[i].y;
        }
        let ccw = area > 0.0;
        ccw != (self.state.front_face == FrontFace::Ccw)
    }

    /// Whether the cull state drops a polygon facing back when `back`.
    fn culled(&self, back: bool) -> bool {
        match self.state.cull {
            Some(CullFace::FrontAndBack) => true,
            Some(CullFace::Front) => !back,
            Some(CullFace::Back) => back,
            None => false,
        }
    }

    /// Triangles `t0` and `t1` (vertex numbers, each in its own order:
    /// consecutive triangles of a list, strip or fan) as one
    /// quadrilateral when they share an edge and
    /// [`Setup::one_quadrilateral`] takes the four corners around it (a
    /// billboard drawn as a strip of four vertices, or as two triangles
    /// of shared indices). Returns true when both are done (set up as one,
    /// or culled), false to set them up one by one. Only filled, inside
    /// every clip plane, facing the same way (each triangle's own order
    /// decides its facing) and where the fragment stage does not read
    /// gl_PrimitiveID (which tells the two apart); [`Setup::chunk`] asks
    /// only without a probe. Flat varyings take each triangle's provoking
    /// vertex, so they too must be the same at the four corners, through
    /// either face's source (the facing is known later).
    pub fn triangle_pair(&self, out: &mut Out, t0: [usize; 3], t1: [usize; 3]) -> bool {
        let fill = self.state.polygon_mode == [PolygonMode::Fill; 2];
        if !fill || self.fs.primitive_id.is_some() {
            return false;
        }
        // The shared edge (s0, s1) and the vertex of each triangle off it.
        let (mut shared, mut n) = ([0usize; 2], 0);
        let mut u0 = None;
        for &v in &t0 {
            match (t1.contains(&v), shared.get_mut(n)) {
                (true, Some(slot)) => {
                    *slot = v;
                    n += 1;
                }
                (true, None) => return false,
                (false, _) => u0 = Some(v),
            }
        }
        let (Some(u0), Some(&u1)) = (u0, t1.iter().find(|v| !t0.contains(v))) else {
            return false;
        };
        if n != 2 || u0 == u1 {
            return false;
        }
        // Around the shared edge as the diagonal from corner 0 to 2.
        let quad = [shared[0], u1, shared[1], u0];
        // The cheap test first (a mesh's normals differ and stop here).
        let data = quad.map(|v| self.data(v));
        if !self.corner_values_agree(&data, &[false, true], false) {
            return false;
        }
        let mut win = [NO_WIN; 4];
        let mut fixed = [(0, 0); 4];
        for (k, &v) in quad.iter().enumerate() {
            match self.corner(v) {
                Corner {
                    outcode: 0,
                    win: Some((w, f)),
                } => (win[k], fixed[k]) = (w, f),
                _ => return false,
            }
        }
        let at = |v: usize| quad.iter().position(|&q| q == v).map_or(NO_WIN, |k| win[k]);
        let back = self.back_facing(&t0.map(at));
        if self.back_facing(&t1.map(at)) != back {
            return false;
        }
        let Some(shape) = self.one_quadrilateral((&win, &fixed)) else {
            return false;
        };
        if self.culled(back) {
            return true;
        }
        // §3.5.5 as for each triangle alone where the window z is read:
        // the corners' z are then the same, its slope 0, o = r · units
        // (elsewhere nothing adds it to a depth).
        let po = self.state.polygon_offset;
        let z_offset = match po.fill {
            true => po.units as f64 / self.depth_steps,
            false => 0.0,
        };
        let [d0, d1, d2, _] = data;
        // (Flat varyings are the same at every corner.)
        let first = [win[0], win[1], win[2]];
        self.push(out, (shape, &first), back, z_offset, &[d0, d1, d2], d0);
        true
    }

    /// Whether each varying the fragment stage reads is the same bits at
    /// the four corners `data` through the source of each face of
    /// `faces` (true: back), flat ones too unless `one_provoking` (the
    /// triangles share their provoking vertex, whose value both take).
    fn corner_values_agree(&self, data: &[&[f32]], faces: &[bool], one_provoking: bool) -> bool {
        self.fs.links.iter().filter(|l| l.read).all(|link| {
            (one_provoking && self.interpolation(link) == Interpolation::Flat)
                || faces.iter().all(|&back| {
                    let mut v = data.iter().map(|d| link_value(link, back, d).to_bits());
                    let first = v.next();
                    v.all(|x| Some(x) == first)
                })
        })
    }

    /// A quadrilateral (`win` and its [`snap`] `fixed` per vertex) as one
    /// primitive instead of its fan's two triangles, where that gives
    /// every pixel the same coverage and values, once its varyings agree
    /// at the corners ([`Setup::corner_values_agree`]): the shape covers
    /// the triangles' pixels exactly ([`Shape::quadrilateral_snapped`]),
    /// and the window z and 1/w, where read, are the same bits at the four
    /// vertices, so that every plane read is that constant in either
    /// triangle ([`crate::interpolate::Basis::plane`],
    /// [`PrimPlanes::varying`]). Not with a probe, whose history names the
    /// triangles. Billboards (sphere impostors) are such quadrilaterals:
    /// one primitive's set-up, bins and walks instead of two, and no quad
    /// along the diagonal shaded twice.
    fn one_quadrilateral(&self, (win, fixed): (&[WinVertex], &[(i64, i64)])) -> Option<Shape> {
        let ([w0, w1, w2, w3], &[f0, f1, f2, f3]) = (win, fixed) else {
            return None;
        };
        if self.probe.is_some() {
            return None;
        }
        let same = |v: [f64; 4]| v.iter().all(|x| x.to_bits() == v[0].to_bits());
        let (z, inv_w) = (
            [w0, w1, w2, w3].map(|w| w.z),
            [w0, w1, w2, w3].map(|w| w.inv_w),
        );
        // Window z only where something reads it: the depth test without
        // gl_FragDepth, or gl_FragCoord.z; 1/w for gl_FragCoord.w and
        // smooth varyings (constants whose perspective product with
        // 1/w is the same in either triangle only when the 1/w are).
        let frag_z = self.fs.frag_coord_zw[0];
        if ((self.fs.frag_depth.is_none() || frag_z) && !same(z)) || (self.reads_w && !same(inv_w))
        {
            return None;
        }
        let shape = Shape::quadrilateral_snapped([f0, f1, f2, f3]);
        #[cfg(test)]
        if shape.is_some() {
            QUADRILATERALS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        }
        shape
    }

    /// Sets up `shape`, whose vertices are `win` (window positions) and
    /// `vertices` (their data).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn push(
        &self,
        out: &mut Out,
        (shape, win): (Shape, &[WinVertex]),
        back: bool,
        z_offset: f64,
        vertices: &[&[f32]],
        provoking: &[f32],
    ) {
        if let Some(p) = self.probe {
            p.note_shape(win);
        }
        let b = shape.bounds();
        let c = self.clip_rect;
        let bounds = (b.0.max(c.0), b.1.max(c.1), b.2.min(c.2), b.3.min(c.3));
        if bounds.0 >= bounds.2 || bounds.1 >= bounds.3 {
            return;
        }
        let planes = self.planes(out, (&shape, win), vertices, (back, provoking));
        if let Some(p) = self.probe {
            p.note_window(win);
        }
        out.prims.push(Prim {
            shape,
            bounds,
            back,
            z_offset,
            planes,
            index: out.prims.len() as u32,
            chunk: out.chunk,
            source: out.source,
        });
    }

    fn point_size(&self, data: &[f32]) -> f32 {
        let size = match (self.state.vertex_program_point_size, self.vs.point_size) {
            (true, Some(o)) => data.get(o).copied().unwrap_or(1.0),
            _ => self.state.point_size,
        };
        if size.is_nan() {
            1.0
        } else {
            size.clamp(1.0, MAX_POINT_SIZE)
        }
    }

    fn point(&self, out: &mut Out, v: &ClipVertex, back: bool, z_offset: f64, provoking: &[f32]) {
        if !self.planes.point_inside(v) {
            return;
        }
        let Some(win) = self.window(v.pos) else {
            return;
        };
        let size = self.point_size(&v.data) as f64;
        let shape = Shape::point(win, size, self.state.point_sprite);
        self.push(out, (shape, &[win]), back, z_offset, &[&v.data], provoking);
    }

    fn line(
        &self,
        out: &mut Out,
        a: &ClipVertex,
        b: &ClipVertex,
        back: bool,
        z_offset: f64,
        provoking: &[f32],
    ) {
        let Some((a, b)) = self.planes.clip_line(a, b) else {
            return;
        };
        let (Some(wa), Some(wb)) = (self.window(a.pos), self.window(b.pos)) else {
            return;
        };
        let shape = Shape::line([wa, wb], self.state.line_width);
        self.push(
            out,
            (shape, &[wa, wb]),
            back,
            z_offset,
            &[&a.data, &b.data],
            provoking,
        );
    }

    /// Vertex `v`'s outcode and window position: from the table when
    /// there is one, else computed.
    #[inline(always)]
    fn corner(&self, v: usize) -> Corner {
        match self.corners.get(v) {
            Some(&c) => c,
            None => self.compute_corner(v),
        }
    }

    pub fn compute_corner(&self, v: usize) -> Corner {
        let d = self.data(v);
        let pos = self.vs.position(d);
        let outcode = self.planes.outcode_of(&pos, &self.vs.eye(d), d);
        Corner {
            outcode,
            // Only read for vertices inside every plane.
            win: match outcode {
                0 => self.window(pos).map(|w| (w, snap(&w))),
                _ => None,
            },
        }
    }

    exec::multiversion! {
        /// Sets up a polygon (`vertices`, `provoking`: vertex numbers;
        /// `fan`: how its mode cuts it into triangles): clipped, culled,
        /// offset, filled as triangles or outlined; compiled for `level`
        /// (the set-up inlined into each copy: the same operations, fused
        /// ones through `mul_add`, so the same values). The portable copy,
        /// [`Setup::polygon`], is also the general path's.
        fn polygon_at(
            &self,
            #[level] level: Level,
            out: &mut Out,
            vertices: &[usize],
            provoking: (usize, Fan),
        );
        copies = [polygon, polygon_avx2, polygon_avx512],
        body = self.polygon_with(out, vertices, provoking)
    }

    #[inline(always)]
    fn polygon_with(&self, out: &mut Out, vertices: &[usize], (provoking, fan): (usize, Fan)) {
        // Line and point modes draw the unclipped polygon's edges/vertices.
        let filled_only = self.state.polygon_mode == [PolygonMode::Fill; 2];
        let prov = self.data(provoking);
        if filled_only && (3..=4).contains(&vertices.len()) {
            // Triangles and quads inside every plane (the usual case) skip
            // the clipper and its copies: what it would return unchanged.
            let mut corners = [Corner {
                outcode: 0,
                win: None,
            }; 4];
            let (mut all, mut any) = (0u32, !0u32);
            for (c, &v) in corners.iter_mut().zip(vertices) {
                *c = self.corner(v);
                all |= c.outcode;
                any &= c.outcode;
            }
            if any != 0 {
                return;
            }
            if all == 0 {
                let mut win = [NO_WIN; 4];
                let mut fixed = [(0, 0); 4];
                let mut data: [&[f32]; 4] = [&[]; 4];
                for (i, (&v, c)) in vertices.iter().zip(&corners).enumerate() {
                    let Some((w, f)) = c.win else {
                        return;
                    };
                    (win[i], fixed[i]) = (w, f);
                    data[i] = self.data(v);
                }
                let n = vertices.len();
                let polygon = (&win[..n], &fixed[..n]);
                self.set_up_polygon(out, polygon, &data[..n], &[], (prov, fan));
                return;
            }
        }
        let original: Vec<ClipVertex> = vertices.iter().map(|&v| self.clip_vertex(v)).collect();
        let (original, clipped) = if filled_only {
            (Vec::new(), self.planes.clip_polygon(original))
        } else {
            let clipped = self.planes.clip_polygon(original.clone());
            (original, clipped)
        };
        if clipped.len() < 3 {
            return;
        }
        let Some(win) = clipped
            .iter()
            .map(|v| self.window(v.pos))
            .collect::<Option<Vec<_>>>()
        else {
            return;
        };
        let data: Vec<&[f32]> = clipped.iter().map(|v| &v.data[..]).collect();
        let fixed: Vec<(i64, i64)> = win.iter().map(snap).collect();
        self.set_up_polygon(out, (&win, &fixed), &data, &original, (prov, fan));
    }

    /// Facing, culling, polygon offset and the polygon mode of a clipped
    /// polygon (`win`, its [`snap`] `fixed` and `data` per vertex, at
    /// least three; `original`: the unclipped polygon, for line and point
    /// modes; filled as the triangles of `fan`).
    #[inline(always)]
    fn set_up_polygon(
        &self,
        out: &mut Out,
        (win, fixed): (&[WinVertex], &[(i64, i64)]),
        data: &[&[f32]],
        original: &[ClipVertex],
        (prov, fan): (&[f32], Fan),
    ) {
        let back = self.back_facing(win);
        if self.culled(back) {
            return;
        }
        let mode = self.state.polygon_mode[back as usize];
        let po = self.state.polygon_offset;
        let offset_on = match mode {
            PolygonMode::Fill => po.fill,
            PolygonMode::Line => po.line,
            PolygonMode::Point => po.point,
        };
        // Fan triangle i, from the snapped positions; `None` when it has
        // no area.
        let triangle = |i: usize| {
            let corner = |j: usize| fixed.get(j).copied().unwrap_or_default();
            Shape::triangle_snapped(fan.triangle(i).map(corner))
        };
        let z_offset = if offset_on {
            // §3.5.5: o = m · factor + r · units.
            let m = (1..win.len() - 1)
                .find(|&i| triangle(i).is_some())
                .map_or(0.0, |i| max_depth_slope(&[win[0], win[i], win[i + 1]]));
            m * po.factor as f64 + po.units as f64 / self.depth_steps
        } else {
            0.0
        };
        match mode {
            PolygonMode::Fill => {
                if let [d0, d1, d2, _] = data {
                    let one = self.corner_values_agree(data, &[back], true);
                    if let Some(shape) = one.then(|| self.one_quadrilateral((win, fixed))).flatten()
                    {
                        let first = [win[0], win[1], win[2]];
                        self.push(out, (shape, &first), back, z_offset, &[d0, d1, d2], prov);
                        return;
                    }
                }
                for i in 1..win.len() - 1 {
                    let Some(shape) = triangle(i) else {
                        continue;
                    };
                    let [a, b, c] = fan.triangle(i);
                    let tri = [win[a], win[b], win[c]];
                    let (Some(&da), Some(&db), Some(&dc)) = (data.get(a), data.get(b), data.get(c))
                    else {
                        continue;
                    };
                    self.push(out, (shape, &tri), back, z_offset, &[da, db, dc], prov);
                }
            }
            PolygonMode::Line => {
                for i in 0..original.len() {
                    let j = (i + 1) % original.len();
                    self.line(out, &original[i], &original[j], back, z_offset, prov);
                }
            }
            PolygonMode::Point => {
                for v in original {
                    self.point(out, v, back, z_offset, prov);
                }
            }
        }
    }
}

/// How `link` is interpolated: GLSL 1.30 §4.3.7, a qualifier overrides
/// the shade model.
fn interpolation(state: &PipelineState, link: &VaryingLink) -> Interpolation {
    match link.interpolation {
        None if state.flat_shading && link.color => Interpolation::Flat,
        None => Interpolation::Smooth,
        Some(i) => i,
    }
}

/// The value `link` reads from a vertex's `data` (its back-face source
/// for a back-facing primitive; 0 where it has none).
fn link_value(link: &VaryingLink, back: bool, data: &[f32]) -> f32 {
    let src = if back { link.back } else { link.front };
    src.and_then(|o| data.get(o)).copied().unwrap_or(0.0)
}
