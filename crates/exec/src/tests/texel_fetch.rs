//! Texel fetches through every executor: native code loads the texels of
//! the levels `Textures::texel_level` gives itself, and must compute the
//! bits `Textures::fetch` gives (the reference interpreter's and the
//! portable executor's): every storage format, coordinates outside the
//! level on every side, offsets, levels, arrays and 1D targets, lanes off,
//! lanes reading different levels (which go back to `fetch`); size
//! queries, hoisted into the prologue for a uniform sampler and level,
//! with and without a prepared pool.

use super::{bits_of, kernel, uniforms};
use crate::{
    supported_variants, Batch, FetchRequest, SampleRequest, TexelLevel, TexelSlice, Textures,
    Variant, LANES,
};
use glsl::ir::Stage;
use glsl::types::SamplerKind;

/// How a test level stores its texels.
#[derive(Clone, Copy, PartialEq)]
enum Store {
    Rgba32,
    Unorm8,
    /// 16-bit red, sign-extended when `true` (`TexelSlice::Red16`).
    Red16(bool),
}

/// One level of a test texture.
struct Level {
    size: [u32; 3],
    axes: u32,
    rgba32: Vec<[f32; 4]>,
    unorm8: Vec<[u8; 4]>,
    red16: Vec<u16>,
    store: Store,
}

/// Green, blue and alpha of every texel of a 16-bit red level.
const REST: [u32; 3] = [0, 7, 1];

impl Level {
    fn new(size: [u32; 3], axes: u32, store: Store, seed: u32) -> Level {
        let n = (size[0] * size[1] * size[2]) as usize;
        let mut s = seed | 1;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            s
        };
        let mut level = Level {
            size,
            axes,
            rgba32: Vec::new(),
            unorm8: Vec::new(),
            red16: Vec::new(),
            store,
        };
        for i in 0..n {
            match store {
                Store::Unorm8 => level.unorm8.push(next().to_le_bytes()),
                Store::Red16(_) => level.red16.push(next() as u16),
                Store::Rgba32 => {
                    // Any bits, subnormals among them (a float fetch
                    // flushes them).
                    let mut t = [0, 1, 2, 3].map(|_| f32::from_bits(next()));
                    if i % 3 == 0 {
                        t[1] = f32::from_bits(next() & 0x807f_ffff);
                    }
                    level.rgba32.push(t);
                }
            }
        }
        level
    }

    fn texel(&self, c: [i32; 3]) -> [f32; 4] {
        let keep = |a: usize| if (a as u32) < self.axes { c[a] } else { 0 };
        let c = [keep(0), keep(1), keep(2)];
        if (0..3).any(|a| c[a] < 0 || c[a] as u32 >= self.size[a]) {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let [w, h, _] = self.size.map(|s| s as usize);
        let i = (c[2] as usize * h + c[1] as usize) * w + c[0] as usize;
        match self.store {
            Store::Rgba32 => self.rgba32[i],
            Store::Unorm8 => self.unorm8[i].map(|b| b as f32 / 255.0),
            Store::Red16(signed) => {
                let r = self.red16[i];
                let r = if signed {
                    r as i16 as i32 as u32
                } else {
                    r as u32
                };
                [r, REST[0], REST[1], REST[2]].map(f32::from_bits)
            }
        }
    }
}

/// Units 0 (2D, two levels), 1 (2D bytes), 2 (2D array), 3 (1D), 4 (2D
/// 16-bit red) and 5 (2D 16-bit signed red).
struct Grid {
    units: Vec<Vec<Level>>,
}

impl Grid {
    fn new() -> Grid {
        Grid {
            units: vec![
                vec![
                    Level::new([6, 5, 1], 2, Store::Rgba32, 11),
                    Level::new([3, 2, 1], 2, Store::Rgba32, 12),
                ],
                vec![Level::new([7, 4, 1], 2, Store::Unorm8, 13)],
                vec![Level::new([5, 3, 4], 3, Store::Rgba32, 14)],
                vec![Level::new([9, 1, 1], 1, Store::Rgba32, 15)],
                vec![Level::new([8, 6, 1], 2, Store::Red16(false), 16)],
                vec![Level::new([5, 7, 1], 2, Store::Red16(true), 17)],
            ],
        }
    }

    fn level(&self, unit: u32, lod: i32) -> Option<&Level> {
        self.units
            .get(unit as usize)?
            .get(usize::try_from(lod).ok()?)
    }
}

impl Textures for Grid {
    fn sample(&self, _: &SampleRequest, _: &mut [[f32; LANES]; 4]) {
        unreachable!("the shaders only fetch")
    }

