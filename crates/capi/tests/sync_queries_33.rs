//! The GL 3.0–3.3 sync-object and query entry points, driven as a C
//! program would on a 3.3 core context: fences, the 64-bit queries,
//! GL_ANY_SAMPLES_PASSED, primitive and timer queries, conditional
//! rendering, and their lookup by name.

use gl::enums::*;

use OSMesa::*;

mod common;

const W: i32 = 8;
const H: i32 = 8;

/// Every entry point this file covers.
const NAMES: &[&str] = &[
    "glFenceSync",
    "glIsSync",
    "glDeleteSync",
    "glClientWaitSync",
    "glWaitSync",
    "glGetSynciv",
    "glGetInteger64v",
    "glQueryCounter",
    "glGetQueryObjecti64v",
    "glGetQueryObjectui64v",
    "glBeginConditionalRender",
    "glEndConditionalRender",
];

/// A program drawing `pos` in green, with a VAO holding a full-window
/// triangle strip of 4 vertices bound.
unsafe fn green_quad() {
    let p = common::program(
        "#version 330 core\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }\n",
        "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.0, 1.0, 0.0, 1.0); }\n",
    );
    common::quad_vertex_array(p, "pos");
    assert_eq!(glGetError(), GL_NO_ERROR);
}

unsafe fn pixel() -> [u8; 4] {
    common::pixel_at(4, 4)
}

#[test]
fn entry_points_are_exported_by_name() {
    common::assert_exported(NAMES);
}

#[test]
fn fences() {
    common::with_context(W, H, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        let s = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        assert!(!s.is_null());
        assert_eq!(glIsSync(s), 1);
        assert_eq!(
            glClientWaitSync(s, GL_SYNC_FLUSH_COMMANDS_BIT, 1_000_000_000),
            GL_ALREADY_SIGNALED
        );
        glWaitSync(s, 0, u64::MAX);
        let mut v = [0i32; 2];
        let mut len = -1;
        glGetSynciv(s, GL_SYNC_STATUS, 2, &mut len, v.as_mut_ptr());
        assert_eq!((len, v[0]), (1, GL_SIGNALED as i32));
        // bufSize 0 writes nothing but the length.
        v[0] = 7;
        glGetSynciv(s, GL_OBJECT_TYPE, 0, &mut len, v.as_mut_ptr());
        assert_eq!((len, v[0]), (0, 7));
        assert_eq!(glGetError(), GL_NO_ERROR);
        glGetSynciv(s, GL_OBJECT_TYPE, -1, &mut len, v.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        let mut t = 0i64;
        glGetInteger64v(GL_MAX_SERVER_WAIT_TIMEOUT, &mut t);
        assert!(t > 0);
        glDeleteSync(s);
        assert_eq!(glIsSync(s), 0);
        assert_eq!(glClientWaitSync(s, 0, 0), GL_WAIT_FAILED);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDeleteSync(std::ptr::null());
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert!(glFenceSync(0, 0).is_null());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
    });
}

#[test]
fn queries_and_conditional_rendering() {
    common::with_context(W, H, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        green_quad();
        let mut q = [0u32; 4];
        glGenQueries(4, q.as_mut_ptr());
        glBeginQuery(GL_ANY_SAMPLES_PASSED, q[0]);
        glBeginQuery(GL_PRIMITIVES_GENERATED, q[1]);
        glBeginQuery(GL_TIME_ELAPSED, q[2]);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glEndQuery(GL_TIME_ELAPSED);
        glQueryCounter(q[3], GL_TIMESTAMP);
        let mut now = 0i64;
        glGetInteger64v(GL_TIMESTAMP, &mut now);
        let (mut any, mut prims, mut elapsed, mut stamp) = (0u32, 0i64, 0u64, 0u64);
        glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &mut any);
        glGetQueryObjecti64v(q[1], GL_QUERY_RESULT, &mut prims);
        glGetQueryObjectui64v(q[2], GL_QUERY_RESULT, &mut elapsed);
        glGetQueryObjectui64v(q[3], GL_QUERY_RESULT, &mut stamp);
        assert_eq!((any, prims), (1, 2));
        assert!(elapsed > 0);
        assert!(stamp > 0 && stamp as i64 <= now, "{stamp} {now}");
        assert_eq!(glGetError(), GL_NO_ERROR);

        // A query nothing passed: the draw and clear are skipped.
        let mut none = 0;
        glGenQueries(1, &mut none);
        glBeginQuery(GL_SAMPLES_PASSED, none);
        glEndQuery(GL_SAMPLES_PASSED);
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBeginConditionalRender(none, GL_QUERY_WAIT);
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glEndConditionalRender();
        assert_eq!(pixel(), [255, 0, 0, 255]);
        glBeginConditionalRender(q[0], GL_QUERY_NO_WAIT);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glEndConditionalRender();
        assert_eq!(pixel(), [0, 255, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glEndConditionalRender();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glBeginConditionalRender(q[1], GL_QUERY_WAIT);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
    });
}
