//! The guide's load tables, digitised as printed (the course guide, ToshDTU 2014, appendices 1 and 2). Each
//! row is (S/H, p/p_max) with S measured from the cylinder head (the top dead centre).
//! docs/errata.md records how the transcription's broken rows were read.

/// Relative piston travel of appendix 1.
const TRAVEL_1: [f64; 11] = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];

/// Appendix 1, stage I: (towards the head: compression and delivery; away from it:
/// expansion and suction). The printed compression row has ten values; the eleventh, at
/// S/H = 1, is the suction pressure where compression starts (0).
const STAGE_1: ([f64; 11], [f64; 11]) = (
    [1.0, 1.0, 1.0, 0.58, 0.40, 0.25, 0.20, 0.13, 0.09, 0.03, 0.0],
    [1.0, 0.35, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
);

/// Appendix 1, stage II: suction at 0.3 of the stage's maximum (P_II min = P_I max).
const STAGE_2: ([f64; 11], [f64; 11]) = (
    [1.0, 1.0, 1.0, 0.75, 0.67, 0.58, 0.52, 0.47, 0.41, 0.35, 0.30],
    [1.0, 0.52, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3],
);

/// Relative piston travel of appendix 2 (0.05 and 0.06 as printed).
const TRAVEL_2: [f64; 13] = [0.0, 0.05, 0.06, 0.10, 0.20, 0.30, 0.40, 0.50, 0.60, 0.70, 0.80, 0.90, 1.0];

/// Appendix 2, four-stroke engine: P/P_z max for strokes I (expansion), II (exhaust),
/// III (intake), IV (compression).
const ENGINE: [[f64; 13]; 4] = [
    [0.46, 0.90, 1.0, 0.85, 0.56, 0.40, 0.31, 0.24, 0.20, 0.16, 0.12, 0.10, 0.05],
    [0.01; 13],
    [0.0, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01, -0.01],
    [0.46, 0.31, 0.28, 0.25, 0.17, 0.10, 0.07, 0.04, 0.02, 0.01, 0.01, 0.0, -0.01],
];

use super::load::Stroke;

fn rows(travel: &[f64], values: &[f64]) -> Vec<(f64, f64)> {
    travel.iter().copied().zip(values.iter().copied()).collect()
}

/// A named indicator diagram: (away from the head, towards it), with the strokes' names.
pub struct Indicator {
    pub away: (Vec<(f64, f64)>, Stroke),
    pub toward: (Vec<(f64, f64)>, Stroke),
}

pub fn compressor(stage: u32) -> Indicator {
    let (toward, away) = if stage == 1 { STAGE_1 } else { STAGE_2 };
    Indicator {
        away: (rows(&TRAVEL_1, &away), Stroke::AwayFromHead),
        toward: (rows(&TRAVEL_1, &toward), Stroke::TowardHead),
    }
}

/// The engine's strokes in the given revolution of its 720° cycle.
pub fn engine(revolution: u32) -> Indicator {
    if revolution == 1 {
        Indicator {
            away: (rows(&TRAVEL_2, &ENGINE[0]), Stroke::Expansion),
            toward: (rows(&TRAVEL_2, &ENGINE[1]), Stroke::Exhaust),
        }
    } else {
        Indicator {
            away: (rows(&TRAVEL_2, &ENGINE[2]), Stroke::Intake),
            toward: (rows(&TRAVEL_2, &ENGINE[3]), Stroke::Compression),
        }
    }
}
