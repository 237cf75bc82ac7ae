//! The rack generation of wheel 1 (the course's «станочное зацепление»): the generating
//! rack (`gears::rack`) in the position where its middle tooth fills the space over the pole
//! P, its datum line shifted x·m from the rolling line that touches the pitch circle at P,
//! the line of generation through P at α to its foot N on the base circle, the wheel's
//! exact teeth (the outline this rack cuts) and its r, r_b, r_a, r_f circles, the pitch p,
//! the shift x·m and the tip round ρ dimensioned. Drawn in the sheet's largest room left
//! free once everything else is placed, at the largest GOST scale that fits it; left out
//! where no room holds it with the rack's pitch at least [`MIN_PITCH_MM`] or a label finds
//! no clean spot.

use super::clip::{clipped_line, visible_arc};
use super::labels::GearWords;
use super::teeth_view::{flank, teeth_path};
use crate::drawing::obstacles::Obstacles;
use crate::drawing::path::{Path, Seg, on_circle};
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, Anchor, Group, MAIN, Pen, THIN, Text};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::drawing::{fmt, scale, symbols};
use crate::gears::pair::Pair;
use crate::gears::rack::{Cutter, Piece};
use crate::gears::tooth::Outline;
use crate::num::math::{Norm, cos, sin};
use crate::num::units::mm;
use kurbo::{Arc, Point, Rect, Vec2};
use std::f64::consts::{FRAC_PI_2, PI};

/// The room's grid and least size, mm.
const CELL: f64 = 4.0;
const MIN_ROOM: (f64, f64) = (100.0, 70.0);
/// The least pitch of the rack on paper, mm: smaller, its rounds and dimensions crowd.
const MIN_PITCH_MM: f64 = 15.0;
/// Paper mm round the picture: the title's two lines and the legend of the datum and
/// rolling lines above (a name at a line's end took more width than the rack), the pitch's
/// dimension over the rack, margins either side (the x·m dimension's value left), below.
const TITLE: f64 = 11.0;
const LEGEND_LINE: f64 = 4.5;
const OVER: f64 = 9.0;
const SIDE: f64 = 4.0;
const BELOW: f64 = 2.0;
/// The legend's line samples, mm long.
const SAMPLE: f64 = 24.0;
/// The rack's body above its spaces' root line, in modules.
const BODY: f64 = 1.2;
/// The most rack teeth either side of the middle one: past them N is too far from P for a
/// picture of the teeth (a wheel of some 150 teeth), and the picture is left out.
const MOST_TEETH: i32 = 8;

/// The picture's extent in the wheel's world (centre at the origin, P at (0, r)) and what
/// it draws there.
struct Extent {
    world: Rect,
    /// Rack teeth either side of the middle one; the wheel's tooth centres (world angles).
    teeth: i32,
    centres: Vec<f64>,
    with_centre: bool,
    /// The wheel's index in the pair.
    wheel: usize,
}

/// The picture's extent, with the wheel's centre where `centre` allows and the wheel is
/// small enough for it.
fn extent(pair: &Pair, wheel: usize, c: &Cutter, o: &Outline, centre: bool) -> Option<Extent> {
    let w = &pair.wheels[wheel];
    let (a, p, m) = (c.alpha, c.pitch, pair.spec.module);
    let n_x = w.pitch * sin(a) * cos(a);
    let teeth = ((n_x / p + 0.3 - 0.5).ceil() as i32).max(1);
    if teeth > MOST_TEETH {
        return None;
    }
    let half = (f64::from(teeth) + 0.5) * p;
    // The wheel's centre where the picture is not then much taller than wide.
    let with_centre = centre && w.pitch <= 1.5 * half;
    let step = 2.0 * PI / f64::from(w.z);
    let centres: Vec<f64> = (-teeth..teeth)
        .map(|j| FRAC_PI_2 + (f64::from(j) + 0.5) * step)
        .filter(|&t| (t - FRAC_PI_2).abs() < 80f64.to_radians() && (w.tip * cos(t)).abs() < half - p / 2.0)
        .collect();
    let top = w.pitch + c.root + BODY * m;
    // The teeth as drawn, in the world (a view at 1 m per mm, y turned down).
    let low_teeth = -teeth_path(View::new(Point::ZERO, 1.0), Vec2::ZERO, o, &flank(o).0, &centres).bbox().y1;
    let n_y = w.pitch - w.pitch * sin(a) * sin(a);
    let bottom = if with_centre { -1.5 * m } else { low_teeth.min(n_y).min(w.root) - m };
    // The lines run a quarter pitch past the rack's ends.
    let ext = 0.25 * p;
    Some(Extent { world: Rect::new(-half - ext, bottom, half + ext, top), teeth, centres, with_centre, wheel })
}

