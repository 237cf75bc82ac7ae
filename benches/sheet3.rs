//! Benchmarks of sheet 3 (`cargo bench --bench sheet3`): profile pieces against the profile's
//! measured error, chord-integration divisions against the error of s and ds/dφ, the exact
//! minimum radius, and sheet 3 of the worked example to SVG and to PDF. The tables are printed
//! first.
#![allow(clippy::disallowed_methods)]

use tmm_sheets::cams::integrate::chords;
use tmm_sheets::cams::radius::Phase;
use tmm_sheets::cams::{Design, design};
use tmm_sheets::num::bezier;
use tmm_sheets::pipeline::{self, DEFAULT_PROJECT, Format};

fn main() {
    tables();
    divan::main();
}

fn guide_design() -> Design {
    pipeline::load(DEFAULT_PROJECT).unwrap().cam.unwrap().design
}

/// Pieces per part of the turn → the working profile's largest deviation (µm, real size);
/// divisions per phase → the integration's largest error of s (% of the lift) and of ds/dφ
/// (% of its peak), for the worked example's rocker (cycloidal law).
fn tables() {
    let d = guide_design();
    let parts = tmm_sheets::cams::profile::parts(&d.spec.program);
    println!("pieces per part | working-profile deviation (µm)");
    for n in [1, 2, 4, 8, 16, 32] {
        let exact = |phi: f64| d.profile.working(d.roller, phi);
        let dev = parts
            .iter()
            .filter(|(a, b)| b > a)
            .map(|&(a, b)| bezier::deviation(&exact, a, b, &bezier::fit(&exact, a, b, n)))
            .fold(0.0, f64::max);
        println!("{n} | {:.3e}", dev * 1e6);
    }
    let p = &d.spec.program;
    let vmax = 2.0 * p.lift / p.rise;
    println!("divisions per phase | error of s (% of lift) | error of ds/dφ (% of peak)");
    for n in [4, 6, 8, 12, 16, 24, 48] {
        let (es, ev) = Phase::BOTH
            .iter()
            .map(|&ph| chords(p, ph, n).error(p))
            .fold((0.0f64, 0.0f64), |m, e| (m.0.max(e.s), m.1.max(e.ds)));
        println!("{n} | {:.4} | {:.4}", es / p.lift * 100.0, ev / vmax * 100.0);
    }
}

/// The whole design: the exact centre, ρ_min, the roller, the pressure angles.
#[divan::bench]
fn design_guide_rocker(bencher: divan::Bencher) {
    let spec = guide_design().spec;
    bencher.bench_local(|| divan::black_box(design(&spec).unwrap().centre.r_min));
}

/// Sheet 3 from the parsed project to the SVG text.
#[divan::bench(sample_count = 20)]
fn sheet3_to_svg(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    bencher.bench_local(|| divan::black_box(pipeline::build(&p, &[3]).unwrap()[0].svg.len()));
}

#[divan::bench(sample_count = 10)]
fn sheet3_scene_to_pdf(bencher: divan::Bencher) {
    let p = pipeline::load(DEFAULT_PROJECT).unwrap();
    let b = pipeline::build(&p, &[3]).unwrap().remove(0);
    bencher.bench_local(|| divan::black_box(pipeline::render(&b, Format::Pdf).unwrap().len()));
}
