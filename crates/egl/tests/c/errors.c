/* EGL's error paths as a C program sees them: bad displays, configs,
 * attributes and APIs, calls with no current context, destroyed surfaces
 * and contexts, a context current on another thread. Each check prints
 * one line
 *
 *     NAME RESULT ERROR
 *
 * RESULT the call's return value (0/1 for EGLBoolean, null/handle for
 * handles), ERROR what eglGetError returned right after it (hex). Links
 * only against libEGL.so.1, so the same binary runs on shaderbox's
 * library (LD_LIBRARY_PATH) and on any other EGL (the system's libglvnd
 * and a vendor such as Mesa's): tests/error_codes.rs compares the two
 * outputs. Uses the surfaceless platform (EGL_MESA_platform_surfaceless)
 * and pbuffers: no window system.
 *
 * Self-contained (no EGL headers needed): egl_min.h has the types and
 * values. */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>

#include "egl_min.h"

#define BOGUS_ATTRIB 0x7777

EGLDisplay eglGetPlatformDisplay(EGLenum, void *, const intptr_t *);
EGLBoolean eglInitialize(EGLDisplay, EGLint *, EGLint *);
EGLBoolean eglTerminate(EGLDisplay);
const char *eglQueryString(EGLDisplay, EGLint);
EGLBoolean eglGetConfigs(EGLDisplay, EGLConfig *, EGLint, EGLint *);
EGLBoolean eglChooseConfig(EGLDisplay, const EGLint *, EGLConfig *, EGLint, EGLint *);
EGLBoolean eglGetConfigAttrib(EGLDisplay, EGLConfig, EGLint, EGLint *);
EGLBoolean eglBindAPI(EGLenum);
EGLenum eglQueryAPI(void);
EGLContext eglCreateContext(EGLDisplay, EGLConfig, EGLContext, const EGLint *);
EGLBoolean eglDestroyContext(EGLDisplay, EGLContext);
EGLBoolean eglQueryContext(EGLDisplay, EGLContext, EGLint, EGLint *);
EGLSurface eglCreatePbufferSurface(EGLDisplay, EGLConfig, const EGLint *);
EGLSurface eglCreateWindowSurface(EGLDisplay, EGLConfig, uintptr_t, const EGLint *);
EGLBoolean eglDestroySurface(EGLDisplay, EGLSurface);
EGLBoolean eglQuerySurface(EGLDisplay, EGLSurface, EGLint, EGLint *);
EGLBoolean eglMakeCurrent(EGLDisplay, EGLSurface, EGLSurface, EGLContext);
EGLContext eglGetCurrentContext(void);
EGLSurface eglGetCurrentSurface(EGLint);
EGLBoolean eglSwapBuffers(EGLDisplay, EGLSurface);
EGLBoolean eglSwapInterval(EGLDisplay, EGLint);
EGLBoolean eglWaitClient(void);
EGLBoolean eglReleaseThread(void);
EGLint eglGetError(void);

static void report(const char *name, long result) {
    printf("%s %ld 0x%04x\n", name, result, (unsigned)eglGetError());
}

static void report_handle(const char *name, const void *handle) {
    printf("%s %s 0x%04x\n", name, handle ? "handle" : "null", (unsigned)eglGetError());
}

#define BOGUS_DISPLAY ((EGLDisplay)(uintptr_t)0x1234)
#define BOGUS_CONFIG ((EGLConfig)(uintptr_t)0x99)
#define BOGUS_CONTEXT ((EGLContext)(uintptr_t)0x5)

struct other {
    EGLDisplay dpy;
    EGLContext ctx;
    EGLSurface surf;
};

/* On a thread of its own: the API before any eglBindAPI, then making
 * current the context and surface current on the main thread. */
static void *other_thread(void *arg) {
    struct other *o = arg;
    printf("thread-query-api-initial 0x%04x 0x%04x\n", eglQueryAPI(), (unsigned)eglGetError());
    eglBindAPI(EGL_OPENGL_API);
    report("thread-make-current-context-of-other-thread",
           eglMakeCurrent(o->dpy, o->surf, o->surf, o->ctx));
    report("thread-release", eglReleaseThread());
    return NULL;
}

