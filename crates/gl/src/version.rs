//! The context's API: its OpenGL version and profile, the strings and
//! numbers that describe them, and what the core profile removes.
//!
//! shaderbox implements three APIs: OpenGL 2.1, and OpenGL 3.3 in its core
//! and compatibility profiles. A request gets the lowest of them that is
//! at least the version asked for and has the profile asked for (a later
//! version is backward compatible with the request, as GLX and EGL let an
//! implementation answer): compatibility requests up to 2.1 get 2.1,
//! compatibility requests for 3.0-3.3 get 3.3 compatibility, and core
//! requests of any version up to 3.3 get 3.3 core (Mesa's OSMesa answers a
//! core request below 3.2 with a core context too). Requests beyond 3.3
//! are refused.
//!
//! The core profile removes what the GL 3.3 core specification's appendix
//! E.2.2 lists. Whole entry points ([`removed_in_core`]) record
//! `GL_INVALID_OPERATION` and do nothing; removed values of kept entry
//! points record the error any other unknown value would (the context's
//! `enable`, `get_*`, draw and texture calls check those through
//! [`Context::is_core`]).

use crate::enums::*;
use crate::Context;

/// An OpenGL profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Profile {
    /// Only what the core profile keeps (GL 3.2+).
    Core,
    /// Everything since GL 1.0 (GL 2.1 contexts are compatibility ones).
    Compatibility,
}

/// The API a context implements.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Api {
    pub major: u32,
    pub minor: u32,
    pub profile: Profile,
}

impl Default for Api {
    fn default() -> Self {
        Api::GL21
    }
}

impl Api {
    /// OpenGL 2.1 (GLSL 1.20).
    pub const GL21: Api = Api {
        major: 2,
        minor: 1,
        profile: Profile::Compatibility,
    };
    /// OpenGL 3.3 core profile (GLSL 3.30).
    pub const GL33_CORE: Api = Api {
        major: 3,
        minor: 3,
        profile: Profile::Core,
    };
    /// OpenGL 3.3 compatibility profile (GLSL 3.30).
    pub const GL33_COMPAT: Api = Api {
        major: 3,
        minor: 3,
        profile: Profile::Compatibility,
    };

    /// The API a request for version `major.minor` of `profile` gets (see
    /// the module docs); `None` when shaderbox has none that satisfies it
    /// (a version above 3.3, or below 1.0).
    pub fn for_request(major: i32, minor: i32, profile: Profile) -> Option<Api> {
        if major < 1 || minor < 0 || (major, minor) > (3, 3) {
            return None;
        }
        Some(match profile {
            Profile::Core => Api::GL33_CORE,
            Profile::Compatibility if major >= 3 => Api::GL33_COMPAT,
            Profile::Compatibility => Api::GL21,
        })
    }

    pub fn is_core(self) -> bool {
        self.profile == Profile::Core
    }

    /// Whether the API is at least `major.minor`.
    pub fn at_least(self, major: u32, minor: u32) -> bool {
        (self.major, self.minor) >= (major, minor)
    }

    /// `glGetString(GL_VERSION)`: `"MAJOR.MINOR"`, then the profile
    /// from 3.2 on, then the implementation (GL 3.3 §6.1.5).
    pub fn version_string(self) -> String {
        let profile = match (self.at_least(3, 2), self.profile) {
            (false, _) => "",
            (true, Profile::Core) => " (Core Profile)",
            (true, Profile::Compatibility) => " (Compatibility Profile)",
        };
        format!("{}.{}{profile} shaderbox", self.major, self.minor)
    }

