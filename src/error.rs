//! [`ParamError`]: what a parameter constructor returns for a value outside its domain.

use crate::real::{Mask, Real};
use core::fmt;

/// A user-built parameter (roughness, IOR, exposure, ...) outside its documented domain.
///
/// Constructors validate once so that kernels never have to: `Ggx::new(-0.1, 0.2)` returns
/// this instead of a lobe that evaluates to NaN a billion times later.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ParamError {
    /// The parameter's name as the constructor documents it (for example `"alpha_x"`).
    pub param: &'static str,
    /// The domain it must lie in, in words (for example `"finite and >= 0"`).
    pub expected: &'static str,
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid parameter `{}`: expected {}",
            self.param, self.expected
        )
    }
}

impl core::error::Error for ParamError {}

/// `Ok(())` when `ok` holds in every lane, else the error for `param`.
///
/// Constructors build `ok` from comparisons, which are false for NaN, so a NaN parameter is
/// rejected without a separate test.
#[inline]
pub fn require<T: Real>(
    ok: T::Mask,
    param: &'static str,
    expected: &'static str,
) -> Result<(), ParamError> {
    if ok.all() {
        Ok(())
    } else {
        Err(ParamError { param, expected })
    }
}
