//! The force analysis against physics it does not compute itself: the balancing force P_m
//! from the kinetostatics must supply exactly the rate of change of the kinetic energy
//! that gravity and the loads do not, and a small crank-slider's P_m is derived by hand.
//!
//! Unlike tests/forces.rs, nothing here reuses the list of applied forces
//! (`Forces::applied`): inertia enters only through the kinetic energy
//! T = Σ ½·m_i·|v_Si|² + ½·J_Si·ω_i², differenced in time over the exact kinematics, so
//! a wrong sign, a missing term or a wrong centre in the inertia loads shows up.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture_names, lever, lever_of};
use kurbo::Vec2;
use proptest::prelude::*;
use std::f64::consts::TAU;
use std::sync::OnceLock;
use tmm_sheets::assert_near;
use tmm_sheets::lever::analysis;
use tmm_sheets::lever::kinetostatics::{self, ForceModel};
use tmm_sheets::lever::linkage::{Mechanism, State};
use tmm_sheets::lever::motion::{self, Motion};
use tmm_sheets::num::Near;

/// Crank rotation between the two solutions of the central difference, h = |ω1|·dt (rad).
///
/// The central difference of T(t) errs by (dt²/6)·T''' (truncation) plus about
/// ε·T/dt (rounding, ε ≈ 2.2·10⁻¹⁶). In terms of the crank angle, with T' ~ n·T·|ω1| for
/// the n-th harmonic of the motion, these are ~ (h²/6)·n² ≈ 2·10⁻¹¹·n² and
/// ε/h ≈ 2·10⁻¹¹ of the power scale: ~10⁻¹⁰ even for sharp harmonics (n ≈ 3).
const H: f64 = 1e-5;

/// Allowed residual of the energy balance, relative to the sum of the magnitudes of its
/// power terms. It is ≥ 1000× the finite-difference error above (and the exact solver's
/// error, ~10⁻¹⁴), yet 10⁵× smaller than what wrong physics produces: reversing the
/// inertia terms leaves a residual of 2·|dT/dt|, a sizeable fraction of the scale
/// (see `reversed_inertia_breaks_the_energy_balance`).
const TOLERANCE: f64 = 1e-7;

/// A fixture with its motion and its loads placed on their strokes.
struct Case {
    name: String,
    mechanism: Mechanism,
    motion: Motion,
    model: ForceModel,
    assigned_phi: f64,
}

/// Every fixture, analysed once for all tests of this file.
fn cases() -> &'static [Case] {
    static CASES: OnceLock<Vec<Case>> = OnceLock::new();
    CASES.get_or_init(|| {
        fixture_names()
            .into_iter()
            .map(|name| {
                let p = lever(&name);
                let k = analysis::kinematics(&p.mechanism, &p.settings).unwrap_or_else(|e| panic!("{name}: {e}"));
                let model = p.forces.as_ref().unwrap_or_else(|| panic!("{name} has a `forces` section"));
                let model =
                    analysis::place_loads(&p.mechanism, &k.motion, model).unwrap_or_else(|e| panic!("{name}: {e}"));
                Case { assigned_phi: k.assigned.phi, motion: k.motion, mechanism: p.mechanism, model, name }
            })
            .collect()
    })
}

/// Kinetic energy of every massive link: ½·m·|v_S|² + ½·J_S·ω² (J), in the order of
/// `ForceModel::masses`.
fn kinetic_energies(model: &ForceModel, s: &State) -> Vec<f64> {
    model
        .masses
        .iter()
        .map(|lm| {
            let v_s = s.points[lm.centre].v;
            let omega = s.links[lm.link].omega;
            0.5 * lm.mass * v_s.hypot2() + 0.5 * lm.j * omega * omega
        })
        .collect()
}

/// The terms of P_m·|v_A| + Σ G_i·v_Si + Σ F_load·v_point = dT/dt at one crank angle, W.
#[derive(Debug)]
struct EnergyBalance {
    /// P_m·|v_A|: the balancing force is signed along v_A.
    balancing: f64,
    /// Σ G_i·v_Si with G_i = (0, −m_i·g).
    gravity: Vec<f64>,
    /// Σ F_load·v of the loaded slider points.
    loads: Vec<f64>,
    /// dT_i/dt of every massive link, by central differences in time.
    kinetic: Vec<f64>,
}