    /// The newest GLSL version the API accepts, as
    /// `glGetString(GL_SHADING_LANGUAGE_VERSION)` reports it.
    pub fn glsl_version_string(self) -> &'static str {
        if self.at_least(3, 3) {
            "3.30"
        } else {
            "1.20"
        }
    }

    /// `GL_CONTEXT_PROFILE_MASK` (GL 3.2+).
    pub fn profile_mask(self) -> u32 {
        match self.profile {
            Profile::Core => GL_CONTEXT_CORE_PROFILE_BIT,
            Profile::Compatibility => GL_CONTEXT_COMPATIBILITY_PROFILE_BIT,
        }
    }

    /// The extensions the API reports: GL_EXTENSIONS' words, or the
    /// strings `glGetStringi(GL_EXTENSIONS, i)` numbers.
    pub fn extensions(self) -> Vec<&'static str> {
        let mut v = crate::get::EXTENSIONS.to_vec();
        if self.at_least(3, 3) {
            v.extend_from_slice(crate::get::EXTENSIONS_33);
        }
        if self.at_least(3, 1) && self.profile == Profile::Compatibility {
            v.push("GL_ARB_compatibility");
        }
        // The extension form of geometry shaders, on GLSL 1.10-1.40.
        if self.profile == Profile::Compatibility {
            v.extend(["GL_ARB_geometry_shader4", "GL_EXT_geometry_shader4"]);
            // Its program attachment points per stage (and a geometry
            // stage linked without a vertex stage) need those geometry
            // shaders.
            v.push("GL_EXT_separate_shader_objects");
        }
        v
    }

    /// The GLSL compile options' view of the API: whether shaders may use
    /// the compatibility profile (and GLSL 1.10/1.20).
    pub fn compatibility(self) -> bool {
        self.profile == Profile::Compatibility
    }
}

/// Entry-point families the core profile removes: the name followed only
/// by a type/arity suffix (`glColor4ub`, `glLightModelfv`), and an
/// optional `ARB`/`EXT`/`MESA` suffix.
const REMOVED_FAMILIES: &[&str] = &[
    "glColor",
    "glEdgeFlag",
    "glEvalCoord",
    "glEvalMesh",
    "glEvalPoint",
    "glFog",
    "glFogCoord",
    "glGetLight",
    "glGetMap",
    "glGetMaterial",
    "glGetPixelMap",
    "glGetTexEnv",
    "glGetTexGen",
    "glIndex",
    "glLight",
    "glLightModel",
    "glLoadMatrix",
    "glLoadTransposeMatrix",
    "glMap1",
    "glMap2",
    "glMapGrid1",
    "glMapGrid2",
    "glMaterial",
    "glMultMatrix",
    "glMultTransposeMatrix",
    "glMultiTexCoord",
    "glNormal",
    "glPixelMap",
    "glPixelTransfer",
    "glRasterPos",
    "glRect",
    "glRotate",
    "glScale",
    "glSecondaryColor",
    "glTexCoord",
    "glTexEnv",
    "glTexGen",
    "glTranslate",
    "glVertex",
    "glWindowPos",
];

/// Entry points the core profile removes, by exact name (before any
/// `ARB`/`EXT`/`MESA` suffix).
const REMOVED_NAMES: &[&str] = &[
    "glAccum",
    "glAlphaFunc",
    "glAreTexturesResident",
    "glArrayElement",
    "glBegin",
    "glBitmap",
    "glCallList",
    "glCallLists",
    "glClearAccum",
    "glClearIndex",
    "glClientActiveTexture",
    "glClipPlane",
    "glColorMaterial",
    "glColorPointer",
    "glCopyPixels",
    "glDeleteLists",
    "glDisableClientState",
    "glDrawPixels",
    "glEdgeFlagPointer",
    "glEnableClientState",
    "glEnd",
    "glEndList",
    "glFeedbackBuffer",
    "glFogCoordPointer",
    "glFrustum",
    "glGenLists",
    "glGetClipPlane",
    "glGetPolygonStipple",
    "glIndexMask",
    "glIndexPointer",
    "glInitNames",
    "glInterleavedArrays",
    "glIsList",
    "glLineStipple",
    "glListBase",
    "glLoadIdentity",
    "glLoadName",
    "glMatrixMode",
    "glNewList",
    "glNormalPointer",
    "glOrtho",
    "glPassThrough",
    "glPixelZoom",
    "glPolygonStipple",
    "glPopAttrib",
    "glPopClientAttrib",
    "glPopMatrix",
    "glPopName",
    "glPrioritizeTextures",
    "glPushAttrib",
    "glPushClientAttrib",
    "glPushMatrix",
    "glPushName",
    "glRenderMode",
    "glSecondaryColorPointer",
    "glSelectBuffer",
    "glShadeModel",
    "glTexCoordPointer",
    "glVertexPointer",
];

