//! The fixed-function fragment stage run directly, without the engine.
//!
//! [`crate::ffgen::fragment_source`] writes the fixed-function fragment
//! stage as GLSL; the draw compiles it into a kernel like any shader.
//! Most of what running that kernel costs on a batch is the engine's set-
//! up around a handful of operations (copying inputs into its register
//! file, native-code entry, copying outputs back). [`FixedFragment`]
//! computes the same program from its [`FragmentShape`] straight from the
//! batch's inputs to its outputs, with the engine's own operations
//! ([`exec::lane`]) in the kernel's order, so the bits are the kernel's
//! (a test compares the two on random states, inputs and textures).
//!
//! It covers the shapes whose lookups are all `texture2DProj` (any
//! texture environment, color sum, any fog mode); other shapes, and the
//! debugger's traced runs, use the kernel itself. On x86-64 with AVX2 or
//! AVX-512 the run keeps the 16 lanes in registers ([`exec::lanes16`]).

use crate::ffgen::{AlphaOp, FogMode, FragmentShape, Lookup, RgbOp};
use exec::lane::{self, flush, FULL};
#[cfg(target_arch = "x86_64")]
use exec::lanes16::{Lanes16, X256, X512};
use exec::{Batch, ExecError, Kernel, Textures, LANES};
use std::sync::Arc;

/// A fixed-function fragment kernel and, when its shape allows, the plan
/// that computes its results directly (see the module documentation).
pub struct FixedFragment {
    kernel: Arc<Kernel>,
    plan: Option<Plan>,
}

/// Where a [`FragmentShape`]'s values are: batch input and output
/// components and uniform words of its kernel.
#[derive(Debug)]
struct Plan {
    /// gl_Color (four components).
    color: usize,
    units: Vec<UnitPlan>,
    /// gl_SecondaryColor, with color sum.
    secondary: Option<usize>,
    fog: Option<FogPlan>,
    /// gl_FragColor, and the number of output components.
    out: usize,
    outputs: usize,
}

#[derive(Debug)]
struct UnitPlan {
    /// gl_TexCoord[unit] (s, t, r, q).
    coord: usize,
    /// The sampler uniform (its value is the unit number).
    sampler: usize,
    /// gl_TextureEnvColor[unit], when the environment reads it.
    env: Option<usize>,
    rgb: RgbOp,
    alpha: AlphaOp,
}

#[derive(Debug)]
struct FogPlan {
    mode: FogMode,
    /// gl_FogFragCoord.
    z: usize,
    /// Words of gl_Fog.color (rgb), .density, .end, .scale.
    color: usize,
    density: usize,
    end: usize,
    scale: usize,
}

impl FixedFragment {
    /// The stage of `kernel`, compiled from `fragment_source(shape)`.
    pub fn new(kernel: Arc<Kernel>, shape: &FragmentShape) -> FixedFragment {
        FixedFragment {
            plan: Plan::new(&kernel, shape),
            kernel,
        }
    }

    /// Whether the batch runs without the engine.
    pub fn direct(&self) -> bool {
        self.plan.is_some()
    }
}

impl Plan {
    /// `None` when a lookup is not `texture2DProj`, or the kernel's
    /// interface lacks a value the shape reads (the kernel then runs).
    fn new(kernel: &Kernel, shape: &FragmentShape) -> Option<Plan> {
        let iface = kernel.interface();
        let input = |name: &str, need: usize| {
            iface
                .input(name)
                .filter(|s| s.components >= need)
                .map(|s| s.offset)
        };
        let word = |path: &str| iface.locate_uniform(path).map(|(w, _)| w);
        let mut units = Vec::new();
        for u in &shape.units {
            if u.lookup != Lookup::Texture2DProj {
                return None;
            }
            let reads_env = u.rgb == RgbOp::BlendEnv || u.alpha == AlphaOp::BlendEnv;
            units.push(UnitPlan {
                coord: input("gl_TexCoord", 4 * u.unit + 4)? + 4 * u.unit,
                sampler: word(&crate::ffgen::sampler_name(u.unit))?,
                env: if reads_env {
                    Some(word(&format!("gl_TextureEnvColor[{}]", u.unit))?)
                } else {
                    None
                },
                rgb: u.rgb,
                alpha: u.alpha,
            });
        }
        let secondary = if shape.color_sum {
            Some(input("gl_SecondaryColor", 4)?)
        } else {
            None
        };
        let fog = match shape.fog {
            Some(mode) => Some(FogPlan {
                mode,
                z: input("gl_FogFragCoord", 1)?,
                color: word("gl_Fog.color")?,
                density: word("gl_Fog.density")?,
                end: word("gl_Fog.end")?,
                scale: word("gl_Fog.scale")?,
            }),
            None => None,
        };
        let out = iface.output("gl_FragColor").filter(|s| s.components == 4)?;
        Some(Plan {
            color: input("gl_Color", 4)?,
            units,
            secondary,
            fog,
            out: out.offset,
            outputs: iface.output_components,
        })
    }

