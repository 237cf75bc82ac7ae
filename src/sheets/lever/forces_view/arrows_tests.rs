//! Tests of `arrows.rs`: twins, arrows along links, the room they take.

use super::*;
use crate::drawing::path::Seg;
use kurbo::Rect;

/// An arrow 11° off the link through its point (3.7 mm of its shaft in the link's
/// line) is set beside the link on the side it leaves it toward, whichever way it
/// points along the link; 25° off, or leaving a block's outline 4 mm out at 11°, it is
/// seen and stays; along the link's line on past its end it is seen too, and stays on
/// its line of action through the joint.
#[test]
fn an_arrow_nearly_along_its_link_is_set_beside_it_on_the_side_it_leaves_toward() {
    let link = [(Point::new(-20.0, 0.0), Point::new(20.0, 0.0))];
    let dir = |deg: f64| Vec2::new(crate::num::math::cos(deg.to_radians()), crate::num::math::sin(deg.to_radians()));
    for deg in [11.0, -11.0, 169.0, -169.0] {
        let d = dir(deg);
        let side = beside_link(&link, Point::ZERO, d, (0.0, 15.0)).expect("set beside");
        assert!(side.dot(d).abs() < 1e-12, "{deg}°: across the arrow");
        assert!(side.y * d.y > 0.0, "{deg}°: toward the side the arrow leaves to, {side:?}");
    }
    assert_eq!(beside_link(&link, Point::ZERO, dir(25.0), (0.0, 15.0)), None);
    assert_eq!(beside_link(&link, Point::ZERO, dir(11.0), (4.0, 15.0)), None);
    let end = [(Point::new(-20.0, 0.0), Point::ZERO)];
    assert!(beside_link(&end, Point::ZERO, dir(177.0), (0.0, 15.0)).is_some(), "into the link from its end");
    assert_eq!(beside_link(&end, Point::ZERO, dir(3.0), (0.0, 15.0)), None, "on past the link's end");
    assert_eq!(beside_link(&end, Point::ZERO, dir(12.0), (0.0, 15.0)), None, "leaving the link's end");
}

/// Three forces at one point, two along one line and one a few degrees off it (as a
/// weight, an inertia force and a gas force at a piston): each arrow and its leader stay
/// on its own line of action through the point, where its moment about any point is
/// the force's, and no arrow lies on another.
#[test]
fn twin_forces_slide_along_their_lines_and_keep_their_arms() {
    let at = Point::new(50.0, 50.0);
    let forces = [Vec2::new(0.0, -300.0), Vec2::new(0.0, -120.0), Vec2::new(20.0, -200.0)];
    let view = View::new(Point::new(20.0, 80.0), 0.01);
    let spans = spans_drawn(view, at, &forces, None);
    // The second (same direction as the first) starts past the first's tip.
    assert!(spans[1].1 > spans[0].2, "{spans:?}");
}

/// Each arrow's unit direction on paper and the least and greatest distance along it
/// from the point of its shaft's ends, every end checked to lie on the force's line
/// through the point; and whether the room [`twin_rows`] gives them is the farthest
/// drawn.
fn spans_drawn(view: View, at: Point, forces: &[Vec2], push: Option<Push>) -> Vec<(Vec2, f64, f64)> {
    let kept = push.clone();
    let mut arrows =
        Arrows { view, links: Vec::new(), push, blocks: Vec::new(), drawn: Vec::new(), mu_f: 20.0, h: 2.5 };
    let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
    let mut labels = Labels::new();
    let mut spans = Vec::new();
    for &f in forces {
        let from = g.items.len();
        arrows.arrow(&mut g, &mut labels, at, f, LabelText::new("F", ""));
        let d = view.dir(f) / f.norm();
        // The shaft's ends (the leader along the line from the point is thin).
        let mut along: Vec<f64> = Vec::new();
        for item in &g.items[from..] {
            let Item::Path { path, pen } = item else { continue };
            let ends = std::iter::once(path.start).chain(path.segs.iter().filter_map(|s| match s {
                Seg::Line(p) => Some(*p),
                _ => None,
            }));
            for p in ends {
                assert!((p - at).cross(d).abs() < 1e-9, "{f:?}: {p:?} is off the line through the point");
                if *pen == VECTOR {
                    along.push((p - at).dot(d));
                }
            }
        }
        spans.push((d, along.iter().copied().fold(f64::INFINITY, f64::min), along.iter().copied().fold(0.0, f64::max)));
    }
    // The room a drawing sizes for them is where each arrow's far end is drawn.
    let rows = twin_rows(forces.iter().map(|&f| (at, view.dir(f))), kept.as_ref(), 20.0);
    assert_eq!(rows.len(), arrows.drawn.len());
    for (row, drawn) in rows.iter().zip(&arrows.drawn) {
        assert!((row.1 - drawn.1).norm() < 1e-9 && (row.2 - drawn.2).abs() < 1e-9, "{row:?} {drawn:?}");
    }
    spans
}

