//! Text listings of a kernel's programs, for snapshot tests and for
//! reading what lowering and the executor's rewrite made of a shader:
//! [`Kernel::print_lowered`] (the program as lowered, which the
//! reference interpreter and `run_traced` run) and
//! [`Kernel::print_rewritten`] (the program the executor runs, after the
//! optimizer's rewrite, `opt`: hoisting into the prologue, dead code,
//! store fusion).
//!
//! Both listings start with the same header and interface:
//!
//! ```text
//! ; fragment kernel, lowered: 212 ops, 96 registers, 7 mask slots, 0 subroutines
//! in  gl_FragCoord vec4 [0..4) -> r0 r1 r2 -
//! out gl_FragColor vec4 [0..4) <- r10 r11 r12 r13
//! uniform viewport vec4 words [0..4)
//! uniform light_enabled float[8] words [4..12) unread
//! ```
//!
//! - `in`: each input variable, its type, its components in
//!   `Batch::inputs` and the register each component is loaded into (`-`:
//!   not loaded); `unread` when the program never reads it.
//! - `out`: each output, its components in `Batch::outputs` and the
//!   register each is taken from (`-`: none); `unwritten` when the shader
//!   never writes it.
//! - `uniform`: each uniform and its range of uniform words; `unread`
//!   when the program never reads it.
//!
//! The lowered listing goes on with the named variables (`var name type
//! rA..rB`: the registers of each global and inlined local), the
//! registers set before the first op (`init r5 = 0x3f800000 ; 1.0`), then
//! one op per line, numbered from 0 (jump targets are these numbers), with
//! a `; stmt @S..E` line (the source span's byte offsets) before the first
//! op of each source statement:
//!
//! ```text
//!    0  fmul r12, r0, r40
//!    1  store r20, r12
//!    2  jnone -> 9
//! ```
//!
//! The rewritten listing has no variables or statement marks; after the
//! interface it gives the pool (`pool r96..r130`: registers the prologue
//! fills once per run or per draw), the registers zeroed at the start of a
//! run (`zero`), the registers read as outputs (`live out`), the
//! `init` registers, then `prologue:` and its ops, then `program:` and the
//! rewritten ops. An op whose destination is written under the current
//! mask (a fused store) has the suffix `.m` on its name: `fmul.m r20, r0,
//! r40`.
//!
//! Ops (destination first; `rN` a register, `mN` a mask slot, `sN` a
//! subroutine's return-address slot, `-> N` an op number):
//! - data: `const rD, 0x3f800000 ; 1.0` (the bits, and as a reading aid
//!   the value as an int when the bits are one of magnitude below 2^16,
//!   else as a float), `mov`, `store` (masked copy), `uniform rD, u[W]`
//!   (`uniform.f`: a float word, subnormals read as zero), `fadd` `fsub`
//!   `fmul` `fdiv` `fneg` `fmac` (`d += a * b`), `dotN rD, (a..), (b..)`,
//!   the `glsl::math` functions by name (`sin`, `pow`, `clamp`,
//!   `inversesqrt`...), `flt` `fle` `feq`, `iadd` `isub` `imul` `idiv`
//!   `ineg` `ilt` `ile` `ieq`, `and` `or` `xor` `not`, `ftoi` `itof` `ftob`
//!   `itob` `btof`, `select rD, c, a, b` (`c ? a : b`), `clampidx rD, a,
//!   max M, stride S`, `gather rD, rB[off max M]`, `scatter rB[off max M],
//!   a`, `gatheru rD, u[W + off max M]`, `ddx`, `ddy`, `noise rD..(n),
//!   rA..(dims)`;
//! - `texture #I sampler2D unit rU coord (s, t, r, q) dims N [compare rC]
//!   lod implicit [bias rB] | lod explicit [rL] -> rD..rD+3`;
//! - `printf #I "format" args`;
//! - control: `savemask mN`, `restoremask mN`, `andmask rC`,
//!   `andnotmask mN, rC`, `jnone -> N` (jump when no lane is active),
//!   `jump -> N`, `loopiter`, `kill [mA mB]` and `discard [mA mB]` (the
//!   mask slots the lanes leave), `call -> N, sK`, `ret sK`,
//!   `syncdiscard [mA mB]`.
//!
//! The listings are deterministic: they depend only on the stage's IR.

