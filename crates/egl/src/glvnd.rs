//! The GLVND EGL vendor interface: `__egl_Main`, which the system's
//! libglvnd `libEGL.so.1` calls after loading this library as a vendor
//! (a JSON file naming it, e.g. through `__EGL_VENDOR_LIBRARY_FILENAMES`).
//!
//! The ABI is libglvnd's `glvnd/libeglabi.h`, major version 0. libglvnd
//! owns the application-facing entry points and the current-context
//! bookkeeping; it reaches this library through the callbacks filled in
//! here:
//! - `getPlatformDisplay`: `eglGetDisplay(EGL_DEFAULT_DISPLAY)` arrives as
//!   platform `EGL_NONE` (our default display); the surfaceless and device
//!   platforms go to [`crate::display`]'s eglGetPlatformDisplay, which
//!   records the EGL error libglvnd reads back through our eglGetError.
//! - `getProcAddress`: every EGL, GLX and GL function ([`crate::procs`]);
//!   libglvnd takes the core EGL functions from it at load time, and
//!   libGLdispatch fills the vendor's GL table from it, so GL calls made
//!   through libOpenGL.so.0 / libGL.so.1 land in capi's gl* functions.
//! - `getDispatchAddress` / `setDispatchIndex`: the vendor-neutral stubs of
//!   the EGL functions libglvnd does not dispatch itself and this library
//!   implements: eglQueryDeviceStringEXT and eglQueryDeviceAttribEXT,
//!   which pick the vendor owning the device (possibly another vendor)
//!   through libglvnd's exports.
//!
//! eglBindAPI is forwarded by libglvnd to every vendor, so the thread's
//! API of [`crate::current`] is the one eglCreateContext sees.

use crate::display::eglGetPlatformDisplay;
use crate::types::*;
use std::ffi::{c_char, c_int, c_void, CStr};
use std::sync::atomic::{AtomicI32, AtomicPtr, Ordering};

/// The major ABI version this library implements (the high 16 bits of
/// `__egl_Main`'s version); a different major is refused.
pub const ABI_MAJOR: u32 = 0;

/// libglvnd's opaque per-vendor handle (`__EGLvendorInfo`).
pub type VendorInfo = c_void;

/// `__EGLapiExports`: the callbacks libglvnd gives its vendors, in the
/// header's order. Only the members of ABI 0.0 are declared (the later
/// `setVendorForDevice` is not used), since the table is read, never sized.
#[repr(C)]
pub struct ApiExports {
    pub thread_init: Option<unsafe extern "C" fn()>,
    pub get_current_api: Option<unsafe extern "C" fn() -> EGLenum>,
    pub get_current_vendor: Option<unsafe extern "C" fn() -> *mut VendorInfo>,
    pub get_current_context: Option<unsafe extern "C" fn() -> EGLContext>,
    pub get_current_display: Option<unsafe extern "C" fn() -> EGLDisplay>,
    pub get_current_surface: Option<unsafe extern "C" fn(EGLint) -> EGLSurface>,
    pub fetch_dispatch_entry: Option<unsafe extern "C" fn(*mut VendorInfo, c_int) -> EglProc>,
    pub set_egl_error: Option<unsafe extern "C" fn(EGLint)>,
    pub set_last_vendor: Option<unsafe extern "C" fn(*mut VendorInfo) -> EGLBoolean>,
    pub get_vendor_from_display: Option<unsafe extern "C" fn(EGLDisplay) -> *mut VendorInfo>,
    pub get_vendor_from_device: Option<unsafe extern "C" fn(EGLDeviceEXT) -> *mut VendorInfo>,
}

/// The required head of `__EGLapiImports`, which the vendor fills in. The
/// optional members after it (entry-point patching, native platform
/// detection) are left as libglvnd initialized them: unused.
#[repr(C)]
pub struct ApiImports {
    pub get_platform_display:
        Option<unsafe extern "C" fn(EGLenum, *mut c_void, *const EGLAttrib) -> EGLDisplay>,
    pub get_supports_api: Option<extern "C" fn(EGLenum) -> EGLBoolean>,
    pub get_vendor_string: Option<extern "C" fn(c_int) -> *const c_char>,
    pub get_proc_address: Option<unsafe extern "C" fn(*const c_char) -> *mut c_void>,
    pub get_dispatch_address: Option<unsafe extern "C" fn(*const c_char) -> *mut c_void>,
    pub set_dispatch_index: Option<unsafe extern "C" fn(*const c_char, c_int)>,
}

/// libglvnd's exports, kept from `__egl_Main` (valid while we are loaded).
static EXPORTS: AtomicPtr<ApiExports> = AtomicPtr::new(std::ptr::null_mut());

