//! EGL error paths, in process (the rlib): every bad call returns its
//! failure value and records the error EGL 1.5 or the extension names.
//! tests/c_program.rs compares the codes of a C program's bad calls with
//! Mesa's.

use std::ptr::null_mut;
use EGL as egl;
use EGL::*;

fn err() -> EGLint {
    egl::error::eglGetError()
}

/// An initialized surfaceless display.
fn display() -> EGLDisplay {
    unsafe {
        let d = egl::display::eglGetPlatformDisplay(
            EGL_PLATFORM_SURFACELESS_MESA,
            null_mut(),
            std::ptr::null(),
        );
        assert!(!d.is_null());
        assert_eq!(
            egl::display::eglInitialize(d, null_mut(), null_mut()),
            EGL_TRUE
        );
        d
    }
}

fn config(d: EGLDisplay, depth: EGLint) -> EGLConfig {
    let attribs = [
        EGL_SURFACE_TYPE,
        EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE,
        EGL_OPENGL_BIT,
        EGL_DEPTH_SIZE,
        depth,
        EGL_NONE,
    ];
    let mut c = null_mut();
    let mut n = 0;
    unsafe {
        assert_eq!(
            egl::config::eglChooseConfig(d, attribs.as_ptr(), &mut c, 1, &mut n),
            EGL_TRUE
        );
    }
    assert_eq!(n, 1);
    c
}

