//! The implementation limits shaderbox advertises, in one place.
//!
//! The built-in constants of GLSL 1.20 §7.4 take these values, the linker
//! checks programs against them, and the GL layer reports them through
//! `glGetIntegerv`. Each is at least the minimum the spec requires (given in
//! the comment) and matches what Mesa's llvmpipe advertises where that
//! matters to existing programs.

/// GL_MAX_UNIFORM_BUFFER_BINDINGS (GL 3.1, minimum 36): the binding points
/// `layout(binding = N)` may name on uniform blocks.
pub const MAX_UNIFORM_BUFFER_BINDINGS: u32 = 36;

/// GL_MIN_PROGRAM_TEXEL_OFFSET and GL_MAX_PROGRAM_TEXEL_OFFSET (GL 3.0
/// §3.8.8: at most −8 and at least 7), GLSL 4.20's
/// `gl_MinProgramTexelOffset` and `gl_MaxProgramTexelOffset`.
pub const MIN_PROGRAM_TEXEL_OFFSET: i32 = -8;
pub const MAX_PROGRAM_TEXEL_OFFSET: i32 = 7;

/// GL_ARB_compute_shader's limits (its minimums, which llvmpipe's exceed
/// only in the counts of work groups): GL_MAX_COMPUTE_WORK_GROUP_COUNT
/// per dimension, GL_MAX_COMPUTE_WORK_GROUP_SIZE per dimension,
/// GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS (their product's bound),
/// GL_MAX_COMPUTE_UNIFORM_COMPONENTS, GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS,
/// GL_MAX_COMPUTE_SHARED_MEMORY_SIZE (bytes).
pub const MAX_COMPUTE_WORK_GROUP_COUNT: [u32; 3] = [65535, 65535, 65535];
pub const MAX_COMPUTE_WORK_GROUP_SIZE: [u32; 3] = [1024, 1024, 64];
pub const MAX_COMPUTE_WORK_GROUP_INVOCATIONS: u32 = 1024;
pub const MAX_COMPUTE_UNIFORM_COMPONENTS: u32 = 1024;
pub const MAX_COMPUTE_TEXTURE_IMAGE_UNITS: u32 = 16;
pub const MAX_COMPUTE_SHARED_MEMORY_SIZE: u32 = 32768;

/// GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS (GL_ARB_shader_storage_buffer_object,
/// minimum 8): the binding points `layout(binding = N)` may name on shader
/// storage blocks.
pub const MAX_SHADER_STORAGE_BUFFER_BINDINGS: u32 = 8;

/// GL_ARB_tessellation_shader's limits (its minimums, which are also
/// llvmpipe's): GL_MAX_PATCH_VERTICES (the size of every per-vertex
/// input array of the tessellation stages), GL_MAX_TESS_GEN_LEVEL, and
/// the components and units of the two stages.
pub const MAX_PATCH_VERTICES: u32 = 32;
pub const MAX_TESS_GEN_LEVEL: u32 = 64;
pub const MAX_TESS_CONTROL_INPUT_COMPONENTS: u32 = 128;
pub const MAX_TESS_CONTROL_OUTPUT_COMPONENTS: u32 = 128;
pub const MAX_TESS_CONTROL_TEXTURE_IMAGE_UNITS: u32 = 16;
pub const MAX_TESS_CONTROL_UNIFORM_COMPONENTS: u32 = 1024;
pub const MAX_TESS_CONTROL_TOTAL_OUTPUT_COMPONENTS: u32 = 4096;
pub const MAX_TESS_EVALUATION_INPUT_COMPONENTS: u32 = 128;
pub const MAX_TESS_EVALUATION_OUTPUT_COMPONENTS: u32 = 128;
pub const MAX_TESS_EVALUATION_TEXTURE_IMAGE_UNITS: u32 = 16;
pub const MAX_TESS_EVALUATION_UNIFORM_COMPONENTS: u32 = 1024;
pub const MAX_TESS_PATCH_COMPONENTS: u32 = 120;

