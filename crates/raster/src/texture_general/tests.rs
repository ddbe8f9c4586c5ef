use super::*;
use crate::ex::Textures;
use crate::state::CompareFunc;
use crate::texture::{MagFilter, MinFilter, Swizzle};
use crate::texture_units::TextureUnits;
use std::sync::Arc;

fn solid(w: u32, h: u32, color: [f32; 4]) -> Image {
    Image::new(w, h, 1, vec![color; (w * h) as usize])
}

/// A 2D texture whose texel (i, j) is (i, j, level, 1).
fn ramp(w: u32, h: u32, levels: u32) -> Texture {
    let imgs = (0..levels)
        .map(|l| {
            let (lw, lh) = ((w >> l).max(1), (h >> l).max(1));
            let mut t = Vec::new();
            for j in 0..lh {
                for i in 0..lw {
                    t.push([i as f32, j as f32, l as f32, 1.0]);
                }
            }
            Image::new(lw, lh, 1, t)
        })
        .collect();
    Texture::new(TextureTarget::Tex2D, imgs)
}

fn at(tex: &Texture, s: f32, t: f32, lod: f32) -> [f32; 4] {
    let q = tex.last_level().expect("complete");
    sample(
        tex,
        q,
        [s, t, 0.0, 1.0],
        LodBase::Value(lod),
        0.0,
        None,
        [0; 3],
    )
}

#[test]
fn nearest_and_linear() {
    let mut tex = ramp(4, 4, 1);
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    assert_eq!(at(&tex, 0.3, 0.6, 0.0), [1.0, 2.0, 0.0, 1.0]);
    tex.mag_filter = MagFilter::Linear;
    // u = 1.5 → exactly texel 1; v = 2.0 → halfway between 1 and 2.
    assert_eq!(at(&tex, 1.5 / 4.0, 0.5, 0.0), [1.0, 1.5, 0.0, 1.0]);
}

/// RGBA8 levels filter by `unorm8_filter`'s definition: 7-bit
/// weights, rows exact, the result m/32640; f32 levels in f32.
#[test]
fn rgba8_levels_filter_in_fixed_point() {
    let texels = vec![
        [0.0, 1.0, 10.0 / 255.0, 1.0],
        [1.0, 0.0, 200.0 / 255.0, 1.0],
    ];
    let mut tex = Texture::new(TextureTarget::Tex2D, vec![Image::new(2, 1, 1, texels)]);
    assert!(tex.levels[0].is_unorm8());
    tex.min_filter = MinFilter::Linear;
    tex.mag_filter = MagFilter::Linear;
    tex.wrap = [Wrap::ClampToEdge; 3];
    // u = 2·0.4 = 0.8: x = ⌊102.4⌋ − 64 = 38, texel 0 and 1, a = 38.
    let got = at(&tex, 0.4, 0.5, 0.0);
    let want = |t0: u8, t1: u8| {
        let h = unorm8_filter::row(t0, t1, 38);
        unorm8_filter::value(unorm8_filter::rows(h, h, 0))
    };
    assert_eq!(got, [want(0, 255), want(255, 0), want(10, 200), 1.0]);
    assert_eq!(got[0], 38.0 * 255.0 / 32640.0);
    // The same texels as f32 (not all k/255): the float weights.
    let texels = vec![[0.0, 1.0, 0.1, 1.0], [1.0, 0.0, 0.7, 1.0]];
    tex.levels = vec![Image::new(2, 1, 1, texels)];
    assert!(!tex.levels[0].is_unorm8());
    let got = at(&tex, 0.4, 0.5, 0.0);
    let alpha = 0.8f32 - 0.5;
    assert_eq!(got[0], (1.0 - 0.0) * alpha * 1.0);
}

