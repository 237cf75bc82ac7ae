//! The mesh's circles and lines clipped to its region: a wheel of hundreds of teeth has
//! circles far larger than the sheet, of which the view draws the part near the mesh.

use crate::drawing::obstacles::segment_meets_rect;
use crate::drawing::scene::{Group, Pen};
use kurbo::{Point, Rect};
use std::f64::consts::PI;

/// The largest arc of a circle (paper centre `c`, radius r) around paper angle `mid` that
/// stays inside `region` and [`TITLE_BLOCK_CLEARANCE`] clear of the title block (a mesh as
/// wide as the tables leave has the block in its region's corner), as (start, sweep) in
/// paper angles; sampled every 0.2°.
pub(super) fn visible_arc(c: Point, r: f64, mid: f64, region: Rect) -> Option<(f64, f64)> {
    let block = crate::drawing::frame::title_block_rect().inflate(TITLE_BLOCK_CLEARANCE, TITLE_BLOCK_CLEARANCE);
    // The stroke's half width inside too.
    let region = region.inflate(-STROKE_ROOM, -STROKE_ROOM);
    let inside = |a: f64| {
        let p = crate::drawing::path::on_circle(c, r, a);
        region.contains(p) && !block.contains(p)
    };
    if !inside(mid) {
        return None;
    }
    let step = 0.2f64.to_radians();
    let reach = |dir: f64| {
        let mut a = 0.0;
        while a + step < PI && inside(mid + dir * (a + step)) {
            a += step;
        }
        a
    };
    let (lo, hi) = (reach(-1.0), reach(1.0));
    Some((mid - lo, lo + hi))
}

/// Room a clipped line's or arc's end keeps from its region's edge for half its stroke, mm
/// (a 363-tooth wheel's tangent, clipped at the edge, had its stroke 0.4 mm over it).
const STROKE_ROOM: f64 = 0.5;

/// How far the circles' arcs stop short of the title block, mm (more than the 0.2° samples'
/// chords can cut a corner by on the sheet's largest circles).
const TITLE_BLOCK_CLEARANCE: f64 = 4.0;

/// A line from a to b clipped to `region` (nothing when it misses).
pub(super) fn clipped_line(g: &mut Group, a: Point, b: Point, region: Rect, pen: Pen) {
    let region = region.inflate(-STROKE_ROOM, -STROKE_ROOM);
    if !segment_meets_rect(a, b, region) {
        return;
    }
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, a.x - region.x0), (d.x, region.x1 - a.x), (-d.y, a.y - region.y0), (d.y, region.y1 - a.y)] {
        if p == 0.0 {
            continue;
        }
        let t = q / p;
        if p < 0.0 { t0 = t0.max(t) } else { t1 = t1.min(t) }
    }
    if t1 > t0 {
        g.line(a + d * t0, a + d * t1, pen);
    }
}
