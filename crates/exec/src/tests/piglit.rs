//! Placeholder for the piglit harness (written next).
