/* A headless EGL program as users write them: the device platform (or
 * EGL_DEFAULT_DISPLAY), a surfaceless context (default attributes: the
 * compatibility profile, with the fixed-function pipeline) drawing a
 * triangle into a framebuffer object, then a pbuffer surface drawing the
 * same triangle into the default framebuffer; pixels are read back and
 * checked. Built and run by tests/c_program.rs against the built
 * libEGL.so; links only against libEGL.so.1 and resolves GL through
 * eglGetProcAddress, as loaders (glad, epoxy) do.
 *
 * Exit status 0 and "ok" on success; the first failed check otherwise.
 * Self-contained (no EGL headers needed): egl_min.h has the types and
 * values. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "egl_min.h"

EGLDisplay eglGetDisplay(void *);
EGLBoolean eglInitialize(EGLDisplay, EGLint *, EGLint *);
EGLBoolean eglChooseConfig(EGLDisplay, const EGLint *, EGLConfig *, EGLint, EGLint *);
EGLBoolean eglBindAPI(EGLenum);
EGLContext eglCreateContext(EGLDisplay, EGLConfig, EGLContext, const EGLint *);
EGLSurface eglCreatePbufferSurface(EGLDisplay, EGLConfig, const EGLint *);
EGLBoolean eglMakeCurrent(EGLDisplay, EGLSurface, EGLSurface, EGLContext);
EGLBoolean eglSwapBuffers(EGLDisplay, EGLSurface);
EGLBoolean eglDestroySurface(EGLDisplay, EGLSurface);
EGLBoolean eglDestroyContext(EGLDisplay, EGLContext);
EGLBoolean eglTerminate(EGLDisplay);
EGLBoolean eglReleaseThread(void);
EGLint eglGetError(void);
const char *eglQueryString(EGLDisplay, EGLint);
void (*eglGetProcAddress(const char *))(void);
typedef EGLBoolean (*PFNEGLQUERYDEVICESEXTPROC)(EGLint, EGLDeviceEXT *, EGLint *);
typedef EGLDisplay (*PFNEGLGETPLATFORMDISPLAYEXTPROC)(EGLenum, void *, const EGLint *);
typedef const char *(*PFNEGLQUERYDEVICESTRINGEXTPROC)(EGLDeviceEXT, EGLint);

typedef unsigned int GLenum;
typedef unsigned int GLuint;
typedef int GLint;
typedef int GLsizei;
typedef float GLfloat;
typedef unsigned char GLubyte;
typedef unsigned int GLbitfield;

#define GL_TRIANGLES 0x0004
#define GL_COLOR_BUFFER_BIT 0x4000
#define GL_RGBA 0x1908
#define GL_RGBA8 0x8058
#define GL_UNSIGNED_BYTE 0x1401
#define GL_FRAMEBUFFER 0x8D40
#define GL_RENDERBUFFER 0x8D41
#define GL_COLOR_ATTACHMENT0 0x8CE0
#define GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define GL_VERSION 0x1F02
#define GL_RENDERER 0x1F01
#define GL_VENDOR 0x1F00

static void (*Clear)(GLbitfield);
static void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
static void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
static void (*Begin)(GLenum);
static void (*End)(void);
static void (*Color3f)(GLfloat, GLfloat, GLfloat);
static void (*Vertex2f)(GLfloat, GLfloat);
static void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *);
static void (*GenFramebuffers)(GLsizei, GLuint *);
static void (*BindFramebuffer)(GLenum, GLuint);
static void (*GenRenderbuffers)(GLsizei, GLuint *);
static void (*BindRenderbuffer)(GLenum, GLuint);
static void (*RenderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
static void (*FramebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
static GLenum (*CheckFramebufferStatus)(GLenum);
static const GLubyte *(*GetString)(GLenum);
static GLenum (*GetError)(void);

#define CHECK(cond) do { if (!(cond)) { \
    fprintf(stderr, "FAILED line %d: %s (EGL error 0x%x)\n", __LINE__, #cond, eglGetError()); \
    return 1; } } while (0)
#define LOAD(var, name) do { *(void **)&var = (void *)eglGetProcAddress(name); CHECK(var != NULL); } while (0)

enum { W = 32, H = 32 };

static void triangle(void) {
    ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    Clear(GL_COLOR_BUFFER_BIT);
    Begin(GL_TRIANGLES);
    Color3f(1.0f, 0.0f, 0.0f);
    Vertex2f(-0.9f, -0.9f);
    Vertex2f(0.9f, -0.9f);
    Vertex2f(0.0f, 0.9f);
    End();
}

/* Center red (inside the triangle), corners blue (outside). */
static int check_pixels(const char *what) {
    GLubyte px[W * H * 4];
    memset(px, 0, sizeof px);
    ReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    const GLubyte *c = px + ((H / 2) * W + W / 2) * 4;
    const GLubyte *k = px + ((H - 1) * W + 0) * 4;
    if (!(c[0] == 255 && c[1] == 0 && c[2] == 0 && k[0] == 0 && k[2] == 255)) {
        fprintf(stderr, "FAILED %s: center %d,%d,%d corner %d,%d,%d\n", what, c[0], c[1], c[2],
                k[0], k[1], k[2]);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv) {
    int use_device = argc > 1 && strcmp(argv[1], "device") == 0;
    EGLDisplay dpy;
    if (use_device) {
        PFNEGLQUERYDEVICESEXTPROC queryDevices =
            (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
        PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay =
            (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
        CHECK(queryDevices && getPlatformDisplay);
        EGLDeviceEXT devices[4];
        EGLint n = 0;
        CHECK(queryDevices(4, devices, &n) && n == 1);
        PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString =
            (PFNEGLQUERYDEVICESTRINGEXTPROC)eglGetProcAddress("eglQueryDeviceStringEXT");
        CHECK(queryDeviceString);
        const char *devext = queryDeviceString(devices[0], EGL_EXTENSIONS);
        CHECK(devext && strstr(devext, "EGL_MESA_device_software"));
        dpy = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], NULL);
    } else {
        dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    }
    CHECK(dpy != EGL_NO_DISPLAY);
    EGLint major = 0, minor = 0;
    CHECK(eglInitialize(dpy, &major, &minor));
    CHECK(major == 1 && minor == 5);
    const EGLint cattr[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                            EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig config;
    EGLint nconf = 0;
    CHECK(eglChooseConfig(dpy, cattr, &config, 1, &nconf) && nconf == 1);
    CHECK(eglBindAPI(EGL_OPENGL_API));
    const EGLint ctxattr[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxattr);
    CHECK(ctx != EGL_NO_CONTEXT);

    /* Surfaceless, into a framebuffer object. */
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
    LOAD(Clear, "glClear");
    LOAD(ClearColor, "glClearColor");
    LOAD(Viewport, "glViewport");
    LOAD(Begin, "glBegin");
    LOAD(End, "glEnd");
    LOAD(Color3f, "glColor3f");
    LOAD(Vertex2f, "glVertex2f");
    LOAD(ReadPixels, "glReadPixels");
    LOAD(GenFramebuffers, "glGenFramebuffersEXT");
    LOAD(BindFramebuffer, "glBindFramebufferEXT");
    LOAD(GenRenderbuffers, "glGenRenderbuffersEXT");
    LOAD(BindRenderbuffer, "glBindRenderbufferEXT");
    LOAD(RenderbufferStorage, "glRenderbufferStorageEXT");
    LOAD(FramebufferRenderbuffer, "glFramebufferRenderbufferEXT");
    LOAD(CheckFramebufferStatus, "glCheckFramebufferStatusEXT");
    LOAD(GetString, "glGetString");
    LOAD(GetError, "glGetError");
    printf("EGL_VENDOR: %s\nGL_VENDOR: %s\nGL_RENDERER: %s\nGL_VERSION: %s\n", eglQueryString(dpy, EGL_VENDOR),
           GetString(GL_VENDOR), GetString(GL_RENDERER), GetString(GL_VERSION));
    GLuint fbo, rb;
    GenFramebuffers(1, &fbo);
    BindFramebuffer(GL_FRAMEBUFFER, fbo);
    GenRenderbuffers(1, &rb);
    BindRenderbuffer(GL_RENDERBUFFER, rb);
    RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    CHECK(CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    Viewport(0, 0, W, H);
    triangle();
    if (check_pixels("surfaceless FBO"))
        return 1;
    BindFramebuffer(GL_FRAMEBUFFER, 0);

    /* A pbuffer: the first surface sets the viewport. */
    const EGLint pattr[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
    EGLSurface pb = eglCreatePbufferSurface(dpy, config, pattr);
    CHECK(pb != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(dpy, pb, pb, ctx));
    triangle();
    CHECK(eglSwapBuffers(dpy, pb));
    if (check_pixels("pbuffer"))
        return 1;
    /* Contents survive a release and a rebind. */
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglMakeCurrent(dpy, pb, pb, ctx));
    if (check_pixels("pbuffer after rebind"))
        return 1;
    CHECK(GetError() == 0);

    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglDestroySurface(dpy, pb));
    CHECK(eglDestroyContext(dpy, ctx));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    printf("ok\n");
    return 0;
}