/// The datum line (dash-dotted, as a centre line) and the rolling line (thin) with their
/// heights over the rolling line and names, for the picture and its legend: one line,
/// dash-dotted, where they coincide.
fn line_names(c: &Cutter, words: &GearWords) -> Vec<(f64, Pen, String)> {
    let l = words.sheet;
    if c.datum.abs() < 1e-12 {
        vec![(0.0, AXIS, l.datum_rolling_line().to_string())]
    } else {
        vec![(c.datum, AXIS, l.datum_line().to_string()), (0.0, THIN, l.rolling_line().to_string())]
    }
}

/// The picture in the largest room `obstacles` leave in `area`, as its own group: first
/// with room kept left of the lines for the x·m value, else without (its label then finds
/// a spot inside the picture, on a leader).
pub(super) fn draw(
    obstacles: &Obstacles,
    area: Rect,
    (pair, wheel): (&Pair, usize),
    o: &Outline,
    words: &GearWords,
) -> Option<Group> {
    let c = Cutter::of(&pair.spec, &pair.wheels[wheel]);
    let value_room = if c.datum.abs() > 1e-12 { shift_text(&c, words).width(3.5) + 4.0 } else { 0.0 };
    // The whole small wheel where that leaves its teeth large enough to read (at 1:1 its
    // x·m of a millimetre and the labels at P piled up), else its teeth by the rack alone.
    let centred = extent(pair, wheel, &c, o, true)?;
    let tries = match centred.with_centre {
        true => vec![(centred, READABLE_PITCH_MM), (extent(pair, wheel, &c, o, false)?, MIN_PITCH_MM)],
        false => vec![(centred, MIN_PITCH_MM)],
    };
    tries.iter().find_map(|(e, least_pitch)| {
        [value_room.max(SHIFT_ARROWS), SHIFT_ARROWS]
            .into_iter()
            .find_map(|left| attempt(obstacles, area, pair, o, words, (&c, e), (SIDE + left, *least_pitch)))
    })
}

/// The least pitch of the rack on paper where the whole wheel is drawn, mm.
const READABLE_PITCH_MM: f64 = 20.0;

/// Room left of the lines for the x·m dimension's arrows, mm.
const SHIFT_ARROWS: f64 = 4.0;
/// The room's own margin inside the free cells, mm.
const PAD: f64 = 2.0;
/// The frame's inset from the room's edge, mm.
const FRAME_IN: f64 = 0.5;

/// The picture with `left` mm kept left of its lines, where it fits at a pitch of at least
/// `least_pitch` mm and every label finds a spot.
fn attempt(
    obstacles: &Obstacles,
    area: Rect,
    pair: &Pair,
    o: &Outline,
    words: &GearWords,
    (c, e): (&Cutter, &Extent),
    (left, least_pitch): (f64, f64),
) -> Option<Group> {
    let names = line_names(c, words);
    let l = words.sheet;
    let legend_w = names.iter().map(|n| LabelText::new(format!("— {}", n.2), "").width(2.5) + SAMPLE + 6.0);
    let n = (e.wheel + 1).to_string();
    let title_w = LabelText::new(l.generation_title(&n), "").width(3.5) + 4.0;
    let least = (legend_w.fold(title_w, f64::max).max(MIN_ROOM.0), MIN_ROOM.1);
    let head = TITLE + LEGEND_LINE * names.len() as f64;
    let (side, high) = (left + SIDE, head + OVER + BELOW);
    let fit =
        |w: f64, h: f64| ((w - side - 2.0 * PAD) / e.world.width()).min((h - high - 2.0 * PAD) / e.world.height());
    // The room kept a little clear of what is round it (the cells see 1 mm round them).
    let cells = super::room::largest(obstacles, area, CELL, least, fit)?;
    let mu = scale::length_scale(1.0 / fit(cells.width(), cells.height()));
    let room = cells.inset(-PAD);
    if c.pitch / mu < least_pitch {
        return None;
    }
    let pic = Rect::new(room.x0 + left, room.y0 + head + OVER, room.x1 - SIDE, room.y1 - BELOW);
    let v = View::centred(e.world, pic, mu);
    let mut g = Group::new(format!("generation{n}"), room);
    // Framed: drawn in a room among the mesh's arcs, its own r, r_b, r_a, r_f circles would
    // read as theirs.
    let f = room.inflate(-FRAME_IN, -FRAME_IN);
    g.path(
        vec![Point::new(f.x0, f.y0), Point::new(f.x1, f.y0), Point::new(f.x1, f.y1), Point::new(f.x0, f.y1)],
        true,
        THIN,
    );
    g.text(Text::new(Point::new(room.x0 + 2.0, room.y0 + 5.0), l.generation_title(&n), 3.5, Anchor::Start));
    let sc = l.scale(&fmt::localise(&scale::ratio(mu), words.lang));
    g.text(Text::new(Point::new(room.x0 + 2.0, room.y0 + 10.0), sc, 2.5, Anchor::Start));
    for (i, (_, pen, name)) in names.iter().enumerate() {
        let base = room.y0 + TITLE + 2.5 + LEGEND_LINE * i as f64;
        let at = Point::new(room.x0 + 2.0, base - 1.0);
        g.writing_line(at, at + Vec2::new(SAMPLE, 0.0), *pen);
        g.text(Text::new(Point::new(at.x + SAMPLE + 2.0, base), format!("— {name}"), 2.5, Anchor::Start));
    }
    let start = g.mark();
    let mut labels = Labels::new();
    draw_rack(&mut g, v, c, pair.wheels[e.wheel].pitch, e.teeth, pair.spec.module);
    draw_wheel(&mut g, &mut labels, v, pic, pair, o, e);
    draw_lines(&mut g, &mut labels, v, &names, pair, e);
    dimensions(&mut g, &mut labels, v, c, pair, e, words);
    let placed = labels.place(&mut g, room);
    g.part_from(format!("generation{n}.drawing"), start);
    (!placed.contains(&false)).then_some(g)
}