use crate::interface::{Interface, Slot};
use crate::program::{Op, Program, Reg, TexKind, TexLod, F1, F2, F3};
use crate::Kernel;
use std::fmt::Write;

impl Kernel {
    /// The lowered program as text: header, interface, variables, initial
    /// registers, ops (the format: [`crate::print`]).
    pub fn print_lowered(&self) -> String {
        let p = &self.program;
        let mut out = String::new();
        header(&mut out, self, "lowered", p);
        self.print_interface(&mut out);
        for v in &p.vars {
            let _ = writeln!(
                out,
                "var {} {} {}",
                v.name,
                ty_name(v.ty, &self.interface),
                range(v.first_register, v.registers)
            );
        }
        print_init(&mut out, p);
        let width = digits(p.ops.len());
        let mut marks = p.statements.iter().peekable();
        for (i, op) in p.ops.iter().enumerate() {
            while let Some(m) = marks.next_if(|m| m.op as usize <= i) {
                let _ = writeln!(out, "; stmt @{}..{}", m.span.start, m.span.end);
            }
            let _ = writeln!(out, "{i:>width$}  {}", op_text(op, false, p));
        }
        out
    }

    /// The program the executor runs, after the rewrite, as text: header,
    /// interface, pool, zeroed and output registers, initial registers,
    /// prologue, ops (the format: [`crate::print`]).
    pub fn print_rewritten(&self) -> String {
        let code = &self.code;
        let p = &code.prog;
        let mut out = String::new();
        header(&mut out, self, "rewritten", p);
        self.print_interface(&mut out);
        let _ = writeln!(
            out,
            "pool {}",
            range(code.pool_base, p.registers.saturating_sub(code.pool_base))
        );
        let _ = writeln!(out, "zero {}", reg_set(&code.zero));
        let _ = writeln!(out, "live out {}", reg_set(&code.live_out));
        print_init(&mut out, p);
        let _ = writeln!(out, "prologue: {} ops", code.prologue.len());
        let width = digits(code.prologue.len().max(code.ins.len()));
        for (i, op) in code.prologue.iter().enumerate() {
            let _ = writeln!(out, "{i:>width$}  {}", op_text(op, false, p));
        }
        let _ = writeln!(out, "program: {} ops", code.ins.len());
        for (i, ins) in code.ins.iter().enumerate() {
            let _ = writeln!(out, "{i:>width$}  {}", op_text(&ins.op, ins.masked, p));
        }
        out
    }

    fn print_interface(&self, out: &mut String) {
        let itf = &self.interface;
        for s in &itf.inputs {
            let reg = |c| self.inputs.iter().find(|i| i.0 == c).map(|i| i.1);
            slot_line(out, "in ", "->", s, itf, reg, "unread");
        }
        for s in &itf.outputs {
            let reg = |c| self.outputs.iter().find(|o| o.1 == c).map(|o| o.0);
            slot_line(out, "out", "<-", s, itf, reg, "unwritten");
        }
        for s in &itf.uniforms {
            let _ = writeln!(
                out,
                "uniform {} {} words [{}..{}){}",
                s.name,
                ty_name(s.ty, itf),
                s.offset,
                s.offset + s.components,
                if s.written { "" } else { " unread" }
            );
        }
    }
}

/// One input or output line: the slot, then the register that holds each
/// of its components (`-` for none), then `unused` when the program does
/// not use the slot.
fn slot_line(
    out: &mut String,
    dir: &str,
    arrow: &str,
    s: &Slot,
    itf: &Interface,
    reg: impl Fn(usize) -> Option<u32>,
    unused: &str,
) {
    let regs: Vec<String> = (s.offset..s.offset + s.components)
        .map(|c| reg(c).map_or("-".to_string(), |r| format!("r{r}")))
        .collect();
    let _ = writeln!(
        out,
        "{dir} {} {arrow} {}{}",
        slot(s, itf),
        regs.join(" "),
        if s.written {
            String::new()
        } else {
            format!(" {unused}")
        }
    );
}

fn header(out: &mut String, k: &Kernel, what: &str, p: &Program) {
    let _ = writeln!(
        out,
        "; {} kernel, {what}: {} ops, {} registers, {} mask slots, {} subroutines",
        k.stage.name(),
        p.ops.len(),
        p.registers,
        p.mask_slots,
        p.subroutines
    );
}