    exec::multiversion! {
        /// The kernel's run on `batch` (see [`Plan::run_with`]), compiled
        /// for the highest level the CPU runs ([`Plan::run_in`] in its
        /// registers): the same IEEE operations (Rust never fuses a
        /// multiply and an add), so the same bits.
        #[inline(always)]
        fn run(&self, batch: &mut Batch, uniforms: &[u32], textures: &dyn Textures);
        level = exec::cpu::Level::best(),
        copies = [run_portable, run_avx2, run_avx512],
        body = {
            portable: self.run_with(batch, uniforms, textures),
            // SAFETY: compiled for AVX2, which the caller's CPU has.
            avx2: unsafe { self.run_in::<X256>(batch, uniforms, textures) },
            // SAFETY: compiled for AVX-512, which the caller's CPU has.
            avx512: unsafe { self.run_in::<X512>(batch, uniforms, textures) },
        }
    }

    /// [`Plan::run_with`]'s operations on all 16 lanes at once in `V`'s
    /// registers (the same IEEE operations and flushes in the same order,
    /// so the same bits; `lane::max`/`min` against the constant bounds of
    /// the clamps as the unordered comparisons that pick the bound for a
    /// NaN); the lookups' coordinates and texels, and exp's lanes, go
    /// through arrays.
    ///
    /// # Safety
    /// The CPU must have `V`'s instruction set, and this must be inlined
    /// into code compiled for it.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn run_in<V: Lanes16>(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) {
        // SAFETY (of every `V` operation): the caller's contract; loads
        // and stores are of 16-lane arrays.
        unsafe {
            let float = |w: usize| f32::from_bits(lane::uniform_word(uniforms, w, true));
            let mut c = input4::<V>(batch, self.color);
            let cur = (batch.active | batch.helper) & FULL;
            let (zero, one) = (V::zero(), V::splat(1.0));
            for u in &self.units {
                let [s, t, _, q] = input4::<V>(batch, u.coord);
                let unit = lane::uniform_word(uniforms, u.sampler, false);
                let t = lookup_2d_in::<V>(textures, unit, [s, t, q], cur);
                let mut e = [zero; 4];
                if let Some(w) = u.env {
                    for (k, e) in e.iter_mut().enumerate() {
                        *e = V::splat(float(w + k));
                    }
                }
                for k in 0..3 {
                    let (ck, tk) = (c[k], t[k]);
                    c[k] = match u.rgb {
                        RgbOp::Color => ck,
                        RgbOp::Texture => tk,
                        RgbOp::Modulate => V::flush(V::mul(ck, tk)),
                        RgbOp::MixByTextureAlpha => mix::<V>(ck, tk, t[3]),
                        RgbOp::BlendEnv => mix::<V>(ck, e[k], tk),
                        RgbOp::Add => V::flush(V::add(ck, tk)),
                    };
                }
                let (ca, ta) = (c[3], t[3]);
                c[3] = match u.alpha {
                    AlphaOp::Color => ca,
                    AlphaOp::Texture => ta,
                    AlphaOp::Modulate => V::flush(V::mul(ca, ta)),
                    AlphaOp::BlendEnv => mix::<V>(ca, e[3], ta),
                    AlphaOp::Add => V::flush(V::add(ca, ta)),
                };
                for ck in c.iter_mut() {
                    *ck = clamp01::<V>(*ck, zero, one);
                }
            }
            if let Some(sec) = self.secondary {
                for (k, ck) in c.iter_mut().take(3).enumerate() {
                    let sum = V::flush(V::add(*ck, input::<V>(batch, sec + k)));
                    *ck = clamp01::<V>(sum, zero, one);
                }
            }
            if let Some(fog) = &self.fog {
                let z = input::<V>(batch, fog.z);
                let (density, end, scale) = (float(fog.density), float(fog.end), float(fog.scale));
                let f = match fog.mode {
                    FogMode::Linear => {
                        V::flush(V::mul(V::flush(V::sub(V::splat(end), z)), V::splat(scale)))
                    }
                    FogMode::Exp | FogMode::Exp2 => {
                        let mut arg = [0f32; LANES];
                        V::store(&mut arg, z);
                        let exp2 = fog.mode == FogMode::Exp2;
                        for x in arg.iter_mut() {
                            *x = if exp2 {
                                let dz = lane::mul(density, *x);
                                lane::exp(lane::mul(lane::neg(dz), dz))
                            } else {
                                lane::exp(lane::mul(lane::neg(density), *x))
                            };
                        }
                        V::flush(V::load(&arg))
                    }
                };
                let f = clamp01::<V>(f, zero, one);
                for (k, ck) in c.iter_mut().take(3).enumerate() {
                    *ck = mix::<V>(V::splat(float(fog.color + k)), *ck, f);
                }
            }
            batch.discarded = 0;
            if batch.outputs.len() < self.outputs {
                batch.outputs.resize(self.outputs, [0.0; LANES]);
            }
            let active = batch.active & FULL;
            // `lane::float_output`: NaN canonical, subnormals flushed
            // (every colour value here is a flushed input or result
            // already: a flushed load, `clamp01`'s or `mix`'s). A colour
            // last clamped (by a unit or the colour sum, no fog after) is
            // never NaN: `clamp01` gives 0 for a NaN.
            let clamped =
                (!self.units.is_empty() || self.secondary.is_some()) && self.fog.is_none();
            if !clamped {
                let canonical = V::splat(f32::from_bits(0x7fc0_0000));
                for ck in c.iter_mut() {
                    *ck = V::select(V::ordered(*ck, *ck), *ck, canonical);
                }
            }
            // (gl_FragColor's four components are inside the outputs:
            // `Plan::new` found them in the interface, sized above.)
            let Some(dst) = batch.outputs.get_mut(self.out..self.out + 4) else {
                return;
            };
            if active == FULL {
                for (d, v) in dst.iter_mut().zip(c) {
                    V::store(d, v);
                }
            } else {
                let m = V::mask(active);
                for (d, v) in dst.iter_mut().zip(c) {
                    V::store_masked(d, m, v);
                }
            }
        }
    }

    /// The kernel's run on `batch`: every lane (helpers included, for the
    /// lookups' derivatives), outputs stored for the active lanes. Each
    /// operation runs over all the lanes at once (plain loops, which
    /// vectorize).
    #[inline(always)]
    fn run_with(&self, batch: &mut Batch, uniforms: &[u32], textures: &dyn Textures) {
        let input = |i: usize| -> Lanes {
            match batch.inputs.get(i) {
                Some(v) => each1(v, flush),
                None => [0.0; LANES],
            }
        };
        let float = |w: usize| f32::from_bits(lane::uniform_word(uniforms, w, true));
        let mut c = [
            input(self.color),
            input(self.color + 1),
            input(self.color + 2),
            input(self.color + 3),
        ];
        let cur = (batch.active | batch.helper) & FULL;
        for u in &self.units {
            let (s, t, q) = (input(u.coord), input(u.coord + 1), input(u.coord + 3));
            let unit = lane::uniform_word(uniforms, u.sampler, false);
            let mut texel = [[0f32; LANES]; 4];
            lookup_2d(textures, unit, &s, &t, &q, cur, &mut texel);
            let t = &texel;
            let e = |k: usize| u.env.map_or(0.0, |w| float(w + k));
            for k in 0..3 {
                let (ck, tk) = (&c[k], &t[k]);
                c[k] = match u.rgb {
                    RgbOp::Color => *ck,
                    RgbOp::Texture => *tk,
                    RgbOp::Modulate => each2(ck, tk, lane::mul),
                    RgbOp::MixByTextureAlpha => each3(ck, tk, &t[3], lane::mix),
                    RgbOp::BlendEnv => each3(ck, &[e(k); LANES], tk, lane::mix),
                    RgbOp::Add => each2(ck, tk, lane::add),
                };
            }
            let (ca, ta) = (&c[3], &t[3]);
            c[3] = match u.alpha {
                AlphaOp::Color => *ca,
                AlphaOp::Texture => *ta,
                AlphaOp::Modulate => each2(ca, ta, lane::mul),
                AlphaOp::BlendEnv => each3(ca, &[e(3); LANES], ta, lane::mix),
                AlphaOp::Add => each2(ca, ta, lane::add),
            };
            for ck in c.iter_mut() {
                *ck = each1(ck, |x| lane::clamp(x, 0.0, 1.0));
            }
        }
        if let Some(sec) = self.secondary {
            for (k, ck) in c.iter_mut().take(3).enumerate() {
                let sum = each2(ck, &input(sec + k), lane::add);
                *ck = each1(&sum, |x| lane::clamp(x, 0.0, 1.0));
            }
        }
        if let Some(fog) = &self.fog {
            let z = input(fog.z);
            let (density, end, scale) = (float(fog.density), float(fog.end), float(fog.scale));
            let f = match fog.mode {
                FogMode::Linear => each1(&z, |z| lane::mul(lane::sub(end, z), scale)),
                FogMode::Exp => each1(&z, |z| lane::exp(lane::mul(lane::neg(density), z))),
                FogMode::Exp2 => each1(&z, |z| {
                    let dz = lane::mul(density, z);
                    lane::exp(lane::mul(lane::neg(dz), dz))
                }),
            };
            let f = each1(&f, |f| lane::clamp(f, 0.0, 1.0));
            for (k, ck) in c.iter_mut().take(3).enumerate() {
                *ck = each3(&[float(fog.color + k); LANES], ck, &f, lane::mix);
            }
        }
        batch.discarded = 0;
        if batch.outputs.len() < self.outputs {
            batch.outputs.resize(self.outputs, [0.0; LANES]);
        }
        let active = batch.active & FULL;
        for (k, ck) in c.iter().enumerate() {
            let mut v = [0.0f32; LANES];
            for l in 0..LANES {
                v[l] = f32::from_bits(lane::float_output(ck[l].to_bits()));
            }
            let Some(dst) = batch.outputs.get_mut(self.out + k) else {
                continue;
            };
            if active == FULL {
                *dst = v;
            } else {
                for (l, (d, v)) in dst.iter_mut().zip(v).enumerate() {
                    if active & (1 << l) != 0 {
                        *d = v;
                    }
                }
            }
        }
    }
}

