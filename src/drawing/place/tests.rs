//! The placer's unit tests: each builds a small drawing and checks where its labels went.
use super::sides::NEARER_BY;
use super::*;
use crate::drawing::layout;
use crate::drawing::obstacles::rect_segment_distance;
use crate::drawing::scene::{Item, Text};
use crate::num::math::{self, Norm};

/// A label asked for inside a ring of discs (rollers round a profile) is placed outside
/// every disc, though no stroke bounds them.
/// The layout measure of a 100 × 100 mm scene of the one group `g` finds nothing.
fn assert_clean(g: Group) {
    let l = layout::measure(&layout::tests::scene(g.items));
    assert!(l.is_clean(), "{l:?}");
}

#[test]
fn labels_keep_out_of_the_discs_they_are_given() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    let mut labels = Labels::new();
    let discs: Vec<(Point, f64)> =
        (0..6).map(|k| (Point::new(50.0, 50.0) + math::from_angle(k as f64) * 6.0, 7.0)).collect();
    for &(c, r) in &discs {
        labels.keep_out(c, r);
    }
    labels.add_text(Point::new(50.0, 50.0), Vec2::ZERO, "12", 2.5);
    assert_eq!(labels.place(&mut g, region), vec![true]);
    let text = g.texts().next().unwrap().bbox();
    for (c, r) in discs {
        let nearest = Point::new(c.x.clamp(text.x0, text.x1), c.y.clamp(text.y0, text.y1));
        assert!((nearest - c).norm() >= r, "the label {text:?} enters the disc at {c:?}");
    }
}

/// A line's name stands off on a leader that starts on the line itself (not short of
/// it) and ends on the name's box, the line not counted as crossed.
#[test]
fn a_lines_name_has_a_leader_from_the_line() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    let on = Point::new(50.0, 50.0);
    g.line(Point::new(10.0, 50.0), Point::new(90.0, 50.0), crate::drawing::scene::MAIN);
    let mut labels = Labels::new();
    labels.add_line_name(on, Vec2::new(0.0, -1.0), LabelText::new("profile", ""), 2.5, 0);
    assert_eq!(labels.place(&mut g, region), vec![true]);
    let text = g.texts().next().unwrap().bbox();
    let leader = g.items.last().and_then(|i| match i {
        Item::Path { path, .. } => Some((path.start, path.end())),
        _ => None,
    });
    let (a, b) = leader.expect("a leader");
    assert!((a - on).norm() < 1e-9, "the leader starts at {a:?}, off the line");
    assert!(text.inflate(0.6, 0.6).contains(b) && text.y1 < on.y, "{b:?} {text:?}");
    assert!((b - a).norm() >= LEADER_FROM - 1e-9);
}

/// A label with further spots is set beside a further one, without a leader, when the
/// first is walled in for a leader's length round (an arrow's name beside its tip rather
/// than off on a long leader from its middle).
#[test]
fn a_label_walled_in_at_its_first_spot_goes_to_a_further_one() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let (first, further) = (Point::new(30.0, 50.0), Point::new(70.0, 50.0));
    for with_further in [false, true] {
        let mut g = Group::new("g", region);
        // Circles round the first spot, 2 mm apart out to 12 mm: no box fits near it.
        for k in 1..=6 {
            g.circle(first, 2.0 * k as f64, THIN);
        }
        let mut labels = Labels::new();
        let label = LabelText::new("P", "M4");
        if with_further {
            labels.add_at_any(&[(first, Vec2::new(0.0, -1.0)), (further, Vec2::new(0.0, -1.0))], label, 3.5);
        } else {
            labels.add(first, Vec2::new(0.0, -1.0), label, 3.5);
        }
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let text = g.texts().next().unwrap().bbox();
        let near_further = (text.center() - further).norm() < 8.0;
        assert_eq!(near_further, with_further, "{text:?}");
        let leaders = g.items.iter().filter(|i| matches!(i, Item::Path { .. })).count();
        assert_eq!(leaders, if with_further { 0 } else { 1 }, "a leader only from the walled-in spot");
    }
}

