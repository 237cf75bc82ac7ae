//! Sheet 3's section of `results.json`, typed (SI; angles in degrees with `_deg`).

use super::{CamBuild, DIVISIONS, Scales};
use crate::cams::Sense;
use crate::cams::follower::Follower;
use crate::cams::integrate::{self, IntegrationError};
use crate::project::CamProject;
use serde::Serialize;

#[derive(Serialize)]
struct Phases {
    rise: f64,
    far_dwell: f64,
    #[serde(rename = "return")]
    ret: f64,
}

#[derive(Serialize)]
struct PerPhase {
    rise: f64,
    #[serde(rename = "return")]
    ret: f64,
}

#[derive(Serialize)]
struct Integration {
    divisions: usize,
    rise: IntegrationError,
    #[serde(rename = "return")]
    ret: IntegrationError,
    s_percent_of_lift: f64,
    ds_percent_of_peak: f64,
    closure_s: f64,
    closure_ds: f64,
}

#[derive(Serialize)]
struct Sheet3<'a> {
    follower: &'static str,
    laws: [&'a str; 2],
    sense: Sense,
    phases_deg: Phases,
    lift: f64,
    r_min: f64,
    centre: [f64; 2],
    roller_radius: f64,
    roller_auto: bool,
    pitch_min_radius_of_curvature: f64,
    pitch_min_radius_of_curvature_at_deg: f64,
    max_pressure_angle_deg: PerPhase,
    allowed_pressure_angle_deg: PerPhase,
    scales: Scales,
    nomogram_mu: f64,
    profile_mu_l: f64,
    profile_pieces: usize,
    profile_deviation: f64,
    /// The pressure angle's diagram's scales, °/mm (absent where the sheet had no room).
    #[serde(skip_serializing_if = "Option::is_none")]
    pressure_diagram: Option<PressureDiagram>,
    integration_error: Integration,
    law_columns: [&'static str; 4],
    /// φ in degrees, s, ds/dφ, d²s/dφ² every quarter degree.
    law: Vec<[f64; 4]>,
    profile_columns: [&'static str; 5],
    /// Each whole degree, the pitch and the working profile's points.
    profile: Vec<(u32, f64, f64, f64, f64)>,
    #[serde(skip_serializing_if = "Option::is_none")]
    offset: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    offset_auto: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre_distance: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    rocker_start_deg: Option<f64>,
}

/// The pressure angle's diagram's scales, °/mm.
#[derive(Serialize)]
struct PressureDiagram {
    mu_phi_deg: f64,
    mu_alpha_deg: f64,
}

/// The law every quarter degree: φ in degrees, s, ds/dφ, d²s/dφ².
fn law_samples(p: &CamProject) -> Vec<[f64; 4]> {
    let pr = &p.design.spec.program;
    let n = 4 * 360;
    (0..n)
        .map(|k| {
            let phi = std::f64::consts::TAU * k as f64 / n as f64;
            let x = pr.at(phi);
            [phi.to_degrees(), x.s, x.ds, x.dds]
        })
        .collect()
}

/// The profiles every whole degree, in the cam's own sense of rotation.
fn profile_samples(p: &CamProject) -> Vec<(u32, f64, f64, f64, f64)> {
    let d = &p.design;
    (0..360)
        .map(|k| {
            let phi = f64::from(k).to_radians();
            let pt = d.profile.pitch(phi).p;
            let w = if d.roller > 0.0 { d.profile.working(d.roller, phi).0 } else { pt };
            let (pt, w) = (d.spec.sense.apply(pt), d.spec.sense.apply(w));
            (k, pt.x, pt.y, w.x, w.y)
        })
        .collect()
}

/// The sheet's section of `results.json`.
pub fn section(p: &CamProject, b: &CamBuild) -> serde_json::Value {
    let d = &p.design;
    let pr = &d.spec.program;
    let err = b.integrated.each_ref().map(|i| i.error(pr));
    let closure = integrate::closure(&b.integrated);
    let rocker = d.centre_distance().zip(d.rocker_start());
    let out = Sheet3 {
        follower: match d.spec.follower {
            Follower::Translating => "translating",
            Follower::Rocker { .. } => "rocker",
        },
        laws: [pr.rise_law.key(), pr.return_law.key()],
        sense: d.spec.sense,
        phases_deg: Phases {
            rise: pr.rise.to_degrees(),
            far_dwell: pr.far_dwell.to_degrees(),
            ret: pr.ret.to_degrees(),
        },
        lift: pr.lift,
        r_min: d.centre.r_min,
        centre: [d.spec.sense.apply(d.centre.o).x, d.centre.o.y],
        roller_radius: d.roller,
        roller_auto: p.roller_auto,
        pitch_min_radius_of_curvature: d.rho_min,
        pitch_min_radius_of_curvature_at_deg: d.rho_min_phi.to_degrees(),
        max_pressure_angle_deg: PerPhase {
            rise: d.max_pressure[0].0.to_degrees(),
            ret: d.max_pressure[1].0.to_degrees(),
        },
        allowed_pressure_angle_deg: PerPhase {
            rise: d.spec.allowed.rise.to_degrees(),
            ret: d.spec.allowed.ret.to_degrees(),
        },
        scales: b.scales,
        nomogram_mu: b.nomogram_mu,
        profile_mu_l: b.profile_mu,
        profile_pieces: b.profile_pieces,
        profile_deviation: b.profile_deviation,
        pressure_diagram: b
            .pressure
            .map(|s| PressureDiagram { mu_phi_deg: s.mu_phi_deg, mu_alpha_deg: s.mu_alpha_deg }),
        integration_error: Integration {
            divisions: DIVISIONS,
            rise: err[0],
            ret: err[1],
            s_percent_of_lift: b.errors.0,
            ds_percent_of_peak: b.errors.1,
            closure_s: closure.0,
            closure_ds: closure.1,
        },
        law_columns: ["phi_deg", "s", "ds", "dds"],
        law: law_samples(p),
        profile_columns: ["phi_deg", "pitch_x", "pitch_y", "working_x", "working_y"],
        profile: profile_samples(p),
        offset: d.offset(),
        offset_auto: d.offset().map(|_| p.offset_auto),
        centre_distance: rocker.map(|r| r.0),
        rocker_start_deg: rocker.map(|r| r.1.to_degrees()),
    };
    serde_json::to_value(&out).expect("the results serialise")
}
