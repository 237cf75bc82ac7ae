//! Profiling aid: solves the worked example at many angles (`valgrind --tool=callgrind`).
use tmm_sheets::{mechanics::State, pipeline};
fn main() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let mut s = State::default();
    let mut acc = 0.0;
    for k in 0..200_000 {
        p.mechanism.solve_into(k as f64 * 0.001, &mut s).unwrap();
        acc += s.points[5].a.x;
    }
    println!("{acc}");
}
