//! Benchmarks of sheet 2 (`cargo bench --bench sheet2`): Bézier pieces per involute flank
//! against their measured deviation and the time to fit them, the planetary search, and
//! sheet 2 of the worked example to SVG and to PDF. The deviation table is printed first.
#![allow(clippy::disallowed_methods)]

use tmm_sheets::gears::pair::{Pair, PairSpec};
use tmm_sheets::gears::planetary::{Scheme, StageSpec, synthesise};
use tmm_sheets::gears::tooth::Outline;
use tmm_sheets::num::bezier;
use tmm_sheets::pipeline::{self, DEFAULT_PROJECT, Format};

fn main() {
    deviation_table();
    divan::main();
}

fn guide_outline() -> Outline {
    let spec = PairSpec::standard(0.005, [17, 19]);
    let pair = Pair::new(&spec).unwrap();
    Outline::new(&spec, &pair.wheels[0])
}

/// Pieces per flank → the largest deviation from the exact involute (µm, real size), for the
/// guide's pinion (m = 5 mm, z = 17) and a large wheel (z = 80).
fn deviation_table() {
    println!("pieces per flank | deviation z=17 (µm) | deviation z=80 (µm)");
    let spec = PairSpec::standard(0.005, [17, 80]);
    let pair = Pair::new(&spec).unwrap();
    let o = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
    for n in [1, 2, 3, 4, 8] {
        let dev = |o: &Outline| {
            let f = |t: f64| o.involute(t);
            bezier::deviation(&f, o.t_low, o.t_tip, &bezier::fit(&f, o.t_low, o.t_tip, n)) * 1e6
        };
        println!("{n} | {:.3e} | {:.3e}", dev(&o[0]), dev(&o[1]));
    }
}

#[divan::bench(args = [1, 2, 4, 8])]
fn fit_involute_flank(bencher: divan::Bencher, pieces: usize) {
    let o = guide_outline();
    let f = |t: f64| o.involute(t);
    bencher.bench_local(|| divan::black_box(bezier::fit(&f, o.t_low, o.t_tip, pieces).len()));
}

#[divan::bench(args = [Scheme::SunPlanetRing, Scheme::DoublePlanet])]
fn planetary_search_u_9_59(bencher: divan::Bencher, scheme: Scheme) {
    let spec = StageSpec::course(scheme, 9.5865);
    bencher.bench_local(|| divan::black_box(synthesise(&spec).map(|s| s.planets).ok()));
}

/// Sheet 2 from the parsed project to the SVG text.
#[divan::bench]
fn sheet2_to_svg(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    bencher.bench_local(|| divan::black_box(pipeline::build(&p, &[2]).unwrap()[0].svg.len()));
}

#[divan::bench(sample_count = 10)]
fn sheet2_scene_to_pdf(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    let b = pipeline::build(&p, &[2]).unwrap().remove(0);
    bencher.bench_local(|| divan::black_box(pipeline::render(&b, Format::Pdf).unwrap().len()));
}