/// On the lever the smaller of two twins is drawn pushing, its tip at the point and its
/// shaft on the other side, where nothing lies there; a third along the first slides past
/// the first's tip. The second slides too where a line of the lever leaves the point on
/// the other side, where a force drawn later points that way, or where its shaft would
/// reach beyond the arrows slid.
#[test]
fn twins_push_from_the_free_side_and_slide_where_it_is_taken() {
    let at = Point::new(50.0, 50.0);
    let view = View::new(Point::new(20.0, 80.0), 0.01);
    let forces = [Vec2::new(0.0, -300.0), Vec2::new(0.0, -120.0), Vec2::new(20.0, -200.0)];
    let on_paper: Vec<(Point, Vec2)> = forces.iter().map(|&f| (at, view.dir(f) / f.norm())).collect();
    let push = |lines: Vec<(Point, Point)>, later: Option<Vec2>, within: Rect| Push {
        lines,
        points: vec![at],
        forces: on_paper.iter().copied().chain(later.map(|e| (at, e))).collect(),
        within,
        keep_lines: true,
    };
    let page = Rect::new(0.0, 0.0, 100.0, 100.0);
    let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), None, page)));
    assert!(spans[1].2.abs() < 1e-9 && spans[1].1 < -5.0, "the second pushes: {spans:?}");
    assert!(spans[2].1 > spans[0].2, "the third slides past the first: {spans:?}");
    // On paper y runs down: the forces point down the page and the pushing side is
    // above the point. A line from the point there, 6° off the second's line:
    let above = vec![(at, at + Vec2::new(3.0, -30.0))];
    let spans = spans_drawn(view, at, &forces, Some(push(above, None, page)));
    assert!(spans[1].1 > spans[0].2, "a line: the second slides: {spans:?}");
    // A force up the page at the point, drawn after them:
    let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), Some(Vec2::new(0.0, -1.0)), page)));
    assert!(spans[1].1 > spans[0].2, "a later force: the second slides: {spans:?}");
    // The arrows slid reach no higher than the point:
    let below = Rect::new(0.0, at.y, 100.0, 100.0);
    let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), None, below)));
    assert!(spans[1].1 > spans[0].2, "beyond the slid arrows' box: the second slides: {spans:?}");
}