/// glEnable/glDisable/glIsEnabled targets the core profile removes
/// (appendix E.2.2; client arrays are glIsEnabled targets): in a core
/// context they are unknown values, `GL_INVALID_ENUM`, and so is their
/// glGet*.
pub const REMOVED_CAPS: &[u32] = &[
    GL_ALPHA_TEST,
    GL_AUTO_NORMAL,
    GL_COLOR_ARRAY,
    GL_COLOR_MATERIAL,
    GL_COLOR_SUM,
    GL_EDGE_FLAG_ARRAY,
    GL_FOG,
    GL_FOG_COORD_ARRAY,
    GL_INDEX_ARRAY,
    GL_INDEX_LOGIC_OP,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_LIGHTING,
    GL_LINE_STIPPLE,
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_COLOR_4,
    GL_MAP2_INDEX,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_NORMALIZE,
    GL_NORMAL_ARRAY,
    GL_POINT_SMOOTH,
    GL_POINT_SPRITE,
    GL_POLYGON_STIPPLE,
    GL_RESCALE_NORMAL,
    GL_SECONDARY_COLOR_ARRAY,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_COORD_ARRAY,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_Q,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_VERTEX_ARRAY,
    GL_VERTEX_PROGRAM_TWO_SIDE,
];

/// glGet* names of state the core profile removes (appendix E.2.2,
/// besides [`REMOVED_CAPS`]): `GL_INVALID_ENUM` in a core context.
pub const REMOVED_STATE: &[u32] = &[
    GL_ACCUM_ALPHA_BITS,
    GL_ACCUM_BLUE_BITS,
    GL_ACCUM_CLEAR_VALUE,
    GL_ACCUM_GREEN_BITS,
    GL_ACCUM_RED_BITS,
    GL_ALPHA_BITS,
    GL_ALPHA_TEST_FUNC,
    GL_ALPHA_TEST_REF,
    GL_ATTRIB_STACK_DEPTH,
    GL_AUX_BUFFERS,
    GL_BLUE_BITS,
    GL_CLIENT_ACTIVE_TEXTURE,
    GL_CLIENT_ATTRIB_STACK_DEPTH,
    GL_COLOR_ARRAY_SIZE,
    GL_COLOR_ARRAY_STRIDE,
    GL_COLOR_ARRAY_TYPE,
    GL_COLOR_MATERIAL_FACE,
    GL_COLOR_MATERIAL_PARAMETER,
    GL_CURRENT_COLOR,
    GL_CURRENT_FOG_COORD,
    GL_CURRENT_INDEX,
    GL_CURRENT_NORMAL,
    GL_CURRENT_RASTER_COLOR,
    GL_CURRENT_RASTER_DISTANCE,
    GL_CURRENT_RASTER_INDEX,
    GL_CURRENT_RASTER_POSITION,
    GL_CURRENT_RASTER_POSITION_VALID,
    GL_CURRENT_RASTER_SECONDARY_COLOR,
    GL_CURRENT_RASTER_TEXTURE_COORDS,
    GL_CURRENT_SECONDARY_COLOR,
    GL_CURRENT_TEXTURE_COORDS,
    GL_DEPTH_BITS,
    GL_EDGE_FLAG,
    GL_FOG_COLOR,
    GL_FOG_COORD_SRC,
    GL_FOG_DENSITY,
    GL_FOG_END,
    GL_FOG_HINT,
    GL_FOG_INDEX,
    GL_FOG_MODE,
    GL_FOG_START,
    GL_GENERATE_MIPMAP_HINT,
    GL_GREEN_BITS,
    GL_INDEX_BITS,
    GL_INDEX_CLEAR_VALUE,
    GL_INDEX_MODE,
    GL_INDEX_WRITEMASK,
    GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_COLOR_CONTROL,
    GL_LIGHT_MODEL_LOCAL_VIEWER,
    GL_LIGHT_MODEL_TWO_SIDE,
    GL_LINE_STIPPLE_PATTERN,
    GL_LINE_STIPPLE_REPEAT,
    GL_LIST_BASE,
    GL_LIST_INDEX,
    GL_LIST_MODE,
    GL_MATRIX_MODE,
    GL_MAX_ATTRIB_STACK_DEPTH,
    GL_MAX_CLIENT_ATTRIB_STACK_DEPTH,
    GL_MAX_LIGHTS,
    GL_MAX_LIST_NESTING,
    GL_MAX_MODELVIEW_STACK_DEPTH,
    GL_MAX_PROJECTION_STACK_DEPTH,
    GL_MAX_TEXTURE_COORDS,
    GL_MAX_TEXTURE_STACK_DEPTH,
    GL_MAX_TEXTURE_UNITS,
    GL_MODELVIEW_MATRIX,
    GL_MODELVIEW_STACK_DEPTH,
    GL_NORMAL_ARRAY_STRIDE,
    GL_NORMAL_ARRAY_TYPE,
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SIZE_MAX,
    GL_POINT_SIZE_MIN,
    GL_POINT_DISTANCE_ATTENUATION,
    GL_POINT_SMOOTH_HINT,
    GL_PROJECTION_MATRIX,
    GL_PROJECTION_STACK_DEPTH,
    GL_RED_BITS,
    GL_RENDER_MODE,
    GL_SHADE_MODEL,
    GL_STENCIL_BITS,
    GL_TEXTURE_COORD_ARRAY_SIZE,
    GL_TEXTURE_COORD_ARRAY_STRIDE,
    GL_TEXTURE_COORD_ARRAY_TYPE,
    GL_TEXTURE_MATRIX,
    GL_TEXTURE_STACK_DEPTH,
    GL_TRANSPOSE_MODELVIEW_MATRIX,
    GL_TRANSPOSE_PROJECTION_MATRIX,
    GL_TRANSPOSE_TEXTURE_MATRIX,
    GL_VERTEX_ARRAY_SIZE,
    GL_VERTEX_ARRAY_STRIDE,
    GL_VERTEX_ARRAY_TYPE,
    GL_ZOOM_X,
    GL_ZOOM_Y,
];