/// Position numbers on neighbouring points stand a space apart, not 0.25 mm: "17" and
/// "16" side by side must not read as "17 16" run together.
#[test]
fn position_numbers_keep_a_space_between_them() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    // The second point at every distance from 1 to 6 mm from the first.
    for k in 0..=50 {
        let mut g = Group::new("g", region);
        // Lines under and over the anchors (and 2 mm strips beyond them) keep both
        // numbers in one row, side by side (a row [`CLEAR`] from each line).
        for y in [41.5, 43.5, 45.5, 51.0, 53.0, 55.0] {
            g.line(Point::new(10.0, y), Point::new(90.0, y), THIN);
        }
        let mut labels = Labels::new();
        let second = 51.0 + 0.1 * k as f64;
        labels.add_text_ranked(Point::new(50.0, 50.0), Vec2::new(0.0, -1.0), "17", 2.5, NUMBERS_RANK);
        labels.add_text_ranked(Point::new(second, 50.0), Vec2::new(0.0, -1.0), "16", 2.5, NUMBERS_RANK);
        assert_eq!(labels.place(&mut g, region), vec![true, true], "at {second}");
        let boxes: Vec<Rect> = g.texts().map(Text::bbox).collect();
        let (a, b) = (boxes[0], boxes[1]);
        assert!(a.y1 <= 50.5 && a.y0 >= 45.5 && b.y1 <= 50.5 && b.y0 >= 45.5, "at {second}: {a:?} {b:?}");
        let apart = (b.x0 - a.x1).max(a.x0 - b.x1);
        assert!(apart >= LABEL_GAP, "at {second}: {apart} mm between {a:?} and {b:?}");
    }
}

/// A stacked label is placed by the box of all its lines: between two lines 8 mm apart
/// where one line of 3.5 mm letters would fit but two do not, it goes elsewhere, and
/// nothing crosses any of its lines; the lines stand in order, one centre.
#[test]
fn a_stacked_label_keeps_every_line_clear() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    for y in [46.0, 54.0] {
        g.line(Point::new(0.0, y), Point::new(100.0, y), THIN);
    }
    let mut labels = Labels::new();
    let lines = ["p=b=s3=".to_string(), "c=s4=s5".to_string()];
    labels.add_text_lines(Point::new(50.0, 50.0), Vec2::new(1.0, 0.0), &lines, 3.5);
    labels.place(&mut g, region);
    let texts: Vec<&Text> = g.texts().collect();
    assert_eq!(texts.iter().map(|t| t.text.as_str()).collect::<Vec<_>>(), lines);
    let (a, b) = (texts[0].bbox(), texts[1].bbox());
    assert!(b.y0 >= a.y1 - 1.0 && (a.center().x - b.center().x).abs() < 1e-9, "{a:?} {b:?}");
    assert_clean(g);
}

/// A leader stops short of its label's letters: a line touching the letters reads as
/// part of them ("α = 45°" with a stroke into the 4).
#[test]
fn a_leader_stops_short_of_its_label() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    let c = Point::new(50.0, 50.0);
    // A disc kept clear round the anchor puts the label beyond the leader's distance.
    let mut labels = Labels::new();
    labels.keep_out(c, 8.0);
    labels.add_text(c, Vec2::new(0.0, 1.0), "45,00°", 3.5);
    assert_eq!(labels.place(&mut g, region), vec![true]);
    let text = g.texts().next().unwrap().bbox();
    let end = g
        .items
        .iter()
        .find_map(|i| match i {
            Item::Path { path, .. } => Some(path.end()),
            _ => None,
        })
        .expect("a leader");
    let gap = (Point::new(end.x.clamp(text.x0, text.x1), end.y.clamp(text.y0, text.y1)) - end).norm();
    assert!(gap >= 0.4, "the leader ends {gap} mm from {text:?}");
}

/// A short side's name is not set beside its long neighbour, where it would read as that
/// side's name (the worked example's enlargement K had "Rᵗ24" beside G4, its own side
/// the short slanted one at the top): each name stands nearer its own side.
#[test]
fn a_sides_name_stands_nearer_its_own_side_than_its_neighbours() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    let (top, low, bottom) = (Point::new(50.0, 30.0), Point::new(47.5, 40.0), Point::new(50.0, 60.0));
    let sides = [(low, top), (top, bottom)];
    let mut labels = Labels::new();
    for ((a, b), (main, sub)) in sides.into_iter().zip([("R", "t24"), ("G", "4")]) {
        g.line(a, b, crate::drawing::scene::VECTOR);
        labels.add_side((a, b), (b - a).turn_90(), LabelText::new(main, sub), 3.5);
    }
    // The stubs where the run joins the polygon.
    g.line(Point::new(42.0, 41.0), low, THIN);
    g.line(bottom, Point::new(45.0, 62.0), THIN);
    assert_eq!(labels.place(&mut g, region), vec![true, true]);
    let boxes: Vec<Rect> = g.texts().map(Text::bbox).collect();
    for (k, own) in sides.iter().enumerate() {
        let other = sides[1 - k];
        let (d_own, d_other) = (rect_segment_distance(boxes[k], *own), rect_segment_distance(boxes[k], other));
        assert!(
            d_own + NEARER_BY <= d_other,
            "label {k} at {:?}: {d_own} mm from its side, {d_other} from the other",
            boxes[k]
        );
    }
    assert_clean(g);
}