impl EnergyBalance {
    fn gravity(&self) -> f64 {
        self.gravity.iter().sum()
    }

    fn loads(&self) -> f64 {
        self.loads.iter().sum()
    }

    fn dt_dt(&self) -> f64 {
        self.kinetic.iter().sum()
    }

    /// The power supplied minus the rate of change of T; zero in true dynamics.
    fn residual(&self) -> f64 {
        self.balancing + self.gravity() + self.loads() - self.dt_dt()
    }

    /// The same with the inertia terms' sign reversed, as if the inertia forces and moments
    /// were +m·a_S and +J_S·ε.
    fn residual_reversed_inertia(&self) -> f64 {
        self.balancing + self.gravity() + self.loads() + self.dt_dt()
    }

    /// Sum of the magnitudes of every power term, the scale of the tolerance.
    fn scale(&self) -> f64 {
        let all = self.gravity.iter().chain(&self.loads).chain(&self.kinetic);
        self.balancing.abs() + all.map(|x| x.abs()).sum::<f64>()
    }
}

/// Evaluates the energy balance at course angle `phi`.
///
/// Only T is differenced; the load term is evaluated at the instant itself, so a load
/// whose branch switches at a slider's dead centre within ±dt does not disturb the
/// difference (T does not depend on the loads). Fixtures assemble over the whole turn
/// without dead points of their groups, so every angle can be analysed.
fn energy_balance(c: &Case, phi: f64) -> EnergyBalance {
    let m = &c.mechanism;
    let s = motion::sample_at(m, &c.motion, phi).unwrap_or_else(|e| panic!("{} at φ = {phi}: {e}", c.name));
    let f = kinetostatics::analyse(m, &s, &c.model).unwrap_or_else(|e| panic!("{} at φ = {phi}: {e}", c.name));

    let v_a = s.points[m.crank().pin].v;
    let balancing = f.p_m * v_a.hypot();

    let gravity = c
        .model
        .masses
        .iter()
        .map(|lm| {
            let g_i = Vec2::new(0.0, -lm.mass * c.model.g);
            g_i.dot(s.points[lm.centre].v)
        })
        .collect();

    let loads = c
        .model
        .loads
        .iter()
        .map(|load| {
            let k = s.points[load.point];
            load.value(k.p, k.v, k.a).force.dot(k.v)
        })
        .collect();

    // θ(t ± dt) = θ ± ω1·dt: the crank turns at the constant signed speed ω1.
    let theta = c.motion.theta(phi);
    let dt = H / m.omega1.abs();
    let solve = |th: f64| m.solve(th).unwrap_or_else(|e| panic!("{} at θ = {th}: {e}", c.name));
    let after = kinetic_energies(&c.model, &solve(theta + m.omega1 * dt));
    let before = kinetic_energies(&c.model, &solve(theta - m.omega1 * dt));
    let kinetic = after.iter().zip(&before).map(|(a, b)| (a - b) / (2.0 * dt)).collect();

    EnergyBalance { balancing, gravity, loads, kinetic }
}

/// The assigned position and seven course angles spread over a turn (off the 30° and 45°
/// grid, so that they are not the drawn positions).
fn angles(c: &Case) -> Vec<f64> {
    let mut phis = vec![c.assigned_phi];
    phis.extend((0..7).map(|k| TAU * (k as f64 + 0.37) / 7.0));
    phis
}

fn check(c: &Case, phi: f64) -> Result<f64, String> {
    let b = energy_balance(c, phi);
    let ratio = b.residual().abs() / b.scale();
    if ratio <= TOLERANCE {
        Ok(ratio)
    } else {
        Err(format!(
            "{} at φ = {:.4}°: P_m·|v_A| = {} W, ΣG·v_S = {} W, ΣF·v = {} W, dT/dt = {} W: residual {} W ({ratio:e} of the scale {} W)",
            c.name,
            phi.to_degrees(),
            b.balancing,
            b.gravity(),
            b.loads(),
            b.dt_dt(),
            b.residual(),
            b.scale()
        ))
    }
}

