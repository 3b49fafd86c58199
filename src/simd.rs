//! The instruction set of the step's hot kernels, chosen at run time.
//!
//! The release build targets baseline x86-64, whose vector instructions
//! (SSE2) hold two `f64`, so that the binary runs on any x86-64 machine. On
//! a CPU with AVX2 (four `f64` per instruction: x86-64 CPUs since about 2013)
//! [`avx2!`] runs a kernel compiled a second time with it. Both versions give
//! the same bits: Rust never fuses a multiply and an add unless the code asks
//! (`mul_add`, which the kernels do not call), and a vector lane does each
//! element's IEEE operations in the order the scalar code does. So a result
//! does not depend on the machine that computed it, and `CDEM_SIMD=baseline`
//! (the environment variable [`ENV`]; or [`set_baseline`]) runs the baseline
//! version on any machine: tests/simd.rs compares the two bit for bit, and
//! `cdem perf` times them side by side (`perf/avx2-speedup`).
//!
//! The kernels: a plastic cell's pass (`physics::plastic`), the condensed
//! element force (`physics::element`) and the block masses' products
//! (`solver::block_mass`).

use std::sync::atomic::{AtomicU8, Ordering};

/// The environment variable that chooses the kernels' instruction set:
/// `auto` (the default: AVX2 where the CPU has it) or `baseline`.
pub const ENV: &str = "CDEM_SIMD";

const UNSET: u8 = 0;
const AVX2: u8 = 1;
const BASELINE: u8 = 2;
static MODE: AtomicU8 = AtomicU8::new(UNSET);

/// A value of [`ENV`] that is neither `auto` nor `baseline`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{ENV}={0:?}: expected \"auto\" (AVX2 where the CPU has it, the default) or \"baseline\"")]
pub struct SimdEnvError(pub String);

/// Whether [`ENV`] asks for the baseline kernels (unset: no); an error for
/// a value that is neither `auto` nor `baseline` (the CLI checks it before
/// any work).
pub fn baseline_from_env() -> Result<bool, SimdEnvError> {
    match std::env::var(ENV) {
        Err(_) => Ok(false),
        Ok(v) if v == "auto" => Ok(false),
        Ok(v) if v == "baseline" => Ok(true),
        Ok(v) => Err(SimdEnvError(v)),
    }
}

/// Runs the kernels' baseline version from now on (`true`), or AVX2 where
/// the CPU has it (`false`), whatever [`ENV`] says: `cdem perf` times both.
pub fn set_baseline(baseline: bool) {
    let avx2 = !baseline && cpu_has_avx2();
    MODE.store(if avx2 { AVX2 } else { BASELINE }, Ordering::Relaxed);
}

/// Runs the kernels' version that [`ENV`] asks for (a value it rejects
/// counts as `auto`): the start, and what `cdem perf` returns to after
/// timing both.
pub fn set_from_env() {
    set_baseline(baseline_from_env().unwrap_or(false));
}

/// Whether the kernels run their AVX2 version: the CPU has it and neither
/// [`ENV`] (read once, [`set_from_env`]) nor [`set_baseline`] asked for the
/// baseline.
#[inline]
pub fn avx2_on() -> bool {
    match MODE.load(Ordering::Relaxed) {
        AVX2 => true,
        BASELINE => false,
        _ => {
            set_from_env();
            MODE.load(Ordering::Relaxed) == AVX2
        }
    }
}

/// Whether this CPU has AVX2.
pub fn cpu_has_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Evaluates `$body` (a kernel's whole body, as a block) compiled with AVX2
/// when [`avx2_on`], else as compiled for the baseline (or on another
/// architecture). What the body calls is compiled with AVX2 where it is
/// inlined into the AVX2 version: it must be `#[inline(always)]` to profit
/// (calls that are not inlined run their baseline version, with the same
/// result).
macro_rules! avx2 {
    ($body:expr) => {{
        #[cfg(target_arch = "x86_64")]
        {
            if $crate::simd::avx2_on() {
                #[target_feature(enable = "avx2")]
                fn with_avx2<R>(f: impl FnOnce() -> R) -> R {
                    f()
                }
                // SAFETY: `avx2_on` is true only on a CPU that has AVX2.
                unsafe { with_avx2(|| $body) }
            } else {
                $body
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            $body
        }
    }};
}
pub(crate) use avx2;