/// One value per lane.
type Lanes = [f32; LANES];

/// `op` on every lane.
#[inline(always)]
fn each1(a: &Lanes, op: impl Fn(f32) -> f32) -> Lanes {
    let mut out = [0.0; LANES];
    for l in 0..LANES {
        out[l] = op(a[l]);
    }
    out
}

/// `op` on every lane of two operands.
#[inline(always)]
fn each2(a: &Lanes, b: &Lanes, op: impl Fn(f32, f32) -> f32) -> Lanes {
    let mut out = [0.0; LANES];
    for l in 0..LANES {
        out[l] = op(a[l], b[l]);
    }
    out
}

/// `op` on every lane of three operands.
#[inline(always)]
fn each3(a: &Lanes, b: &Lanes, c: &Lanes, op: impl Fn(f32, f32, f32) -> f32) -> Lanes {
    let mut out = [0.0; LANES];
    for l in 0..LANES {
        out[l] = op(a[l], b[l], c[l]);
    }
    out
}

/// Input component `i` of `batch`, flushed (zeros past the inputs).
///
/// # Safety
/// As for [`Plan::run_in`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn input<V: Lanes16>(batch: &Batch, i: usize) -> V::F {
    // SAFETY: the caller's contract.
    unsafe {
        match batch.inputs.get(i) {
            Some(v) => V::flush(V::load(v)),
            None => V::zero(),
        }
    }
}