/// The ends of the vector-pen shafts drawn since item `from`.
fn shafts(g: &Group, from: usize) -> Vec<(Point, Point)> {
    (g.items[from..].iter())
        .filter_map(|item| match item {
            Item::Path { path, pen } if *pen == VECTOR => match path.segs.last() {
                Some(Seg::Line(p)) => Some((path.start, *p)),
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// On a group's drawing a force at a link's end pointing into the link is drawn pushing,
/// its tip at the joint and its shaft on the link's line past the end; at a point inside
/// the link, where the link goes on past the point, it is set beside the link as before.
#[test]
fn an_arrow_into_its_link_at_the_links_end_pushes_from_outside() {
    let (a, b) = (Point::new(30.0, 50.0), Point::new(70.0, 50.0));
    let view = View::new(Point::new(0.0, 100.0), 1.0);
    let push = Push {
        lines: vec![(a, b)],
        points: vec![a, b],
        forces: vec![(a, Vec2::new(1.0, 0.0))],
        within: Rect::new(0.0, 0.0, 100.0, 100.0),
        keep_lines: false,
    };
    let mut arrows = Arrows {
        view,
        links: vec![(a, b)],
        push: Some(push),
        blocks: Vec::new(),
        drawn: Vec::new(),
        mu_f: 1.0,
        h: 3.5,
    };
    let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
    let mut labels = Labels::new();
    arrows.arrow(&mut g, &mut labels, a, Vec2::new(12.0, 0.0), LabelText::new("R", "n"));
    let [(start, tip)] = shafts(&g, 0)[..] else { panic!("one shaft") };
    assert!((start.y - a.y).abs() < 1e-9 && (tip.y - a.y).abs() < 1e-9, "on the link's line");
    assert!(start.x < a.x - 5.0 && tip.x <= a.x, "pushing from outside: {start:?} {tip:?}");
    // Inside the link (its middle), the link goes on past the point: beside it.
    let from = g.items.len();
    arrows.arrow(&mut g, &mut labels, a.midpoint(b), Vec2::new(12.0, 0.0), LabelText::new("P", ""));
    let [(start, tip)] = shafts(&g, from)[..] else { panic!("one shaft") };
    assert!(((start.y - a.y).abs() - BESIDE).abs() < 1e-9 && tip.x > start.x, "beside: {start:?} {tip:?}");
}

/// A second force at a point pointing opposite to the first is set beside it, off the
/// first's line (a thin line joins it to its point): drawn from the point both, they read
/// as one arrow with a head at each end.
#[test]
fn an_arrow_opposite_to_an_earlier_one_at_its_point_is_set_beside_it() {
    let at = Point::new(50.0, 50.0);
    let view = View::new(Point::new(0.0, 100.0), 1.0);
    let mut arrows =
        Arrows { view, links: Vec::new(), push: None, blocks: Vec::new(), drawn: Vec::new(), mu_f: 1.0, h: 3.5 };
    let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
    let mut labels = Labels::new();
    arrows.arrow(&mut g, &mut labels, at, Vec2::new(0.0, -10.0), LabelText::new("G", ""));
    let from = g.items.len();
    arrows.arrow(&mut g, &mut labels, at, Vec2::new(0.0, 10.0), LabelText::new("P", ""));
    let [(start, tip)] = shafts(&g, from)[..] else { panic!("one shaft") };
    assert!(((start.x - at.x).abs() - BESIDE).abs() < 1e-9 && start.x == tip.x, "beside: {start:?} {tip:?}");
    assert!(g.items[from..].iter().any(|i| matches!(i, Item::Path { pen, .. } if *pen == THIN)), "joined to its point");
}

/// Two forces on a slider's block the same way (an inertia force and a gas force along
/// the guide): the second pushes into the block from its other side; where a line lies
/// there, it leaves the outline beside the first, inside the block's width. Slid end to end
/// they read as one arrow with two heads.
#[test]
fn twins_at_a_block_push_from_its_other_side_or_leave_it_side_by_side() {
    let at = Point::new(50.0, 50.0);
    let view = View::new(Point::new(0.0, 100.0), 1.0);
    let block = (at, Vec2::new(1.0, 0.0), 5.0, 2.5);
    let twins = |g: &mut Group| {
        let mut arrows =
            Arrows { view, links: Vec::new(), push: None, blocks: vec![block], drawn: Vec::new(), mu_f: 1.0, h: 3.5 };
        let mut labels = Labels::new();
        let from = g.items.len();
        arrows.arrow(g, &mut labels, at, Vec2::new(-8.0, 0.0), LabelText::new("P", "i5"));
        arrows.arrow(g, &mut labels, at, Vec2::new(-20.0, 0.0), LabelText::new("P", "c5"));
        let drawn = shafts(g, from);
        let [first, second] = drawn[..] else { panic!("two shafts: {drawn:?}") };
        assert!(!g.items[from..].iter().any(|i| matches!(i, Item::Path { pen, .. } if *pen == THIN)), "no stub");
        (first, second)
    };
    let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
    let ((s1, t1), (s2, t2)) = twins(&mut g);
    assert!((s1.x - (at.x - 5.0)).abs() < 1e-9 && t1.x < s1.x && s1.y == at.y, "from the outline: {s1:?} {t1:?}");
    // (A shaft stops short of its tip, under the head.)
    assert!((at.x + 5.0..at.x + 8.0).contains(&t2.x) && s2.x > t2.x && t2.y == at.y, "pushing: {s2:?} {t2:?}");
    // A line right of the block (the guide's continuation, a rod): beside the first.
    let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
    g.line(Point::new(at.x + 6.0, at.y), Point::new(at.x + 40.0, at.y), THIN);
    let ((s1, _), (s2, t2)) = twins(&mut g);
    assert!((s2.x - (at.x - 5.0)).abs() < 1e-9 && t2.x < s2.x, "from the outline, leftward: {s2:?} {t2:?}");
    assert!((s2.y - at.y).abs() <= 2.5 && (s1.y - s2.y).abs() >= BLOCK_BESIDE_MIN - 1e-9, "side by side: {s2:?}");
}
