//! Statistics of an ensemble of factors of safety (docs/method.md section 4.7),
//! as Slide's probabilistic analysis reports them.
//!
//! For samples `F_1 .. F_n`:
//! - mean `mu`, standard deviation `sigma` (with `n - 1`), percentiles by
//!   linear interpolation between order statistics (`p (n - 1)`, "type 7");
//! - probability of failure `PF = #{F_k < 1} / n`, with the 95 % Wilson score
//!   interval `(p + z^2/2n +- z sqrt(p (1 - p) / n + z^2 / 4n^2)) / (1 + z^2/n)`,
//!   `z = 1.959964` (it stays inside [0, 1] and is not empty at `PF = 0`);
//! - reliability index, normal: `beta = (mu - 1) / sigma`; lognormal:
//!   `beta = ln(mu / sqrt(1 + V^2)) / sqrt(ln(1 + V^2))`, `V = sigma / mu`;
//! - the convergence of `mu` and `PF` with `n`: the same statistics of the first
//!   `n` members, at `n` = 10, 20, 50, 100, 200, 500, ... and at the full count.

use serde::Serialize;

/// The 97.5 % quantile of the standard normal distribution.
pub const Z95: f64 = 1.959_963_984_540_054;

/// Statistics of one sampled quantity.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Distribution {
    pub n: usize,
    pub mean: f64,
    pub std_dev: f64,
    /// 95 % confidence interval of the mean: `mu +- z sigma / sqrt(n)`.
    pub mean_ci95: [f64; 2],
    pub min: f64,
    pub max: f64,
    /// 5th, 50th and 95th percentiles.
    pub p05: f64,
    pub p50: f64,
    pub p95: f64,
}

/// Failure statistics of a factor of safety.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reliability {
    /// `PF = P(F < 1)`, the fraction of members below 1.
    pub probability_of_failure: f64,
    /// 95 % Wilson score interval of `PF`.
    pub pf_ci95: [f64; 2],
    /// `(mu - 1) / sigma`.
    pub beta_normal: f64,
    /// `ln(mu / sqrt(1 + V^2)) / sqrt(ln(1 + V^2))`.
    pub beta_lognormal: f64,
}

/// One row of the convergence table: statistics of the first `n` members,
/// each with its 95 % interval (the same as the full ensemble's).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConvergencePoint {
    pub n: usize,
    pub mean: f64,
    /// `mu +- z sigma / sqrt(n)` of the first `n` ([`Distribution::mean_ci95`]).
    pub mean_ci95: [f64; 2],
    pub probability_of_failure: f64,
    /// The Wilson score interval of `PF` of the first `n` ([`wilson95`]).
    pub pf_ci95: [f64; 2],
}

/// Statistics of finite samples; `None` for an empty set.
pub fn distribution(samples: &[f64]) -> Option<Distribution> {
    let n = samples.len();
    if n == 0 {
        return None;
    }
    let mean = samples.iter().sum::<f64>() / n as f64;
    let var = if n > 1 { samples.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1) as f64 } else { 0.0 };
    let std_dev = var.sqrt();
    let half = Z95 * std_dev / (n as f64).sqrt();
    let mut sorted = samples.to_vec();
    sorted.sort_by(f64::total_cmp);
    Some(Distribution {
        n,
        mean,
        std_dev,
        mean_ci95: [mean - half, mean + half],
        min: sorted[0],
        max: sorted[n - 1],
        p05: percentile(&sorted, 0.05),
        p50: percentile(&sorted, 0.50),
        p95: percentile(&sorted, 0.95),
    })
}

/// The `p`-quantile of sorted samples, linear between order statistics.
pub fn percentile(sorted: &[f64], p: f64) -> f64 {
    let h = p.clamp(0.0, 1.0) * (sorted.len() - 1) as f64;
    let (i, f) = (h.floor() as usize, h - h.floor());
    if i + 1 < sorted.len() {
        sorted[i] + f * (sorted[i + 1] - sorted[i])
    } else {
        sorted[i]
    }
}

