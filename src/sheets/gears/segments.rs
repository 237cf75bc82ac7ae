//! The segments a student draws or measures on sheet 2: on the mesh, every circle's radius
//! (the compass is set to it), the centre distance a_w, the line of action N1N2 and its
//! active part g_α (B1B2), the arc of action on wheel 1's working circle, the pitch p and
//! the base pitch p_b, the tooth thicknesses s and s_a (arcs) and the tooth height h; on
//! the planetary views, the wheels' radii and the carrier's arm a_H. Values in mm as the
//! note's tables give them, the scale in mm per paper mm.

use crate::gears::pair::Pair;
use crate::gears::planetary::Stage;
use crate::num::units::mm;
use crate::report::{AnswerKeys, Segment, ascii_key};

/// The mesh's segments, drawn at μ_l `mu` (m/mm) in part `part`.
pub fn mesh(p: &Pair, mu: f64, part: &str, answers: &AnswerKeys) -> Vec<Segment> {
    let scale = mm(mu);
    let seg = |name: &str, value: f64, key: &str| {
        Segment::new(format!("{part}.{name}"), name, mm(value), "mm", scale).answering(key, answers)
    };
    let mut out = Vec::new();
    for (i, w) in p.wheels.iter().enumerate() {
        let n = i + 1;
        out.extend([
            seg(&format!("r_{n}"), w.pitch, &format!("wheels.r.{n}")),
            seg(&format!("r_b{n}"), w.base, &format!("wheels.r_b.{n}")),
            seg(&format!("r_a{n}"), w.tip, &format!("wheels.r_a.{n}")),
            seg(&format!("r_f{n}"), w.root, &format!("wheels.r_f.{n}")),
            seg(&format!("r_w{n}"), w.working, &format!("wheels.r_w.{n}")),
            seg(&format!("s_{n}"), w.tooth_thickness, &format!("wheels.s.{n}")),
            seg(&format!("s_a{n}"), w.tip_thickness, &format!("wheels.s_a.{n}")),
        ]);
    }
    // The arc of action: wheel 1 turns through g_α / r_b1 while the contact runs B1B2.
    let w1 = &p.wheels[0];
    out.extend([
        seg("a_w", p.centre_distance, "pair.a_w"),
        seg("N1N2", p.line_of_action, ""),
        seg("g_alpha", p.active_length, "pair.g_alpha"),
        seg("arc_B1B2", p.active_length * w1.working / w1.base, ""),
        seg("p", p.pitch, "pair.p"),
        seg("p_b", p.base_pitch, "pair.p_b"),
        seg("h", p.tooth_height, "pair.h"),
    ]);
    out
}

/// The planetary views' radii and the carrier's arm, drawn at μ_l `mu` (m/mm).
pub fn planetary(s: &Stage, module: f64, mu: f64, part: &str, answers: &AnswerKeys) -> Vec<Segment> {
    let scale = mm(mu);
    let r = |z: u32| module * f64::from(z) / 2.0;
    let seg = |name: &str, value: f64| {
        let key = ascii_key(name);
        Segment::new(format!("{part}.{key}"), name, mm(value), "mm", scale)
            .answering(&format!("planetary.{key}"), answers)
    };
    // The note's names: a double planet's second gear is 2′.
    let names: &[&str] = if s.z.len() == 4 { &["1", "2", "2′", "3"] } else { &["1", "2", "3"] };
    let mut out: Vec<Segment> = names.iter().zip(&s.z).map(|(n, &z)| seg(&format!("r_{n}"), r(z))).collect();
    out.push(seg("a_H", r(s.z[0]) + r(s.z[1])));
    out
}