fn print_init(out: &mut String, p: &Program) {
    for &(r, bits) in &p.init {
        let _ = writeln!(out, "init r{r} = {}", bits_text(bits));
    }
}

fn ty_name(ty: glsl::types::Type, itf: &Interface) -> String {
    let names = |id: glsl::types::StructId| {
        itf.structs
            .get(id.0 as usize)
            .map_or_else(|| "<struct>".to_string(), |s| s.name.clone())
    };
    ty.display(&names).to_string()
}

fn slot(s: &Slot, itf: &Interface) -> String {
    format!(
        "{} {} [{}..{})",
        s.name,
        ty_name(s.ty, itf),
        s.offset,
        s.offset + s.components
    )
}

fn digits(n: usize) -> usize {
    n.max(1).saturating_sub(1).to_string().len()
}

/// `rA..rB` (inclusive) for `n` registers from `first`; `-` for none.
fn range(first: Reg, n: u32) -> String {
    match n {
        0 => "-".to_string(),
        1 => format!("r{first}"),
        _ => format!("r{first}..r{}", first + n - 1),
    }
}

/// Registers in order, runs of consecutive ones as `rA..rB`; `-` for none.
fn reg_set(regs: &[Reg]) -> String {
    let mut sorted = regs.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    let mut parts = Vec::new();
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i;
        while j + 1 < sorted.len() && sorted[j + 1] == sorted[j] + 1 {
            j += 1;
        }
        parts.push(range(sorted[i], (j - i + 1) as u32));
        i = j + 1;
    }
    if parts.is_empty() {
        "-".to_string()
    } else {
        parts.join(" ")
    }
}

/// `0x3f800000 ; 1.0`: the bits, then the value as an int when the bits
/// are a small int, else as a float.
fn bits_text(bits: u32) -> String {
    let i = bits as i32;
    if (-0x10000..0x10000).contains(&i) {
        format!("{bits:#010x} ; {i}")
    } else {
        format!("{bits:#010x} ; {:?}", f32::from_bits(bits))
    }
}

fn f1_name(f: F1) -> &'static str {
    match f {
        F1::Radians => "radians",
        F1::Degrees => "degrees",
        F1::Sin => "sin",
        F1::Cos => "cos",
        F1::Tan => "tan",
        F1::Asin => "asin",
        F1::Acos => "acos",
        F1::Atan => "atan",
        F1::Exp => "exp",
        F1::Log => "log",
        F1::Exp2 => "exp2",
        F1::Log2 => "log2",
        F1::Sqrt => "sqrt",
        F1::InverseSqrt => "inversesqrt",
        F1::Abs => "abs",
        F1::Sign => "sign",
        F1::Floor => "floor",
        F1::Ceil => "ceil",
        F1::Fract => "fract",
        F1::Sinh => "sinh",
        F1::Cosh => "cosh",
        F1::Tanh => "tanh",
        F1::Asinh => "asinh",
        F1::Acosh => "acosh",
        F1::Atanh => "atanh",
        F1::Trunc => "trunc",
        F1::Round => "round",
        F1::RoundEven => "roundEven",
        F1::ModfFract => "modf_fract",
        F1::FlushBits => "flush_bits",
    }
}

fn f2_name(f: F2) -> &'static str {
    match f {
        F2::Atan2 => "atan2",
        F2::Pow => "pow",
        F2::Mod => "mod",
        F2::Min => "min",
        F2::Max => "max",
        F2::Step => "step",
    }
}

fn f3_name(f: F3) -> &'static str {
    match f {
        F3::Clamp => "clamp",
        F3::Mix => "mix",
        F3::SmoothStep => "smoothstep",
    }
}

/// `[m1 m4]`: the mask slots `kill_slots[start..end]`.
fn slots(p: &Program, start: u32, end: u32) -> String {
    let s: Vec<String> = p
        .kill_slots
        .get(start as usize..end as usize)
        .unwrap_or(&[])
        .iter()
        .map(|m| format!("m{m}"))
        .collect();
    format!("[{}]", s.join(" "))
}

fn opt_reg(r: Option<Reg>) -> String {
    r.map_or_else(|| "-".to_string(), |r| format!("r{r}"))
}

