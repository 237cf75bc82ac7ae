//! Circles flattened once a build. An index is made over a drawing again and again (the
//! mechanism's for its dimensions, its turn arrows and its labels, every layout's measure of
//! the whole sheet), and each time every joint's circle was flattened anew: a build of the
//! worked example's sheet 1 flattened 980 circles, 378 of them distinct, a third of its
//! flattening. A circle's segments are a function of its centre and radius alone, so they
//! are remembered by those exact bits and copied: the same segments, found once. (Curved
//! paths, remembered alike by every number of their pieces, gained nothing measurable:
//! most are flattened once.)

use kurbo::Point;
use std::cell::RefCell;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// The segments of the circle of centre `c` and radius `r` appended to `out`: remembered
/// from an earlier call in this build on this thread, else found by `flatten` (appending
/// them to the buffer it is given) and kept.
pub(super) fn circle(c: Point, r: f64, out: &mut Vec<(Point, Point)>, flatten: impl FnOnce(&mut Vec<(Point, Point)>)) {
    CIRCLES.with_borrow_mut(|memo| {
        // Remembered within one build: another build (or a benchmark's next repetition)
        // flattens its circles afresh.
        let now = BUILD.load(Relaxed);
        if memo.build != now || memo.segs.len() > MOST_SEGMENTS {
            *memo = Circles { build: now, ..Circles::default() };
        }
        let key = [c.x.to_bits(), c.y.to_bits(), r.to_bits()];
        let (from, to) = match memo.spans.get(&key) {
            Some(&span) => span,
            None => {
                let from = memo.segs.len();
                flatten(&mut memo.segs);
                memo.spans.insert(key, (from, memo.segs.len()));
                (from, memo.segs.len())
            }
        };
        out.extend_from_slice(&memo.segs[from..to]);
    });
}

/// Starts a new build: circles flattened before are forgotten (each thread's at its next
/// circle).
pub fn new_build() {
    BUILD.fetch_add(1, Relaxed);
}

/// The build the remembered circles belong to ([`new_build`]).
static BUILD: AtomicU64 = AtomicU64::new(0);

/// At most this many remembered segments (a few MB): a caller that never starts a new
/// build still keeps the memo bounded.
const MOST_SEGMENTS: usize = 1 << 17;

/// The circles flattened in the current build on this thread: each one's centre and radius
/// as bits, and its span of `segs`.
#[derive(Default)]
struct Circles {
    build: u64,
    spans: HashMap<[u64; 3], (usize, usize)>,
    segs: Vec<(Point, Point)>,
}

thread_local! {
    static CIRCLES: RefCell<Circles> = RefCell::default();
}
