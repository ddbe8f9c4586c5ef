//! Lane-parallel execution of GLSL programs (being written; see docs/ARCHITECTURE.md).
