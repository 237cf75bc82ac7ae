use super::*;
use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::Text;
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN};
use kurbo::Rect;

fn scene(items: Vec<Item>) -> Scene {
    let mut g = Group::new("velocity plans", Rect::new(0.0, 0.0, 100.0, 100.0));
    g.items = items;
    Scene { ink: Default::default(), name: "s".into(), width: 100.0, height: 80.0, title: "t".into(), groups: vec![g] }
}

fn dxf(s: &Scene, v: DxfVersion) -> String {
    String::from_utf8(write(s, v).unwrap()).unwrap()
}

/// The values of every `code` pair after the first `0 / kind`.
fn values<'a>(dxf: &'a str, kind: &str, code: &str) -> Vec<&'a str> {
    let lines: Vec<&str> = dxf.split("\r\n").collect();
    let start = (0..lines.len() - 1).step_by(2).find(|&i| lines[i].trim() == "0" && lines[i + 1] == kind).unwrap();
    let mut out = Vec::new();
    let mut i = start + 2;
    while i + 1 < lines.len() && lines[i].trim() != "0" {
        if lines[i].trim() == code {
            out.push(lines[i + 1]);
        }
        i += 2;
    }
    out
}

#[test]
fn y_is_flipped_up_from_the_sheets_height() {
    let s = scene(vec![Item::Path {
        path: Path::polyline(&[Point::new(1.0, 2.0), Point::new(3.0, 70.0)], false),
        pen: MAIN,
    }]);
    let d = dxf(&s, DxfVersion::R2000);
    assert_eq!(values(&d, "LINE", "10"), ["1.0"]);
    assert_eq!(values(&d, "LINE", "20"), ["78.0"]);
    assert_eq!(values(&d, "LINE", "21"), ["10.0"]);
    assert_eq!(values(&d, "LINE", "8"), ["velocity_plans-contour"]);
}

#[test]
fn an_arc_clockwise_on_paper_runs_clockwise_in_dxf() {
    // From the sheet's right (angle 0) a quarter turn clockwise on paper: down the sheet.
    let s = scene(vec![Item::Path { path: Path::arc(Point::new(50.0, 40.0), 10.0, 0.0, PI / 2.0), pen: THIN }]);
    let d = dxf(&s, DxfVersion::R2000);
    // In DXF (y up) that arc lies below the centre: counter-clockwise from 270° to 360°.
    assert_eq!(values(&d, "ARC", "50"), ["270.0"]);
    assert_eq!(values(&d, "ARC", "51"), ["0.0"]);
    assert_eq!(values(&d, "ARC", "20"), ["40.0"]);
    // Anticlockwise on paper, from the left a quarter up the sheet: 90°..180° in DXF.
    let s = scene(vec![Item::Path { path: Path::arc(Point::new(50.0, 40.0), 10.0, PI, PI / 2.0), pen: THIN }]);
    let d = dxf(&s, DxfVersion::R2000);
    assert_eq!((values(&d, "ARC", "50"), values(&d, "ARC", "51")), (vec!["90.0"], vec!["180.0"]));
    // In a polyline: the bulge of a clockwise (on paper, and so in DXF) arc is negative.
    let mut p = Path::arc(Point::new(50.0, 40.0), 10.0, 0.0, PI / 2.0);
    p.segs.push(Seg::Line(Point::new(0.0, 0.0)));
    let d = dxf(&scene(vec![Item::Path { path: p, pen: THIN }]), DxfVersion::R2000);
    assert_eq!(values(&d, "LWPOLYLINE", "42"), [num(-math::tan(PI / 8.0), BULGE)]);
    assert_eq!(values(&d, "LWPOLYLINE", "20"), ["40.0", "30.0", "80.0"]);
}

#[test]
fn non_ascii_letters_are_escaped() {
    assert_eq!(escape("Механизм"), "\\U+041C\\U+0435\\U+0445\\U+0430\\U+043D\\U+0438\\U+0437\\U+043C");
    assert_eq!(escape("oʻ μ ω ≈ 5°"), "o\\U+02BB \\U+03BC \\U+03C9 \\U+2248 5\\U+00B0");
    assert_eq!(escape("a\\b 3 %%"), "a\\U+005Cb 3 %\\U+0025");
    let s = scene(vec![Item::Text(Text::new(Point::new(10.0, 10.0), "ТММ КП", 5.0, Anchor::Start))]);
    let d = dxf(&s, DxfVersion::R12);
    assert_eq!(values(&d, "TEXT", "1"), ["\\U+0422\\U+041C\\U+041C \\U+041A\\U+041F"]);
    assert!(d.is_ascii());
}