/// λ_base is the quad's: its first lane's derivatives decide the level
/// of every lane of the quad, the biases stay per lane.
#[test]
fn level_of_detail_is_per_quad() {
    let mut tex = ramp(8, 8, 4);
    tex.mag_filter = MagFilter::Nearest;
    tex.min_filter = MinFilter::NearestMipmapNearest;
    let units = TextureUnits::new(vec![TextureUnit {
        tex_2d: Some(std::sync::Arc::new(tex)),
        ..TextureUnit::default()
    }]);
    let mut ddx = [[0.0; LANES]; 3];
    let mut ddy = [[0.0; LANES]; 3];
    let mut bias = [0.0; LANES];
    // Quad q's first lane: λ = q (ds/dx = 2^q/8); the others would say
    // λ = 0.
    ddx[0] = std::array::from_fn(|l| {
        if l % 4 == 0 {
            (1 << (l / 4)) as f32 / 8.0
        } else {
            0.125
        }
    });
    ddy[1] = [0.125; LANES];
    // Lane 6's own bias: one level coarser than its quad's.
    bias[6] = 1.0;
    let req = SampleRequest {
        unit: [0; LANES],
        target: SamplerKind::Sampler2D,
        coord: [[0.5; LANES], [0.5; LANES], [0.0; LANES], [1.0; LANES]],
        compare: None,
        lod: Lod::Derivatives { ddx, ddy, bias },
        offset: None,
        compare_only: false,
        mask: 0xffff,
    };
    let mut out = [[0.0; LANES]; 4];
    units.sample_general(&req, &mut out);
    for (l, &got) in out[2].iter().enumerate() {
        let level = (l / 4 + usize::from(l == 6)).min(3) as f32;
        assert_eq!(got, level, "lane {l}");
    }
}

#[test]
fn wrap_modes() {
    let mut tex = ramp(4, 1, 1);
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    tex.border_color = [9.0; 4];
    let s = |tex: &Texture, s: f32| at(tex, s, 0.5, 0.0)[0];
    tex.wrap[0] = Wrap::Repeat;
    assert_eq!(s(&tex, 1.3), 1.0);
    assert_eq!(s(&tex, -0.1), 3.0);
    tex.wrap[0] = Wrap::MirroredRepeat;
    assert_eq!(s(&tex, 1.1), 3.0);
    assert_eq!(s(&tex, -0.1), 0.0);
    tex.wrap[0] = Wrap::ClampToEdge;
    assert_eq!(s(&tex, 7.0), 3.0);
    tex.wrap[0] = Wrap::Clamp;
    assert_eq!(s(&tex, 1.0), 3.0);
    assert_eq!(s(&tex, -2.0), 0.0);
    tex.wrap[0] = Wrap::ClampToBorder;
    assert_eq!(s(&tex, 1.5), 9.0);
    assert_eq!(s(&tex, 0.9), 3.0);
    // LINEAR: CLAMP blends with the border at the edge, CLAMP_TO_EDGE not.
    tex.mag_filter = MagFilter::Linear;
    tex.wrap[0] = Wrap::Clamp;
    assert_eq!(s(&tex, 1.0), 0.5 * 3.0 + 0.5 * 9.0);
    tex.wrap[0] = Wrap::ClampToEdge;
    assert_eq!(s(&tex, 1.0), 3.0);
    tex.wrap[0] = Wrap::Repeat;
    assert_eq!(s(&tex, 0.0), 0.5 * 3.0 + 0.5 * 0.0);
}

#[test]
fn lod_selection() {
    let mut tex = ramp(8, 8, 4);
    tex.mag_filter = MagFilter::Nearest;
    tex.min_filter = MinFilter::NearestMipmapNearest;
    let level = |tex: &Texture, lod: f32| at(tex, 0.5, 0.5, lod)[2];
    assert_eq!(level(&tex, 0.4), 0.0);
    assert_eq!(level(&tex, 0.6), 1.0);
    assert_eq!(level(&tex, 1.4), 1.0);
    assert_eq!(level(&tex, 1.6), 2.0);
    assert_eq!(level(&tex, 9.0), 3.0);
    tex.min_filter = MinFilter::NearestMipmapLinear;
    assert_eq!(level(&tex, 1.25), 1.25);
    assert_eq!(level(&tex, 5.0), 3.0);
    // c = 0.5 for LINEAR mag with a NEAREST_MIPMAP min filter: λ = 0.4 magnifies.
    tex.mag_filter = MagFilter::Linear;
    assert_eq!(level(&tex, 0.4), 0.0);
    // Clamped by MAX_LOD and biased.
    tex.max_lod = 1.0;
    assert_eq!(level(&tex, 3.0), 1.0);
    tex.max_lod = 1000.0;
    tex.lod_bias = 1.0;
    assert_eq!(level(&tex, 1.0), 2.0);
}

#[test]
fn lod_from_derivatives() {
    let mut tex = ramp(8, 8, 4);
    tex.mag_filter = MagFilter::Nearest;
    tex.min_filter = MinFilter::NearestMipmapNearest;
    // ds/dx = 4/8: four texels per pixel → λ = 2.
    let q = tex.last_level().unwrap();
    let lod = LodBase::Derivatives([0.5, 0.0, 0.0], [0.0, 0.125, 0.0]);
    assert_eq!(
        sample(&tex, q, [0.5, 0.5, 0.0, 1.0], lod, 0.0, None, [0; 3])[2],
        2.0
    );
    // A shader bias of -1 gives level 1.
    assert_eq!(
        sample(&tex, q, [0.5, 0.5, 0.0, 1.0], lod, -1.0, None, [0; 3])[2],
        1.0
    );
}

