//! Running the memory ops of a program ([`Op::Load`], [`Op::StoreMem`],
//! [`Op::Atomic`], [`Op::MemSize`], [`Op::Barrier`]) against a run's
//! [`Memory`]: the one implementation the engine and the reference
//! interpreter share, lane by lane in lane order.

use crate::memory::Memory;
use crate::program::{Op, Reg};
use crate::{LaneMask, LANES};

/// Runs a memory op ([`Op::Load`], [`Op::StoreMem`], [`Op::Atomic`],
/// [`Op::MemSize`], [`Op::Barrier`]) on the lanes of `cur`, reading
/// registers through `get`; the register it defines and its lanes, if
/// any. `None` for every other op.
pub(crate) fn run_op(
    op: &Op,
    cur: LaneMask,
    get: impl Fn(Reg) -> [u32; LANES],
    mem: Option<&dyn Memory>,
) -> Option<Option<(Reg, [u32; LANES])>> {
    let lanes = (0..LANES).filter(|l| cur & (1 << l) != 0);
    Some(match *op {
        Op::Load { d, space, addr } => {
            let (s, a) = (get(space), get(addr));
            let mut out = [0; LANES];
            if let Some(m) = mem {
                for l in lanes {
                    out[l] = m.load(s[l], a[l]);
                }
            }
            Some((d, out))
        }
        Op::StoreMem { space, addr, a } => {
            let (s, ad, v) = (get(space), get(addr), get(a));
            if let Some(m) = mem {
                for l in lanes {
                    m.store(s[l], ad[l], v[l]);
                }
            }
            None
        }
        Op::Atomic {
            f,
            d,
            space,
            addr,
            a,
            b,
        } => {
            let (s, ad, x, y) = (get(space), get(addr), get(a), get(b));
            let mut out = [0; LANES];
            if let Some(m) = mem {
                for l in lanes {
                    out[l] = m.atomic(s[l], ad[l], f, x[l], y[l]);
                }
            }
            Some((d, out))
        }
        Op::MemSize { d, space } => {
            let s = get(space);
            let mut out = [0; LANES];
            if let Some(m) = mem {
                for l in 0..LANES {
                    out[l] = m.size(s[l]);
                }
            }
            Some((d, out))
        }
        Op::Barrier => {
            if let Some(m) = mem {
                m.barrier();
            }
            None
        }
        _ => return None,
    })
}
