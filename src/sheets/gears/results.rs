//! Sheet 2's section of `results.json`, typed (SI; angles in degrees with `_deg`).

use super::{GearsBuild, INVOLUTE_PIECES, READ_TO_MM};
use crate::gears::pair::Pair;
use crate::gears::planetary::ConditionKind;
use crate::project::GearsProject;
use serde::Serialize;

#[derive(Serialize)]
struct Radii {
    pitch: [f64; 2],
    base: [f64; 2],
    tip: [f64; 2],
    root: [f64; 2],
    working: [f64; 2],
}

#[derive(Serialize)]
struct PairOut {
    module: f64,
    z: [u32; 2],
    shift: [f64; 2],
    shift_auto: [bool; 2],
    pressure_angle_deg: f64,
    working_pressure_angle_deg: f64,
    centre_distance: f64,
    reference_centre_distance: f64,
    y: f64,
    delta_y: f64,
    ratio: f64,
    contact_ratio: f64,
    contact_ratio_drawing: f64,
    radii: Radii,
    tooth_height: f64,
    pitch: f64,
    base_pitch: f64,
    tooth_thickness: [f64; 2],
    tip_thickness: [f64; 2],
    /// By the exact rule (the drawn outline): x < h_a* − z·sin²α/2.
    undercut: [bool; 2],
    x_min: [f64; 2],
    /// By the course's rule, as the sheet's table and notes give it: x < (17 − z)/17.
    undercut_course: [bool; 2],
    x_min_course: [f64; 2],
    /// A tip reaching past where the other wheel's involute begins.
    interference: [bool; 2],
    /// The radius where each involute begins (the form circle, or where an undercut root's
    /// fillet cuts it): the involute contact cannot go lower.
    involute_from: [f64; 2],
}

#[derive(Serialize)]
struct DrawingOut {
    mu_l: f64,
    tooth_height_mm: f64,
    involute_pieces_per_flank: usize,
    involute_deviation: f64,
    fillet_deviation: f64,
    planetary_mu_l: Option<f64>,
}

#[derive(Serialize)]
struct ConditionOut {
    name: ConditionKind,
    value: f64,
    limit: f64,
    ok: bool,
}

#[derive(Serialize)]
struct PlanetaryOut<'a> {
    scheme: &'static str,
    z: &'a [u32],
    planets: u32,
    ratio: f64,
    ratio_required: f64,
    tolerance: f64,
    module: f64,
    conditions: Vec<ConditionOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    graphic: Option<GraphicOut>,
}

/// The ratio read off the plan of angular velocities: the segments 0–1 and 0–H as drawn (mm),
/// the ratio of the two read to `read_to_mm` (absent when 0–H reads shorter than that).
#[derive(Serialize)]
struct GraphicOut {
    segment_01_mm: f64,
    segment_0h_mm: f64,
    read_to_mm: f64,
    ratio: Option<f64>,
}

#[derive(Serialize)]
struct Sheet2<'a> {
    pair: PairOut,
    drawing: DrawingOut,
    #[serde(skip_serializing_if = "Option::is_none")]
    planetary: Option<PlanetaryOut<'a>>,
    /// The specific sliding's diagram, where the mesh leaves it room.
    #[serde(skip_serializing_if = "Option::is_none")]
    sliding: Option<SlidingOut>,
}

/// λ1 at B1 and λ2 at B2 (the flanks' largest specific sliding on the active line) and the
/// diagram's scales.
#[derive(Serialize)]
struct SlidingOut {
    /// Absent where that end of the active line is at N (interference: unbounded).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda1_b1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda2_b2: Option<f64>,
    mu_l: f64,
    mu_lambda: f64,
}

fn pair_out(p: &GearsProject, pr: &Pair, eps_drawn: f64) -> PairOut {
    let w = &pr.wheels;
    let each = |f: &dyn Fn(usize) -> f64| [f(0), f(1)];
    PairOut {
        module: pr.spec.module,
        z: [w[0].z, w[1].z],
        shift: each(&|i| w[i].shift),
        shift_auto: p.auto_shift,
        pressure_angle_deg: pr.spec.pressure_angle.to_degrees(),
        working_pressure_angle_deg: pr.working_pressure_angle.to_degrees(),
        centre_distance: pr.centre_distance,
        reference_centre_distance: pr.reference_centre_distance,
        y: pr.y,
        delta_y: pr.delta_y,
        ratio: pr.ratio,
        contact_ratio: pr.contact_ratio,
        contact_ratio_drawing: eps_drawn,
        radii: Radii {
            pitch: each(&|i| w[i].pitch),
            base: each(&|i| w[i].base),
            tip: each(&|i| w[i].tip),
            root: each(&|i| w[i].root),
            working: each(&|i| w[i].working),
        },
        tooth_height: pr.tooth_height,
        pitch: pr.pitch,
        base_pitch: pr.base_pitch,
        tooth_thickness: each(&|i| w[i].tooth_thickness),
        tip_thickness: each(&|i| w[i].tip_thickness),
        undercut: [w[0].undercut, w[1].undercut],
        x_min: each(&|i| w[i].x_min),
        undercut_course: [w[0].undercut_by_course(), w[1].undercut_by_course()],
        x_min_course: each(&|i| w[i].x_min_course),
        interference: pr.interference,
        involute_from: pr.involute_from,
    }
}

/// The sheet's section of `results.json`.
pub fn section(p: &GearsProject, b: &GearsBuild) -> serde_json::Value {
    let out = Sheet2 {
        pair: pair_out(p, &p.pair, b.mesh.contact_ratio_drawn),
        drawing: DrawingOut {
            mu_l: b.mesh.mu,
            tooth_height_mm: b.mesh.tooth_height_mm,
            involute_pieces_per_flank: INVOLUTE_PIECES,
            involute_deviation: b.mesh.involute_deviation,
            fillet_deviation: b.mesh.fillet_deviation,
            planetary_mu_l: b.planetary_mu,
        },
        planetary: p.planetary.as_ref().map(|pl| PlanetaryOut {
            scheme: pl.stage.scheme.key(),
            z: &pl.stage.z,
            planets: pl.stage.planets,
            ratio: pl.stage.ratio,
            ratio_required: pl.stage.ratio_required,
            tolerance: pl.stage.tolerance,
            module: pl.module,
            conditions: pl
                .stage
                .conditions
                .iter()
                .map(|c| ConditionOut { name: c.name, value: c.value, limit: c.limit, ok: c.ok })
                .collect(),
            graphic: b.planetary_reading.map(|r| GraphicOut {
                segment_01_mm: r.sun_mm,
                segment_0h_mm: r.carrier_mm,
                read_to_mm: READ_TO_MM,
                ratio: r.ratio,
            }),
        }),
        sliding: b.sliding.map(|s| SlidingOut {
            lambda1_b1: s.lambda[0],
            lambda2_b2: s.lambda[1],
            mu_l: s.mu_l,
            mu_lambda: s.mu_lambda,
        }),
    };
    serde_json::to_value(&out).expect("the results serialise")
}