/// `__EGL_VENDOR_STRING_PLATFORM_EXTENSIONS`.
const VENDOR_STRING_PLATFORM_EXTENSIONS: c_int = 0;
/// The platform extensions, for libglvnd's client extension string.
const PLATFORM_EXTENSIONS: &CStr = c"EGL_EXT_platform_device EGL_MESA_platform_surfaceless";

/// `__egl_Main`: the handshake. Accepts ABI major version 0 (any minor:
/// only members present since 0.0 are used) and fills the required
/// callbacks.
#[no_mangle]
pub unsafe extern "C" fn __egl_Main(
    version: u32,
    exports: *const ApiExports,
    _vendor: *mut VendorInfo,
    imports: *mut ApiImports,
) -> EGLBoolean {
    if version >> 16 != ABI_MAJOR || exports.is_null() || imports.is_null() {
        return EGL_FALSE;
    }
    EXPORTS.store(exports as *mut ApiExports, Ordering::Release);
    // SAFETY: libglvnd passes its writable imports table (at least the
    // members declared in ApiImports, present since ABI 0.0).
    unsafe {
        let i = &mut *imports;
        i.get_platform_display = Some(get_platform_display);
        i.get_supports_api = Some(get_supports_api);
        i.get_vendor_string = Some(get_vendor_string);
        i.get_proc_address = Some(get_proc_address);
        i.get_dispatch_address = Some(get_dispatch_address);
        i.set_dispatch_index = Some(set_dispatch_index);
    }
    EGL_TRUE
}

/// eglGetDisplay and eglGetPlatformDisplay for libglvnd.
unsafe extern "C" fn get_platform_display(
    platform: EGLenum,
    native: *mut c_void,
    attribs: *const EGLAttrib,
) -> EGLDisplay {
    if platform == EGL_NONE as EGLenum {
        // eglGetDisplay(EGL_DEFAULT_DISPLAY) (libglvnd passes no other
        // native display with EGL_NONE).
        return crate::display::eglGetDisplay(native);
    }
    // SAFETY: libglvnd passes the application's arguments through.
    unsafe { eglGetPlatformDisplay(platform, native, attribs) }
}

/// OpenGL only (eglCreateContext refuses OpenGL ES).
extern "C" fn get_supports_api(api: EGLenum) -> EGLBoolean {
    crate::error::boolean(api == EGL_OPENGL_API)
}

extern "C" fn get_vendor_string(name: c_int) -> *const c_char {
    match name {
        VENDOR_STRING_PLATFORM_EXTENSIONS => PLATFORM_EXTENSIONS.as_ptr(),
        _ => std::ptr::null(),
    }
}

/// The real function `name` (EGL, GLX or GL), or null.
unsafe extern "C" fn get_proc_address(name: *const c_char) -> *mut c_void {
    // SAFETY: a NUL-terminated name from libglvnd.
    match name_of(name).and_then(crate::procs::lookup) {
        Some(p) => p as *mut c_void,
        None => std::ptr::null_mut(),
    }
}

fn name_of<'a>(name: *const c_char) -> Option<&'a str> {
    if name.is_null() {
        return None;
    }
    // SAFETY: non-null NUL-terminated string (libglvnd's contract).
    unsafe { CStr::from_ptr(name) }.to_str().ok()
}

/// The EGL functions this library dispatches for libglvnd: name, the
/// vendor-neutral stub, and the dispatch index libglvnd assigned (-1
/// until setDispatchIndex).
struct Dispatched {
    name: &'static str,
    stub: *const (),
    index: &'static AtomicI32,
}

static QUERY_DEVICE_STRING: AtomicI32 = AtomicI32::new(-1);
static QUERY_DEVICE_ATTRIB: AtomicI32 = AtomicI32::new(-1);

fn dispatched() -> [Dispatched; 2] {
    [
        Dispatched {
            name: "eglQueryDeviceStringEXT",
            stub: dispatch_query_device_string as *const (),
            index: &QUERY_DEVICE_STRING,
        },
        Dispatched {
            name: "eglQueryDeviceAttribEXT",
            stub: dispatch_query_device_attrib as *const (),
            index: &QUERY_DEVICE_ATTRIB,
        },
    ]
}

unsafe extern "C" fn get_dispatch_address(name: *const c_char) -> *mut c_void {
    let Some(name) = name_of(name) else {
        return std::ptr::null_mut();
    };
    dispatched()
        .iter()
        .find(|d| d.name == name)
        .map_or(std::ptr::null_mut(), |d| d.stub as *mut c_void)
}

