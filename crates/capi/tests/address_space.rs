//! A host that limits its address space after its first GL calls keeps
//! room for its own allocations: piglit's `shader_runner` lowers
//! `RLIMIT_AS` to 256 MiB for its `rlimit` tests after making the
//! context, then compiles, draws and reads back (it used to crash in its
//! own `malloc`, mimalloc's 1 GiB arena having used up the limit).
//!
//! The limit is set in a child process (this test binary run again), so
//! that it binds nothing else.

use gl::enums::*;
use std::ffi::{c_int, c_void};
use std::process::Command;
use std::ptr::null_mut;
use OSMesa::*;

mod common;
use common::shader;

const CHILD: &str = "SHADERBOX_ADDRESS_SPACE_CHILD";

#[repr(C)]
struct Rlimit {
    cur: u64,
    max: u64,
}
const RLIMIT_AS: c_int = 9;

extern "C" {
    fn setrlimit(resource: c_int, limit: *const Rlimit) -> c_int;
    fn malloc(size: usize) -> *mut c_void;
    fn free(p: *mut c_void);
}

/// The process's address space, in bytes (`VmSize`).
fn vm_size() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("VmSize:")).unwrap();
    let kib: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kib << 10
}

/// The size of the largest mapping of the process, in bytes.
fn largest_mapping() -> u64 {
    let maps = std::fs::read_to_string("/proc/self/maps").unwrap();
    maps.lines()
        .filter_map(|l| {
            let (a, b) = l.split(' ').next()?.split_once('-')?;
            Some(u64::from_str_radix(b, 16).ok()? - u64::from_str_radix(a, 16).ok()?)
        })
        .max()
        .unwrap_or(0)
}

/// Draws a quad with a GLSL program (compile, link, draw, read back).
unsafe fn draw_with_a_program(color: &str) -> [u8; 4] {
    let vs = shader(GL_VERTEX_SHADER, "void main() { gl_Position = gl_Vertex; }");
    let fs = shader(
        GL_FRAGMENT_SHADER,
        &format!("void main() {{ gl_FragColor = vec4({color}); }}"),
    );
    let prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glLinkProgram(prog);
    let mut ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &mut ok);
    assert_eq!(ok, 1);
    glUseProgram(prog);
    glBegin(GL_QUADS);
    glVertex2f(-1.0, -1.0);
    glVertex2f(1.0, -1.0);
    glVertex2f(1.0, 1.0);
    glVertex2f(-1.0, 1.0);
    glEnd();
    common::pixel_at(3, 3)
}

fn child() {
    unsafe {
        let mut buf = Vec::new();
        let ctx = common::current_context(&mut buf, 16, 16, None);
        assert_eq!(draw_with_a_program("1.0, 0.0, 0.0, 1.0"), [255, 0, 0, 255]);
        // (Memory checkers build without mimalloc: the system allocator.)
        #[cfg(feature = "mimalloc")]
        assert_eq!(
            OSMesa::allocator::arena_reserve_kib(),
            OSMesa::allocator::ARENA_RESERVE_KIB
        );
        // No reservation near the size of piglit's limit (mimalloc's
        // default arena is 1 GiB); glibc's per-thread arenas (64 MiB each)
        // and the libraries make up the rest.
        let largest = largest_mapping();
        assert!(largest < 128 << 20, "a mapping of {} MiB", largest >> 20);
        // The limit leaves 32 MiB above what is in use.
        let limit = vm_size() + (32 << 20);
        assert_eq!(
            setrlimit(
                RLIMIT_AS,
                &Rlimit {
                    cur: limit,
                    max: limit
                }
            ),
            0
        );
        // The host's own large allocation (piglit's probe buffers).
        let p = malloc(8 << 20);
        assert!(!p.is_null(), "malloc failed at {} MiB", vm_size() >> 20);
        free(p);
        assert_eq!(draw_with_a_program("0.0, 1.0, 0.0, 1.0"), [0, 255, 0, 255]);
        OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn a_host_address_space_limit_after_the_first_draw_leaves_room() {
    if std::env::var_os(CHILD).is_some() {
        return child();
    }
    let out = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "a_host_address_space_limit_after_the_first_draw_leaves_room",
            "--test-threads=1",
            "--nocapture",
        ])
        .env(CHILD, "1")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "child: {}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}