    fn fetch(&self, req: &FetchRequest, out: &mut [[f32; LANES]; 4]) {
        for l in (0..LANES).filter(|l| req.mask & (1 << l) != 0) {
            let t = match self.level(req.unit[l], req.lod[l]) {
                Some(level) => level.texel([0, 1, 2].map(|a| req.coord[a][l])),
                None => [0.0, 0.0, 0.0, 1.0],
            };
            for k in 0..4 {
                out[k][l] = t[k];
            }
        }
    }

    fn size(&self, unit: u32, _: SamplerKind, lod: i32) -> [i32; 3] {
        self.level(unit, lod).map_or([0; 3], |l| {
            std::array::from_fn(|a| {
                if (a as u32) < l.axes {
                    l.size[a] as i32
                } else {
                    0
                }
            })
        })
    }

    fn texel_level(&self, unit: u32, _: SamplerKind, lod: i32) -> Option<TexelLevel<'_>> {
        let level = self.level(unit, lod)?;
        Some(TexelLevel {
            size: level.size,
            axes: level.axes,
            texels: match level.store {
                Store::Rgba32 => TexelSlice::Rgba32(&level.rgba32),
                Store::Unorm8 => TexelSlice::Unorm8(&level.unorm8),
                Store::Red16(signed) => TexelSlice::Red16 {
                    red: &level.red16,
                    signed,
                    rest: REST,
                },
            },
        })
    }
}

#[test]
fn native_texel_fetches_are_the_textures_fetches() {
    let k = kernel(
        Stage::Fragment,
        "#version 130
        uniform usampler2D ui;
        uniform sampler2D bytes;
        uniform sampler2DArray layers;
        uniform isampler1D line;
        uniform usampler2D narrow;
        uniform isampler2D signed_narrow;
        uniform int lod;
        in vec4 v;
        out uvec4 a;
        out vec4 b, c;
        out ivec4 d, e;
        void main() {
            ivec2 p = ivec2(floor(v.xy * 8.0)) + 1;
            a = texelFetch(ui, p, lod);
            b = texelFetchOffset(bytes, p, 0, ivec2(1, -1));
            if (v.z > 0.0)
                c = texelFetch(layers, ivec3(p, int(floor(v.w * 4.0))), 0);
            d = texelFetch(line, p.x + p.y, 0);
            // Lanes on different levels.
            e = ivec4(texelFetch(ui, p, int(v.z > 0.5)));
            // A constant row and layer (native code drops only the
            // axes held at 0).
            e += ivec4(texelFetch(ui, ivec2(p.x, 2), 0)) + texelFetch(line, 3, 0)
                + ivec4(texelFetch(layers, ivec3(p.y, 0, 1), 0));
            // 16-bit red levels, zero- and sign-extended.
            a += texelFetch(narrow, p - 2, 0);
            d += texelFetch(signed_narrow, p.yx - 1, 0);
            // Sizes of a uniform level (hoisted into the prologue) and
            // of per-lane levels.
            e += ivec4(textureSize(ui, lod), textureSize(layers, 0).z + textureSize(line, 0),
                textureSize(ui, int(v.w > 0.0)).x);
        }",
    );
    // textureSize(ui, lod) is made by the prologue.
    assert!(k
        .code
        .prologue
        .iter()
        .any(|op| matches!(op, crate::program::Op::Texture { .. })));
    let grid = Grid::new();
    for level in 0..3u32 {
        let u = uniforms(
            &k,
            &[
                ("ui", &[0]),
                ("bytes", &[1]),
                ("layers", &[2]),
                ("line", &[3]),
                ("narrow", &[4]),
                ("signed_narrow", &[5]),
                ("lod", &[level]),
            ],
        );
        for round in 0..24u32 {
            let active = [0xffff, 0x0ff0, 0x8001][round as usize % 3];
            let mut base = Batch::for_kernel(&k, active);
            super::variants::fill(&mut base, round + 31);
            let mut want = base.clone();
            let r0 = k.run_reference(&mut want, &u, &grid);
            assert_eq!(r0, Ok(()));
            let prepared = k.prepare(&u, &grid);
            for v in supported_variants() {
                // Without and with the pool (its size queries and the
                // fetches' levels) made once.
                for prepared in [None, Some(&prepared)] {
                    let mut got = base.clone();
                    // (run_variant compiles the native code first.)
                    let r = match prepared {
                        None => k.run_variant(v, &mut got, &u, &grid),
                        p => crate::dispatch::run_on(v, &k, &k.code, &mut got, &u, &grid, p),
                    };
                    let what = format!("{} prepared {}", v.name(), prepared.is_some());
                    assert_eq!(r, r0, "{what}");
                    assert_eq!(
                        bits_of(&got.outputs),
                        bits_of(&want.outputs),
                        "{what}, level {level} round {round}"
                    );
                }
            }
        }
    }
    if supported_variants().contains(&Variant::Jit) {
        assert!(matches!(k.native_code(), Some(Ok(_))));
    }
}