#[test]
fn labels_keep_off_lines_crossing_at_their_anchor_and_off_each_other() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    let c = Point::new(50.0, 50.0);
    // Eight lines radiating from the anchor leave only narrow sectors.
    for k in 0..8 {
        let d = math::from_angle(k as f64 * std::f64::consts::FRAC_PI_4 + 0.2) * 40.0;
        g.line(c, c + d, THIN);
    }
    let mut labels = Labels::new();
    for name in ["A", "B", "C", "S", "D"] {
        labels.add(c, Vec2::new(1.0, -1.0), LabelText::new(name, "2"), 5.0);
    }
    let placed = labels.place(&mut g, region);
    assert!(placed.iter().all(|&clear| clear), "{placed:?}");
    assert_clean(g);
}

/// A pivot in a fan of thin lines (its crank's other positions), walled in by a thick line
/// so that every free spot is far off: with the fan breakable, its letter stands beside the
/// pivot on no leader, the lines it stands on are interrupted for it (none meets its box;
/// their pieces outside it are all still drawn) and the measure finds nothing; with the same
/// lines not breakable, it hangs off on a long leader as before.
#[test]
fn a_label_in_a_fan_of_breakable_lines_stands_beside_its_point_and_breaks_them() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let o = Point::new(50.0, 50.0);
    let fan = |g: &mut Group| {
        let start = g.mark();
        for k in 0..24 {
            g.line(o, o + math::from_angle(f64::from(k) * std::f64::consts::TAU / 24.0) * 30.0, THIN);
        }
        start
    };
    let place = |breakable: bool| {
        let mut g = Group::new("g", region);
        let start = fan(&mut g);
        if breakable {
            g.breakable_from(start);
        }
        let mut labels = Labels::new();
        labels.add(o, Vec2::new(1.0, -1.0), LabelText::new("O", ""), 5.0);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        g
    };
    let g = place(true);
    let text = g.texts().next().unwrap().bbox();
    let strokes: Vec<(Point, Point)> = g
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Path { path, .. } => Some((path.start, path.end())),
            _ => None,
        })
        .collect();
    assert!(strokes.iter().any(|&(a, _)| a != o), "some lines are interrupted for it");
    assert!(
        strokes.iter().all(|&(a, b)| !crate::drawing::obstacles::segment_meets_rect(a, b, text.inflate(1.0, 1.0))),
        "a piece within 1 mm of the label"
    );
    assert!(rect_segment_distance(text, (o, o)) < LEADER_FROM, "{text:?} is not beside {o:?}");
    assert!(strokes.iter().all(|&(a, _)| a == o || (a - o).norm() < 15.0), "a piece starts far out");
    // The pieces cover each line's whole length but the part in the label's box.
    let drawn: f64 = strokes.iter().map(|&(a, b)| (b - a).norm()).sum();
    assert!(drawn > 24.0 * 30.0 - 24.0 * 12.0 && drawn < 24.0 * 30.0, "{drawn}");
    assert_clean(g);
    let g = place(false);
    let text = g.texts().next().unwrap().bbox();
    assert!(rect_segment_distance(text, (o, o)) >= 25.0, "{text:?}: clear only beyond the fan");
}

