//! Link-time checks. Work in progress.
