//! Bit-identical pictures whatever the draw thread count and executor
//! variant: random `shaderbox render` scenes of the kind
//! scripts/mesa-sweep.py compares with Mesa, each rendered at 1, 2 and 4
//! threads with every `SHADERBOX_KERNEL` variant this CPU runs (the native
//! code both as it runs by default, interpreted until its code is ready,
//! and compiled from the first run), the PNG files compared byte for byte
//! with the one-thread portable picture.
//!
//! The variant is chosen once per process, so each picture is a process
//! of its own. The rasterizer's loops follow the interpreter variant's
//! level (`SHADERBOX_RASTER_ISA`), so each instruction set runs them too.

use exec::Variant;
use std::path::PathBuf;
use std::process::Command;

/// The option lists of mesa-sweep.py's `scenes`, with its sizes halved
/// (the same shapes: square, wide, tall, odd; at least two 64×64 tiles in
/// one direction, so the threads split the picture).
const SIZES: [(u32, u32); 5] = [(128, 128), (150, 100), (166, 205), (256, 192), (320, 240)];
const STYLES: [&str; 3] = ["spacefill", "spacefill", "ballstick"];
const EFFECTS: [&str; 5] = ["plain", "outline", "x", "x-red", "transparent"];
const FOGS: [&str; 4] = ["none", "linear", "exp", "exp2"];
const PROJECTIONS: [&str; 2] = ["ortho", "perspective"];
const LIGHT_SETS: [&str; 4] = ["0,1", "0", "1,2,3", "0,1,2,3,5,6,7"];

/// splitmix64: a fixed sequence on every machine, so the scenes are too.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[(self.next() % items.len() as u64) as usize]
    }

    fn angle(&mut self) -> i64 {
        (self.next() % 361) as i64 - 180
    }
}

/// `count` scenes drawn as mesa-sweep.py draws them: size, style, effect
/// (spacefill only), fog, projection, rotation and light set.
fn scenes(count: usize, seed: u64) -> Vec<Vec<String>> {
    let mut rng = Rng(seed);
    (0..count)
        .map(|_| {
            let (w, h) = rng.pick(&SIZES);
            let style = rng.pick(&STYLES);
            let effect = if style == "spacefill" {
                rng.pick(&EFFECTS)
            } else {
                "plain"
            };
            let fog = rng.pick(&FOGS);
            let projection = rng.pick(&PROJECTIONS);
            let rotate = format!("{},{},{}", rng.angle(), rng.angle(), rng.angle());
            let lights = rng.pick(&LIGHT_SETS);
            [
                "--size",
                &format!("{w}x{h}"),
                "--style",
                style,
                "--effect",
                effect,
                "--fog",
                fog,
                "--projection",
                projection,
                "--rotate",
                &rotate,
                "--lights",
                lights,
            ]
            .iter()
            .map(|s| s.to_string())
            .collect()
        })
        .collect()
}

/// A way of running the executor: the variant, and for native code
/// whether kernels compile on their first run.
#[derive(Clone, Copy, Debug)]
struct Executor {
    variant: Variant,
    native_from_first_run: bool,
}

fn executors() -> Vec<Executor> {
    let mut out = Vec::new();
    for variant in exec::supported_variants() {
        out.push(Executor {
            variant,
            native_from_first_run: false,
        });
        if variant == Variant::Jit {
            out.push(Executor {
                variant,
                native_from_first_run: true,
            });
        }
    }
    out
}

/// The PNG bytes of one scene rendered in a process of its own.
fn render(args: &[String], threads: usize, ex: Executor, out: &PathBuf) -> Vec<u8> {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_shaderbox"));
    cmd.arg("render")
        .args(args)
        .arg("-o")
        .arg(out)
        .env("SHADERBOX_THREADS", threads.to_string())
        .env("SHADERBOX_KERNEL", ex.variant.name())
        .env("SHADERBOX_RASTER_ISA", ex.variant.level().name())
        .env_remove("SHADERBOX_JIT_AFTER");
    if ex.native_from_first_run {
        cmd.env("SHADERBOX_JIT_AFTER", "1");
    }
    let o = cmd.output().expect("the shaderbox binary runs");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.success(),
        "render {args:?} with {threads} threads, {ex:?}: {stderr}"
    );
    // An unsupported variant would fall back with a message: the picture
    // would not be the variant's.
    assert!(
        !stderr.contains("SHADERBOX_KERNEL"),
        "{ex:?} not taken: {stderr}"
    );
    std::fs::read(out).unwrap()
}

#[test]
fn random_scenes_are_identical_across_threads_and_executors() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("determinism");
    std::fs::create_dir_all(&dir).unwrap();
    let executors = executors();
    assert!(executors.len() >= 2, "{executors:?}");
    let portable = Executor {
        variant: Variant::Portable,
        native_from_first_run: false,
    };
    for (i, args) in scenes(4, 36).iter().enumerate() {
        let base = render(args, 1, portable, &dir.join(format!("scene{i}-base.png")));
        for ex in &executors {
            for threads in [1, 2, 4] {
                if threads == 1 && ex.variant == Variant::Portable {
                    continue;
                }
                let got = render(args, threads, *ex, &dir.join(format!("scene{i}.png")));
                assert!(
                    got == base,
                    "scene {i} ({}) differs with {threads} threads, {ex:?}",
                    args.join(" ")
                );
            }
        }
    }
}

#[test]
fn the_scene_generator_covers_the_option_lists() {
    // A generator stuck on one value would test one scene kind only.
    let all = scenes(64, 36);
    let lists: [&[&str]; 5] = [&STYLES, &FOGS, &PROJECTIONS, &LIGHT_SETS, &EFFECTS];
    for list in lists {
        for v in list {
            assert!(
                all.iter().any(|s| s.iter().any(|a| a == v)),
                "{v} never drawn"
            );
        }
    }
    assert_eq!(all, scenes(64, 36), "the same seed gives the same scenes");
}