int main(void) {
    EGLint n = 0, v = 0;
    setvbuf(stdout, NULL, _IOLBF, 0);
    report("initial-error", 1);

    /* Bad displays. */
    report("initialize-bogus-display", eglInitialize(BOGUS_DISPLAY, NULL, NULL));
    report("initialize-no-display", eglInitialize(EGL_NO_DISPLAY, NULL, NULL));
    report("terminate-bogus-display", eglTerminate(BOGUS_DISPLAY));
    report("get-configs-bogus-display", eglGetConfigs(BOGUS_DISPLAY, NULL, 0, &n));
    report_handle("query-string-no-display-extensions",
                  eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS));
    report_handle("query-string-no-display-vendor", eglQueryString(EGL_NO_DISPLAY, EGL_VENDOR));
    report_handle("query-string-bogus-display", eglQueryString(BOGUS_DISPLAY, EGL_VENDOR));
    report_handle("platform-display-unknown-platform",
                  eglGetPlatformDisplay(0x1234, EGL_DEFAULT_DISPLAY, NULL));
    report_handle("platform-display-x11",
                  eglGetPlatformDisplay(EGL_PLATFORM_X11_EXT, EGL_DEFAULT_DISPLAY, NULL));
    report("make-current-bogus-display",
           eglMakeCurrent(BOGUS_DISPLAY, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));

    EGLDisplay dpy =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    report_handle("platform-display-surfaceless", dpy);
    if (!dpy)
        return 1;
    /* Not initialized yet. */
    report("get-configs-not-initialized", eglGetConfigs(dpy, NULL, 0, &n));
    report_handle("query-string-not-initialized", eglQueryString(dpy, EGL_VENDOR));
    report("initialize", eglInitialize(dpy, NULL, NULL));

    /* Configs. */
    report("get-configs-null-count", eglGetConfigs(dpy, NULL, 0, NULL));
    EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                     EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                     EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig cfg = NULL;
    report("choose-config", eglChooseConfig(dpy, want, &cfg, 1, &n) && n > 0);
    if (!cfg)
        return 1;
    EGLint bad_attrib[] = {BOGUS_ATTRIB, 1, EGL_NONE};
    report("choose-config-bogus-attribute", eglChooseConfig(dpy, bad_attrib, NULL, 0, &n));
    report("choose-config-null-count", eglChooseConfig(dpy, want, NULL, 0, NULL));
    report("config-attrib-bogus-config", eglGetConfigAttrib(dpy, BOGUS_CONFIG, EGL_DEPTH_SIZE, &v));
    report("config-attrib-bogus-attribute", eglGetConfigAttrib(dpy, cfg, BOGUS_ATTRIB, &v));

    /* APIs. */
    printf("query-api-initial 0x%04x 0x%04x\n", eglQueryAPI(), (unsigned)eglGetError());
    report("bind-api-bogus", eglBindAPI(0x1234));
    report("bind-api-opengl-es", eglBindAPI(EGL_OPENGL_ES_API));
    report("bind-api-opengl", eglBindAPI(EGL_OPENGL_API));

    /* Contexts. */
    EGLint none[] = {EGL_NONE};
    report_handle("create-context-bogus-config", eglCreateContext(dpy, BOGUS_CONFIG, NULL, none));
    report_handle("create-context-bogus-display", eglCreateContext(BOGUS_DISPLAY, cfg, NULL, none));
    report_handle("create-context-bogus-share", eglCreateContext(dpy, cfg, BOGUS_CONTEXT, none));
    report_handle("create-context-bogus-attribute",
                  eglCreateContext(dpy, cfg, NULL, bad_attrib));
    EGLint v34[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 4, EGL_NONE};
    report_handle("create-context-version-3.4", eglCreateContext(dpy, cfg, NULL, v34));
    EGLint v27[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 7, EGL_NONE};
    report_handle("create-context-version-2.7", eglCreateContext(dpy, cfg, NULL, v27));
    EGLint v99[] = {EGL_CONTEXT_MAJOR_VERSION, 9, EGL_CONTEXT_MINOR_VERSION, 9, EGL_NONE};
    report_handle("create-context-version-9.9", eglCreateContext(dpy, cfg, NULL, v99));
    EGLContext ctx = eglCreateContext(dpy, cfg, NULL, none);
    report_handle("create-context", ctx);
    if (!ctx)
        return 1;
    report("query-context-bogus-attribute", eglQueryContext(dpy, ctx, BOGUS_ATTRIB, &v));
    report("query-context-bogus-context",
           eglQueryContext(dpy, BOGUS_CONTEXT, EGL_CONTEXT_CLIENT_TYPE, &v));

    /* Surfaces. */
    EGLint neg[] = {EGL_WIDTH, -1, EGL_NONE};
    report_handle("pbuffer-negative-width", eglCreatePbufferSurface(dpy, cfg, neg));
    report_handle("pbuffer-bogus-attribute", eglCreatePbufferSurface(dpy, cfg, bad_attrib));
    report_handle("pbuffer-bogus-config", eglCreatePbufferSurface(dpy, BOGUS_CONFIG, none));
    report_handle("window-surface-pbuffer-config", eglCreateWindowSurface(dpy, cfg, 0, none));
    EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 4, EGL_NONE};
    EGLSurface surf = eglCreatePbufferSurface(dpy, cfg, size);
    report_handle("pbuffer", surf);
    if (!surf)
        return 1;
    report("query-surface-bogus-attribute", eglQuerySurface(dpy, surf, BOGUS_ATTRIB, &v));
    report("query-surface-bogus-surface",
           eglQuerySurface(dpy, (EGLSurface)(uintptr_t)0x77, EGL_WIDTH, &v));

    /* No current context. */
    report_handle("current-context-none", eglGetCurrentContext());
    report_handle("current-surface-none", eglGetCurrentSurface(EGL_DRAW));
    report("swap-buffers-not-current", eglSwapBuffers(dpy, surf));
    report("swap-interval-no-context", eglSwapInterval(dpy, 0));
    report("wait-client-no-context", eglWaitClient());

    /* eglMakeCurrent's argument checks. */
    report("make-current-draw-without-read", eglMakeCurrent(dpy, surf, EGL_NO_SURFACE, ctx));
    report("make-current-surface-without-context",
           eglMakeCurrent(dpy, surf, surf, EGL_NO_CONTEXT));
    report("make-current-bogus-context", eglMakeCurrent(dpy, surf, surf, BOGUS_CONTEXT));
    report("make-current-bogus-surface",
           eglMakeCurrent(dpy, (EGLSurface)(uintptr_t)0x77, (EGLSurface)(uintptr_t)0x77, ctx));
    report("make-current", eglMakeCurrent(dpy, surf, surf, ctx));
    report_handle("current-surface-bogus-which", eglGetCurrentSurface(BOGUS_ATTRIB));
    report("swap-buffers", eglSwapBuffers(dpy, surf));

    /* The context and surface are current here: another thread. */
    struct other o = {dpy, ctx, surf};
    pthread_t t;
    if (pthread_create(&t, NULL, other_thread, &o) == 0)
        pthread_join(t, NULL);

    report("release-current",
           eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));

    /* Destroyed surface and context. */
    report("destroy-surface", eglDestroySurface(dpy, surf));
    report("query-surface-destroyed", eglQuerySurface(dpy, surf, EGL_WIDTH, &v));
    report("destroy-surface-destroyed", eglDestroySurface(dpy, surf));
    report("make-current-destroyed-surface", eglMakeCurrent(dpy, surf, surf, ctx));
    report("swap-buffers-destroyed-surface", eglSwapBuffers(dpy, surf));
    report("destroy-context", eglDestroyContext(dpy, ctx));
    report("destroy-context-destroyed", eglDestroyContext(dpy, ctx));
    report("make-current-destroyed-context",
           eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
    report("query-context-destroyed", eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &v));

    report("release-thread", eglReleaseThread());
    printf("query-api-after-release 0x%04x 0x%04x\n", eglQueryAPI(), (unsigned)eglGetError());
    report("terminate", eglTerminate(dpy));
    report("get-configs-terminated", eglGetConfigs(dpy, NULL, 0, &n));
    return 0;
}