/// A cutter piece on paper (the rack's frame lifted by r into the wheel's world).
fn push_piece(path: &mut Path, v: View, r: f64, piece: Piece) {
    let lift = Vec2::new(0.0, r);
    match piece {
        Piece::Line(_, b) => path.segs.push(Seg::Line(v.p(b + lift))),
        Piece::Arc { centre, radius, start, sweep } => {
            let arc = Arc::new(v.p(centre + lift), (v.len(radius), v.len(radius)), -start, -sweep, 0.0);
            path.segs.push(Seg::Arc(arc));
        }
    }
}

/// The rack: its teeth from the middle of the space left of the first to the middle of the
/// space right of the last, closed by its body.
fn draw_rack(g: &mut Group, v: View, c: &Cutter, r: f64, teeth: i32, m: f64) {
    let pieces: Vec<Piece> = (-teeth..=teeth).flat_map(|k| c.tooth(f64::from(k) * c.pitch)).collect();
    let half = (f64::from(teeth) + 0.5) * c.pitch;
    let lift = Vec2::new(0.0, r);
    let mut path = Path::new(v.p(Vec2::new(-half, c.root) + lift));
    for piece in pieces {
        push_piece(&mut path, v, r, piece);
    }
    let top = c.root + BODY * m;
    for q in [Vec2::new(half, top), Vec2::new(-half, top), Vec2::new(-half, c.root)] {
        path.segs.push(Seg::Line(v.p(q + lift)));
    }
    g.curve(path, MAIN);
}

/// The wheel's teeth, its circles (named at their left ends) and its centre where drawn.
fn draw_wheel(g: &mut Group, labels: &mut Labels, v: View, pic: Rect, pair: &Pair, o: &Outline, e: &Extent) {
    let (w, n) = (&pair.wheels[e.wheel], e.wheel + 1);
    let (fl, _, _) = flank(o);
    g.curve(teeth_path(v, Vec2::ZERO, o, &fl, &e.centres), MAIN);
    let oc = v.p(Vec2::ZERO);
    let set = [
        (w.tip, THIN, LabelText::new("r", format!("a{n}"))),
        (w.root, THIN, LabelText::new("r", format!("f{n}"))),
        (w.base, THIN, LabelText::new("r", format!("b{n}"))),
        (w.pitch, AXIS, LabelText::new("r", n.to_string())),
    ];
    for (r, pen, name) in set {
        if let Some((a0, sweep)) = visible_arc(oc, v.len(r), -FRAC_PI_2, pic) {
            g.curve(Path::arc(oc, v.len(r), a0, sweep), pen);
            // Named near the arc's left end, else near its right end: the circles crowd
            // together at one end of the inset where the other may have room.
            let at = |t: f64| on_circle(oc, v.len(r), a0 + sweep * t);
            let ends = [(at(0.04), Vec2::new(-1.0, 0.0)), (at(0.96), Vec2::new(1.0, 0.0))];
            labels.add_on_line_at_any(&ends, name, 3.5, 2);
        }
    }
    let top = v.p(Vec2::new(0.0, e.world.y1));
    clipped_line(g, top, Point::new(top.x, pic.y1), pic.inflate(0.0, 4.0), AXIS);
    if e.with_centre {
        g.dot(oc, 0.8);
        labels.add_ranked(oc, Vec2::new(1.0, 0.6), LabelText::new("O", n.to_string()), 3.5, 0);
    }
}

