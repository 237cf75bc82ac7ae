//! The rocker's swing angle ψ, dimensioned at its pivot between its two extreme positions
//! (positions 0 and the other extreme), as the course's drawings of a crank-rocker or a
//! kulisa give it beside the slider's stroke H.

use super::{MechanismView, SENSE_R};
use crate::drawing::fmt;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::path::on_circle;
use crate::drawing::place::Labels;
use crate::drawing::scene::Group;
use crate::drawing::symbols::{ARROW_LEN, angular_dimension, turn};
use crate::drawing::text::LabelText;
use crate::lever::linkage::Output;
use crate::num::math::{self, Norm};
use kurbo::{Point, Vec2};

/// The shares of the rocker's drawn length tried as the arc's radius: the arc crosses every
/// drawn position of the rocker at any of them, and the one crossing fewest other lines is
/// taken (the nearest the pivot of those at least [`ARC_READ`] long).
const RADII: [f64; 4] = [0.35, 0.5, 0.65, 0.8];

/// The least arc between the arrowheads' tips, mm: two heads and a gap.
const ARC_MIN: f64 = 2.0 * ARROW_LEN + 2.0;
/// An arc shorter than this is taken only where every longer one crosses more lines, mm: a
/// small swing's arc near the pivot sits where the rocker's positions crowd (the jaw
/// crusher's ψ = 7.8° was 11 mm long among them at a third of the rocker's length).
const ARC_READ: f64 = 20.0;

/// The swing angle's arc with its arrowheads and its value, if the output is a rocker with
/// two extreme positions drawn and the arc has room for its arrows.
pub(super) fn swing(v: &MechanismView, g: &mut Group, labels: &mut Labels) -> Option<()> {
    let Output::Rocker { link } = v.m.output else { return None };
    let pivot = v.m.frame.iter().find(|(id, _)| v.m.links[link].points.contains(id))?;
    let first = v.k.positions.first().filter(|p| p.extreme)?;
    let other = v.k.positions.iter().skip(1).find(|p| p.extreme)?;
    let c = v.view.p(pivot.1);
    let dirs = [first, other].map(|p| v.view.dir(p.state.links[link].dir));
    let (from, to) = (dirs[0] / dirs[0].norm(), dirs[1] / dirs[1].norm());
    let (a0, sweep) = turn(from, to);
    // The rocker's drawn length: its farthest point from the pivot over the positions.
    let reach =
        v.k.positions
            .iter()
            .flat_map(|p| v.m.links[link].points.iter().map(move |&id| (p.state.points[id].p - pivot.1).norm()))
            .fold(0.0, f64::max);
    let length = v.view.len(reach);
    let inside = g.region.inflate(-2.0, -2.0);
    let drawn = Obstacles::of_items(&g.items);
    let crossings = |r: f64| {
        let pts: Vec<Point> = (0..=24).map(|k| on_circle(c, r, a0 + sweep * f64::from(k) / 24.0)).collect();
        let fits = pts.iter().all(|&p| inside.contains(p));
        fits.then(|| drawn.hits_polyline(&pts))
    };
    let r = RADII
        .iter()
        .map(|s| s * length)
        .filter(|&r| r >= SENSE_R.1 + 3.0 && r * sweep.abs() >= ARC_MIN)
        .filter_map(|r| crossings(r).map(|n| (n, r * sweep.abs() < ARC_READ, r)))
        .min_by(|a, b| (a.0, a.1).cmp(&(b.0, b.1)).then(a.2.total_cmp(&b.2)))?
        .2;
    angular_dimension(g, c, (from, to), r, ARC_READ);
    let psi = sweep.abs().to_degrees();
    let mid = a0 + sweep / 2.0;
    // At one precision with the sheet's other dimensions (0,01 at most, fewer where exact:
    // ψ = 60°), not four significant digits (7,777° beside 40,26° and 60,00°).
    let value = format!(" = {}°", fmt::dimension(psi, v.words.lang));
    labels.add(
        on_circle(c, r, mid),
        Vec2::new(math::cos(mid), math::sin(mid)),
        LabelText::new("ψ", "").with_tail(value),
        3.5,
    );
    Some(())
}