/// Input components `i..i + 4` of `batch`, flushed (zeros past the
/// inputs; one bounds check when all four are there).
///
/// # Safety
/// As for [`Plan::run_in`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn input4<V: Lanes16>(batch: &Batch, i: usize) -> [V::F; 4] {
    // SAFETY: the caller's contract.
    unsafe {
        // (No closures: see `exec::lanes16`.)
        match batch.inputs.get(i..i + 4) {
            Some([a, b, c, d]) => [
                V::flush(V::load(a)),
                V::flush(V::load(b)),
                V::flush(V::load(c)),
                V::flush(V::load(d)),
            ],
            _ => [
                input::<V>(batch, i),
                input::<V>(batch, i + 1),
                input::<V>(batch, i + 2),
                input::<V>(batch, i + 3),
            ],
        }
    }
}

/// `lane::mix` on every lane.
///
/// # Safety
/// As for [`Plan::run_in`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn mix<V: Lanes16>(x: V::F, y: V::F, t: V::F) -> V::F {
    // SAFETY: the caller's contract.
    unsafe {
        let a = V::flush(V::mul(x, V::sub(V::splat(1.0), t)));
        V::flush(V::add(a, V::flush(V::mul(y, t))))
    }
}

/// `lane::clamp(x, 0, 1)` on every lane (`zero`, `one`: those splatted)
/// of a flushed `x`: `lane::max(x, 0)` is 0 where `!(x >= 0)`,
/// `lane::min(m, 1)` is 1 where `!(m <= 1)` (the bounds are not NaN).
/// The result is one of x, 0 and 1, so flushed already: the clamp's
/// flush has nothing to do (every caller's `x` is a flushed load or
/// result).
///
/// # Safety
/// As for [`Plan::run_in`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn clamp01<V: Lanes16>(x: V::F, zero: V::F, one: V::F) -> V::F {
    // SAFETY: the caller's contract.
    unsafe {
        let m = V::select(V::lt_or_nan(x, zero), zero, x);
        V::select(V::gt_or_nan(m, one), one, m)
    }
}