/// A label whose only clean leader runs 70 mm down a channel between two lines (a force
/// polygon's small side named at the far end of its neighbours) stands instead just outside
/// the channel, its short leader across one of them.
#[test]
fn a_label_takes_a_short_leader_across_a_line_over_a_long_clean_one() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut g = Group::new("g", region);
    // A channel 9 mm wide, closed at its top, open at its bottom (y = 85); the label is
    // wider than the channel, and every box beside the anchor outside it is more than a
    // leader's least length off.
    g.path(
        vec![Point::new(45.5, 85.0), Point::new(45.5, 2.0), Point::new(54.5, 2.0), Point::new(54.5, 85.0)],
        false,
        THIN,
    );
    let anchor = Point::new(50.0, 6.0);
    let mut labels = Labels::new();
    labels.add(anchor, Vec2::new(0.0, 1.0), LabelText::new("R", "12").with_tail(" = 1234"), 3.5);
    assert_eq!(labels.place(&mut g, region), vec![true]);
    let leader = g.leaders.first().map(|&k| match &g.items[k] {
        Item::Path { path, .. } => (path.end() - path.start).norm(),
        _ => f64::NAN,
    });
    let leader = leader.expect("a leader out of the channel");
    assert!(leader < crossings::LONG, "a leader of {leader} mm");
    assert_clean(g);
}

/// A line's name whose first points are walled in takes a further point of its line
/// (`along`) where it stands near, rather than hang on a long leader across the walls (a
/// small cam's working profile named 56 mm off across the cam, task 4 variant 40 in
/// Russian); without such a point it stays off on the long leader.
#[test]
fn a_lines_name_walled_in_at_its_first_points_goes_along_its_line() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let (walled, open, up) =
        ([Point::new(20.0, 50.0), Point::new(40.0, 50.0)], Point::new(80.0, 50.0), Vec2::new(0.0, -1.0));
    for with_along in [false, true] {
        let mut g = Group::new("g", region);
        g.line(Point::new(5.0, 50.0), Point::new(95.0, 50.0), crate::drawing::scene::MAIN);
        // Circles round the first points, 2 mm apart out to 16 mm.
        for (c, k) in walled.iter().flat_map(|&c| (1..=8).map(move |k| (c, k))) {
            g.circle(c, 2.0 * k as f64, THIN);
        }
        let mut labels = Labels::new();
        let along = if with_along { vec![(open, up)] } else { Vec::new() };
        labels.add_line_name_at_any(&walled.map(|p| (p, up)), &along, LabelText::new("profile", ""), 2.5, 0);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let (a, b) = g
            .leaders
            .first()
            .map(|&k| match &g.items[k] {
                Item::Path { path, .. } => (path.start, path.end()),
                _ => panic!("a leader that is no line"),
            })
            .expect("a line's name has a leader");
        let long = (b - a).norm() >= LONG_LEADER;
        assert_eq!(long, !with_along, "a leader of {} mm from {a:?}", (b - a).norm());
        assert_eq!((a - open).norm() < 1e-9, with_along, "the leader starts at {a:?}");
    }
}

/// Two force arrows from one point (the worked example's G₃ and P_и3 at S₃): each name
/// stands nearer its own arrow than the other, or hangs on a leader to it — with the spots
/// beside each arrow asked plainly, "G₃" stood at P_и3's tip and read as its name.
#[test]
fn an_arrows_name_stands_nearer_its_own_arrow_than_its_twin() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let at = Point::new(50.0, 50.0);
    let arrows = [(Vec2::new(-0.8, 0.6), ("P", "и3")), (Vec2::new(0.0, 1.0), ("G", "3"))];
    let mut g = Group::new("g", region);
    // The link through the point, as the force drawing has it.
    g.line(Point::new(30.0, 30.0), Point::new(70.0, 70.0), crate::drawing::scene::MAIN);
    let mut labels = Labels::new();
    let segments: Vec<(Point, Point)> = arrows.iter().map(|&(d, _)| (at, at + d * 7.0)).collect();
    for (&(d, (main, sub)), &(start, _)) in arrows.iter().zip(&segments) {
        crate::drawing::symbols::vector(&mut g, start, start + d * 7.0, crate::drawing::scene::VECTOR);
        let n = d.turn_90();
        let along = |k: f64| start + d * (7.0 * k);
        let spots = [(along(0.55), n), (along(0.55), -n), (along(0.85), n), (along(0.85), -n), (along(0.25), n)];
        labels.add_side_at_any(&spots, (start, start + d * 7.0), LabelText::new(main, sub), 3.5);
    }
    let drawn = g.items.len();
    assert_eq!(labels.place(&mut g, region), vec![true, true]);
    let boxes: Vec<Rect> = g.texts().map(Text::bbox).collect();
    // A leader's far end on a box: that name is read along its leader.
    let leader_ends: Vec<Point> = (g.items[drawn..].iter())
        .filter_map(|i| match i {
            Item::Path { path, .. } => Some(path.end()),
            _ => None,
        })
        .collect();
    for (k, own) in segments.iter().enumerate() {
        let other = segments[1 - k];
        let (d_own, d_other) = (rect_segment_distance(boxes[k], *own), rect_segment_distance(boxes[k], other));
        let on_leader = leader_ends.iter().any(|&e| boxes[k].inflate(1.0, 1.0).contains(e));
        assert!(
            on_leader || d_own + NEARER_BY <= d_other,
            "name {k} at {:?}: {d_own} mm from its arrow, {d_other} from the other",
            boxes[k]
        );
    }
    assert_clean(g);
}

