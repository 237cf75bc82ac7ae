//! A build computes only what its request needs, proved by the counts of the costly steps
//! (`num::work`): a sheet not asked for is not analysed, a format not asked for is not
//! written, a sheet without force drawings solves no kinetostatics.
//!
//! One test in its own binary: the counts are process-wide, and tests in one binary run
//! in parallel.

mod common;

use common::fixture;
use tmm_sheets::num::work::{Step, taken};
use tmm_sheets::pipeline;

const STEPS: [Step; 9] = [
    Step::LinkageAnalysis,
    Step::ForceAnalysis,
    Step::MechanismDrawing,
    Step::GearPair,
    Step::CamDesign,
    Step::Svg,
    Step::Pdf,
    Step::Png,
    Step::Dxf,
];

/// How many times each step was taken while `f` ran.
fn steps_taken(f: impl FnOnce()) -> [u64; 9] {
    let before = STEPS.map(taken);
    f();
    let after = STEPS.map(taken);
    std::array::from_fn(|i| after[i] - before[i])
}

fn count(steps: &[u64; 9], step: Step) -> u64 {
    steps[STEPS.iter().position(|&s| s == step).expect("a counted step")]
}

#[test]
fn a_build_takes_only_the_steps_its_request_needs() {
    // Loading designs the pair and the cam, once each, so that a section the design refuses
    // is refused at its line (or, not asked for, warned about) before anything is drawn;
    // the linkage is analysed by the sheet that draws it.
    let mut p = None;
    let load = steps_taken(|| p = Some(fixture("worked-example")));
    let p = p.expect("loaded");
    assert_eq!([count(&load, Step::GearPair), count(&load, Step::CamDesign)], [1, 1], "{load:?}");
    assert_eq!(count(&load, Step::LinkageAnalysis), 0, "{load:?}");

    // Sheet 2 alone: no linkage, no force analysis; one SVG.
    let only_2 = steps_taken(|| {
        pipeline::build(&p, &[2]).expect("sheet 2 builds");
    });
    assert_eq!(count(&only_2, Step::LinkageAnalysis), 0, "{only_2:?}");
    assert_eq!(count(&only_2, Step::ForceAnalysis), 0, "{only_2:?}");
    assert_eq!(count(&only_2, Step::Svg), 1, "{only_2:?}");

    // Sheet 3 alone: nothing of sheet 1.
    let only_3 = steps_taken(|| {
        pipeline::build(&p, &[3]).expect("sheet 3 builds");
    });
    assert_eq!(count(&only_3, Step::LinkageAnalysis) + count(&only_3, Step::ForceAnalysis), 0, "{only_3:?}");

    // Sheet 1 alone: the linkage once (the layouts it tries share it).
    let only_1 = steps_taken(|| {
        pipeline::build(&p, &[1]).expect("sheet 1 builds");
    });
    assert_eq!(count(&only_1, Step::LinkageAnalysis), 1, "{only_1:?}");
    assert!(count(&only_1, Step::ForceAnalysis) >= 1, "{only_1:?}");

    // The kulisa's sheet 1 composes 19 variants, 51 sheets in all, at one place of its
    // mechanism: drawn there once (twice where two compositions on rayon's pool miss it
    // together), not once a composition.
    let kulisa = fixture("kulisa");
    let compositions = steps_taken(|| {
        pipeline::build(&kulisa, &[1]).expect("the kulisa's sheet 1 builds");
    });
    assert!((1..=2).contains(&count(&compositions, Step::MechanismDrawing)), "{compositions:?}");

    // No build designs the pair or the cam again: the load's designs are drawn.
    for steps in [&only_1, &only_2, &only_3] {
        assert_eq!(count(steps, Step::GearPair) + count(steps, Step::CamDesign), 0, "{steps:?}");
    }

    // Without force drawings, no kinetostatics.
    let mut kinematic = p.clone();
    kinematic.lever.as_mut().expect("a mechanism").forces = None;
    let no_forces = steps_taken(|| {
        pipeline::build(&kinematic, &[1]).expect("sheet 1 builds");
    });
    assert_eq!(count(&no_forces, Step::ForceAnalysis), 0, "{no_forces:?}");

    // The outputs: `--no-png --no-pdf` writes no PDF and no PNG; the default writes a PDF
    // and a PNG a sheet; `--dxf` a DXF a sheet.
    let built = pipeline::build(&p, &[]).expect("the worked example builds");
    let svg_only = steps_taken(|| {
        pipeline::outputs(&p, &built, &pipeline::formats(false, None, None)).expect("written");
    });
    assert_eq!(count(&svg_only, Step::Pdf) + count(&svg_only, Step::Png) + count(&svg_only, Step::Dxf), 0);
    let every = steps_taken(|| {
        let formats = pipeline::formats(true, Some(20.0), Some(pipeline::DxfVersion::R12));
        pipeline::outputs(&p, &built, &formats).expect("written");
    });
    for step in [Step::Pdf, Step::Png, Step::Dxf] {
        assert_eq!(count(&every, step), 3, "{step:?}: {every:?}");
    }
    // No sheet is analysed again to write its files.
    for steps in [&svg_only, &every] {
        for step in [Step::LinkageAnalysis, Step::ForceAnalysis, Step::GearPair, Step::CamDesign] {
            assert_eq!(count(steps, step), 0, "{step:?}: {steps:?}");
        }
    }
}
