//! Work in progress: filled in by its own branch before release.