/// One op; `masked`: its destination is written under the current mask.
fn op_text(op: &Op, masked: bool, p: &Program) -> String {
    use Op::*;
    let m = if masked { ".m" } else { "" };
    let un = |name: &str, d: Reg, a: Reg| format!("{name}{m} r{d}, r{a}");
    let bin = |name: &str, d: Reg, a: Reg, b: Reg| format!("{name}{m} r{d}, r{a}, r{b}");
    match *op {
        Const { d, bits } => format!("const{m} r{d}, {}", bits_text(bits)),
        Load { d, space, addr } => format!("load{m} r{d}, mem[r{space}][r{addr}]"),
        StoreMem { space, addr, a } => format!("storemem mem[r{space}][r{addr}], r{a}"),
        Atomic {
            f,
            d,
            space,
            addr,
            a,
            b,
        } => format!("atomic.{f:?}{m} r{d}, mem[r{space}][r{addr}], r{a}, r{b}"),
        MemSize { d, space } => format!("memsize{m} r{d}, mem[r{space}]"),
        Barrier => "barrier".to_string(),
        Mov { d, a } => un("mov", d, a),
        Store { d, a } => un("store", d, a),
        Uniform { d, word, float } => {
            format!(
                "uniform{}{m} r{d}, u[{word}]",
                if float { ".f" } else { "" }
            )
        }
        FAdd { d, a, b } => bin("fadd", d, a, b),
        FSub { d, a, b } => bin("fsub", d, a, b),
        FMul { d, a, b } => bin("fmul", d, a, b),
        FDiv { d, a, b } => bin("fdiv", d, a, b),
        FNeg { d, a } => un("fneg", d, a),
        FMac { d, a, b } => bin("fmac", d, a, b),
        Dot { d, n, a, b } => {
            let n = (n as usize).min(4);
            let list = |v: &[Reg]| {
                v.iter()
                    .map(|r| format!("r{r}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            format!("dot{n}{m} r{d}, ({}), ({})", list(&a[..n]), list(&b[..n]))
        }
        F1 { f, d, a } => un(f1_name(f), d, a),
        F2 { f, d, a, b } => bin(f2_name(f), d, a, b),
        F3 { f, d, a, b, c } => format!("{}{m} r{d}, r{a}, r{b}, r{c}", f3_name(f)),
        FLt { d, a, b } => bin("flt", d, a, b),
        FLe { d, a, b } => bin("fle", d, a, b),
        FEq { d, a, b } => bin("feq", d, a, b),
        IAdd { d, a, b } => bin("iadd", d, a, b),
        ISub { d, a, b } => bin("isub", d, a, b),
        IMul { d, a, b } => bin("imul", d, a, b),
        IDiv { d, a, b } => bin("idiv", d, a, b),
        INeg { d, a } => un("ineg", d, a),
        ILt { d, a, b } => bin("ilt", d, a, b),
        ILe { d, a, b } => bin("ile", d, a, b),
        IEq { d, a, b } => bin("ieq", d, a, b),
        UDiv { d, a, b } => bin("udiv", d, a, b),
        IMod { d, a, b } => bin("imod", d, a, b),
        UMod { d, a, b } => bin("umod", d, a, b),
        ULt { d, a, b } => bin("ult", d, a, b),
        ULe { d, a, b } => bin("ule", d, a, b),
        Shl { d, a, b } => bin("shl", d, a, b),
        ShrS { d, a, b } => bin("shrs", d, a, b),
        ShrU { d, a, b } => bin("shru", d, a, b),
        BitAnd { d, a, b } => bin("band", d, a, b),
        BitOr { d, a, b } => bin("bor", d, a, b),
        BitXor { d, a, b } => bin("bxor", d, a, b),
        BitNot { d, a } => un("bnot", d, a),
        And { d, a, b } => bin("and", d, a, b),
        Or { d, a, b } => bin("or", d, a, b),
        Xor { d, a, b } => bin("xor", d, a, b),
        Not { d, a } => un("not", d, a),
        FToI { d, a } => un("ftoi", d, a),
        IToF { d, a } => un("itof", d, a),
        FToU { d, a } => un("ftou", d, a),
        UToF { d, a } => un("utof", d, a),
        FToB { d, a } => un("ftob", d, a),
        IToB { d, a } => un("itob", d, a),
        BToF { d, a } => un("btof", d, a),
        Select { d, c, a, b } => format!("select{m} r{d}, r{c}, r{a}, r{b}"),
        ClampIdx { d, a, max, stride } => {
            format!("clampidx{m} r{d}, r{a}, max {max}, stride {stride}")
        }
        Gather { d, base, off, max } => format!("gather{m} r{d}, r{base}[r{off} max {max}]"),
        Scatter { base, off, max, a } => format!("scatter r{base}[r{off} max {max}], r{a}"),
        GatherUniform {
            d,
            word,
            off,
            max,
            float,
        } => format!(
            "gatheru{}{m} r{d}, u[{word} + r{off} max {max}]",
            if float { ".f" } else { "" }
        ),
        DdX { d, a } => un("ddx", d, a),
        DdY { d, a } => un("ddy", d, a),
        Noise { d, n, a, dims } => {
            format!("noise{m} {}, {}", range(d, n as u32), range(a, dims as u32))
        }
        Texture { index } => match p.textures.get(index as usize) {
            Some(t) => {
                let kind = match t.kind {
                    TexKind::Sample => "texture",
                    TexKind::Fetch => "texel_fetch",
                    TexKind::Size => "texture_size",
                };
                let mut s = format!(
                    "{kind} #{index} {} unit r{} coord (r{} r{} r{} r{}) dims {}",
                    t.target.name(),
                    t.unit,
                    t.coord[0],
                    t.coord[1],
                    t.coord[2],
                    t.coord[3],
                    t.dims
                );
                if let Some(c) = t.compare {
                    let _ = write!(s, " compare r{c}");
                }
                match t.lod {
                    TexLod::Implicit { bias } => {
                        s.push_str(" lod implicit");
                        if let Some(b) = bias {
                            let _ = write!(s, " bias r{b}");
                        }
                    }
                    TexLod::Explicit(l) => {
                        let _ = write!(s, " lod explicit {}", opt_reg(l));
                    }
                    TexLod::Grad { ddx, ddy } => {
                        let _ = write!(
                            s,
                            " grad x (r{} r{} r{}) y (r{} r{} r{})",
                            ddx[0], ddx[1], ddx[2], ddy[0], ddy[1], ddy[2]
                        );
                    }
                }
                if let Some(o) = t.offset {
                    let _ = write!(s, " offset (r{} r{} r{})", o[0], o[1], o[2]);
                }
                let _ = write!(s, " -> {}", range(t.d, 4));
                s
            }
            None => format!("texture #{index} <missing>"),
        },
        Printf { index } => match p.printfs.get(index as usize) {
            Some(site) => {
                let args: Vec<String> = site.args.iter().map(|r| format!("r{r}")).collect();
                format!(
                    "printf #{index} \"{}\" {}",
                    glsl::ir::print::format_string(&site.format),
                    args.join(" ")
                )
            }
            None => format!("printf #{index} <missing>"),
        },
        SaveMask { slot } => format!("savemask m{slot}"),
        RestoreMask { slot } => format!("restoremask m{slot}"),
        AndMask { c } => format!("andmask r{c}"),
        AndNotMask { slot, c } => format!("andnotmask m{slot}, r{c}"),
        JumpIfNone { target } => format!("jnone -> {target}"),
        Jump { target } => format!("jump -> {target}"),
        LoopIter => "loopiter".to_string(),
        Kill { start, end } => format!("kill {}", slots(p, start, end)),
        Discard { start, end } => format!("discard {}", slots(p, start, end)),
        Call { target, slot } => format!("call -> {target}, s{slot}"),
        Ret { slot } => format!("ret s{slot}"),
        SyncDiscard { start, end } => format!("syncdiscard {}", slots(p, start, end)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn register_sets_and_constants() {
        assert_eq!(reg_set(&[]), "-");
        assert_eq!(reg_set(&[7, 1, 2, 3, 9, 8]), "r1..r3 r7..r9");
        assert_eq!(reg_set(&[4]), "r4");
        assert_eq!(bits_text(1.0f32.to_bits()), "0x3f800000 ; 1.0");
        assert_eq!(bits_text(3), "0x00000003 ; 3");
        assert_eq!(bits_text(-1i32 as u32), "0xffffffff ; -1");
        assert_eq!(bits_text((-0.5f32).to_bits()), "0xbf000000 ; -0.5");
    }
}