/// A value's statement set on the line of another text, a word's space from it, reads as
/// one phrase with it ("φ₁ = 150,0° 1" at a load diagram's axis, "α_п = 40° 2" beside a
/// nomogram's point): a label stating a value keeps `APART` heights off a text level with
/// it, and any label keeps as far off a statement already drawn. Each label's first spot is
/// free of lines and texts but 3 mm from the other text, and the measure counts the pair.
#[test]
fn a_statement_and_a_text_on_its_line_stand_apart() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let fixed = |text: &str| Text::new(Point::new(52.5, 51.3), text, 3.5, Anchor::Start);
    // The statement is the label, the text drawn; then the other way round.
    let cases = [
        ("1", LabelText::new("φ", "1").with_tail(" = 150,0°"), Vec2::new(-1.0, 0.0)),
        ("H = 100,0 mm", LabelText::new("ε", "4"), Vec2::new(-1.0, 0.0)),
    ];
    for (drawn, label, pref) in cases {
        let mut g = Group::new("g", region);
        g.text(fixed(drawn));
        let mut labels = Labels::new();
        labels.add(Point::new(50.0, 50.0), pref, label.clone(), 3.5);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let l = layout::measure(&layout::tests::scene(g.items));
        assert!(l.is_clean(), "{label:?} beside “{drawn}”: {:?}", l.problems);
    }
}

/// A position's number a word's space from a point's letter reads as the letter's index
/// («2 A»: the guide's A₂; a teacher read a crank's «2» 1.8 mm before «A»): a number kept
/// apart from taller texts ([`Labels::add_text_apart`]) stands off the letter's line
/// beside it, of either lettering height, and the measure finds the drawing clean; set as
/// a plain label, its first spot 3 mm before the letter, the measure counts the pair.
#[test]
fn a_position_number_stands_apart_from_a_points_letter() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    for (h, apart) in [(2.5, true), (3.5, true), (3.5, false)] {
        let mut g = Group::new("g", region);
        // The letter a label of its own, placed first (rank 0), as a mechanism's are.
        let mut labels = Labels::new();
        labels.add_text_ranked(Point::new(53.0, 50.0), Vec2::new(1.0, 0.0), "A", 5.0, 0);
        if apart {
            labels.add_text_apart(Point::new(50.0, 50.0), Vec2::new(-1.0, 0.0), "2", h, 2);
        } else {
            labels.add_text_ranked(Point::new(50.0, 50.0), Vec2::new(-1.0, 0.0), "2", h, 2);
        }
        assert_eq!(labels.place(&mut g, region), vec![true, true]);
        let mut scene = layout::tests::scene(g.items);
        scene.groups[0].id = "mechanism".into();
        let l = layout::measure(&scene);
        assert_eq!(l.texts_run_together, usize::from(!apart), "{h} mm, apart {apart}: {:?}", l.problems);
    }
}

/// A taller letter placed after a number kept apart from taller texts (a repair round
/// puts a label that found no clean spot first) keeps off the number's line beside it too,
/// wherever its first spot is.
#[test]
fn a_letter_placed_after_a_position_number_stands_apart_from_it() {
    let region = Rect::new(0.0, 0.0, 100.0, 100.0);
    let mut counts = Vec::new();
    for dy in [-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0] {
        let mut g = Group::new("g", region);
        let mut labels = Labels::new();
        labels.add_text_apart(Point::new(50.0, 50.0), Vec2::new(1.0, 0.0), "11", 2.5, 0);
        labels.add_text_ranked(Point::new(60.0, 50.0 + dy), Vec2::new(-1.0, 0.0), "B", 5.0, 1);
        assert_eq!(labels.place(&mut g, region), vec![true, true]);
        let mut scene = layout::tests::scene(g.items);
        scene.groups[0].id = "mechanism".into();
        counts.push(layout::measure(&scene).texts_run_together);
    }
    assert_eq!(counts, vec![0; counts.len()]);
}