#[test]
fn balancing_force_supplies_the_rate_of_change_of_kinetic_energy_on_every_fixture() {
    assert_eq!(cases().len(), fixture_names().len());
    let mut worst: (f64, String) = (0.0, String::new());
    for c in cases() {
        for phi in angles(c) {
            let ratio = check(c, phi).unwrap_or_else(|e| panic!("{e}"));
            if ratio > worst.0 {
                worst = (ratio, format!("{} at φ = {:.2}°", c.name, phi.to_degrees()));
            }
        }
    }
    eprintln!("worst relative residual of the energy balance: {:e} ({})", worst.0, worst.1);
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::with_cases(32) })]
    #[test]
    fn the_energy_balance_holds_at_any_angle(which in 0usize..64, phi in 0.0f64..TAU) {
        let c = &cases()[which % cases().len()];
        let result = check(c, phi);
        prop_assert!(result.is_ok(), "{}", result.unwrap_err());
    }
}

/// The test above has teeth: with the inertia terms reversed the balance fails, on the
/// worked example at its assigned position by ~10⁵ times the tolerance and more.
#[test]
fn reversed_inertia_breaks_the_energy_balance() {
    let c = cases().iter().find(|c| c.name == "worked-example").expect("the worked example is a fixture");
    for phi in angles(c) {
        let b = energy_balance(c, phi);
        let right = b.residual().abs() / b.scale();
        let wrong = b.residual_reversed_inertia().abs() / b.scale();
        assert!(right <= TOLERANCE, "φ = {:.2}°: the true balance leaves {right:e}", phi.to_degrees());
        if phi == c.assigned_phi {
            eprintln!("worked example at φ1: reversed inertia leaves {wrong:e} of the scale (true physics {right:e})");
            assert!(wrong >= 1e-2, "φ1: reversed inertia leaves only {wrong:e} of the scale");
        }
    }
}

/// An axial crank-slider with a heavy rod and slider, gravity and a resistance, worked by hand.
///
/// O at the origin, the guide along +x through O, B beyond O (branch forward); crank OA = r
/// at the absolute angle θ turning at the constant signed speed ω; rod AB = l with its
/// centre S2 at AS2 = k·l, mass m2, J_S2; slider B of mass m3; λ = r/l, sin β = λ·sin θ,
/// cos β = √(1 − λ²·sin²θ). The rod's direction A → B is at the angle −β.
///
/// Kinematics (the textbook's exact formulas, differentiated by hand):
///   x_B  = r·cos θ + l·cos β
///   ẋ_B  = −r·ω·(sin θ + λ·sin θ·cos θ / cos β)
///   ẍ_B  = −r·ω²·(cos θ + λ·cos 2θ / cos β + λ³·sin² 2θ / (4·cos³β))
///   ω2   = −β̇ = −λ·ω·cos θ / cos β
///   ε2   = −β̈ =  λ·(1 − λ²)·ω²·sin θ / cos³β
///   S2   = A + k·(B − A): v_S2 = ((1−k)·(−r·ω·sin θ) + k·ẋ_B, (1−k)·r·ω·cos θ),
///          a_S2 = ((1−k)·(−r·ω²·cos θ) + k·ẍ_B, −(1−k)·r·ω²·sin θ)
///
/// Energy: dT/dt = m2·v_S2·a_S2 + J_S2·ω2·ε2 + m3·ẋ_B·ẍ_B (the massless crank turns
/// uniformly). The powers: gravity on the rod −m2·g·v_S2,y (the slider moves horizontally);
/// the resistance, against the slider's motion, −F_w·ẋ_B while ẋ_B > 0 (working stroke)
/// and F_i·ẋ_B while ẋ_B < 0 (idle stroke). The balancing force at A, along v_A, of power
/// P_m·r·|ω|, supplies the rest:
///   P_m = (dT/dt − P_gravity − P_resistance) / (r·|ω|).
struct CrankSlider {
    r: f64,
    l: f64,
    k: f64,
    m2: f64,
    j2: f64,
    m3: f64,
    g: f64,
    /// Signed crank speed, rad/s (counter-clockwise positive).
    omega: f64,
    f_work: f64,
    f_idle: f64,
}

