//! Binning: set-up primitives sorted into the frame's [`TILE`]×[`TILE`]
//! tiles.
//!
//! Takes a set-up chunk's primitives (their clipped pixel bounds); gives
//! per tile the primitives overlapping it, in order ([`ChunkBins::new`],
//! run per chunk on the workers), and for the draw the chunks' bins read
//! in chunk order ([`Bins`]): each tile's primitives in draw order.

use crate::framebuffer::Framebuffer;
use crate::interpolate::Plane;
use crate::prim::Prim;
use crate::rasterize::PixelRect;

/// Tile size: fragments are produced tile by tile, each tile seeing the
/// primitives in draw order; tiles run in parallel.
pub const TILE: i64 = 64;

/// The frame's 64×64 tiles.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) struct TileGrid {
    w: i64,
    h: i64,
    tiles_x: i64,
    tiles: usize,
}

impl TileGrid {
    pub fn new(fb: &Framebuffer) -> TileGrid {
        let (w, h) = (fb.width as i64, fb.height as i64);
        let tiles_x = (w + TILE - 1) / TILE;
        let tiles_y = (h + TILE - 1) / TILE;
        TileGrid {
            w,
            h,
            tiles_x,
            tiles: (tiles_x * tiles_y).max(0) as usize,
        }
    }

    /// How many tiles there are.
    pub fn count(&self) -> usize {
        self.tiles
    }

    /// The tile row of tile `t`.
    pub fn row(&self, t: usize) -> usize {
        t / self.tiles_x.max(1) as usize
    }

    /// Tile `t`'s pixels, clipped to the frame.
    pub fn rect(&self, t: usize) -> PixelRect {
        let tiles_x = self.tiles_x.max(1);
        let (tx, ty) = (t as i64 % tiles_x, t as i64 / tiles_x);
        let (x, y) = (tx * TILE, ty * TILE);
        (x, y, (x + TILE).min(self.w), (y + TILE).min(self.h))
    }

    /// Calls `f` with each tile a primitive's bounds overlap, row by row
    /// (most primitives of a big mesh overlap one: no loop for those).
    #[inline(always)]
    pub fn tiles_each(&self, prim: &Prim, mut f: impl FnMut(usize)) {
        let (w, h, tiles_x) = (self.w, self.h, self.tiles_x);
        let b = prim.bounds;
        let (x0, y0) = (b.0.clamp(0, w), b.1.clamp(0, h));
        let (x1, y1) = (b.2.clamp(x0, w), b.3.clamp(y0, h));
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let (tx0, tx1) = (x0 / TILE, (x1 - 1) / TILE);
        let (ty0, ty1) = (y0 / TILE, (y1 - 1) / TILE);
        if tx0 == tx1 && ty0 == ty1 {
            return f((ty0 * tiles_x + tx0) as usize);
        }
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                f((ty * tiles_x + tx) as usize);
            }
        }
    }
}

/// One set-up chunk's primitives by tile (a counting sort):
/// `items[starts[t]..starts[t + 1]]` are the chunk indices of the
/// primitives overlapping tile `t`, in order.
pub(crate) struct ChunkBins {
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl ChunkBins {
    pub fn new(prims: &[Prim], grid: &TileGrid) -> ChunkBins {
        let mut starts = vec![0u32; grid.tiles + 1];
        for prim in prims {
            grid.tiles_each(prim, |t| {
                if let Some(c) = starts.get_mut(t + 1) {
                    *c += 1;
                }
            });
        }
        for t in 0..grid.tiles {
            starts[t + 1] += starts[t];
        }
        let mut next = starts.clone();
        let mut items = vec![0u32; starts[grid.tiles] as usize];
        for (i, prim) in prims.iter().enumerate() {
            grid.tiles_each(prim, |t| {
                if let Some(n) = next.get_mut(t) {
                    if let Some(slot) = items.get_mut(*n as usize) {
                        *slot = i as u32;
                    }
                    *n += 1;
                }
            });
        }
        ChunkBins { starts, items }
    }

    pub fn tile(&self, t: usize) -> &[u32] {
        let (a, b) = (self.starts.get(t), self.starts.get(t + 1));
        match (a, b) {
            (Some(&a), Some(&b)) => self.items.get(a as usize..b as usize).unwrap_or(&[]),
            _ => &[],
        }
    }
}

/// The draw's primitives by tile: each chunk's bins and the index of its
/// first primitive in the draw.
pub(crate) struct Bins {
    pub grid: TileGrid,
    chunks: Vec<(ChunkBins, u32)>,
}

impl Bins {
    pub fn new(chunks: Vec<ChunkBins>, parts: &[(Vec<Prim>, Vec<Plane>)], grid: TileGrid) -> Bins {
        let mut base = 0u32;
        let chunks = chunks
            .into_iter()
            .zip(parts)
            .map(|(b, part)| {
                let first = base;
                base = base.saturating_add(part.0.len() as u32);
                (b, first)
            })
            .collect();
        Bins { grid, chunks }
    }

    /// Whether some primitive overlaps tile `t`.
    pub fn occupies(&self, t: usize) -> bool {
        self.chunks.iter().any(|(b, _)| !b.tile(t).is_empty())
    }

    /// The draw indices of tile `t`'s primitives, in draw order.
    pub fn tile(&self, t: usize) -> Vec<u32> {
        let n = self.chunks.iter().map(|(b, _)| b.tile(t).len()).sum();
        let mut out = Vec::with_capacity(n);
        for (b, first) in &self.chunks {
            out.extend(b.tile(t).iter().map(|&i| first + i));
        }
        out
    }
}
