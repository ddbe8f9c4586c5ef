//! The level of detail of every lane of a request, as `levels::lambda`
//! computes it lane by lane: λ_base once per 2×2 quad from its first
//! lane's derivatives (given, or the quad differences of s and t), then
//! each lane's biases and the texture's clamps (the x86 variants take
//! the derivatives in registers, `wide::quad_derivatives`). The levels λ
//! selects are picked by the driver (`sample_in`), over the lanes.

use super::LodRef;
#[cfg(target_arch = "x86_64")]
use super::{NO_WIDE, WIDE_AVX512, X256, X512};
use crate::ex::LANES;
use crate::texture::levels::{lod_log2, MAX_LOD_BIAS};
use crate::texture::{Image, Texture};

/// `levels::lambda` for every lane (the lanes outside the request's
/// mask get some value): with derivatives, λ_base once per quad from the
/// derivatives of its first lane (`levels::quad_first`), then each
/// lane's biases and clamps. In the x86 variants (`WIDE`) every lane
/// takes its quad's derivatives in registers (`wide::quad_derivatives`)
/// and λ_base is computed for all sixteen; the portable one computes it
/// for the quads' first lanes (eight lanes, the four twice: four-lane
/// loops compile to scalar code) and spreads it.
#[inline(always)]
pub(super) fn lambdas<const WIDE: u8>(
    tex: &Texture,
    base_img: &Image,
    unit_bias: f32,
    lod: LodRef,
    st: [&[f32; LANES]; 2],
) -> [f32; LANES] {
    // (Loops, not closures: a closure is compiled without the caller's
    // target features.)
    const HALF: usize = LANES / 2;
    let (given, bias) = match lod {
        LodRef::Explicit(v) => {
            // The general path adds a shader bias of 0.
            return clamp_lambdas(tex, v, &[unit_bias + 0.0; LANES]);
        }
        LodRef::Derivatives { ddx, ddy, bias } => (Some([ddx[0], ddx[1], ddy[0], ddy[1]]), bias),
        LodRef::Implicit => (None, &[0.0; LANES]),
    };
    let mut extra = [0.0f32; LANES];
    for l in 0..LANES {
        extra[l] = unit_bias + bias[l];
    }
    #[cfg(target_arch = "x86_64")]
    if WIDE != NO_WIDE {
        // SAFETY: `WIDE` names the instruction set of the code this is
        // inlined into, which runs only on CPUs that have it.
        let [sx, tx, sy, ty] = unsafe {
            if WIDE == WIDE_AVX512 {
                super::wide::quad_derivatives::<X512>(given, st)
            } else {
                super::wide::quad_derivatives::<X256>(given, st)
            }
        };
        let base = lambda_bases(base_img, [&sx, &tx], [&sy, &ty]);
        return clamp_lambdas(tex, &base, &extra);
    }
    // The quads' first lanes' derivatives (S along x, T along x, S along
    // y, T along y), the four quads twice.
    let mut first = [[0.0f32; HALF]; 4];
    match given {
        Some(given) => {
            for (f, a) in first.iter_mut().zip(given) {
                for k in 0..HALF {
                    f[k] = a[4 * (k % (LANES / 4))];
                }
            }
        }
        None => {
            let [s, t] = st;
            let [sx, tx, sy, ty] = &mut first;
            let rows = sx
                .iter_mut()
                .zip(tx.iter_mut())
                .zip(sy.iter_mut().zip(ty.iter_mut()));
            for (k, ((sx, tx), (sy, ty))) in rows.enumerate() {
                let q = 4 * (k % (LANES / 4));
                (*sx, *tx) = (s[q + 1] - s[q], t[q + 1] - t[q]);
                (*sy, *ty) = (s[q + 2] - s[q], t[q + 2] - t[q]);
            }
        }
    }
    let quads = lambda_bases(base_img, [&first[0], &first[1]], [&first[2], &first[3]]);
    let mut base = [0.0f32; LANES];
    for l in 0..LANES {
        base[l] = quads[l / 4];
    }
    clamp_lambdas(tex, &base, &extra)
}

/// λ_base (`levels::lambda`'s log2 ρ) from the derivatives of S and T,
/// for N lanes at once.
#[inline(always)]
fn lambda_bases<const N: usize>(
    base_img: &Image,
    ddx: [&[f32; N]; 2],
    ddy: [&[f32; N]; 2],
) -> [f32; N] {
    let (w, h) = (base_img.width as f32, base_img.height as f32);
    let mut rho = [0.0f32; N];
    for l in 0..N {
        let (ux, uy) = (ddx[0][l] * w, ddy[0][l] * w);
        let mut sx = 0.0f32 + ux * ux;
        let mut sy = 0.0f32 + uy * uy;
        let (ux, uy) = (ddx[1][l] * h, ddy[1][l] * h);
        sx += ux * ux;
        sy += uy * uy;
        // `math::max(math::sqrt(sx), math::sqrt(sy))` as one square root
        // of the larger sum: a correctly rounded square root (the
        // instruction, as `math::sqrt`) never decreases, so the same
        // value; a NaN sum picks the other as `math::max` picks the other
        // root, and a NaN here makes λ NaN whatever its bits.
        let m = if sx.is_nan() || sx < sy { sy } else { sx };
        rho[l] = m.sqrt();
    }
    // Every lane (`lod_log2` is branch-free and total), so that the loop
    // vectorizes.
    let mut base = [0.0f32; N];
    for l in 0..N {
        base[l] = lod_log2(rho[l]);
    }
    base
}

/// λ = clamp(base + clamp(texture bias + `extra`), min, max), per lane.
#[inline(always)]
fn clamp_lambdas<const N: usize>(tex: &Texture, base: &[f32; N], extra: &[f32; N]) -> [f32; N] {
    let (tex_bias, min_lod, max_lod) = (tex.lod_bias, tex.min_lod, tex.max_lod);
    let mut lam = [0.0f32; N];
    for l in 0..N {
        let b = tex_bias + extra[l];
        // (Constant bounds: the clamp's assertion folds away.)
        let b = b.clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS);
        let mut x = base[l] + b;
        if x > max_lod {
            x = max_lod;
        }
        if x < min_lod {
            x = min_lod;
        }
        lam[l] = x;
    }
    lam
}
