//! The OpenGL 2.1 state machine (being written; see docs/ARCHITECTURE.md).