/// The datum and rolling lines, the line of generation P–N and α at P.
fn draw_lines(g: &mut Group, labels: &mut Labels, v: View, lines: &[(f64, Pen, String)], pair: &Pair, e: &Extent) {
    let w = &pair.wheels[e.wheel];
    let c = Cutter::of(&pair.spec, w);
    for &(y, pen, _) in lines {
        g.line(v.p(Vec2::new(e.world.x0, w.pitch + y)), v.p(Vec2::new(e.world.x1, w.pitch + y)), pen);
    }
    let a = c.alpha;
    let (pole, n) = (Vec2::new(0.0, w.pitch), Vec2::new(sin(a), cos(a)) * w.base);
    let (pp, np) = (v.p(pole), v.p(n));
    let along = (np - pp) / (np - pp).norm();
    g.line(pp - along * 8.0, np + along * 6.0, THIN);
    g.dot(pp, 0.7);
    g.dot(np, 0.6);
    labels.add_ranked(pp, Vec2::new(-1.0, 1.0), LabelText::new("P", ""), 3.5, 0);
    labels.add_ranked(np, Vec2::new(1.0, 0.3), LabelText::new("N", ""), 3.5, 0);
    let r = ((np - pp).norm() * 0.6).min(20.0);
    let at = symbols::angle_mark(g, pp, Vec2::new(1.0, 0.0), along, r);
    labels.add_on_line_at_any(&[(at, Vec2::new(1.0, 0.4))], LabelText::new("α", ""), 3.5, 1);
}

/// The shift's value, "x·m = 1,8".
fn shift_text(c: &Cutter, words: &GearWords) -> LabelText {
    LabelText::new("x·m", "").with_tail(format!(" = {}", fmt::dimension(mm(c.datum), words.lang)))
}

/// The pitch p over the rack between two right flanks on the datum line, the shift x·m
/// from the rolling line to the datum line at the lines' left ends, and the tip round ρ.
fn dimensions(g: &mut Group, labels: &mut Labels, v: View, c: &Cutter, pair: &Pair, e: &Extent, words: &GearWords) {
    let (w, lang, m) = (&pair.wheels[e.wheel], words.lang, pair.spec.module);
    let lift = Vec2::new(0.0, w.pitch);
    let (a, b) = (v.p(c.flank_on_datum(0.0) + lift), v.p(c.flank_on_datum(c.pitch) + lift));
    let over = v.p(Vec2::new(0.0, w.pitch + c.root + BODY * m)).y - 5.0;
    let mid = symbols::dimension(g, a, b, Vec2::new(0.0, over - a.y));
    let value = |x: f64| fmt::dimension(mm(x), lang);
    labels.add_ranked(
        mid,
        Vec2::new(0.0, -1.0),
        LabelText::new("p", "").with_tail(format!(" = {}", value(c.pitch))),
        3.5,
        1,
    );
    if c.datum.abs() > 1e-12 {
        let (d, r) = (v.p(Vec2::new(e.world.x0, w.pitch + c.datum)), v.p(Vec2::new(e.world.x0, w.pitch)));
        let mid = symbols::dimension(g, d, r, Vec2::new(-2.0, 0.0));
        labels.add_ranked(mid, Vec2::new(-1.0, if c.datum > 0.0 { 1.0 } else { -1.0 }), shift_text(c, words), 3.5, 1);
    }
    // The round at the tip of the tooth left of the middle one, at its middle (away from
    // P, N and α, which crowd the right), else the mirrored round right of the middle.
    let mid_round = |side: f64| {
        let centre = Vec2::new(side * (c.pitch + c.centre.x), c.centre.y) + lift;
        let a = -FRAC_PI_2 / 2.0 - c.alpha / 2.0;
        let on = centre + Vec2::new(side * cos(a), sin(a)) * c.rho;
        (v.p(on), Vec2::new(side, 1.0))
    };
    let rho = LabelText::new("ρ", "").with_tail(format!(" = {}", value(c.rho)));
    labels.add_ranked_at_any(&[mid_round(-1.0), mid_round(1.0)], rho, 3.5, 1);
}