/// [`lookup_2d`] of flushed `(s, t, q)` in `V`'s registers, the texels
/// (flushed, unless the lookup says none needs it) returned in them.
///
/// # Safety
/// As for [`Plan::run_in`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn lookup_2d_in<V: Lanes16>(
    textures: &dyn Textures,
    unit: u32,
    [s, t, q]: [V::F; 3],
    cur: u32,
) -> [V::F; 4] {
    let mut out = [[0f32; LANES]; 4];
    let mut normal = true;
    // SAFETY: the caller's contract.
    unsafe {
        if cur != 0 {
            let (mut s_q, mut t_q) = ([0f32; LANES], [0f32; LANES]);
            // q is 1 on every lane when the coordinates have no q (a
            // constant varying): x / 1 is x, bit for bit but for a
            // signalling NaN's quieting, which no lookup tells apart (a
            // NaN coordinate reads as one whatever its bits), without the
            // two divisions.
            let one = V::splat(1.0);
            if V::bits(V::ge(q, one)) & V::bits(V::not_gt(q, one)) == 0xffff {
                V::store(&mut s_q, s);
                V::store(&mut t_q, t);
            } else {
                V::store(&mut s_q, V::flush(V::div(s, q)));
                V::store(&mut t_q, V::flush(V::div(t, q)));
            }
            normal = textures.sample_2d_implicit(unit, [&s_q, &t_q], cur, &mut out);
        }
        let mut texel = [V::zero(); 4];
        for (v, o) in texel.iter_mut().zip(&out) {
            // (No flush when the lookup says no texel is subnormal; the
            // lanes outside `cur` are zeros.)
            *v = match normal {
                true => V::load(o),
                false => V::flush(V::load(o)),
            };
        }
        texel
    }
}

/// `texture2DProj` of unit `unit` at `(s, t, _, q)` on the lanes `cur`,
/// as the engine runs it: s/q and t/q (`FDiv`), the implicit LOD from
/// their quad differences, the texels flushed into `out` (zero on the
/// other lanes). Inlined into [`Plan::run`]'s variants (compiled for
/// their instruction sets).
#[inline(always)]
fn lookup_2d(
    textures: &dyn Textures,
    unit: u32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    q: &[f32; LANES],
    cur: u32,
    out: &mut [[f32; LANES]; 4],
) {
    *out = [[0f32; LANES]; 4];
    if cur != 0 {
        let (mut s_q, mut t_q) = ([0f32; LANES], [0f32; LANES]);
        for l in 0..LANES {
            s_q[l] = lane::div(s[l], q[l]);
            t_q[l] = lane::div(t[l], q[l]);
        }
        // The request itself (the x86 variants take the shortcut).
        textures.sample(&exec::implicit_2d_request(unit, [&s_q, &t_q], cur), out);
    }
    for c in out.iter_mut() {
        for x in c.iter_mut() {
            *x = flush(*x);
        }
    }
}