#[test]
fn incomplete_textures_sample_black() {
    let mut tex = ramp(8, 8, 2);
    assert_eq!(tex.last_level(), None, "mipmaps missing");
    tex.min_filter = MinFilter::Linear;
    assert_eq!(tex.last_level(), Some(0));
    let units = TextureUnits::new(vec![TextureUnit {
        tex_2d: Some(Arc::new(ramp(8, 8, 2))),
        ..TextureUnit::default()
    }]);
    let req = SampleRequest {
        unit: [0; LANES],
        target: SamplerKind::Sampler2D,
        coord: [[0.5; LANES]; 4],
        compare: None,
        lod: Lod::Explicit([0.0; LANES]),
        offset: None,
        compare_only: false,
        mask: 0b11,
    };
    let mut out = [[7.0; LANES]; 4];
    units.sample(&req, &mut out);
    assert_eq!([out[0][0], out[1][0], out[2][0], out[3][0]], MISSING);
    assert_eq!(out[0][2], 7.0, "lanes outside the mask untouched");
    // Unbound unit.
    let req = SampleRequest {
        unit: [3; LANES],
        ..req
    };
    units.sample(&req, &mut out);
    assert_eq!(out[3][1], 1.0);
}

/// A cube map array picks the face as a cube map does and the cube as an
/// array its layer (clamp(RNE(q), 0, cubes − 1)); every filter and level
/// reads that layer-face of each level.
#[test]
fn cube_map_array_layer_faces() {
    // Two cubes, 2×2 then 1×1: texel value (layer-face, level).
    let level = |size: u32, l: f32| {
        let t = (0..12)
            .flat_map(|lf| vec![[lf as f32, l, 0.0, 1.0]; (size * size) as usize])
            .collect();
        Image::new(size, size, 12, t)
    };
    let mut tex = Texture::new(TextureTarget::CubeArray, vec![level(2, 0.0), level(1, 1.0)]);
    assert_eq!(tex.last_level(), Some(1));
    // Every level has the base level's layer-faces.
    tex.levels[1] = Image::new(1, 1, 6, vec![[0.0; 4]; 6]);
    assert_eq!(tex.last_level(), None);
    tex.levels.truncate(1);
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    assert_eq!(tex.last_level(), Some(0));
    let at = |tex: &Texture, dir: [f32; 3], layer: f32, lod: f32| {
        let q = tex.last_level().unwrap();
        let c = [dir[0], dir[1], dir[2], layer];
        sample(tex, q, c, LodBase::Value(lod), 0.0, None, [0; 3])
    };
    assert_eq!(at(&tex, [0.0, 0.0, -1.0], 0.0, 0.0)[0], 5.0);
    assert_eq!(at(&tex, [0.0, 0.0, -1.0], 1.0, 0.0)[0], 11.0);
    // The layer rule of arrays: ⌊q + ½⌋ clamped, NaN the first.
    assert_eq!(at(&tex, [1.0, 0.2, 0.1], 0.49, 0.0)[0], 0.0);
    assert_eq!(at(&tex, [1.0, 0.2, 0.1], 0.5, 0.0)[0], 6.0);
    assert_eq!(at(&tex, [-1.0, 0.2, 0.1], 7.0, 0.0)[0], 7.0);
    assert_eq!(at(&tex, [-1.0, 0.2, 0.1], -3.0, 0.0)[0], 1.0);
    assert_eq!(at(&tex, [-1.0, 0.2, 0.1], f32::NAN, 0.0)[0], 1.0);
    assert_eq!(at(&tex, [0.0, -2.0, 0.1], 1.0, 0.0)[0], 9.0);
    // Bilinear on a face: the four taps of one layer-face.
    tex.mag_filter = MagFilter::Linear;
    let v = at(&tex, [0.3, 1.0, -0.2], 1.0, -1.0);
    assert!((v[0] - 8.0).abs() < 1e-5, "{v:?}");
    // Mipmapped: the level from λ, the layer-face on each.
    tex.levels = vec![level(2, 0.0), level(1, 1.0)];
    tex.mag_filter = MagFilter::Nearest;
    tex.min_filter = MinFilter::NearestMipmapNearest;
    assert_eq!(at(&tex, [0.0, 1.0, 0.0], 1.0, 1.0), [8.0, 1.0, 0.0, 1.0]);
    assert_eq!(at(&tex, [0.0, 1.0, 0.0], 1.0, 0.0), [8.0, 0.0, 0.0, 1.0]);
    tex.min_filter = MinFilter::NearestMipmapLinear;
    let v = at(&tex, [0.0, 1.0, 0.0], 1.0, 0.25);
    assert!(
        (v[0] - 8.0).abs() < 1e-5 && (v[1] - 0.25).abs() < 1e-6,
        "{v:?}"
    );
    // A non-square base level is incomplete.
    let flat = Image::new(2, 1, 12, vec![[0.0; 4]; 24]);
    assert_eq!(
        Texture::new(TextureTarget::CubeArray, vec![flat]).last_level(),
        None
    );
    // textureSize counts cubes.
    let units = [TextureUnit {
        cube_array: Some(Arc::new(tex)),
        ..TextureUnit::default()
    }];
    assert_eq!(
        size_general(&units, 0, SamplerKind::SamplerCubeArray, 0),
        [2, 2, 2]
    );
    assert_eq!(
        size_general(&units, 0, SamplerKind::ISamplerCubeArray, 1),
        [1, 1, 2]
    );
    assert_eq!(
        size_general(&units, 0, SamplerKind::SamplerCube, 0),
        [0, 0, 0]
    );
}

