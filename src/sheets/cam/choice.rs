//! Which of sheet 3's variants is kept: the one that leaves the least of the sheet empty
//! (the usual width by the rule on a tie) among those whose layout is no less clean, a
//! smaller profile only for a clearly emptier sheet.

use super::{CamBuild, KIND};
use crate::drawing::layout::{self, Layout};
use crate::drawing::{frame, scene::Scene};
use crate::sheets::{Context, scaffold};

/// How much emptier another variant must leave the sheet than the usual one (its share of
/// empty cells), so that a cell's worth of ink does not flip the layout.
const USUAL_MARGIN: f64 = 0.005;
/// How much emptier a variant drawing the profile at half the scale must leave the sheet
/// (in proportion to the scales' ratio's logarithm: 0.0064 for 5:2 against 2:1): custom-laws
/// in Uzbek went from 5:2 to 1:1 for 0.001 of share when ω's arrow turned elsewhere, and
/// translating-offset-auto in Russian to 1:1 from 2:1 for 0.014, its axes' fan crowding
/// the phases' arcs and ω — the profile's size is what a reader sees first.
const HALF_PROFILE_MARGIN: f64 = 0.02;

/// Of `usual` and `rest`, the build kept, each measured as its whole sheet (the kept one
/// carries that sheet and its measure in `Composition::measured`: `finish` takes them
/// rather than measuring the same sheet again): the fewest faults, then the least empty
/// once each has paid the margin its smaller profile must earn against the largest profile
/// of them all ([`HALF_PROFILE_MARGIN`] a halving), `usual` less [`USUAL_MARGIN`]; on a tie
/// the first. Against the largest profile, not against the best so far: task 4 variant 40
/// in Russian kept its cam at 1:10 (0.429 empty) over the same cam at 1:5 (0.431), which
/// was compared with the 1:10 sheet once that had beaten the usual 1:5 one (0.454).
pub(super) fn kept(ctx: &Context, mut usual: CamBuild, rest: impl Iterator<Item = CamBuild>) -> CamBuild {
    let (faults, empty) = measured(ctx, &mut usual);
    let first = ((faults, empty - USUAL_MARGIN), usual);
    let all: Vec<((usize, f64), CamBuild)> =
        std::iter::once(first).chain(rest.map(|mut b| (measured(ctx, &mut b), b))).collect();
    let finest = all.iter().map(|(_, b)| b.profile_mu).fold(f64::INFINITY, f64::min);
    // A larger μ draws the profile smaller.
    let score = |((faults, empty), b): &((usize, f64), CamBuild)| {
        (*faults, empty + HALF_PROFILE_MARGIN * (b.profile_mu / finest).log2().max(0.0))
    };
    let scored = all.into_iter().map(|c| (score(&c), c.1));
    scored.reduce(|best, next| if next.0 < best.0 { next } else { best }).expect("the usual build").1
}

/// A build's whole sheet as the layout measure finds it: its faults (texts crossed or
/// overlapping, items out of their regions) and its share of empty cells. The sheet and its
/// measure are kept in the build's composition; where the title block refuses the sheet's
/// texts (then `finish` refuses it too), its drawings alone are measured.
fn measured(ctx: &Context, b: &mut CamBuild) -> (usize, f64) {
    let faults = |l: &Layout| l.faults().iter().sum::<usize>();
    match scaffold::scene(ctx, KIND, &b.composition) {
        Ok(scene) => {
            let (layout, share) = scaffold::measure_with_share(&scene, &b.composition);
            let out = (faults(&layout), share);
            b.composition.measured = Some((scene, layout));
            out
        }
        Err(_) => {
            let (width, height) = frame::page();
            let groups = b.composition.groups.clone();
            let scene =
                Scene { ink: Default::default(), name: String::new(), width, height, title: String::new(), groups };
            let empty = layout::empty_share(&scene, frame::inner(), frame::title_block_rect(), &[]);
            (faults(&layout::measure(&scene)), empty)
        }
    }
}