impl raster::ShaderStage for FixedFragment {
    fn interface(&self) -> &exec::Interface {
        self.kernel.interface()
    }

    fn run(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        match &self.plan {
            Some(plan) => {
                plan.run(batch, uniforms, textures);
                Ok(())
            }
            None => self.kernel.run(batch, uniforms, textures),
        }
    }

    fn prepare<'t>(
        &self,
        uniforms: &[u32],
        textures: &'t dyn exec::Textures,
    ) -> Option<exec::Prepared<'t>> {
        match self.plan {
            Some(_) => None,
            None => Some(self.kernel.prepare(uniforms, textures)),
        }
    }

    fn run_prepared(
        &self,
        batch: &mut Batch,
        prepared: &exec::Prepared<'_>,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        // (The direct run prepares nothing: `prepare` gave `None`.)
        match &self.plan {
            Some(_) => raster::ShaderStage::run(self, batch, uniforms, textures),
            None => self.kernel.run_prepared(batch, prepared, textures),
        }
    }

    fn depth_only(&self) -> Option<Box<dyn raster::ShaderStage>> {
        raster::ShaderStage::depth_only(&*self.kernel)
    }

    fn does_nothing(&self) -> bool {
        raster::ShaderStage::does_nothing(&*self.kernel)
    }

    fn always_completes(&self) -> bool {
        self.kernel.always_completes()
    }

    fn writes_every_output(&self) -> bool {
        // The plan stores gl_FragColor on every active lane and discards
        // nothing: every output when it is the only one.
        self.plan
            .as_ref()
            .is_some_and(|p| p.out == 0 && p.outputs == 4)
    }

    fn lanes_independent(&self) -> bool {
        self.kernel.lanes_independent()
    }

    fn run_probed(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        lane: usize,
        trace: &mut dyn exec::Trace,
    ) -> Result<(), ExecError> {
        raster::ShaderStage::run_probed(&*self.kernel, batch, uniforms, textures, lane, trace)
    }

    fn run_watching(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        first: u32,
        out: &mut [[u32; LANES]],
    ) -> Result<(), ExecError> {
        raster::ShaderStage::run_watching(&*self.kernel, batch, uniforms, textures, first, out)
    }

    fn run_printing(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        sink: &mut dyn exec::PrintSink,
    ) -> Result<(), ExecError> {
        raster::ShaderStage::run_printing(&*self.kernel, batch, uniforms, textures, sink)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffgen::{fragment_source, UnitShape};
    use raster::ShaderStage;
    use std::sync::Arc;

    pub(super) fn kernel(src: &str) -> Kernel {
        let opts = glsl::CompileOptions::new(glsl::Stage::Fragment);
        let sh = glsl::compile(&[src], &opts);
        assert!(sh.ok(), "{}\n{src}", sh.info_log());
        let prog = glsl::link::link(&[&sh]);
        assert!(prog.ok(), "{}", prog.info_log());
        Kernel::new(&prog.stages[0]).expect("lowers")
    }

    pub(super) struct Rng(pub(super) u32);
    impl Rng {
        fn next(&mut self) -> u32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 17;
            self.0 ^= self.0 << 5;
            self.0
        }
        fn pick<T: Copy>(&mut self, from: &[T]) -> T {
            from[self.next() as usize % from.len()]
        }
        /// Mostly moderate values, some awkward ones.
        fn value(&mut self) -> f32 {
            match self.next() % 16 {
                0 => self.pick(&[0.0, -0.0, 1.0, f32::NAN, f32::INFINITY, -f32::INFINITY]),
                1 => f32::from_bits(self.next() & 0x807f_ffff), // subnormal
                2 => f32::from_bits(self.next()),
                _ => (self.next() >> 8) as f32 / 16_777_216.0 * 3.0 - 1.0,
            }
        }
    }

    pub(super) fn texture(rng: &mut Rng, size: u32) -> Arc<raster::Texture> {
        let mut levels = Vec::new();
        let mut n = size;
        loop {
            let texels = (0..n * n)
                .map(|_| [0; 4].map(|_| (rng.next() % 256) as f32 / 255.0))
                .collect();
            levels.push(raster::Image::new(n, n, 1, texels));
            if n == 1 {
                break;
            }
            n /= 2;
        }
        let mut tex = raster::Texture::new(raster::TextureTarget::Tex2D, levels);
        tex.min_filter = raster::MinFilter::LinearMipmapLinear;
        tex.mag_filter = raster::MagFilter::Linear;
        Arc::new(tex)
    }

    /// The direct run gives the kernel's bits, in every instruction set's
    /// variant the CPU has, on random shapes (every texture environment
    /// function, color sum, each fog mode), uniforms, textures, inputs and
    /// lane masks.
    #[test]
    fn direct_runs_match_the_kernel_bit_for_bit() {
        let mut rng = Rng(0x9e37_79b9);
        let rgb = [
            RgbOp::Color,
            RgbOp::Texture,
            RgbOp::Modulate,
            RgbOp::MixByTextureAlpha,
            RgbOp::BlendEnv,
            RgbOp::Add,
        ];
        let alpha = [
            AlphaOp::Color,
            AlphaOp::Texture,
            AlphaOp::Modulate,
            AlphaOp::BlendEnv,
            AlphaOp::Add,
        ];
        let fogs = [
            None,
            Some(FogMode::Linear),
            Some(FogMode::Exp),
            Some(FogMode::Exp2),
        ];
        let textures = raster::TextureUnits::new(vec![
            raster::TextureUnit {
                tex_2d: Some(texture(&mut rng, 16)),
                ..Default::default()
            },
            raster::TextureUnit::default(),
            raster::TextureUnit {
                tex_2d: Some(texture(&mut rng, 8)),
                lod_bias: 0.5,
                ..Default::default()
            },
        ]);
        let mut checked = 0;
        for round in 0..96 {
            let units: Vec<usize> = match round % 4 {
                0 => vec![],
                1 => vec![0],
                2 => vec![2],
                _ => vec![0, 1, 2],
            };
            let shape = FragmentShape {
                units: units
                    .iter()
                    .map(|&unit| UnitShape {
                        unit,
                        lookup: Lookup::Texture2DProj,
                        rgb: rng.pick(&rgb),
                        alpha: rng.pick(&alpha),
                    })
                    .collect(),
                color_sum: rng.next() & 1 == 0,
                fog: fogs[(round / 4) % 4],
            };
            let k = Arc::new(kernel(&fragment_source(&shape)));
            let stage = FixedFragment::new(k.clone(), &shape);
            assert!(stage.direct(), "{shape:?}");
            let iface = k.interface();
            let mut uniforms: Vec<u32> = (0..iface.uniform_words)
                .map(|_| rng.value().to_bits())
                .collect();
            for u in &shape.units {
                let (w, _) = iface
                    .locate_uniform(&crate::ffgen::sampler_name(u.unit))
                    .expect("sampler");
                uniforms[w] = u.unit as u32;
            }
            let plan = stage.plan.as_ref().expect("direct");
            for i in 0..20 {
                let mut batch = Batch {
                    inputs: (0..iface.input_components)
                        .map(|_| [0.0; LANES].map(|_| rng.value()))
                        .collect(),
                    outputs: vec![[0.5; LANES]; iface.output_components],
                    active: rng.next() & 0xffff,
                    discarded: 0,
                    helper: 0,
                };
                batch.helper = rng.next() & 0xffff & !batch.active;
                // Half the batches with q = 1 everywhere (coordinates
                // without q), which the variants do not divide by.
                if i % 2 == 0 {
                    for u in &plan.units {
                        if let Some(q) = batch.inputs.get_mut(u.coord + 3) {
                            *q = [1.0; LANES];
                        }
                    }
                }
                let mut want = batch.clone();
                k.run(&mut want, &uniforms, &textures).expect("kernel runs");
                let mut got = batch.clone();
                stage.run(&mut got, &uniforms, &textures).expect("runs");
                // And each instruction set's variant the CPU has.
                let mut variants = vec![batch.clone()];
                plan.run_with(&mut variants[0], &uniforms, &textures);
                #[cfg(target_arch = "x86_64")]
                {
                    if X256::supported() {
                        let mut b = batch.clone();
                        // SAFETY: the CPU has the features.
                        unsafe { plan.run_avx2(&mut b, &uniforms, &textures) };
                        variants.push(b);
                    }
                    if X512::supported() {
                        let mut b = batch.clone();
                        // SAFETY: the CPU has the features.
                        unsafe { plan.run_avx512(&mut b, &uniforms, &textures) };
                        variants.push(b);
                    }
                }
                for got in std::iter::once(&got).chain(&variants) {
                    assert_eq!(got.discarded, want.discarded);
                    for (g, w) in got.outputs.iter().zip(&want.outputs) {
                        let (g, w) = (g.map(f32::to_bits), w.map(f32::to_bits));
                        assert_eq!(g, w, "{shape:?}");
                    }
                }
                checked += variants.len();
            }
        }
        // The portable variant at least, on every batch.
        assert!(checked >= 96 * 20);
    }

    /// Other lookups run the kernel.
    #[test]
    fn other_lookups_run_the_kernel() {
        let shape = FragmentShape {
            units: vec![UnitShape {
                unit: 0,
                lookup: Lookup::TextureCube,
                rgb: RgbOp::Modulate,
                alpha: AlphaOp::Modulate,
            }],
            color_sum: false,
            fog: None,
        };
        let k = Arc::new(kernel(&fragment_source(&shape)));
        assert!(!FixedFragment::new(k, &shape).direct());
    }
}