#[test]
fn cube_face_selection() {
    assert_eq!(cube_face([1.0, 0.5, -0.2]), (0, 0.2, -0.5, 1.0));
    assert_eq!(cube_face([-1.0, 0.5, -0.2]), (1, -0.2, -0.5, -1.0));
    assert_eq!(cube_face([0.1, 2.0, 0.3]), (2, 0.1, 0.3, 2.0));
    assert_eq!(cube_face([0.1, -2.0, 0.3]), (3, 0.1, -0.3, -2.0));
    assert_eq!(cube_face([0.1, 0.2, 3.0]), (4, 0.1, -0.2, 3.0));
    assert_eq!(cube_face([0.1, 0.2, -3.0]), (5, -0.1, -0.2, -3.0));
    // Sampling picks the face layer.
    let faces: Vec<[f32; 4]> = (0..6).map(|f| [f as f32, 0.0, 0.0, 1.0]).collect();
    let mut tex = Texture::new(TextureTarget::Cube, vec![Image::new(1, 1, 6, faces)]);
    tex.min_filter = MinFilter::Linear;
    let q = tex.last_level().unwrap();
    for (dir, face) in [
        ([0.0, 0.0, -1.0], 5.0),
        ([0.0, 1.0, 0.0], 2.0),
        ([-1.0, 0.0, 0.0], 1.0),
    ] {
        assert_eq!(
            sample(
                &tex,
                q,
                [dir[0], dir[1], dir[2], 1.0],
                LodBase::Value(0.0),
                0.0,
                None,
                [0; 3]
            )[0],
            face
        );
    }
}

