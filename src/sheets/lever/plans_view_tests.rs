//! The plan view's label lines.
use super::*;

#[test]
fn names_of_one_point_stack_as_one_chain() {
    let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert_eq!(lines(&names(&["p", "b"])), ["p=b"]);
    assert_eq!(lines(&names(&["p", "b", "s3", "c", "s4", "s5", "d"])), ["p=b=s3=", "c=s4=s5=", "d"]);
    assert_eq!(lines(&names(&["b", "d", "s4", "s5"])), ["b=d=", "s4=s5"]);
    assert_eq!(lines(&names(&["a"])), ["a"]);
    assert!(lines(&names(&["p", "b", "s3", "c"])).iter().all(|l| !l.starts_with('=')));
}

/// A label as its runs' texts in order, each subscript in brackets: "n[BA]=b=".
fn runs_of(t: &LabelText) -> String {
    let mut out = t.main.clone();
    for (sub, tail) in std::iter::once((&t.sub, &t.tail)).chain(t.then.iter().map(|(s, t)| (s, t))) {
        if !sub.is_empty() {
            out.push_str(&format!("[{sub}]"));
        }
        out.push_str(tail);
    }
    out
}

#[test]
fn every_names_index_is_a_subscript_a_normals_pair_and_a_points_digits() {
    let runs = |l: &str| runs_of(&subscripted(l));
    assert_eq!(runs("n_BA"), "n[BA]");
    assert_eq!(runs("a=n_BA"), "a=n[BA]");
    assert_eq!(runs("n_BA=b="), "n[BA]=b=");
    assert_eq!(runs("p=b=s3="), "p=b=s[3]=");
    assert_eq!(runs("d=s4=s5"), "d=s[4]=s[5]", "two subscripts on one line");
    assert_eq!(runs("a3=n_O3O1=k"), "a[3]=n[O3O1]=k", "a pair's names with digits");
    assert_eq!(runs("b=k"), "b=k");
    assert_eq!(runs("b'=c1x"), "b'=c1x", "an index is digits only");
    let t = subscripted("d=s4=s5");
    assert_eq!((t.main.as_str(), t.sub.as_str(), t.tail.as_str()), ("d=s", "4", "=s"));
    let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let one: Vec<_> = label_lines(&names(&["a", "n_BA", "n_CD"])).iter().map(runs_of).collect();
    assert_eq!(one, ["a=n[BA]=n[CD]"], "three names a line, subscripted or not");
}

#[test]
fn packed_cells_fill_the_body_in_order_without_overlap() {
    let body = Rect::new(0.0, 0.0, 200.0, 100.0);
    let cells = pack(&[(60.0, 40.0), (80.0, 30.0), (50.0, 45.0), (90.0, 20.0)], body).expect("fits");
    for (i, a) in cells.iter().enumerate() {
        assert!(a.x0 >= 0.0 && a.x1 <= 200.0 + 1e-9 && a.y1 <= 100.0 + 1e-9, "{a:?}");
        for b in &cells[i + 1..] {
            assert!(a.intersect(*b).area() <= 1e-9, "{a:?} {b:?}");
        }
    }
    assert!(cells[3].y0 > cells[0].y0, "the fourth cell starts a row");
    assert!(pack(&[(60.0, 140.0)], body).is_none());
}

/// `n` square plans of side `small` (plan units) and one `ratio` times as large, sized in
/// a 300 × 250 mm region.
fn sized(n: usize, small: f64, ratio: f64) -> (Sizing, Vec<f64>) {
    let square = |side: f64| Rect::new(0.0, 0.0, side, side);
    let mut boxes = vec![square(small); n];
    boxes.push(square(small * ratio));
    let measured = PlanBoxes { labels: vec![10.0; boxes.len()], boxes: boxes.clone() };
    let sizing = size_plans(Rect::new(0.0, 0.0, 300.0, 250.0), &measured, 20.0);
    let sides = boxes.iter().zip(&sizing.mu).map(|(b, mu)| b.width() / mu).collect();
    (sizing, sides)
}

/// The small plans at 22.5 mm, under the own scale's 25 mm but measurable, keep the
/// large plan's scale (they had one of their own before).
#[test]
fn plans_seven_times_apart_keep_one_scale_and_are_measurable() {
    let (sizing, sides) = sized(8, 0.09, 7.0);
    assert_eq!(sizing.own_count(), 0, "{:?}", sizing.mu);
    assert!(sides[..8].iter().all(|&s| (MEASURABLE_PLAN..MIN_PLAN).contains(&s)), "{sides:?}");
    assert!((sides[8] / sides[0] - 7.0).abs() < 1e-9, "{sides:?}");
}

#[test]
fn only_a_plan_a_hundred_times_the_rest_leaves_the_common_scale() {
    let (sizing, sides) = sized(8, 0.1, 100.0);
    assert_eq!(sizing.own_count(), 1, "{:?}", sizing.mu);
    assert!(sizing.own(8), "the large plan has its own μ: {:?}", sizing.mu);
    assert!(sides[..8].iter().all(|&s| s >= MIN_PLAN), "{sides:?}");
    assert!(sides[8] <= MAX_PLAN + 1e-9, "{sides:?}");
}