/// The 95 % Wilson score interval of a proportion `k / n`.
pub fn wilson95(k: usize, n: usize) -> [f64; 2] {
    let all = k == n;
    let (p, n) = (k as f64 / n as f64, n as f64);
    let z2 = Z95 * Z95;
    let centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
    let half = Z95 * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt() / (1.0 + z2 / n);
    // At k = 0 (k = n) the bound is 0 (1) exactly, not its rounding.
    let lo = if k == 0 { 0.0 } else { (centre - half).max(0.0) };
    let hi = if all { 1.0 } else { (centre + half).min(1.0) };
    [lo, hi]
}

/// Failure statistics of factors of safety; `None` for an empty set.
pub fn reliability(fs: &[f64]) -> Option<Reliability> {
    let d = distribution(fs)?;
    let failed = fs.iter().filter(|&&f| f < 1.0).count();
    let v = d.std_dev / d.mean;
    let s = (1.0 + v * v).ln();
    Some(Reliability {
        probability_of_failure: failed as f64 / fs.len() as f64,
        pf_ci95: wilson95(failed, fs.len()),
        beta_normal: (d.mean - 1.0) / d.std_dev,
        beta_lognormal: (d.mean / (1.0 + v * v).sqrt()).ln() / s.sqrt(),
    })
}

/// Mean and PF of the first `n` members, with their 95 % intervals, at 10,
/// 20, 50, 100, ... and at the end.
pub fn convergence(fs: &[f64]) -> Vec<ConvergencePoint> {
    let mut ns: Vec<usize> =
        (1..).flat_map(|e: u32| [1, 2, 5].map(|m| m * 10usize.pow(e))).take_while(|&n| n < fs.len()).collect();
    ns.push(fs.len());
    ns.into_iter()
        .filter(|&n| n > 0)
        .filter_map(|n| {
            let head = distribution(&fs[..n])?;
            let failed = fs[..n].iter().filter(|&&f| f < 1.0).count();
            Some(ConvergencePoint {
                n,
                mean: head.mean,
                mean_ci95: head.mean_ci95,
                probability_of_failure: failed as f64 / n as f64,
                pf_ci95: wilson95(failed, n),
            })
        })
        .collect()
}

/// The standard normal distribution function, `Phi(x) = erfc(-x / sqrt 2) / 2`.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * erfc(-x / std::f64::consts::SQRT_2)
}

/// Complementary error function: the Chebyshev fit `erfcc` of Press et al.,
/// Numerical Recipes (2nd ed., section 6.2), fractional error below 1.2e-7
/// everywhere: far finer than the Monte-Carlo intervals it is compared with.
fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let r = t
        * (-z * z - 1.265_512_23
            + t * (1.000_023_68
                + t * (0.374_091_96
                    + t * (0.096_784_18
                        + t * (-0.186_288_06
                            + t * (0.278_868_07
                                + t * (-1.135_203_98
                                    + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77)))))))))
            .exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_interpolate_between_order_statistics() {
        let s = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(percentile(&s, 0.5), 3.0);
        assert_eq!(percentile(&s, 0.25), 2.0);
        assert!((percentile(&s, 0.1) - 1.4).abs() < 1e-15);
    }

    #[test]
    fn wilson_interval_of_zero_failures_is_not_empty() {
        let [lo, hi] = wilson95(0, 100);
        assert_eq!(lo, 0.0);
        // z^2 / (n + z^2) = 3.8415 / 103.8415
        assert!((hi - 3.841_458_820_694_124 / 103.841_458_820_694_12).abs() < 1e-12, "{hi}");
    }

    #[test]
    fn normal_cdf_matches_tabulated_values() {
        // Phi(0) = 0.5, Phi(1) = 0.841344746, Phi(-1.959964) = 0.025 (tables).
        assert!((normal_cdf(0.0) - 0.5).abs() < 1e-7);
        assert!((normal_cdf(1.0) - 0.841_344_746).abs() < 1e-7);
        assert!((normal_cdf(-Z95) - 0.025).abs() < 1e-7);
    }

    #[test]
    fn lognormal_index_of_a_narrow_distribution_is_close_to_the_normal_one() {
        let fs: Vec<f64> = (0..1001).map(|k| 1.5 + 0.01 * ((k as f64) / 1000.0 - 0.5)).collect();
        let r = reliability(&fs).unwrap();
        assert!((r.beta_lognormal / r.beta_normal - 1.0).abs() < 0.5, "{r:?}");
        assert!(r.beta_normal > 100.0 && r.probability_of_failure == 0.0);
    }
}
