//! Sheet 3's pressure angle diagram α(φ): drawn where the views leave room, its curve the
//! profile's pressure angle at its stated scale, each phase's allowed angle dashed at its
//! height; for a translating follower the angle against tan α = (ds/dφ − e)/(s₀ + s),
//! computed here from the law the results give.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::root;
use kurbo::Point;
use tmm_sheets::drawing::scene::{Group, Item, LineType};
use tmm_sheets::pipeline;

/// The cam fixtures and the worked example, each built as sheet 3 alone.
fn built() -> Vec<(String, pipeline::Built)> {
    let mut texts: Vec<(String, String)> = std::fs::read_dir(root().join("fixtures/cams"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| (p.file_stem().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    texts.sort();
    texts.insert(0, ("worked-example".into(), pipeline::DEFAULT_PROJECT.to_string()));
    texts
        .into_iter()
        .map(|(name, text)| {
            let p = pipeline::load(&text).unwrap();
            (name, pipeline::build(&p, &[3]).unwrap().remove(0))
        })
        .collect()
}

/// A stroked path's points (its lines' ends), pen width and line type.
fn points(item: &Item) -> Option<(Vec<Point>, f64, LineType)> {
    common::path_points(item).map(|(pts, pen)| (pts, pen.width, pen.line))
}

/// The diagram's x axis (paper y): where its position ticks, the 1.5 mm vertical strokes
/// under it, start.
fn axis_y(g: &Group) -> f64 {
    let tops: Vec<f64> = g
        .items
        .iter()
        .filter_map(points)
        .filter(|(p, w, l)| {
            p.len() == 2 && *w < 0.5 && *l == LineType::Solid && (p[0].x - p[1].x).abs() < 1e-9 && {
                let len = (p[0].y - p[1].y).abs();
                (len - 1.5).abs() < 1e-6
            }
        })
        .map(|(p, _, _)| p[0].y.min(p[1].y))
        .collect();
    assert!(tops.len() >= 10, "the position ticks: {tops:?}");
    let axis = tops[0];
    assert!(tops.iter().all(|y| (y - axis).abs() < 1e-6), "one axis: {tops:?}");
    axis
}

#[test]
fn the_pressure_diagram_draws_the_profiles_angle_and_the_allowed_ones_at_its_scale() {
    for (name, b) in built() {
        let r = &b.output.results;
        let Some(g) = b.output.scene.groups.iter().find(|g| g.id == "pressure") else {
            panic!("{name}: no pressure angle diagram; empty share {}", r["layout"]["empty_share"]);
        };
        let mu = r["pressure_diagram"]["mu_alpha_deg"].as_f64().unwrap();
        let axis = axis_y(g);
        let curve = g.items.iter().filter_map(points).find(|(_, w, _)| *w > 0.5).unwrap().0;
        let highest = curve.iter().map(|p| (axis - p.y) * mu).fold(0.0, f64::max);
        let max = &r["max_pressure_angle_deg"];
        let reached = max["rise"].as_f64().unwrap().max(max["return"].as_f64().unwrap());
        // Sampled four times a degree: the drawn peak is within 0.2 mm of the exact one.
        assert!((highest - reached).abs() <= 0.2 * mu, "{name}: drawn peak {highest}°, exact {reached}°");
        let allowed = &r["allowed_pressure_angle_deg"];
        let dashed: Vec<f64> = g
            .items
            .iter()
            .filter_map(points)
            .filter(|(_, _, l)| *l == LineType::Dashed)
            .map(|(p, _, _)| (axis - p[0].y) * mu)
            .collect();
        for phase in ["rise", "return"] {
            let a = allowed[phase].as_f64().unwrap();
            assert!(dashed.iter().any(|d| (d - a).abs() < 0.01 * mu), "{name}: no dashed line at {a}°: {dashed:?}");
        }
        let region = g.region;
        assert!(curve.iter().all(|p| region.contains(*p)), "{name}: the curve leaves its region");
    }
}

/// A translating follower offset by e from the cam's centre, its pitch base radius r₀:
/// tan α = (ds/dφ − e)/(s₀ + s), s₀ = √(r₀² − e²), the offset on the side that lowers the
/// rise's angle. The results' largest angles and the diagram's curve are that angle.
#[test]
fn a_translating_followers_pressure_angle_is_the_textbook_ones() {
    let (name, b) = built().into_iter().find(|(n, _)| n == "translating-offset-auto").unwrap();
    let r = &b.output.results;
    let e = r["offset"].as_f64().unwrap().abs();
    let r0 = r["r_min"].as_f64().unwrap();
    let s0 = (r0 * r0 - e * e).sqrt();
    let ph = &r["phases_deg"];
    let (rise, dwell, ret) =
        (ph["rise"].as_f64().unwrap(), ph["far_dwell"].as_f64().unwrap(), ph["return"].as_f64().unwrap());
    let mut largest = [0.0f64; 2];
    let mut at = Vec::new();
    for row in r["law"].as_array().unwrap() {
        let v: Vec<f64> = row.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        let (phi, s, ds) = (v[0], v[1], v[2]);
        let alpha = ((ds - e) / (s0 + s)).atan().to_degrees().abs();
        if phi <= rise {
            largest[0] = largest[0].max(alpha);
        } else if phi >= rise + dwell && phi <= rise + dwell + ret {
            largest[1] = largest[1].max(alpha);
        }
        if phi <= rise + dwell + ret {
            at.push((phi, alpha));
        }
    }
    let max = &r["max_pressure_angle_deg"];
    for (k, phase) in ["rise", "return"].into_iter().enumerate() {
        let exact = max[phase].as_f64().unwrap();
        assert!((exact - largest[k]).abs() < 0.05, "{name} {phase}: {exact}° against the textbook's {}°", largest[k]);
    }
    // The drawn curve against the textbook angle at its own φ.
    let g = b.output.scene.groups.iter().find(|g| g.id == "pressure").unwrap();
    let (mu_phi, mu) = (
        r["pressure_diagram"]["mu_phi_deg"].as_f64().unwrap(),
        r["pressure_diagram"]["mu_alpha_deg"].as_f64().unwrap(),
    );
    let axis = axis_y(g);
    let curve = g.items.iter().filter_map(points).find(|(_, w, _)| *w > 0.5).unwrap().0;
    let x0 = curve[0].x;
    for &(phi, alpha) in at.iter().step_by(20) {
        let p =
            curve.iter().min_by(|a, b| ((a.x - x0) * mu_phi - phi).abs().total_cmp(&((b.x - x0) * mu_phi - phi).abs()));
        let drawn = (axis - p.unwrap().y) * mu;
        assert!((drawn - alpha).abs() < 0.3 * mu + 0.5, "{name}: at φ = {phi}° drawn {drawn}°, textbook {alpha}°");
    }
}

/// A knife-edged rocker's tabulated pressure angles are its linkage's, computed here with
/// the pivot A at the origin, the cam's centre O at (a_w, 0) and the rocker at ψ = ψ₀ + β
/// from AO: the relative instant centre P of cam and rocker lies on AO at a_w/(1 − i), i =
/// dβ/dφ (the rocker's angular velocity over the cam's), and the contact normal runs from
/// the knife edge B through P, so the angle from B's velocity (across AB) to it is
/// tan α = (l(1 − i) − a_w cos ψ)/(a_w sin ψ). The law is coded here (the guide's law 2,
/// β = β_max(3x² − 2x³) on the rise, falling back likewise on the return); only a_w and ψ₀
/// come from the design. The signed angle passes through zero late in the return, between
/// its positions of 142.5° and 150°: the drawn |α| dips there, and a teacher asked why.
#[test]
fn a_knife_rockers_tabulated_pressure_angles_are_its_linkages() {
    let (_, b) = built().into_iter().find(|(n, _)| n == "knife-rocker").unwrap();
    let r = &b.output.results;
    let (l, beta_max) = (0.12, 20f64.to_radians());
    let (a_w, psi_0) = (r["centre_distance"].as_f64().unwrap(), r["rocker_start_deg"].as_f64().unwrap().to_radians());
    let (rise, ret) = (90f64.to_radians(), 60f64.to_radians());
    // β and dβ/dφ of the guide's law 2 at φ (no far dwell).
    let law = |phi: f64| {
        let (x, sign, span) = if phi <= rise { (phi / rise, 1.0, rise) } else { ((phi - rise) / ret, -1.0, ret) };
        let (s, ds) = (x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x));
        let beta = if sign > 0.0 { beta_max * s } else { beta_max * (1.0 - s) };
        (beta, sign * beta_max * ds / span)
    };
    let signed = |phi_deg: f64| {
        let (beta, i) = law(phi_deg.to_radians());
        let psi = psi_0 + beta;
        (l * (1.0 - i) - a_w * psi.cos()).atan2(a_w * psi.sin()).to_degrees()
    };
    let mut checked = 0;
    for id in ["law-rise", "law-return"] {
        let t = b.output.tables.iter().find(|t| t.table.id == id).unwrap();
        let row = |key: &str| &t.table.rows.iter().find(|r| r.key == key).unwrap().values;
        for (&phi, &alpha) in row("phi").iter().zip(row("alpha")) {
            let exact = signed(phi).abs();
            assert!((alpha - exact).abs() < 1e-6, "{id} at φ = {phi}°: {alpha}° against the linkage's {exact}°");
            checked += 1;
        }
    }
    assert!(checked >= 15, "only {checked} tabulated angles");
    let (before, after) = (signed(142.5), signed(150.0));
    assert!(before * after < 0.0 && before.abs() > 15.0, "no sign change: {before}° at 142.5°, {after}° at 150°");
}
