//! Elementary functions that give the same bits on every machine.
//!
//! `f64::sin` and friends call the platform's C library, whose results may differ in the last
//! bit between CPUs (glibc picks FMA or AVX2 variants of `sin`, `cos`, `atan2`, `pow`, ... at
//! load time) and between platforms (aarch64's libm is compiled with contracted multiply-adds).
//! Every result-determining computation calls these instead: the `libm` crate (a port of
//! musl's), plain Rust arithmetic in a fixed order. `clippy.toml` disallows the `f64`
//! methods, so a new call to them fails `cargo clippy`. `sqrt`, `abs`, `powi` and the
//! comparison functions are exactly rounded or exact everywhere and stay as they are.

/// Sine (radians).
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// Cosine (radians).
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// `(sin x, cos x)`.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// Four-quadrant arctangent of `y / x`, in `[-π, π]`.
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// Arccosine, in `[0, π]`.
#[inline]
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

/// Arcsine, in `[-π/2, π/2]`.
#[inline]
pub fn asin(x: f64) -> f64 {
    libm::asin(x)
}

/// `x` to the real power `y`.
#[inline]
pub fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// Natural logarithm.
#[inline]
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact values the functions must reproduce, and agreement with the platform's to an
    /// ulp or two elsewhere (they are different implementations of the same functions).
    #[test]
    fn agree_with_exact_values_and_the_platform_library() {
        assert_eq!(sin(0.0), 0.0);
        assert_eq!(cos(0.0), 1.0);
        assert_eq!(atan2(1.0, 1.0), std::f64::consts::FRAC_PI_4);
        assert_eq!(acos(-1.0), std::f64::consts::PI);
        assert_eq!(asin(1.0), std::f64::consts::FRAC_PI_2);
        assert_eq!(powf(2.0, 10.0), 1024.0);
        #[allow(clippy::disallowed_methods)]
        for i in 0..1000 {
            let x = (i as f64 - 500.0) * 0.0123;
            let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1e-300);
            assert!(close(sin(x), x.sin()) && close(cos(x), x.cos()), "{x}");
            assert_eq!(sin_cos(x), (sin(x), cos(x)));
            assert!(close(atan2(x, 0.7), x.atan2(0.7)), "{x}");
            let c = (x / 6.2).clamp(-1.0, 1.0);
            assert!(close(acos(c), c.acos()) && close(asin(c), c.asin()), "{c}");
            assert!(close(powf(x.abs(), 0.75), x.abs().powf(0.75)), "{x}");
        }
    }
}