/// `gl_MaxLights` (minimum 8).
pub const MAX_LIGHTS: u32 = 8;
/// `gl_MaxClipPlanes` (minimum 6).
pub const MAX_CLIP_PLANES: u32 = 8;
/// `gl_MaxTextureUnits`: fixed-function texture units (minimum 2).
pub const MAX_TEXTURE_UNITS: u32 = 8;
/// `gl_MaxTextureCoords` (minimum 2).
pub const MAX_TEXTURE_COORDS: u32 = 8;
/// `gl_MaxVertexAttribs` (minimum 16).
pub const MAX_VERTEX_ATTRIBS: u32 = 16;
/// `gl_MaxVertexUniformComponents` (minimum 512).
pub const MAX_VERTEX_UNIFORM_COMPONENTS: u32 = 16384;
/// `gl_MaxVaryingFloats` (minimum 32).
pub const MAX_VARYING_FLOATS: u32 = 64;
/// `gl_MaxVertexTextureImageUnits` (minimum 0).
pub const MAX_VERTEX_TEXTURE_IMAGE_UNITS: u32 = 16;
/// `gl_MaxCombinedTextureImageUnits` (minimum 2).
pub const MAX_COMBINED_TEXTURE_IMAGE_UNITS: u32 = 32;
/// `gl_MaxTextureImageUnits` (minimum 2).
pub const MAX_TEXTURE_IMAGE_UNITS: u32 = 16;
/// `gl_MaxFragmentUniformComponents` (minimum 64).
pub const MAX_FRAGMENT_UNIFORM_COMPONENTS: u32 = 16384;
/// `gl_MaxDrawBuffers` (minimum 1).
pub const MAX_DRAW_BUFFERS: u32 = 8;
/// `gl_MaxClipDistances` (GLSL 1.30, minimum 8): the same planes as
/// `gl_MaxClipPlanes`.
pub const MAX_CLIP_DISTANCES: u32 = MAX_CLIP_PLANES;
/// `gl_MaxVertexOutputComponents` (GLSL 1.50, minimum 64): the output
/// components a vertex shader of GLSL 1.50 or later writes (twice the
/// minimum, as Mesa's llvmpipe; `MAX_VARYING_FLOATS` for earlier
/// versions).
pub const MAX_VERTEX_OUTPUT_COMPONENTS: u32 = 128;
/// `gl_MaxFragmentInputComponents` (GLSL 1.50, minimum 128): the input
/// components a fragment shader of GLSL 1.50 or later reads.
pub const MAX_FRAGMENT_INPUT_COMPONENTS: u32 = 128;
/// The locations `layout(location)` may give the inputs and outputs
/// between stages (GL_ARB_separate_shader_objects: at least a fourth of
/// the stage's component count).
pub const MAX_VARYING_LOCATIONS: u32 = MAX_VERTEX_OUTPUT_COMPONENTS / 4;
/// The geometry stage's limits (GLSL 1.50 gives every stage their
/// constants): the spec's minimums.
pub const MAX_GEOMETRY_INPUT_COMPONENTS: u32 = 64;
pub const MAX_GEOMETRY_OUTPUT_COMPONENTS: u32 = 128;
pub const MAX_GEOMETRY_TEXTURE_IMAGE_UNITS: u32 = 16;
pub const MAX_GEOMETRY_OUTPUT_VERTICES: u32 = 256;
pub const MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS: u32 = 1024;
pub const MAX_GEOMETRY_UNIFORM_COMPONENTS: u32 = 1024;
pub const MAX_GEOMETRY_VARYING_COMPONENTS: u32 = 64;

/// Largest shader source, in bytes, all strings together: a longer one is
/// refused before it is copied. Compiling costs up to about 30 bytes of
/// memory per source byte (a source of nothing but one-character tokens),
/// so this keeps a compile under 1 GiB. Spans are 32-bit offsets, so the
/// limit must stay under 4 GiB.
pub const MAX_SOURCE_BYTES: usize = 32 << 20;
/// Macro expansion depth at which the preprocessor gives up (recursive
/// macros are not expanded again, so this only bounds pathological input).
pub const MAX_MACRO_EXPANSION_DEPTH: u32 = 256;
/// Nesting depth of parentheses, blocks and conditionals at which the parser
/// stops with an error instead of exhausting the stack.
pub const MAX_NESTING_DEPTH: u32 = 256;
/// Functions that may be on the call stack at once, `main` included: a
/// longer chain of calls is a compile error (or a link error when the
/// chain crosses shader objects). GLSL has no recursion, so the executor
/// inlines calls, to this depth: a chain that compiles is never what
/// sends a program to the slower subroutine path (deep chains used to run
/// there, seconds per draw). Inlining recurses once per level (about
/// 30 KiB of stack each in an unoptimized build), on a thread of its own
/// with a stack sized for this limit (`exec`'s lowering).
pub const MAX_CALL_DEPTH: u32 = 128;
/// Total tokens a preprocessed shader may have (guards against macro bombs).
pub const MAX_TOKENS: usize = 4_000_000;
/// Largest array size accepted in a declaration.
pub const MAX_ARRAY_SIZE: u32 = 1 << 20;
/// Diagnostics reported for one shader; past this the rest are summarized
/// in one note (a binary file fed as a shader would otherwise produce
/// thousands).
pub const MAX_DIAGNOSTICS: usize = 100;
/// Longest name (in bytes) that a "did you mean" note is looked for: the
/// comparison costs the product of two names' lengths, and the typos such
/// a note helps with are in names people type.
pub const MAX_SUGGESTED_NAME_LEN: usize = 64;
/// "Did you mean" searches one shader may make; later errors of the same
/// kind get none (each search compares against every visible name).
pub const MAX_SUGGESTIONS: u32 = 16;