unsafe extern "C" fn set_dispatch_index(name: *const c_char, index: c_int) {
    if let Some(name) = name_of(name) {
        if let Some(d) = dispatched().iter().find(|d| d.name == name) {
            d.index.store(index, Ordering::Release);
        }
    }
}

/// libglvnd's exports table (set by `__egl_Main` before any stub can be
/// handed out).
fn exports() -> Option<&'static ApiExports> {
    // SAFETY: the pointer libglvnd gave us stays valid while we are loaded.
    unsafe { EXPORTS.load(Ordering::Acquire).as_ref() }
}

/// The implementation of dispatched function `index` in the vendor owning
/// `device`, recorded as the last vendor (so eglGetError asks it); or
/// EGL_BAD_DEVICE_EXT recorded in libglvnd when no vendor owns it.
fn device_vendor_entry(device: EGLDeviceEXT, index: &AtomicI32) -> EglProc {
    let e = exports()?;
    // SAFETY: libglvnd's callbacks, called as its header documents.
    unsafe {
        if let Some(init) = e.thread_init {
            init();
        }
        let vendor = e.get_vendor_from_device?(device);
        let i = index.load(Ordering::Acquire);
        let f = if vendor.is_null() || i < 0 {
            None
        } else {
            e.fetch_dispatch_entry?(vendor, i)
        };
        match f {
            Some(f) => {
                e.set_last_vendor?(vendor);
                Some(f)
            }
            None => {
                e.set_egl_error?(EGL_BAD_DEVICE_EXT);
                None
            }
        }
    }
}

unsafe extern "C" fn dispatch_query_device_string(
    device: EGLDeviceEXT,
    name: EGLint,
) -> *const c_char {
    match device_vendor_entry(device, &QUERY_DEVICE_STRING) {
        // SAFETY: the vendor's eglQueryDeviceStringEXT, by its signature.
        Some(f) => unsafe {
            let f: unsafe extern "C" fn(EGLDeviceEXT, EGLint) -> *const c_char =
                std::mem::transmute(f);
            f(device, name)
        },
        None => std::ptr::null(),
    }
}

unsafe extern "C" fn dispatch_query_device_attrib(
    device: EGLDeviceEXT,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    match device_vendor_entry(device, &QUERY_DEVICE_ATTRIB) {
        // SAFETY: the vendor's eglQueryDeviceAttribEXT, by its signature.
        Some(f) => unsafe {
            let f: unsafe extern "C" fn(EGLDeviceEXT, EGLint, *mut EGLAttrib) -> EGLBoolean =
                std::mem::transmute(f);
            f(device, attribute, value)
        },
        None => EGL_FALSE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::display::CLIENT_EXTENSIONS;

    // libglvnd also reads the client extensions from
    // eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS): the two agree.
    #[test]
    fn platform_extensions_are_client_extensions() {
        let all = CLIENT_EXTENSIONS.to_str().unwrap();
        for e in PLATFORM_EXTENSIONS.to_str().unwrap().split(' ') {
            assert!(all.split(' ').any(|x| x == e), "{e}");
        }
    }

    #[test]
    fn handshake_refuses_another_major_version() {
        let mut imports = ApiImports {
            get_platform_display: None,
            get_supports_api: None,
            get_vendor_string: None,
            get_proc_address: None,
            get_dispatch_address: None,
            set_dispatch_index: None,
        };
        // A non-null exports pointer is never read by the handshake.
        let exports = std::ptr::NonNull::<ApiExports>::dangling().as_ptr();
        unsafe {
            assert_eq!(
                __egl_Main(1 << 16, exports, std::ptr::null_mut(), &mut imports),
                EGL_FALSE
            );
            assert!(imports.get_proc_address.is_none());
        }
    }

    #[test]
    fn proc_and_dispatch_addresses() {
        unsafe {
            assert!(!get_proc_address(c"eglInitialize".as_ptr()).is_null());
            assert!(!get_proc_address(c"glClear".as_ptr()).is_null());
            assert!(get_proc_address(c"glNotAFunction".as_ptr()).is_null());
            assert!(!get_dispatch_address(c"eglQueryDeviceStringEXT".as_ptr()).is_null());
            // libglvnd dispatches the core functions itself.
            assert!(get_dispatch_address(c"eglInitialize".as_ptr()).is_null());
        }
        assert_eq!(get_supports_api(EGL_OPENGL_API), EGL_TRUE);
        assert_eq!(get_supports_api(EGL_OPENGL_ES_API), EGL_FALSE);
        assert!(get_vendor_string(1).is_null());
    }
}