/// `cargo test --release -p shaderbox-gl bench_direct_run -- --ignored
/// --nocapture`: time per batch of the direct run and of the kernel on
/// full batches, for the shapes of the fixed-function mesh (linear fog)
/// and of the textured layers (MODULATE of a trilinear 512² texture).
#[cfg(test)]
mod bench {
    use super::tests::{kernel, texture, Rng};
    use super::*;
    use crate::ffgen::{fragment_source, UnitShape};
    use raster::ShaderStage;

    #[test]
    #[ignore]
    fn bench_direct_run() {
        let fog = FragmentShape {
            units: vec![],
            color_sum: false,
            fog: Some(FogMode::Linear),
        };
        let textured = FragmentShape {
            units: vec![UnitShape {
                unit: 0,
                lookup: Lookup::Texture2DProj,
                rgb: RgbOp::Modulate,
                alpha: AlphaOp::Modulate,
            }],
            color_sum: false,
            fog: None,
        };
        let textures = raster::TextureUnits::new(vec![raster::TextureUnit {
            tex_2d: Some(texture(&mut Rng(7), 512)),
            ..Default::default()
        }]);
        for (name, shape) in [("linear fog", fog), ("textured", textured)] {
            let k = Arc::new(kernel(&fragment_source(&shape)));
            let stage = FixedFragment::new(k.clone(), &shape);
            let iface = k.interface();
            let uniforms = vec![0u32; iface.uniform_words];
            // Colour 0.5, texture coordinates over a few texels per quad
            // (q = 1).
            let mut inputs = vec![[0.5; LANES]; iface.input_components];
            if let Some(tc) = iface.input("gl_TexCoord") {
                let (x, y) = (
                    std::array::from_fn(|l| 0.3 + ((l & 1) + 2 * (l / 4)) as f32 / 700.0),
                    std::array::from_fn(|l| 0.6 + ((l >> 1) & 1) as f32 / 600.0),
                );
                inputs[tc.offset] = x;
                inputs[tc.offset + 1] = y;
                inputs[tc.offset + 3] = [1.0; LANES];
            }
            let mut batch = Batch {
                inputs,
                outputs: vec![[0.0; LANES]; iface.output_components],
                active: 0xffff,
                discarded: 0,
                helper: 0,
            };
            const RUNS: u32 = 300_000;
            // Alternating, best of three (the machine is shared).
            let (mut direct, mut engine) = (f64::MAX, f64::MAX);
            for _ in 0..3 {
                let t = std::time::Instant::now();
                for _ in 0..RUNS {
                    stage.run(&mut batch, &uniforms, &textures).expect("runs");
                }
                direct = direct.min(t.elapsed().as_secs_f64());
                let t = std::time::Instant::now();
                for _ in 0..RUNS {
                    k.run(&mut batch, &uniforms, &textures).expect("runs");
                }
                engine = engine.min(t.elapsed().as_secs_f64());
            }
            let ns = |s: f64| s / RUNS as f64 * 1e9;
            println!(
                "{name}: direct {:.1} ns per batch, kernel {:.1} ns",
                ns(direct),
                ns(engine)
            );
        }
    }
}