impl CrankSlider {
    fn p_m(&self, theta: f64) -> f64 {
        let CrankSlider { r, l, k, m2, j2, m3, g, omega: w, f_work, f_idle } = *self;
        let lam = r / l;
        let (sin, cos) = theta.sin_cos();
        let (sin2, cos2) = (2.0 * theta).sin_cos();
        let cb = (1.0 - lam * lam * sin * sin).sqrt();

        let x_dot = -r * w * (sin + lam * sin * cos / cb);
        let x_ddot = -r * w * w * (cos + lam * cos2 / cb + lam.powi(3) * sin2 * sin2 / (4.0 * cb.powi(3)));
        let omega2 = -lam * w * cos / cb;
        let eps2 = lam * (1.0 - lam * lam) * w * w * sin / cb.powi(3);
        let v_s2 = Vec2::new((1.0 - k) * (-r * w * sin) + k * x_dot, (1.0 - k) * r * w * cos);
        let a_s2 = Vec2::new((1.0 - k) * (-r * w * w * cos) + k * x_ddot, -(1.0 - k) * r * w * w * sin);

        let dt_dt = m2 * v_s2.dot(a_s2) + j2 * omega2 * eps2 + m3 * x_dot * x_ddot;
        let gravity = -m2 * g * v_s2.y;
        let resistance = if x_dot > 0.0 { -f_work * x_dot } else { f_idle * x_dot };
        (dt_dt - gravity - resistance) / (r * w.abs())
    }
}

#[test]
fn crank_slider_with_heavy_links_matches_the_balancing_force_worked_by_hand() {
    let (r, l, k, m2, j2, m3, rpm, f_work, f_idle) = (0.06, 0.25, 0.3, 2.4, 0.015, 3.5, 600.0, 800.0, 150.0);
    for (sense, sign) in [("ccw", 1.0), ("cw", -1.0)] {
        let text = format!(
            "project: {{title: t}}
mechanism:
  frame: [{{name: O, at: [0, 0]}}]
  crank: {{pivot: O, pin: A, length: {r}, rpm: {rpm}, sense: {sense}}}
  groups:
    - rrp: {{links: [2, 3], joint: A, point: B, length: {l}, guide: {{through: [0, 0], angle_deg: 0}}, branch: forward}}
  points:
    - {{name: S2, link: 2, from: A, toward: B, ratio: {k}, mass_centre: true}}
    - {{name: S3, link: 3, from: B, mass_centre: true}}
analysis: {{positions: 12, start: max}}
forces:
  links: [{{link: 2, mass: {m2}, inertia: {j2}}}, {{link: 3, mass: {m3}}}]
  loads:
    - resistance: {{point: B, working: forward, force: {f_work}, idle_force: {f_idle}}}
"
        );
        let p = lever_of(&text);
        let hand = CrankSlider {
            r,
            l,
            k,
            m2,
            j2,
            m3,
            g: 9.81, // the project file's default
            omega: sign * rpm * TAU / 60.0,
            f_work,
            f_idle,
        };
        assert_near!(p.mechanism.omega1, hand.omega, 1e-12, "ω1");
        let kin = analysis::kinematics(&p.mechanism, &p.settings).expect("kinematics");
        let model =
            analysis::place_loads(&p.mechanism, &kin.motion, p.forces.as_ref().expect("forces")).expect("loads placed");
        // Absolute crank angles, off the dead centres (0°, 180°) where the resistance turns.
        for deg in [20.0, 75.0, 110.0, 165.0, 230.0, 290.0, 340.0] {
            let theta = f64::to_radians(deg);
            let s = p.mechanism.solve(theta).expect("assembles");
            let f = kinetostatics::analyse(&p.mechanism, &s, &model).expect("solvable");
            let expected = hand.p_m(theta);
            assert_near!(f.p_m, expected, Near::rel(1e-9).floor(1e-12), "{sense}, θ = {deg}°: P_m against the hand's");
        }
    }
}
