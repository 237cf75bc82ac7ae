//! Properties of the exact mechanics over every fixture and full crank turns:
//! loop closure, analytic derivatives against finite differences, plan geometry.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture_names, lever, lever_of};
use kurbo::Vec2;
use std::f64::consts::TAU;
use tmm_sheets::assert_near;
use tmm_sheets::lever::linkage::{Mechanism, State, Step};
use tmm_sheets::lever::motion::{Start, analyse_motion};
use tmm_sheets::lever::plans::{SegKind, acceleration_plan, relations, velocity_plan};
use tmm_sheets::num::Near;

/// Residual of every constraint of every step, metres.
fn closure_residual(m: &Mechanism, s: &State) -> f64 {
    let p = |id: usize| s.points[id].p;
    let mut worst: f64 = 0.0;
    let mut check = |r: f64| worst = worst.max(r.abs());
    for st in &m.steps {
        match *st {
            Step::Crank { pivot, pin, length, .. } => check((p(pin) - p(pivot)).hypot() - length),
            Step::Rrr { p: a, q, b, l_pb, l_qb, .. } => {
                check((p(b) - p(a)).hypot() - l_pb);
                check((p(b) - p(q)).hypot() - l_qb);
            }
            Step::Rrp { p: a, d, length, through, dir, .. } => {
                check((p(d) - p(a)).hypot() - length);
                check((p(d) - through).cross(dir));
            }
            Step::Rpr { a, c, a3, links } => {
                check((p(a3) - p(a)).hypot());
                let e = s.links[links[1]].dir;
                check((p(a) - p(c)).cross(e));
            }
            Step::Attach { point, from, distance, .. } => check((p(point) - p(from)).hypot() - distance.abs()),
        }
    }
    worst
}

fn angles() -> impl Iterator<Item = f64> {
    (0..72).map(|k| TAU * k as f64 / 72.0 + 0.013)
}

#[test]
fn every_fixture_closes_its_loops_to_1e12_m() {
    for name in fixture_names() {
        let p = lever(&name);
        for th in angles() {
            let s = p.mechanism.solve(th).unwrap_or_else(|e| panic!("{name} at {th}: {e:?}"));
            let r = closure_residual(&p.mechanism, &s);
            assert!(r <= 1e-12, "{name}: closure residual {r:e} m at θ = {th}");
        }
    }
}

