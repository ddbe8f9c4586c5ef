//! The GL 2.1 primitive pipeline (being written; see docs/ARCHITECTURE.md).