#[test]
fn runs_are_texts_where_the_setter_puts_them() {
    let mut t = Text::new(Point::new(50.0, 40.0), "v", 5.0, Anchor::Middle).with_sub("BA", " = 1");
    t.rotate = 90.0;
    let s = scene(vec![Item::Text(t.clone())]);
    let d = dxf(&s, DxfVersion::R2000);
    let lines: Vec<&str> = d.split("\r\n").collect();
    let texts: Vec<usize> = (0..lines.len() - 1).step_by(2).filter(|&i| lines[i + 1] == "TEXT").collect();
    assert_eq!(texts.len(), 3);
    assert_eq!(entity_counts(&s, DxfVersion::R2000)["TEXT"], 3);
    let set = text::set(&t);
    // The first run starts where the setter's frame puts its origin; turned 90°
    // anticlockwise its baseline runs up the sheet, so in DXF its x stays, y grows.
    let p = set.transform * set.runs[0].origin;
    assert_eq!(values(&d, "TEXT", "10"), [num(p.x, MM)]);
    assert_eq!(values(&d, "TEXT", "20"), [num(80.0 - p.y, MM)]);
    assert_eq!(values(&d, "TEXT", "50"), ["90.0"]);
    assert_eq!(values(&d, "TEXT", "51"), ["15.0"]);
    assert!(p.y > 40.0, "the middle anchor puts the start below the anchor: {p:?}");
}

#[test]
fn two_writes_are_equal_and_counts_match() {
    let mut items = vec![
        Item::Path {
            path: Path::polyline(&[Point::new(0.0, 0.0), Point::new(5.0, 5.0), Point::new(9.0, 1.0)], true),
            pen: DASHED,
        },
        Item::Circle { c: Point::new(20.0, 20.0), r: 3.0, pen: MAIN, filled: false },
        Item::Circle { c: Point::new(30.0, 20.0), r: 0.6, pen: THIN, filled: true },
        Item::Fill { path: Path::polyline(&[Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(1.0, 3.0)], true) },
    ];
    items.push(Item::Path {
        path: Path::cubics(&[kurbo::CubicBez::new((0.0, 0.0), (10.0, 20.0), (30.0, 20.0), (40.0, 0.0))]),
        pen: THIN,
    });
    let s = scene(items);
    for v in [DxfVersion::R2000, DxfVersion::R12] {
        assert_eq!(write(&s, v).unwrap(), write(&s, v).unwrap());
    }
    let c = entity_counts(&s, DxfVersion::R2000);
    assert_eq!(c.get("LWPOLYLINE"), Some(&2));
    assert_eq!(c.get("HATCH"), Some(&2));
    assert_eq!(c.get("CIRCLE"), Some(&1));
    let c = entity_counts(&s, DxfVersion::R12);
    assert_eq!(c.get("POLYLINE"), Some(&2));
    assert!(c["SOLID"] > 2, "{c:?}");
    let d = dxf(&s, DxfVersion::R2000);
    assert!(d.contains("\r\nDASHED\r\n") && d.contains("\r\nvelocity_plans-dashed\r\n"));
}

#[test]
fn a_non_finite_number_is_refused() {
    let bad = Item::Circle { c: Point::new(f64::NAN, 1.0), r: 1.0, pen: THIN, filled: false };
    assert!(matches!(write(&scene(vec![bad]), DxfVersion::R2000), Err(BackendError::NonFinite { .. })));
}

#[test]
fn numbers_are_fixed_and_never_negative_zero() {
    assert_eq!(num(-0.0001, MM), "0.0");
    assert_eq!(num(12.0, MM), "12.0");
    assert_eq!(num(8.4666666, MM), "8.467");
    assert_eq!(degrees(-90.0), 270.0);
    assert_eq!(degrees(360.0), 0.0);
    assert_eq!(lineweight_of(0.45), 50);
    assert_eq!(lineweight_of(1.2), 120);
    assert_eq!(lineweight_of(0.25), 25);
}

#[test]
fn ear_clipping_covers_a_concave_outline() {
    let l = [(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (1.0, 1.0), (1.0, 4.0), (0.0, 4.0)].map(|(x, y)| Point::new(x, y));
    let t = triangles(&l);
    assert_eq!(t.len(), 4);
    let area: f64 = t.iter().map(|[a, b, c]| ((*b - *a).cross(*c - *a)).abs() / 2.0).sum();
    assert!((area - 7.0).abs() < 1e-12, "{area}");
}

#[test]
fn each_line_kind_has_its_colour_for_a_plotter_without_lineweights() {
    let line = |pen| Item::Path { path: Path::polyline(&[Point::new(1.0, 2.0), Point::new(3.0, 4.0)], false), pen };
    let s = scene(vec![line(MAIN), line(THIN), line(DASHED)]);
    for v in [DxfVersion::R12, DxfVersion::R2000] {
        let d = dxf(&s, v);
        let lines: Vec<&str> = d.split("\r\n").collect();
        // Each LAYER record's name (2) and colour (62), in order.
        let colour = |layer: &str| {
            let at = lines.iter().position(|l| *l == layer).unwrap_or_else(|| panic!("no layer {layer}"));
            let k = (at..lines.len()).step_by(2).find(|&i| lines[i - 1].trim() == "62").unwrap();
            lines[k].trim().to_string()
        };
        assert_eq!(colour("velocity_plans-contour"), "7");
        assert_eq!(colour("velocity_plans-thin"), "3");
        assert_eq!(colour("velocity_plans-dashed"), "6");
    }
}
