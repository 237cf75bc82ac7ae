use tmm_sheets::{mechanics::motion, model};
fn main() {
    let text = std::fs::read_to_string(std::env::args().nth(1).unwrap()).unwrap();
    let f = model::parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let (m, s) = model::build(&f).unwrap_or_else(|e| panic!("{e}"));
    let mo = motion::analyse_motion(&m, s.sense, s.start).unwrap();
    println!("theta0 = {:.4}°, other = {:?}", mo.theta0.to_degrees(), mo.other_extreme.map(f64::to_degrees));
    for k in 0..s.positions {
        let phi = std::f64::consts::TAU * k as f64 / s.positions as f64;
        let st = m.solve(mo.theta(phi)).unwrap();
        let v = |n: &str| st.points[m.point_id(n).unwrap()].v.hypot();
        let w = |l: u32| st.links[m.link_by_number(l).unwrap()].omega.abs();
        println!("{k}: vB {:.3} vD {:.3} vS2 {:.3} w2 {:.3} w3 {:.3} w4 {:.3}", v("B"), v("D"), v("S2"), w(2), w(3), w(4));
    }
}