fn context(d: EGLDisplay, c: EGLConfig, attribs: &[EGLint]) -> EGLContext {
    assert_eq!(egl::current::eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
    unsafe { egl::context::eglCreateContext(d, c, null_mut(), attribs.as_ptr()) }
}

#[test]
fn bad_display() {
    let bogus = 0x1234 as EGLDisplay;
    let mut v = 0;
    unsafe {
        assert_eq!(
            egl::display::eglInitialize(bogus, null_mut(), null_mut()),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_DISPLAY);
        assert_eq!(
            egl::display::eglInitialize(null_mut(), null_mut(), null_mut()),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_DISPLAY);
        assert_eq!(
            egl::config::eglGetConfigs(bogus, null_mut(), 0, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_DISPLAY);
        assert!(egl::display::eglQueryString(bogus, EGL_VENDOR).is_null());
        assert_eq!(err(), EGL_BAD_DISPLAY);
        // EGL_NO_DISPLAY answers the client extensions only.
        assert!(!egl::display::eglQueryString(null_mut(), EGL_EXTENSIONS).is_null());
        assert_eq!(err(), EGL_SUCCESS);
        assert!(egl::display::eglQueryString(null_mut(), EGL_VENDOR).is_null());
        assert_eq!(err(), EGL_BAD_DISPLAY);
        // Unknown platforms and native displays.
        assert!(
            egl::display::eglGetPlatformDisplay(0x31D5, null_mut(), std::ptr::null()).is_null()
        );
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert!(egl::display::eglGetPlatformDisplay(
            EGL_PLATFORM_DEVICE_EXT,
            0x40 as _,
            std::ptr::null()
        )
        .is_null());
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert!(egl::display::eglGetDisplay(0x40 as _).is_null());
        assert_eq!(
            egl::current::eglMakeCurrent(bogus, null_mut(), null_mut(), null_mut()),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_DISPLAY);
    }
}

#[test]
fn not_initialized() {
    // The device display, never initialized by any other test.
    unsafe {
        let mut dev = null_mut();
        let mut n = 0;
        assert_eq!(
            egl::display::eglQueryDevicesEXT(1, &mut dev, &mut n),
            EGL_TRUE
        );
        assert_eq!(n, 1);
        let d =
            egl::display::eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, dev, std::ptr::null());
        assert!(!d.is_null());
        let mut v = 0;
        assert_eq!(
            egl::config::eglGetConfigs(d, null_mut(), 0, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_NOT_INITIALIZED);
        assert!(egl::display::eglQueryString(d, EGL_VENDOR).is_null());
        assert_eq!(err(), EGL_NOT_INITIALIZED);
        assert_eq!(
            egl::display::eglQueryDevicesEXT(1, &mut dev, null_mut()),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert!(egl::display::eglQueryDeviceStringEXT(null_mut(), EGL_EXTENSIONS).is_null());
        assert_eq!(err(), EGL_BAD_DEVICE_EXT);
    }
}

#[test]
fn configs() {
    let d = display();
    let mut n = 0;
    let mut v = 0;
    unsafe {
        assert_eq!(
            egl::config::eglGetConfigs(d, null_mut(), 0, &mut n),
            EGL_TRUE
        );
        assert_eq!(n, 2);
        assert_eq!(
            egl::config::eglGetConfigs(d, null_mut(), 0, null_mut()),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_PARAMETER);
        let c = config(d, 24);
        assert_eq!(
            egl::config::eglGetConfigAttrib(d, c, EGL_DEPTH_SIZE, &mut v),
            EGL_TRUE
        );
        assert_eq!(v, 24);
        assert_eq!(
            egl::config::eglGetConfigAttrib(d, c, EGL_STENCIL_SIZE, &mut v),
            EGL_TRUE
        );
        assert_eq!(v, 8);
        let c0 = config(d, 0);
        assert_eq!(
            egl::config::eglGetConfigAttrib(d, c0, EGL_DEPTH_SIZE, &mut v),
            EGL_TRUE
        );
        assert_eq!(v, 0);
        assert_eq!(
            egl::config::eglGetConfigAttrib(d, c, 0x7777, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        assert_eq!(
            egl::config::eglGetConfigAttrib(d, 0x99 as _, EGL_DEPTH_SIZE, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_CONFIG);
        // A config of another display.
        let d0 = egl::display::eglGetDisplay(null_mut());
        assert_eq!(
            egl::display::eglInitialize(d0, null_mut(), null_mut()),
            EGL_TRUE
        );
        assert_eq!(
            egl::config::eglGetConfigAttrib(d0, c, EGL_DEPTH_SIZE, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_CONFIG);
        // Unknown attribute in a request; windows (the default surface
        // type) and OpenGL ES (the default renderable type) match nothing.
        let bad = [0x7777, 1, EGL_NONE];
        assert_eq!(
            egl::config::eglChooseConfig(d, bad.as_ptr(), null_mut(), 0, &mut n),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        let none = [EGL_NONE];
        assert_eq!(
            egl::config::eglChooseConfig(d, none.as_ptr(), null_mut(), 0, &mut n),
            EGL_TRUE
        );
        assert_eq!(n, 0);
        let big = [
            EGL_SURFACE_TYPE,
            EGL_PBUFFER_BIT,
            EGL_RENDERABLE_TYPE,
            EGL_OPENGL_BIT,
            EGL_DEPTH_SIZE,
            32,
            EGL_NONE,
        ];
        assert_eq!(
            egl::config::eglChooseConfig(d, big.as_ptr(), null_mut(), 0, &mut n),
            EGL_TRUE
        );
        assert_eq!(n, 0);
    }
}

#[test]
fn contexts_and_api() {
    let d = display();
    let c = config(d, 24);
    unsafe {
        assert_eq!(egl::current::eglBindAPI(EGL_OPENGL_ES_API), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert_eq!(egl::current::eglBindAPI(EGL_OPENVG_API), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_PARAMETER);
        // No API bound yet on a fresh thread: EGL_BAD_MATCH.
        let (du, cu) = (d as usize, c as usize);
        let t = std::thread::spawn(move || {
            let ctx =
                egl::context::eglCreateContext(du as _, cu as _, null_mut(), [EGL_NONE].as_ptr());
            (ctx.is_null(), err(), egl::current::eglQueryAPI())
        })
        .join()
        .unwrap();
        assert_eq!(t, (true, EGL_BAD_MATCH, EGL_NONE as EGLenum));
        let v = |maj: EGLint, min: EGLint| {
            let ctx = context(
                d,
                c,
                &[
                    EGL_CONTEXT_MAJOR_VERSION,
                    maj,
                    EGL_CONTEXT_MINOR_VERSION,
                    min,
                    EGL_NONE,
                ],
            );
            (ctx.is_null(), err(), ctx)
        };
        let (null, e, ctx) = v(2, 1);
        assert!(!null && e == EGL_SUCCESS);
        let (null, e, ctx33) = v(3, 3);
        assert!(!null && e == EGL_SUCCESS);
        assert_eq!(
            egl::context::eglDestroyContext(d, ctx33),
            EGL_TRUE as EGLBoolean
        );
        assert_eq!(v(3, 4).1, EGL_BAD_MATCH);
        assert_eq!(v(4, 1).1, EGL_BAD_MATCH);
        assert_eq!(v(2, 7).1, EGL_BAD_MATCH);
        let ctx2 = context(d, c, &[0x7777, 0, EGL_NONE]);
        assert!(ctx2.is_null());
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        assert!(
            egl::context::eglCreateContext(d, null_mut(), null_mut(), [EGL_NONE].as_ptr())
                .is_null()
        );
        assert_eq!(err(), EGL_BAD_CONFIG);
        assert!(egl::context::eglCreateContext(d, c, 0x5 as _, [EGL_NONE].as_ptr()).is_null());
        assert_eq!(err(), EGL_BAD_CONTEXT);
        let mut val = 0;
        assert_eq!(
            egl::context::eglQueryContext(d, ctx, EGL_CONTEXT_CLIENT_TYPE, &mut val),
            EGL_TRUE
        );
        assert_eq!(val as EGLenum, EGL_OPENGL_API);
        assert_eq!(
            egl::context::eglQueryContext(d, ctx, 0x7777, &mut val),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        // Destroyed: the handle is refused.
        assert_eq!(egl::context::eglDestroyContext(d, ctx), EGL_TRUE);
        assert_eq!(egl::context::eglDestroyContext(d, ctx), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_CONTEXT);
        assert_eq!(
            egl::current::eglMakeCurrent(d, null_mut(), null_mut(), ctx),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_CONTEXT);
    }
}

#[test]
fn surfaces_and_current() {
    let d = display();
    let c = config(d, 24);
    let ctx = context(d, c, &[EGL_NONE]);
    assert!(!ctx.is_null());
    unsafe {
        let s = egl::surface::eglCreatePbufferSurface(
            d,
            c,
            [EGL_WIDTH, 8, EGL_HEIGHT, 4, EGL_NONE].as_ptr(),
        );
        assert!(!s.is_null());
        assert!(
            egl::surface::eglCreatePbufferSurface(d, c, [EGL_WIDTH, -1, EGL_NONE].as_ptr())
                .is_null()
        );
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert!(
            egl::surface::eglCreatePbufferSurface(d, c, [0x7777, 1, EGL_NONE].as_ptr()).is_null()
        );
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        assert!(egl::surface::eglCreateWindowSurface(d, c, 0, std::ptr::null()).is_null());
        assert_eq!(err(), EGL_BAD_MATCH);
        let mut v = 0;
        assert_eq!(
            egl::surface::eglQuerySurface(d, s, EGL_WIDTH, &mut v),
            EGL_TRUE
        );
        assert_eq!(v, 8);
        assert_eq!(
            egl::surface::eglQuerySurface(d, s, 0x7777, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_ATTRIBUTE);
        // Swapping a surface that is not current.
        assert_eq!(egl::surface::eglSwapBuffers(d, s), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_SURFACE);
        // Draw without read.
        assert_eq!(
            egl::current::eglMakeCurrent(d, s, null_mut(), ctx),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_MATCH);
        // Surfaces without a context.
        assert_eq!(egl::current::eglMakeCurrent(d, s, s, null_mut()), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_MATCH);
        assert_eq!(egl::current::eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
        assert_eq!(egl::current::eglGetCurrentContext(), ctx);
        assert_eq!(egl::current::eglGetCurrentSurface(EGL_DRAW), s);
        assert!(egl::current::eglGetCurrentSurface(0x7777).is_null());
        assert_eq!(err(), EGL_BAD_PARAMETER);
        assert_eq!(egl::surface::eglSwapBuffers(d, s), EGL_TRUE);
        // The context and surface are current here: another thread gets
        // EGL_BAD_ACCESS for either.
        let (dd, ss, cc) = (d as usize, s as usize, ctx as usize);
        let other = std::thread::spawn(move || {
            egl::current::eglBindAPI(EGL_OPENGL_API);
            let r1 = egl::current::eglMakeCurrent(dd as _, null_mut(), null_mut(), cc as _);
            let e1 = err();
            let c2 = egl::context::eglCreateContext(
                dd as _,
                config(dd as _, 24),
                null_mut(),
                [EGL_NONE].as_ptr(),
            );
            let r2 = egl::current::eglMakeCurrent(dd as _, ss as _, ss as _, c2);
            let e2 = err();
            (r1, e1, r2, e2)
        })
        .join()
        .unwrap();
        assert_eq!(
            other,
            (EGL_FALSE, EGL_BAD_ACCESS, EGL_FALSE, EGL_BAD_ACCESS)
        );
        // Destroyed while current: still current, the handle refused.
        assert_eq!(egl::surface::eglDestroySurface(d, s), EGL_TRUE);
        assert_eq!(
            egl::surface::eglQuerySurface(d, s, EGL_WIDTH, &mut v),
            EGL_FALSE
        );
        assert_eq!(err(), EGL_BAD_SURFACE);
        assert_eq!(egl::current::eglGetCurrentSurface(EGL_DRAW), s);
        assert_eq!(egl::current::eglReleaseThread(), EGL_TRUE);
        assert!(egl::current::eglGetCurrentContext().is_null());
        assert_eq!(egl::current::eglQueryAPI(), EGL_NONE as EGLenum);
        // Surfaceless.
        let ctx = context(d, c, &[EGL_NONE]);
        assert_eq!(
            egl::current::eglMakeCurrent(d, null_mut(), null_mut(), ctx),
            EGL_TRUE
        );
        assert_eq!(
            egl::current::eglMakeCurrent(d, null_mut(), null_mut(), null_mut()),
            EGL_TRUE
        );
        assert_eq!(egl::surface::eglDestroySurface(d, s), EGL_FALSE);
        assert_eq!(err(), EGL_BAD_SURFACE);
    }
}

#[test]
fn proc_addresses() {
    for name in [
        c"eglGetDisplay",
        c"eglQueryDevicesEXT",
        c"glClear",
        c"glCreateShader",
        c"glXGetProcAddressARB",
    ] {
        assert!(
            unsafe { egl::procs::eglGetProcAddress(name.as_ptr()) }.is_some(),
            "{name:?}"
        );
    }
    assert!(unsafe { egl::procs::eglGetProcAddress(c"glNoSuchThing".as_ptr()) }.is_none());
    assert!(unsafe { egl::procs::eglGetProcAddress(std::ptr::null()) }.is_none());
    for name in egl::procs::EGL_NAMES {
        assert!(egl::procs::lookup(name).is_some());
    }
    assert_eq!(capi::context::caught_panics(), 0);
}
