//! Sheet 3's notes under the diagrams, in the sheet's language.

use super::DIVISIONS;
use super::labels::CamWords;
use crate::cams::follower::Follower;
use crate::cams::laws::Law;
use crate::cams::{CamWarning, Design};
use crate::drawing::fmt;
use crate::num::units::mm;
use crate::project::CamProject;

/// The notes under the diagrams: the phases, the integration, the nomogram's and the
/// profile's accuracy, the roller, the user's assumptions; `errors` are the integration's
/// (percent of the lift and of the analog's peak) with its chords a division.
pub fn sheet_notes(
    p: &CamProject,
    (errors, chords): ((f64, f64), usize),
    deviation: f64,
    words: &CamWords,
) -> Vec<String> {
    let (l, lang) = (words.sheet, words.lang);
    let d = &p.design;
    let pr = &d.spec.program;
    // Whole degrees as the file gives them (70°, not 70,00°).
    let deg = |x: f64| fmt::trimmed(x.to_degrees(), lang);
    let (kind, q, dq) = match d.spec.follower {
        Follower::Translating => (l.follower_translating(), "s", "ds/dφ"),
        Follower::Rocker { .. } => (l.follower_rocker(), "β", "dβ/dφ"),
    };
    let mut out = vec![
        format!(
            "{kind}. {}",
            l.phases(&deg(pr.rise), &deg(pr.far_dwell), &deg(pr.ret), &deg(pr.rise + pr.far_dwell + pr.ret))
        ),
        {
            let (es, ev) = (fmt::value(errors.0, lang), fmt::value(errors.1, lang));
            let n = DIVISIONS.to_string();
            if chords > 1 {
                l.integration_note_chords(&n, &chords.to_string(), q, dq, &es, &ev)
            } else {
                l.integration_note(&n, q, dq, &es, &ev)
            }
        },
        l.nomogram_note(&allowed_angles(d, words)),
    ];
    if d.roller == 0.0 {
        let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
        out.push(if rocker { l.knife_note_rocker() } else { l.knife_note() }.to_string());
    } else {
        out.push(l.profile_note(&fmt::bound_above(deviation * 1e6, lang)));
    }
    // What the build warns of the roller, the sheet says too: a sheet handed in must not
    // hide that its roller is not the course's.
    let v = |x: f64| fmt::value(x, lang);
    for w in &d.warnings {
        out.push(match *w {
            CamWarning::RollerBelowCourse { r, rho_min, .. } => l.roller_reduced(&v(mm(r)), &v(mm(rho_min))),
            CamWarning::RollerOutsideCourse { r, r_min } => {
                l.roller_outside(&v(mm(r)), &v(r / r_min), &v(mm(0.25 * r_min)), &v(mm(0.4 * r_min)))
            }
            CamWarning::RollerNearCurvature { r, rho_min } => l.roller_near_curvature(&v(mm(r)), &v(mm(0.8 * rho_min))),
        });
    }
    for (k, law) in [&p.laws.0, &p.laws.1].into_iter().enumerate() {
        if let Law::Custom(c) = law
            && (k == 0 || p.laws.0 != p.laws.1)
        {
            let corners: Vec<String> =
                c.corners().map(|(x, a)| format!("({}; {})", fmt::value(x, lang), fmt::value(a, lang))).collect();
            let mut note = l.law_custom_note(&law_name(p, law, words), &corners.join(", "));
            // The return runs the law backwards: its acceleration analog has the opposite sign.
            if k == 1 || p.laws.0 == p.laws.1 {
                note.push_str(l.law_custom_return());
            }
            out.push(note);
        }
    }
    out.extend(p.assumptions.iter().map(|a| a.get(lang).to_string()));
    out
}

/// The allowed pressure angle as the note states it: one value, or each phase's.
fn allowed_angles(d: &Design, words: &CamWords) -> String {
    let deg = |x: f64| format!("{}°", fmt::trimmed(x.to_degrees(), words.lang));
    let a = &d.spec.allowed;
    if a.rise == a.ret { deg(a.rise) } else { words.sheet.angles_two(&deg(a.rise), &deg(a.ret)) }
}

/// A law's name on the sheet: the built-in law's in the sheet's language; for a law of the
/// project's table, the name the file gives, else the replaced law's, else its key.
pub fn law_name(p: &CamProject, law: &Law, words: &CamWords) -> String {
    let l = words.sheet;
    match law {
        Law::Standard(s) => l.law(*s).to_string(),
        Law::Custom(c) => match p.law_names.iter().find(|(k, _)| k == c.key()) {
            Some((_, name)) => name.get(words.lang).to_string(),
            None => c.replaces().map_or_else(|| c.key().to_string(), |s| l.law(s).to_string()),
        },
    }
}

/// The title over the diagrams: the law's name (or both phases' laws).
pub(super) fn laws_title(p: &CamProject, words: &CamWords) -> String {
    let l = words.sheet;
    let rocker = matches!(p.design.spec.follower, Follower::Rocker { .. });
    if p.laws.0 == p.laws.1 {
        let name = law_name(p, &p.laws.0, words);
        if rocker { l.laws_title_rocker(&name) } else { l.laws_title(&name) }
    } else {
        l.laws_title_two(&law_name(p, &p.laws.0, words), &law_name(p, &p.laws.1, words))
    }
}