const fn bytes_eq(a: &[u8], b: &[u8]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

const fn ends_with(s: &[u8], end: &[u8]) -> bool {
    if s.len() < end.len() {
        return false;
    }
    let start = s.len() - end.len();
    let mut i = 0;
    while i < end.len() {
        if s[start + i] != end[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// `name` without a trailing vendor suffix (`ARB`, `EXT`, `MESA`).
const fn strip_vendor(name: &[u8]) -> &[u8] {
    let mut k = 0;
    let suffixes: [&[u8]; 3] = [b"ARB", b"EXT", b"MESA"];
    while k < suffixes.len() {
        if ends_with(name, suffixes[k]) {
            return name.split_at(name.len() - suffixes[k].len()).0;
        }
        k += 1;
    }
    name
}

/// Whether `rest` is a type/arity suffix: digits, the type letters
/// (`b s i f d ub us ui`) and `v`.
const fn is_type_suffix(rest: &[u8]) -> bool {
    let mut i = 0;
    while i < rest.len() {
        if !matches!(
            rest[i],
            b'0'..=b'9' | b'b' | b's' | b'i' | b'f' | b'd' | b'u' | b'v'
        ) {
            return false;
        }
        i += 1;
    }
    true
}

/// Whether the core profile removes the entry point `name` (GL 3.3 core
/// appendix E.2.2): calling it in a core context records
/// `GL_INVALID_OPERATION` and does nothing. A `const fn` so that a C ABI
/// decides it per entry point at compile time.
pub const fn removed_in_core(name: &str) -> bool {
    let name = strip_vendor(name.as_bytes());
    let mut i = 0;
    while i < REMOVED_NAMES.len() {
        if bytes_eq(name, REMOVED_NAMES[i].as_bytes()) {
            return true;
        }
        i += 1;
    }
    let mut i = 0;
    while i < REMOVED_FAMILIES.len() {
        let fam = REMOVED_FAMILIES[i].as_bytes();
        if name.len() >= fam.len() {
            let (head, rest) = name.split_at(fam.len());
            if bytes_eq(head, fam) && is_type_suffix(rest) {
                return true;
            }
        }
        i += 1;
    }
    false
}

impl Context {
    /// The API this context implements.
    pub fn api(&self) -> Api {
        self.api
    }

    /// Whether this is a core-profile context.
    pub fn is_core(&self) -> bool {
        self.api.is_core()
    }

    /// For an entry point the core profile removes: in a core context,
    /// records `GL_INVALID_OPERATION` and returns true (the call must do
    /// nothing); otherwise false.
    pub fn refuse_removed(&mut self) -> bool {
        if self.api.is_core() {
            self.set_error(GL_INVALID_OPERATION);
            true
        } else {
            false
        }
    }

    /// For a glEnable/glDisable/glIsEnabled target: in a core context, a
    /// removed one ([`REMOVED_CAPS`]) records `GL_INVALID_ENUM` and
    /// returns true (the call must do nothing).
    pub fn refuse_removed_cap(&mut self, cap: u32) -> bool {
        let removed = self.api.is_core() && REMOVED_CAPS.contains(&cap);
        if removed {
            self.set_error(GL_INVALID_ENUM);
        }
        removed
    }

    /// Whether `pname` names state this context's profile removed.
    pub fn is_removed_state(&self, pname: u32) -> bool {
        self.api.is_core() && (REMOVED_STATE.contains(&pname) || REMOVED_CAPS.contains(&pname))
    }

    /// For a glGet* name: in a core context, removed state
    /// ([`REMOVED_STATE`], [`REMOVED_CAPS`]) records `GL_INVALID_ENUM` and
    /// returns true.
    pub fn refuse_removed_state(&mut self, pname: u32) -> bool {
        let removed = self.is_removed_state(pname);
        if removed {
            self.set_error(GL_INVALID_ENUM);
        }
        removed
    }

    /// glGetStringi (GL 3.0+): the `index`th extension of
    /// `GL_EXTENSIONS`. `GL_INVALID_ENUM` for another name (or in a 2.1
    /// context, which has no glGetStringi), `GL_INVALID_VALUE` for an
    /// index past `GL_NUM_EXTENSIONS`.
    pub fn get_stringi(&mut self, name: u32, index: u32) -> Option<&'static str> {
        if name != GL_EXTENSIONS || !self.api.at_least(3, 0) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let ext = self.api.extensions();
        match ext.get(index as usize) {
            Some(&e) => Some(e),
            None => {
                self.set_error(GL_INVALID_VALUE);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn requests_get_the_lowest_api_at_least_as_new() {
        use Profile::*;
        assert_eq!(Api::for_request(1, 0, Compatibility), Some(Api::GL21));
        assert_eq!(Api::for_request(2, 1, Compatibility), Some(Api::GL21));
        assert_eq!(
            Api::for_request(3, 0, Compatibility),
            Some(Api::GL33_COMPAT)
        );
        assert_eq!(Api::for_request(3, 2, Core), Some(Api::GL33_CORE));
        assert_eq!(Api::for_request(1, 0, Core), Some(Api::GL33_CORE));
        assert_eq!(Api::for_request(3, 4, Core), None);
        assert_eq!(Api::for_request(4, 5, Compatibility), None);
        assert_eq!(Api::for_request(0, 9, Compatibility), None);
        assert_eq!(Api::for_request(3, -1, Core), None);
    }

    #[test]
    fn version_strings() {
        assert_eq!(Api::GL21.version_string(), "2.1 shaderbox");
        assert_eq!(
            Api::GL33_CORE.version_string(),
            "3.3 (Core Profile) shaderbox"
        );
        assert_eq!(
            Api::GL33_COMPAT.version_string(),
            "3.3 (Compatibility Profile) shaderbox"
        );
        assert_eq!(Api::GL33_CORE.glsl_version_string(), "3.30");
        assert!(Api::GL33_COMPAT
            .extensions()
            .contains(&"GL_ARB_compatibility"));
        assert!(!Api::GL33_CORE
            .extensions()
            .contains(&"GL_ARB_compatibility"));
        assert!(!Api::GL21.extensions().contains(&"GL_ARB_compatibility"));
    }

    #[test]
    fn removed_entry_points() {
        for name in [
            "glBegin",
            "glVertex3f",
            "glVertex4dv",
            "glColor4ub",
            "glColor3usv",
            "glMultiTexCoord2fARB",
            "glSecondaryColor3fEXT",
            "glWindowPos2iMESA",
            "glFogf",
            "glFogCoordfv",
            "glLightModelfv",
            "glGetTexEnviv",
            "glRectf",
            "glMap1d",
            "glMapGrid2f",
            "glTranslatef",
            "glPushAttrib",
            "glNewList",
            "glEdgeFlag",
            "glEdgeFlagv",
            "glClientActiveTextureARB",
        ] {
            assert!(removed_in_core(name), "{name}");
        }
        for name in [
            "glColorMask",
            "glColorMaski",
            "glVertexAttrib4f",
            "glVertexAttribPointer",
            "glVertexAttribIPointer",
            "glMapBuffer",
            "glMapBufferRange",
            "glScissor",
            "glTexImage2D",
            "glTexParameteri",
            "glGetTexImage",
            "glFlush",
            "glIndexed",
            "glRectangle",
            "glLinkProgram",
            "glDrawArrays",
            "glEnable",
        ] {
            assert!(!removed_in_core(name), "{name} is kept");
        }
        // Compile-time use.
        const BEGIN: bool = removed_in_core("glBegin");
        const _: () = assert!(BEGIN);
    }
}
