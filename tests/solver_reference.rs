//! The linkage solver against an independent reference: the worked example's six-bar
//! (crank, four-bar RRR, slider RRP, centres of mass) in the textbook's angle form, written
//! here from the loop-closure equation O + r·e^{iθ} + a·e^{iφ2} = C + b·e^{iφ3} and the
//! slider's triangle, differentiated by hand. The solver uses vectors, unit directions and
//! 2×2 systems; the reference uses angles, acos and atan2. They agree to 2·10⁻¹⁶ (positions)
//! … 1.6·10⁻¹⁵ (accelerations) of each quantity's largest value over the turn; the bound of
//! 10⁻¹⁴ catches any optimisation of the solver that changes a result beyond its round-off
//! (the finite-difference checks of tests/mechanics.rs allow 10⁻⁶).
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

use kurbo::Vec2;
use std::f64::consts::TAU;
use tmm_sheets::lever::{Kin, LinkKin, Solution, State, Turn};
use tmm_sheets::pipeline::{self, DEFAULT_PROJECT};

/// Position, velocity and acceleration of a point, and angle, ω, ε of a link.
#[derive(Clone, Copy)]
struct P {
    p: Vec2,
    v: Vec2,
    a: Vec2,
}

struct Reference {
    points: Vec<(&'static str, P)>,
    /// (link number, unit direction, ω, ε)
    links: Vec<(u32, Vec2, f64, f64)>,
}

fn polar(len: f64, angle: f64) -> Vec2 {
    Vec2::new(len * angle.cos(), len * angle.sin())
}

/// The worked example (fixtures/worked-example.yaml) at crank angle θ with crank speed ω1.
fn reference(th: f64, w1: f64) -> Reference {
    let (r, a, b, l) = (0.12, 0.46, 0.39, 1.5);
    let c = Vec2::new(0.33, 0.06);
    let y0 = 0.06; // the slider's guide, horizontal
    // Crank (ε1 = 0).
    let pa = P { p: polar(r, th), v: polar(r * w1, th + TAU / 4.0), a: polar(r * w1 * w1, th + TAU / 2.0) };
    // Four-bar: B to the left of A → C.
    let ac = c - pa.p;
    let k = ac.hypot();
    let alpha = ((a * a + k * k - b * b) / (2.0 * a * k)).acos();
    let f2 = ac.y.atan2(ac.x) + alpha;
    let bp = pa.p + polar(a, f2);
    let f3 = (bp.y - c.y).atan2(bp.x - c.x);
    let w2 = -r * w1 * (th - f3).sin() / (a * (f2 - f3).sin());
    let w3 = r * w1 * (th - f2).sin() / (b * (f3 - f2).sin());
    let e2 = (b * w3 * w3 - a * w2 * w2 * (f2 - f3).cos() - r * w1 * w1 * (th - f3).cos()) / (a * (f2 - f3).sin());
    let e3 = (a * w2 * w2 + r * w1 * w1 * (th - f2).cos() - b * w3 * w3 * (f3 - f2).cos()) / (b * (f3 - f2).sin());
    let pb = P { p: bp, v: polar(b * w3, f3 + TAU / 4.0), a: polar(b * e3, f3 + TAU / 4.0) - polar(b * w3 * w3, f3) };
    // Slider D ahead of B on y = y0: u² + h² = l² with u = x_D − x_B, h = y0 − y_B.
    let h = y0 - pb.p.y;
    let u = (l * l - h * h).sqrt();
    let du = h * pb.v.y / u;
    let ddu = (h * pb.a.y - pb.v.y * pb.v.y - du * du) / u;
    let pd = P { p: Vec2::new(pb.p.x + u, y0), v: Vec2::new(pb.v.x + du, 0.0), a: Vec2::new(pb.a.x + ddu, 0.0) };
    // The rod's angle atan2(h, u): ω4 = (u·h' − h·u')/l², ε4 its derivative.
    let w4 = (-u * pb.v.y - h * du) / (l * l);
    let e4 = (-u * pb.a.y - h * ddu) / (l * l);
    let mid = |x: P, y: P| P { p: (x.p + y.p) * 0.5, v: (x.v + y.v) * 0.5, a: (x.a + y.a) * 0.5 };
    let fixed = |p: Vec2| P { p, v: Vec2::ZERO, a: Vec2::ZERO };
    Reference {
        points: vec![
            ("O", fixed(Vec2::ZERO)),
            ("C", fixed(c)),
            ("A", pa),
            ("B", pb),
            ("D", pd),
            ("S2", mid(pa, pb)),
            ("S3", mid(fixed(c), pb)),
            ("S4", mid(pb, pd)),
            ("S5", pd),
        ],
        links: vec![
            (1, polar(1.0, th), w1, 0.0),
            (2, polar(1.0, f2), w2, e2),
            (3, polar(1.0, f3), w3, e3),
            (4, Vec2::new(u, h) / l, w4, e4),
            (5, Vec2::new(1.0, 0.0), 0.0, 0.0),
        ],
    }
}

/// The largest difference over a full turn, relative to the largest magnitude of its kind
/// (positions, velocities, accelerations, directions, ω, ε).
#[test]
fn the_six_bar_matches_its_textbook_closed_form() {
    let lever = pipeline::load(DEFAULT_PROJECT).unwrap().lever.unwrap();
    let m = &lever.mechanism;
    let w1 = m.omega1;
    let mut s = State::default();
    // [p, v, a, dir, ω, ε]: (largest difference, largest magnitude)
    let mut worst = [(0.0f64, 0.0f64); 6];
    let mut note = |kind: usize, got: Vec2, want: Vec2| {
        worst[kind].0 = worst[kind].0.max((got - want).hypot());
        worst[kind].1 = worst[kind].1.max(want.hypot());
    };
    for k in 0..3600 {
        let th = TAU * k as f64 / 3600.0;
        m.solve_into(th, &mut s).unwrap();
        let want = reference(th, w1);
        for (name, q) in &want.points {
            let got = s.points[m.point_id(name).unwrap()];
            note(0, got.p, q.p);
            note(1, got.v, q.v);
            note(2, got.a, q.a);
        }
        for &(number, dir, w, e) in &want.links {
            let got = s.links[m.link_by_number(number).unwrap()];
            note(3, got.dir, dir);
            note(4, Vec2::new(got.omega, 0.0), Vec2::new(w, 0.0));
            note(5, Vec2::new(got.eps, 0.0), Vec2::new(e, 0.0));
        }
    }
    for (kind, (diff, scale)) in ["p", "v", "a", "dir", "ω", "ε"].iter().zip(worst) {
        assert!(diff <= 1e-14 * scale, "{kind}: differs by {diff:e}, {:e} of its scale {scale:e}", diff / scale);
    }
}

/// Every bit of a point's position, velocity and acceleration.
fn kin_bits(k: Kin) -> [u64; 6] {
    [k.p.x, k.p.y, k.v.x, k.v.y, k.a.x, k.a.y].map(f64::to_bits)
}

/// Every bit of a link's direction, angle, ω and ε.
fn link_bits(l: LinkKin) -> [u64; 5] {
    [l.dir.x, l.dir.y, l.angle(), l.omega, l.eps].map(f64::to_bits)
}

/// The whole turn solved at once (`solve_turn`, the angles in SIMD lanes, kept in columns,
/// read in place through `Turn::at` and copied out by `Turn::state_into`) holds what
/// `solve_into` finds angle by angle, bit for bit: every
/// point's p, v, a, every link's direction, angle, ω and ε, every slide, on every fixture's
/// mechanism (each kind of step, the kulisa's slides among them) and a coupler too short
/// for part of the turn, both senses, 360 angles and counts that leave the last block of
/// lanes part full, one `Turn` reused throughout (its buffers resized, its frame reset
/// for each mechanism); where a part of the turn fails, the first angle that fails is the
/// one `solve_into` fails first, with the same step and reason.
#[test]
fn the_turn_in_columns_is_solve_into_bit_for_bit() {
    let short = std::fs::read_to_string("tests/bad-input/118-rrr-too-short.yaml").unwrap();
    let mut texts = vec![DEFAULT_PROJECT.to_string(), short];
    for entry in std::fs::read_dir("fixtures").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "yaml") {
            texts.push(std::fs::read_to_string(path).unwrap());
        }
    }
    let mut turn = Turn::default();
    let (mut compared, mut kulisa_slides) = (0, 0);
    for text in &texts {
        let m = pipeline::load_for(text, &[1]).unwrap().lever.unwrap().mechanism;
        for (n, sense) in [(360, 1.0), (359, -1.0), (361, 1.0), (360, -1.0)] {
            let thetas: Vec<f64> = (0..n).map(|k| sense * TAU * k as f64 / 360.0 + 0.3).collect();
            let got = m.solve_turn(&thetas, &mut turn);
            assert_eq!(turn.len(), n);
            let (mut first_failure, mut s, mut copied) = (None, State::default(), State::default());
            for (k, &th) in thetas.iter().enumerate() {
                if let Err(f) = m.solve_into(th, &mut s) {
                    first_failure.get_or_insert((k, f));
                    continue;
                }
                let at = turn.at(k);
                assert_eq!(at.theta().to_bits(), th.to_bits());
                for (id, &kin) in s.points.iter().enumerate() {
                    assert_eq!(kin_bits(at.point(id)), kin_bits(kin), "point {} at angle {k}", m.name(id));
                }
                for (id, &link) in s.links.iter().enumerate() {
                    assert_eq!(link_bits(at.link(id)), link_bits(link), "link {id} at angle {k}");
                }
                for (i, &(d, d_dot, d_ddot)) in s.slides.iter().enumerate() {
                    let want = [d, d_dot, d_ddot].map(f64::to_bits);
                    let (d, d_dot, d_ddot) = turn.slide(k, i);
                    assert_eq!([d, d_dot, d_ddot].map(f64::to_bits), want, "slide of step {i} at angle {k}");
                    kulisa_slides += usize::from(d != 0.0);
                }
                turn.state_into(k, &mut copied);
                assert_eq!(copied.theta.to_bits(), s.theta.to_bits());
                assert_eq!(
                    copied.points.iter().map(|&k| kin_bits(k)).collect::<Vec<_>>(),
                    s.points.iter().map(|&k| kin_bits(k)).collect::<Vec<_>>()
                );
                assert_eq!(
                    copied.links.iter().map(|&l| link_bits(l)).collect::<Vec<_>>(),
                    s.links.iter().map(|&l| link_bits(l)).collect::<Vec<_>>()
                );
                let slide_bits =
                    |s: &State| s.slides.iter().map(|&(a, b, c)| [a, b, c].map(f64::to_bits)).collect::<Vec<_>>();
                assert_eq!(slide_bits(&copied), slide_bits(&s));
                compared += 1;
            }
            assert_eq!(got.err(), first_failure);
        }
    }
    assert!(compared > 8 * 4 * 300, "{compared} angles compared");
    assert!(kulisa_slides > 0, "a fixture with a kulisa");
    // The short coupler fails somewhere, so the failures above were compared.
    let m = pipeline::load_for(&texts[1], &[1]).unwrap().lever.unwrap().mechanism;
    assert!(m.solve_turn(&[0.0, 3.0], &mut turn).is_err());
}
