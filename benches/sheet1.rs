//! Benchmarks (`cargo bench`): the exact solver over a full turn, the force analysis,
//! sheet 1 to SVG, and the scene to PDF and PNG, on the guide's worked example (the six-bar
//! vibrating conveyor).
#![allow(clippy::disallowed_methods)]

use std::f64::consts::TAU;
use tmm_sheets::lever::{State, Turn, analysis, kinetostatics};
use tmm_sheets::pipeline::{self, DEFAULT_PROJECT, Format};

fn main() {
    divan::main();
}

/// 360 positions with velocities and accelerations, the whole turn at once (the angles
/// overlapped) into a `Turn`, reusing its buffers.
#[divan::bench]
fn solve_360_positions(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap().lever.unwrap();
    let thetas: Vec<f64> = (0..360).map(|k| TAU * k as f64 / 360.0).collect();
    let mut turn = Turn::default();
    bencher.bench_local(|| {
        p.mechanism.solve_turn(divan::black_box(&thetas), &mut turn).unwrap();
        divan::black_box(turn.point(359, 5).a.x)
    });
}

/// The same turn, then each angle copied into a `State` of its own (for comparison: what
/// keeping 360 states costs), reusing the turn's and the states' buffers.
#[divan::bench]
fn solve_360_states(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap().lever.unwrap();
    let thetas: Vec<f64> = (0..360).map(|k| TAU * k as f64 / 360.0).collect();
    let mut turn = Turn::default();
    let mut states = vec![State::default(); 360];
    bencher.bench_local(|| {
        p.mechanism.solve_turn(divan::black_box(&thetas), &mut turn).unwrap();
        for (k, s) in states.iter_mut().enumerate() {
            turn.state_into(k, s);
        }
        divan::black_box(states[359].points[5].a.x)
    });
}

/// The same 360 positions one angle at a time, reusing one state buffer.
#[divan::bench]
fn solve_360_positions_one_by_one(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap().lever.unwrap();
    let mut s = State::default();
    bencher.bench_local(|| {
        let mut acc = 0.0;
        for k in 0..360 {
            p.mechanism.solve_into(TAU * k as f64 / 360.0, &mut s).unwrap();
            acc += s.points[5].a.x;
        }
        divan::black_box(acc)
    });
}

/// The force analysis at φ1 alone (inertia, groups, crank, lever, power balance), with the
/// loads already placed on their strokes.
#[divan::bench]
fn kinetostatics_at_phi1(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap().lever.unwrap();
    let k = analysis::kinematics(&p.mechanism, &p.settings).unwrap();
    let model = analysis::place_loads(&p.mechanism, &k.motion, p.forces.as_ref().unwrap()).unwrap();
    bencher
        .bench_local(|| divan::black_box(kinetostatics::analyse(&p.mechanism, &k.assigned.state, &model).unwrap().p_m));
}

/// Everything sheet 1 needs, from the parsed project to the SVG text.
#[divan::bench]
fn sheet1_to_svg(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    bencher.bench_local(|| divan::black_box(pipeline::build(&p, &[1]).unwrap()[0].svg.len()));
}

#[divan::bench(sample_count = 10)]
fn scene_to_pdf(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    let b = pipeline::build(&p, &[1]).unwrap().remove(0);
    bencher.bench_local(|| divan::black_box(pipeline::render(&b, Format::Pdf).unwrap().len()));
}

#[divan::bench(sample_count = 5)]
fn scene_to_png_100dpi(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    let b = pipeline::build(&p, &[1]).unwrap().remove(0);
    bencher.bench_local(|| divan::black_box(pipeline::render(&b, Format::Png { dpi: 100.0 }).unwrap().len()));
}