/// Central differences in time: θ changes by ω1·dt.
#[test]
fn velocities_and_accelerations_match_finite_differences() {
    for name in fixture_names() {
        let p = lever(&name);
        let m = &p.mechanism;
        let w = m.omega1;
        let dt = 1e-6 / w.abs();
        for th in angles() {
            let s = m.solve(th).unwrap();
            let (sp, sm) = (m.solve(th + w * dt).unwrap(), m.solve(th - w * dt).unwrap());
            let vscale = s.points.iter().map(|k| k.v.hypot()).fold(1e-3, f64::max);
            let ascale = s.points.iter().map(|k| k.a.hypot()).fold(1e-3, f64::max);
            for i in 0..s.points.len() {
                // A kulisa image is the kulisa's material point under the block at this
                // instant, not a point that stays under it: its velocity is not d/dt of
                // the coincident position. Its motion is checked through the relations.
                if m.is_kulisa_image(i) {
                    continue;
                }
                let v_fd = (sp.points[i].p - sm.points[i].p) / (2.0 * dt);
                let a_fd = (sp.points[i].v - sm.points[i].v) / (2.0 * dt);
                assert!(
                    (v_fd - s.points[i].v).hypot() <= 1e-6 * vscale,
                    "{name} v of {} at θ={th}: {:?} vs {:?}",
                    m.name(i),
                    v_fd,
                    s.points[i].v
                );
                assert!((a_fd - s.points[i].a).hypot() <= 1e-6 * ascale, "{name} a of {} at θ={th}", m.name(i));
            }
            for l in 0..s.links.len() {
                let w_fd = (sp.links[l].angle() - sm.links[l].angle() + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0;
                let w_fd = w_fd / (2.0 * dt);
                let e_fd = (sp.links[l].omega - sm.links[l].omega) / (2.0 * dt);
                let wscale = s.links.iter().map(|k| k.omega.abs()).fold(1e-3, f64::max);
                let escale = s.links.iter().map(|k| k.eps.abs()).fold(1e-3, f64::max);
                assert_near!(w_fd, s.links[l].omega, Near::rel(1e-6).floor(1e-6 * wscale), "{name} ω of link {l}");
                assert_near!(e_fd, s.links[l].eps, Near::rel(1e-6).floor(1e-6 * escale), "{name} ε of link {l}");
            }
        }
    }
}

/// Graphically, a plan closes when its relative vectors have the prescribed directions:
/// v_xy ⟂ xy, aⁿ ∥ xy (towards y), aᵗ ⟂ xy, and every chain ends at its image point.
#[test]
fn velocity_and_acceleration_plans_close() {
    for name in fixture_names() {
        let p = lever(&name);
        let m = &p.mechanism;
        for th in angles() {
            let s = m.solve(th).unwrap();
            let scale = s.points.iter().map(|k| k.v.hypot() + k.a.hypot()).fold(1e-3, f64::max);
            for r in relations(m) {
                let xy = s.points[r.x].p - s.points[r.y].p;
                let v_rel = s.points[r.x].v - s.points[r.y].v;
                if r.sliding {
                    let e = s.links[r.link].dir;
                    assert!(v_rel.cross(e).abs() <= 1e-9 * scale, "{name}: sliding velocity along the kulisa");
                } else {
                    assert!(v_rel.dot(xy).abs() <= 1e-9 * scale * xy.hypot(), "{name}: v_{} ⟂ link", r.name(m));
                }
            }
            let ap = acceleration_plan(m, &s);
            for seg in &ap.segs {
                assert!(seg.from.is_finite() && seg.to.is_finite());
            }
            // Each normal/tangential pair is a closed chain y → n → x.
            let normals: Vec<_> = ap.segs.iter().filter(|g| g.kind == SegKind::Normal).collect();
            let tangents: Vec<_> = ap.segs.iter().filter(|g| g.kind == SegKind::Tangential).collect();
            assert_eq!(normals.len(), tangents.len());
            let turning: Vec<_> = relations(m).into_iter().filter(|r| !r.sliding).collect();
            for ((n, t), r) in normals.iter().zip(&tangents).zip(&turning) {
                let xy = s.points[r.x].p - s.points[r.y].p;
                assert!((n.to - t.from).hypot() <= 1e-12 * scale);
                assert!((t.to - s.points[r.x].a).hypot() <= 1e-9 * scale, "{name}: chain ends at the image");
                assert!((n.to - n.from).cross(xy).abs() <= 1e-9 * scale * xy.hypot(), "{name}: aⁿ ∥ link");
                assert!((n.to - n.from).dot(xy) <= 1e-9 * scale * xy.hypot(), "{name}: aⁿ towards the centre");
                assert!((t.to - t.from).dot(xy).abs() <= 1e-9 * scale * xy.hypot(), "{name}: aᵗ ⟂ link");
            }
            let vp = velocity_plan(m, &s);
            assert!(vp.images.iter().all(|i| i.at.is_finite()));
        }
    }
}

#[test]
fn position_zero_is_an_exact_extreme_of_the_output() {
    for name in fixture_names() {
        let p = lever(&name);
        let m = &p.mechanism;
        let motion = analyse_motion(m, p.settings.sense, p.settings.start).unwrap();
        let s0 = m.solve(motion.theta0).unwrap();
        let (_, v) = m.output_value(&s0);
        assert!(v.abs() <= 1e-9 * m.omega1.abs(), "{name}: output velocity {v} at position 0");
        if let Some(e) = motion.other_extreme {
            let (_, v) = m.output_value(&m.solve(motion.theta(e)).unwrap());
            assert!(v.abs() <= 1e-9 * m.omega1.abs(), "{name}: output velocity {v} at the other extreme");
        }
        // min/max picks the right one: neighbours lie on the right side.
        let (x0, _) = m.output_value(&s0);
        for d in [-0.05, 0.05] {
            let (x, _) = m.output_value(&m.solve(motion.theta0 + d).unwrap());
            match p.settings.start {
                Start::Min => assert!(x >= x0, "{name}: position 0 is not the minimum"),
                Start::Max => assert!(x <= x0, "{name}: position 0 is not the maximum"),
                Start::Angle(_) => {}
            }
        }
    }
}

/// Sweeps the crank slowly through whole turns in both senses: the solution is finite
/// everywhere, including the crank-slider's dead centres.
#[test]
fn full_turns_through_dead_centres_stay_finite() {
    for name in fixture_names() {
        let m = lever(&name).mechanism;
        let mut s = State::default();
        for k in 0..3600 {
            let th = TAU * k as f64 / 3600.0;
            m.solve_into(th, &mut s).unwrap();
            assert!(s.points.iter().all(|q| q.p.is_finite() && q.v.is_finite() && q.a.is_finite()), "{name} at {th}");
        }
    }
}

/// A rocker swinging across the negative x axis (where atan2 wraps from +180° to −180°)
/// still gets the right minimum and maximum.
#[test]
fn rocker_extremes_do_not_depend_on_where_angles_wrap() {
    let text = std::fs::read_to_string(common::root().join("fixtures/four-bar.yaml")).unwrap();
    let original = lever_of(&text).mechanism;
    let link = original.link_by_number(3).unwrap();
    let mean = (0..72).fold(Vec2::ZERO, |acc, k| acc + original.solve(TAU * k as f64 / 72.0).unwrap().links[link].dir);
    // Turn the frame about O so that the swing is centred on 180°.
    let rot = std::f64::consts::PI - mean.atan2();
    let o1 = Vec2::new(0.20 * rot.cos(), 0.20 * rot.sin());
    let text = text.replace("at: [0.20, 0]", &format!("at: [{:.15}, {:.15}]", o1.x, o1.y));
    for start in ["min", "max"] {
        let p = lever_of(&text.replace("positions: 12", &format!("positions: 12\n  start: {start}")));
        let m = &p.mechanism;
        let angles: Vec<f64> = (0..72).map(|k| m.solve(TAU * k as f64 / 72.0).unwrap().links[link].angle()).collect();
        assert!(angles.iter().any(|&a| a > 3.0) && angles.iter().any(|&a| a < -3.0), "the swing crosses ±180°");
        let motion = analyse_motion(m, p.settings.sense, p.settings.start).unwrap();
        let angle_at = |th: f64| m.solve(th).unwrap().links[link].angle().rem_euclid(TAU); // continuous across −x
        let a0 = angle_at(motion.theta0);
        for d in [-0.05, 0.05] {
            let a = angle_at(motion.theta0 + d);
            if start == "min" {
                assert!(a >= a0, "{start}: {a} < {a0}")
            } else {
                assert!(a <= a0, "{start}: {a} > {a0}")
            }
        }
    }
}

/// The drawn trajectories: every exact point of the path, densely sampled, lies within the
/// fit's tolerance of the cubic pieces, and the pieces join into one closed curve.
#[test]
fn fitted_trajectories_follow_the_exact_paths() {
    use tmm_sheets::lever::analysis::{self, TRAJECTORY_FIT};
    use tmm_sheets::lever::motion::sample_at;
    use tmm_sheets::lever::trajectory::distance_to;
    for name in fixture_names() {
        let p = lever(&name);
        let m = &p.mechanism;
        let k = analysis::kinematics(m, &p.settings).unwrap();
        let extent = {
            let pts: Vec<Vec2> = k.trajectories.iter().flat_map(|t| t.samples.iter().copied()).collect();
            let (lo, hi) = pts.iter().fold((Vec2::splat(f64::MAX), Vec2::splat(f64::MIN)), |(lo, hi), p| {
                (Vec2::new(lo.x.min(p.x), lo.y.min(p.y)), Vec2::new(hi.x.max(p.x), hi.y.max(p.y)))
            });
            (hi - lo).hypot()
        };
        let crank = m.crank().length;
        for t in &k.trajectories {
            let c = &t.fitted.cubics;
            assert!(c.len() >= 16, "{name}: {} pieces", c.len());
            for w in c.windows(2) {
                assert_eq!(w[0].p3, w[1].p0, "{name}: the pieces join");
            }
            assert!((c[0].p0 - c[c.len() - 1].p3).hypot() < 1e-15, "{name}: the path closes");
            // Relative to the extent of everything that moves: at least the centres' extent
            // and the crank's diameter, at most a few times that.
            let tol = t.fitted.tolerance;
            assert!(
                tol >= TRAJECTORY_FIT * extent.max(2.0 * crank) * 0.999
                    && tol <= TRAJECTORY_FIT * 10.0 * extent.max(2.0 * crank),
                "{name}: tolerance {tol:e}"
            );
            for j in 0..1440 {
                let phi = TAU * (j as f64 + 0.37) / 1440.0;
                let exact = sample_at(m, &k.motion, phi).unwrap().points[t.point].p;
                let d = distance_to(c, exact.to_point());
                assert!(
                    d <= tol,
                    "{name}: {} is {d:e} m from its drawn path at φ = {phi} (tolerance {tol:e})",
                    m.name(t.point)
                );
            }
        }
    }
}

/// Every image of an acceleration plan lies on a drawn line: a centre of mass on the whole
/// relative acceleration of its link (the line ab), so no image floats in empty space.
#[test]
fn every_acceleration_image_lies_on_a_drawn_vector() {
    for name in fixture_names() {
        let p = lever(&name);
        let m = &p.mechanism;
        let s = m.solve(0.7).unwrap();
        let plan = acceleration_plan(m, &s);
        let size = plan.extent();
        for img in &plan.images {
            let on = plan.segs.iter().any(|sg| {
                let (a, b) = (sg.from, sg.to);
                let ab = b - a;
                let t = if ab.hypot2() > 0.0 { ((img.at - a).dot(ab) / ab.hypot2()).clamp(0.0, 1.0) } else { 0.0 };
                (a + ab * t - img.at).hypot() <= 1e-9 * size
            });
            assert!(on, "{name}: image {} of the acceleration plan lies on no drawn vector", img.label);
        }
    }
}
