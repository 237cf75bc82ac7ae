//! Property tests over random mechanisms and angles, and the crank-slider against its
//! closed-form textbook expressions (an independent reference).
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

use kurbo::Vec2;
use proptest::prelude::*;
use std::f64::consts::TAU;
use tmm_sheets::lever::Kin;
use tmm_sheets::lever::dyads::{crank, rrp, rrr};

/// Axial crank-slider: x_B = r·cosθ + √(l² − r²sin²θ) and its time derivatives.
fn slider_closed_form(r: f64, l: f64, th: f64, w: f64) -> (f64, f64, f64) {
    let (s, c) = th.sin_cos();
    let q = (l * l - r * r * s * s).sqrt();
    let x = r * c + q;
    let dx = -r * s - r * r * s * c / q; // d/dθ
    let ddx = -r * c - r * r * (c * c - s * s) / q - r.powi(4) * s * s * c * c / q.powi(3);
    (x, dx * w, ddx * w * w)
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::with_cases(256) })]

    #[test]
    fn crank_slider_matches_the_closed_form(r in 0.02f64..0.3, lam in 0.05f64..0.45, th in 0.0f64..TAU, w in -80.0f64..80.0) {
        let l = r / lam;
        let o = Kin::fixed(Vec2::ZERO);
        let (a, _) = crank(&o, r, th, w);
        let sol = rrp(&a, l, Vec2::ZERO, Vec2::new(1.0, 0.0), 1.0).unwrap();
        let (x, v, acc) = slider_closed_form(r, l, th, w);
        prop_assert!((sol.point.p.x - x).abs() <= 1e-12);
        prop_assert!(sol.point.p.y.abs() <= 1e-15);
        prop_assert!((sol.point.v.x - v).abs() <= 1e-9 * (1.0 + v.abs()));
        prop_assert!((sol.point.a.x - acc).abs() <= 1e-9 * (1.0 + acc.abs()));
    }

    /// Random Grashof crank-rockers: closure and derivative identities of the RRR dyad.
    #[test]
    fn random_four_bars_close_and_differentiate(
        crank_len in 0.02f64..0.1, coupler in 0.2f64..0.5, rocker in 0.2f64..0.5,
        ground in 0.2f64..0.5, th in 0.0f64..TAU, w in 1.0f64..50.0, left in any::<bool>()
    ) {
        // Grashof with the crank shortest: s + l ≤ p + q.
        let longest = coupler.max(rocker).max(ground);
        let others = coupler + rocker + ground - longest;
        prop_assume!(crank_len + longest <= others - 1e-3);
        let o = Kin::fixed(Vec2::ZERO);
        let c = Kin::fixed(Vec2::new(ground, 0.0));
        let br = if left { 1.0 } else { -1.0 };
        let solve = |t: f64| {
            let (a, _) = crank(&o, crank_len, t, w);
            (a, rrr(&a, &c, coupler, rocker, br))
        };
        // s + l < p + q strictly with the crank shortest: the crank turns fully and the
        // transmission angle never reaches 0° or 180°, so every angle must solve.
        let (a, sol) = solve(th);
        prop_assert!(sol.is_ok(), "a Grashof crank-rocker failed at θ = {th}: {sol:?}");
        let sol = sol.unwrap();
        prop_assert!(((sol.point.p - a.p).hypot() - coupler).abs() <= 1e-12);
        prop_assert!(((sol.point.p - c.p).hypot() - rocker).abs() <= 1e-12);
        let h = 1e-6;
        let (_, sp) = solve(th + h);
        let (_, sm) = solve(th - h);
        let (sp, sm) = (sp.expect("solves at θ + h"), sm.expect("solves at θ − h"));
        let v_fd = (sp.point.p - sm.point.p) * (w / (2.0 * h));
        let a_fd = (sp.point.v - sm.point.v) * (w / (2.0 * h));
        let vs = sol.point.v.hypot().max(w * crank_len);
        let as_ = sol.point.a.hypot().max(w * w * crank_len);
        prop_assert!((v_fd - sol.point.v).hypot() <= 1e-5 * vs);
        prop_assert!((a_fd - sol.point.a).hypot() <= 1e-5 * as_);
    }
}