#[test]
fn shadow_compare_and_depth_modes() {
    let mut tex = Texture::new(
        TextureTarget::Tex2D,
        vec![solid(2, 2, [0.5, 0.0, 0.0, 1.0])],
    );
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    tex.depth_format = true;
    let q = tex.last_level().unwrap();
    let s = |tex: &Texture, r: f32| {
        sample(
            tex,
            q,
            [0.5, 0.5, 0.0, 1.0],
            LodBase::Value(0.0),
            0.0,
            Some(r),
            [0; 3],
        )
    };
    assert_eq!(
        s(&tex, 0.9),
        [0.5, 0.5, 0.5, 1.0],
        "no compare: depth as luminance"
    );
    tex.compare = Some(CompareFunc::LessEqual);
    assert_eq!(s(&tex, 0.4), [1.0, 1.0, 1.0, 1.0]);
    assert_eq!(s(&tex, 0.6), [0.0, 0.0, 0.0, 1.0]);
    tex.depth_mode = DepthTextureMode::Intensity;
    assert_eq!(s(&tex, 0.6), [0.0; 4]);
    tex.depth_mode = DepthTextureMode::Alpha;
    assert_eq!(s(&tex, 0.4), [0.0, 0.0, 0.0, 1.0]);
    tex.compare = Some(CompareFunc::Greater);
    // R is clamped to [0, 1]: 7 > 0.5.
    assert_eq!(s(&tex, 7.0), [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn garbage_coordinates_do_not_panic() {
    let vals = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1e30,
        -1e30,
        0.0,
        1.0,
        f32::MAX,
    ];
    for target in [
        TextureTarget::Tex1D,
        TextureTarget::Tex2D,
        TextureTarget::Tex3D,
        TextureTarget::Cube,
        TextureTarget::CubeArray,
    ] {
        let depth = match target {
            TextureTarget::Cube => 6,
            TextureTarget::CubeArray => 12,
            _ => 2,
        };
        let h = if target == TextureTarget::Tex1D { 1 } else { 2 };
        let d = if matches!(
            target,
            TextureTarget::Tex3D | TextureTarget::Cube | TextureTarget::CubeArray
        ) {
            depth
        } else {
            1
        };
        let img = Image::new(2, h, d, vec![[0.5; 4]; (2 * h * d) as usize]);
        for wrap in [
            Wrap::Repeat,
            Wrap::Clamp,
            Wrap::ClampToEdge,
            Wrap::ClampToBorder,
            Wrap::MirroredRepeat,
        ] {
            for filter in [MinFilter::Nearest, MinFilter::LinearMipmapLinear] {
                let mut tex = Texture::new(target, vec![img.clone()]);
                tex.wrap = [wrap; 3];
                tex.min_filter = filter;
                tex.mag_filter = MagFilter::Linear;
                tex.max_level = 0;
                tex.depth_format = true;
                tex.compare = Some(CompareFunc::Less);
                let q = tex.last_level().expect("complete");
                for &a in &vals {
                    for &b in &vals {
                        let lod = LodBase::Derivatives([a, b, a], [b, a, 1.0]);
                        let _ = sample(&tex, q, [a, b, 0.25, a], lod, b, Some(a), [0; 3]);
                        let _ = sample(
                            &tex,
                            q,
                            [b, 0.5, a, b],
                            LodBase::Value(a),
                            0.0,
                            None,
                            [0; 3],
                        );
                    }
                }
            }
        }
    }
}

/// A level of `w × h × d` texels whose texel (i, j, k) is (i, j, k, 1).
fn texel_ramp(w: u32, h: u32, d: u32) -> Image {
    let mut t = Vec::new();
    for k in 0..d {
        for j in 0..h {
            for i in 0..w {
                t.push([i as f32, j as f32, k as f32, 1.0]);
            }
        }
    }
    Image::new(w, h, d, t)
}

fn nearest(mut tex: Texture) -> Texture {
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    tex
}

fn at_offset(tex: &Texture, coord: [f32; 3], offset: [i32; 3]) -> [f32; 4] {
    let q = tex.last_level().expect("complete");
    let [s, t, r] = coord;
    sample(
        tex,
        q,
        [s, t, r, 1.0],
        LodBase::Value(0.0),
        0.0,
        None,
        offset,
    )
}

#[test]
fn array_layers_are_the_rounded_coordinate_clamped() {
    let tex = nearest(Texture::new(
        TextureTarget::Tex2DArray,
        vec![texel_ramp(4, 2, 3)],
    ));
    // Layer = clamp(floor(r + 0.5), 0, 2).
    for (r, layer) in [(0.49, 0.0), (0.5, 1.0), (1.7, 2.0), (-3.0, 0.0), (9.0, 2.0)] {
        assert_eq!(
            at_offset(&tex, [0.6, 0.7, r], [0; 3]),
            [2.0, 1.0, layer, 1.0],
            "{r}"
        );
    }
    // A 1D array's layers are its rows.
    let tex = nearest(Texture::new(
        TextureTarget::Tex1DArray,
        vec![texel_ramp(4, 3, 1)],
    ));
    assert_eq!(
        at_offset(&tex, [0.3, 1.6, 0.0], [0; 3]),
        [1.0, 2.0, 0.0, 1.0]
    );
    // Linear filtering blends within the layer only.
    let mut tex = Texture::new(TextureTarget::Tex2DArray, vec![texel_ramp(4, 4, 2)]);
    tex.min_filter = MinFilter::Linear;
    assert_eq!(
        at_offset(&tex, [0.25, 0.25, 1.2], [0; 3]),
        [0.5, 0.5, 1.0, 1.0]
    );
}

#[test]
fn rectangles_take_texel_coordinates() {
    let mut tex = nearest(Texture::new(TextureTarget::Rect, vec![texel_ramp(5, 3, 1)]));
    tex.wrap = [Wrap::ClampToEdge; 3];
    assert_eq!(
        at_offset(&tex, [3.5, 2.9, 0.0], [0; 3]),
        [3.0, 2.0, 0.0, 1.0]
    );
    // CLAMP_TO_EDGE keeps coordinates in [½, n − ½].
    assert_eq!(
        at_offset(&tex, [-4.0, 7.0, 0.0], [0; 3]),
        [0.0, 2.0, 0.0, 1.0]
    );
    tex.mag_filter = MagFilter::Linear;
    assert_eq!(
        at_offset(&tex, [2.0, 1.5, 0.0], [0; 3]),
        [1.5, 1.0, 0.0, 1.0]
    );
    // Mipmapping filters do not apply: the one level is complete.
    tex.min_filter = MinFilter::LinearMipmapLinear;
    assert_eq!(tex.last_level(), Some(0));
}

#[test]
fn offsets_move_the_texel_before_wrapping() {
    let tex = nearest(Texture::new(
        TextureTarget::Tex2D,
        vec![texel_ramp(4, 4, 1)],
    ));
    assert_eq!(
        at_offset(&tex, [0.3, 0.6, 0.0], [1, -1, 0]),
        [2.0, 1.0, 0.0, 1.0]
    );
    // REPEAT wraps the offset texel.
    assert_eq!(
        at_offset(&tex, [0.9, 0.1, 0.0], [2, -1, 0]),
        [1.0, 3.0, 0.0, 1.0]
    );
    let mut tex = tex;
    tex.wrap = [Wrap::ClampToEdge; 3];
    assert_eq!(
        at_offset(&tex, [0.9, 0.1, 0.0], [2, -1, 0]),
        [3.0, 0.0, 0.0, 1.0]
    );
}

#[test]
fn integer_textures_read_one_texel_unfiltered() {
    let bits = |v: [i32; 4]| v.map(|x| f32::from_bits(x as u32));
    let texels = vec![bits([1, -2, 3, 4]), bits([5, 6, -7, 8])];
    let mut tex = Texture::new(TextureTarget::Tex2D, vec![Image::new(2, 1, 1, texels)]);
    tex.integer = true;
    tex.min_filter = MinFilter::Linear;
    tex.mag_filter = MagFilter::Linear;
    let got = at_offset(&tex, [0.74, 0.5, 0.0], [0; 3]).map(f32::to_bits);
    assert_eq!(got, bits([5, 6, -7, 8]).map(f32::to_bits));
}

#[test]
fn gradients_are_each_lanes_own() {
    let mut tex = ramp(8, 8, 4);
    tex.min_filter = MinFilter::NearestMipmapNearest;
    let units = TextureUnits::new(vec![TextureUnit {
        tex_2d: Some(Arc::new(tex)),
        ..TextureUnit::default()
    }]);
    // Lane l's derivatives select level l % 4 (2^l texels per pixel).
    let mut ddx = [[0.0; LANES]; 3];
    let ddy = [[0.0; LANES]; 3];
    for (l, d) in ddx[0].iter_mut().enumerate() {
        *d = (1u32 << (l % 4)) as f32 / 8.0;
    }
    let req = SampleRequest {
        unit: [0; LANES],
        target: SamplerKind::Sampler2D,
        coord: [[0.5; LANES]; 4],
        compare: None,
        lod: Lod::Gradients { ddx, ddy },
        offset: None,
        compare_only: false,
        mask: 0xffff,
    };
    let mut out = [[0.0; LANES]; 4];
    units.sample(&req, &mut out);
    for (l, &level) in out[2].iter().enumerate() {
        assert_eq!(level, (l % 4) as f32, "lane {l}");
    }
}

#[test]
fn fetches_and_sizes() {
    let mut arr = Texture::new(
        TextureTarget::Tex2DArray,
        vec![
            texel_ramp(4, 2, 3),
            texel_ramp(2, 1, 3),
            texel_ramp(1, 1, 3),
        ],
    );
    arr.base_level = 0;
    arr.min_filter = MinFilter::NearestMipmapNearest;
    let mut rect = Texture::new(TextureTarget::Rect, vec![texel_ramp(5, 3, 1)]);
    rect.min_filter = MinFilter::Nearest;
    let units = TextureUnits::new(vec![TextureUnit {
        tex_2d_array: Some(Arc::new(arr)),
        rect: Some(Arc::new(rect)),
        ..TextureUnit::default()
    }]);
    let fetch = |target, c: [i32; 3], lod: i32| {
        let req = FetchRequest {
            unit: [0; LANES],
            target,
            coord: c.map(|x| [x; LANES]),
            lod: [lod; LANES],
            mask: 1,
        };
        let mut out = [[0.0; LANES]; 4];
        units.fetch(&req, &mut out);
        [out[0][0], out[1][0], out[2][0], out[3][0]]
    };
    assert_eq!(
        fetch(SamplerKind::Sampler2DArray, [3, 1, 2], 0),
        [3.0, 1.0, 2.0, 1.0]
    );
    assert_eq!(
        fetch(SamplerKind::Sampler2DArray, [1, 0, 1], 1),
        [1.0, 0.0, 1.0, 1.0]
    );
    // Outside the level, past the last level, a negative level.
    assert_eq!(fetch(SamplerKind::Sampler2DArray, [4, 0, 0], 0), MISSING);
    assert_eq!(fetch(SamplerKind::Sampler2DArray, [0, 0, 3], 0), MISSING);
    assert_eq!(fetch(SamplerKind::Sampler2DArray, [0, 0, 0], 3), MISSING);
    assert_eq!(fetch(SamplerKind::Sampler2DArray, [0, 0, 0], -1), MISSING);
    assert_eq!(
        fetch(SamplerKind::Sampler2DRect, [4, 2, 9], 0),
        [4.0, 2.0, 0.0, 1.0]
    );
    assert_eq!(fetch(SamplerKind::Sampler2D, [0, 0, 0], 0), MISSING);
    assert_eq!(units.size(0, SamplerKind::Sampler2DArray, 0), [4, 2, 3]);
    assert_eq!(units.size(0, SamplerKind::ISampler2DArray, 1), [2, 1, 3]);
    assert_eq!(units.size(0, SamplerKind::Sampler2DArray, 2), [1, 1, 3]);
    assert_eq!(units.size(0, SamplerKind::Sampler2DArray, 3), [0, 0, 0]);
    assert_eq!(units.size(0, SamplerKind::Sampler2DRect, 0), [5, 3, 0]);
    assert_eq!(units.size(0, SamplerKind::Sampler2D, 0), [0, 0, 0]);
    assert_eq!(units.size(1, SamplerKind::Sampler2DRect, 0), [0, 0, 0]);
}

#[test]
fn glsl130_shadow_lookups_ignore_the_depth_texture_mode() {
    let mut tex = Texture::new(
        TextureTarget::Tex2D,
        vec![solid(2, 2, [0.5, 0.5, 0.5, 1.0])],
    );
    tex.depth_format = true;
    tex.compare = Some(CompareFunc::Less);
    tex.min_filter = MinFilter::Nearest;
    tex.mag_filter = MagFilter::Nearest;
    for (mode, legacy) in [
        (DepthTextureMode::Alpha, [0.0, 0.0, 0.0, 1.0]),
        (DepthTextureMode::Red, [1.0, 0.0, 0.0, 1.0]),
        (DepthTextureMode::Intensity, [1.0; 4]),
    ] {
        tex.depth_mode = mode;
        let units = TextureUnits::new(vec![TextureUnit {
            tex_2d: Some(Arc::new(tex.clone())),
            ..TextureUnit::default()
        }]);
        let mut req = SampleRequest {
            unit: [0; LANES],
            target: SamplerKind::Sampler2DShadow,
            coord: [[0.5; LANES]; 4],
            compare: Some([0.25; LANES]),
            lod: Lod::Explicit([0.0; LANES]),
            offset: None,
            compare_only: false,
            mask: 1,
        };
        let mut out = [[0.0; LANES]; 4];
        units.sample(&req, &mut out);
        assert_eq!(
            [out[0][0], out[1][0], out[2][0], out[3][0]],
            legacy,
            "{mode:?}"
        );
        req.compare_only = true;
        units.sample(&req, &mut out);
        assert_eq!(out[0][0], 1.0, "{mode:?}");
    }
}

/// `fetch_general` (whose lanes sharing a unit and level take
/// `fetch_shared`) gives the lane-by-lane results: every target with
/// texel fetches, in and out of the level, on levels past the last, with
/// swizzles, sRGB and depth textures (which `fetch_shared` declines);
/// and the levels `plain_level` gives read as stored give them too.
#[test]
fn shared_fetches_match_the_lane_path() {
    let mut arr = Texture::new(
        TextureTarget::Tex2DArray,
        vec![texel_ramp(4, 2, 3), texel_ramp(2, 1, 3)],
    );
    arr.min_filter = MinFilter::NearestMipmapNearest;
    let rect = nearest(Texture::new(TextureTarget::Rect, vec![texel_ramp(5, 3, 1)]));
    let t3d = nearest(Texture::new(
        TextureTarget::Tex3D,
        vec![texel_ramp(3, 2, 4)],
    ));
    let t1d = nearest(Texture::new(
        TextureTarget::Tex1DArray,
        vec![texel_ramp(6, 2, 1)],
    ));
    let mut t2d = nearest(ramp(4, 4, 1));
    t2d.swizzle = [Swizzle::B, Swizzle::R, Swizzle::One, Swizzle::G];
    let mut depth = nearest(ramp(4, 4, 1));
    depth.depth_format = true;
    let mut srgb = nearest(Texture::new(
        TextureTarget::Tex2D,
        vec![solid(3, 3, [0.25, 0.5, 0.75, 0.5])],
    ));
    srgb.srgb = true;
    let unit = |tex_2d: Texture| TextureUnit {
        tex_2d_array: Some(Arc::new(arr.clone())),
        rect: Some(Arc::new(rect.clone())),
        tex_3d: Some(Arc::new(t3d.clone())),
        tex_1d_array: Some(Arc::new(t1d.clone())),
        tex_2d: Some(Arc::new(tex_2d)),
        ..TextureUnit::default()
    };
    let units = vec![
        unit(t2d),
        unit(depth),
        unit(srgb),
        unit(nearest(ramp(4, 4, 1))),
    ];
    let targets = [
        SamplerKind::Sampler2DArray,
        SamplerKind::Sampler2DRect,
        SamplerKind::Sampler3D,
        SamplerKind::Sampler1DArray,
        SamplerKind::Sampler2D,
        SamplerKind::Sampler1D,
    ];
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = |n: u64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed % n
    };
    let (mut shared, mut levels) = (0, 0);
    for round in 0..4000 {
        let target = targets[next(targets.len() as u64) as usize];
        // Mostly one unit and level for all lanes, sometimes not.
        let (u, lod) = (next(5) as u32, next(4) as i32 - 1);
        let mixed = round % 4 == 0;
        let req = FetchRequest {
            unit: std::array::from_fn(|_| if mixed { next(5) as u32 } else { u }),
            target,
            coord: std::array::from_fn(|_| std::array::from_fn(|_| next(9) as i32 - 2)),
            lod: std::array::from_fn(|_| if mixed { next(3) as i32 } else { lod }),
            mask: next(1 << 16) as u32,
        };
        let (mut got, mut want) = ([[7.0; LANES]; 4], [[7.0; LANES]; 4]);
        shared += usize::from(fetch_shared(&units, &req, &mut [[0.0; LANES]; 4]));
        fetch_general(&units, &req, &mut got);
        fetch_lanes(&units, &req, &mut want);
        for c in 0..4 {
            for l in 0..LANES {
                assert_eq!(got[c][l].to_bits(), want[c][l].to_bits(), "{req:?} {c} {l}");
            }
        }
        // `Textures::texel_level`'s contract: where it gives the level,
        // each lane's texel read from it as stored (the way native code
        // reads it) is the lane path's.
        if let Some((_, level)) = plain_level(&units, u, target, lod) {
            for l in (0..LANES).filter(|l| req.mask & (1 << l) != 0 && !mixed) {
                let keep = |a: usize| {
                    if (a as u32) < level.axes {
                        req.coord[a][l]
                    } else {
                        0
                    }
                };
                let c = [keep(0), keep(1), keep(2)];
                let inside = (0..3).all(|a| c[a] >= 0 && (c[a] as u32) < level.size[a]);
                let texel = if inside {
                    let [w, h, _] = level.size.map(|s| s as usize);
                    let i = (c[2] as usize * h + c[1] as usize) * w + c[0] as usize;
                    match level.texels {
                        TexelSlice::Rgba32(t) => t[i],
                        TexelSlice::Unorm8(t) => t[i].map(|b| b as f32 / 255.0),
                        TexelSlice::Red16 { red, signed, rest } => {
                            let r = match signed {
                                true => red[i] as i16 as i32 as u32,
                                false => red[i] as u32,
                            };
                            [r, rest[0], rest[1], rest[2]].map(f32::from_bits)
                        }
                    }
                } else {
                    [0.0, 0.0, 0.0, 1.0]
                };
                for c in 0..4 {
                    assert_eq!(texel[c].to_bits(), want[c][l].to_bits(), "{req:?} {c} {l}");
                }
                levels += 1;
            }
        }
    }
    // The fast path was exercised, and declined too.
    assert!(shared > 200 && shared < 3900, "{shared}");
    assert!(levels > 1000, "{levels}");
}
