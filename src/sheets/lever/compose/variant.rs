//! The variants of sheet 1's composition: how tables 3–5 are lettered and where the force
//! drawings, table 1 and tables 3–5 go, the rule's and the fuller ones tried in turn.

use crate::drawing::table::{CELL_TEXT, LARGE_TEXT};

/// How one composition of sheet 1 letters its tables 3–5, whether its force drawings grow
/// into the room their cells leave, fill the region beside the mechanism first, and whether
/// table 1 goes down into the corner beside the title block.
#[derive(Clone, Copy)]
pub(super) struct Variant {
    pub(super) text_h: f64,
    pub(super) grow_drawings: bool,
    pub(super) side_first: bool,
    pub(super) tables_beside: bool,
    pub(super) corner: bool,
    pub(super) compact_groups: bool,
    /// Whether a force column narrower than the widest is widened as far as every plan
    /// keeps its scale (see `widen`).
    pub(super) widen: bool,
}

impl Variant {
    pub(super) const RULE: Variant = Variant {
        text_h: CELL_TEXT,
        grow_drawings: false,
        side_first: false,
        tables_beside: false,
        corner: false,
        compact_groups: false,
        widen: false,
    };

    /// This variant with tables 3–5 in the other lettering.
    pub(super) fn in_other_lettering(self) -> Variant {
        Variant { text_h: if self.text_h == CELL_TEXT { LARGE_TEXT } else { CELL_TEXT }, ..self }
    }
}

/// The variants tried, two at a time on rayon's pool, on a sheet still more than
/// `EMPTY_MOST` empty, until one is not: each a step further from the rule's layout.
pub(super) const FULLER: [[Variant; 2]; 7] = {
    let grown = Variant { grow_drawings: true, ..Variant::RULE };
    let side = Variant { side_first: true, ..grown };
    let corner = Variant { corner: true, ..side };
    let side_beside = Variant { tables_beside: true, ..side };
    let beside = Variant { tables_beside: true, ..grown };
    let compact = Variant { compact_groups: true, ..beside };
    let side_compact = Variant { compact_groups: true, ..side_beside };
    [
        [grown, Variant { text_h: LARGE_TEXT, ..grown }],
        [side, Variant { text_h: LARGE_TEXT, ..side }],
        [corner, Variant { text_h: LARGE_TEXT, ..corner }],
        [side_beside, Variant { text_h: LARGE_TEXT, ..side_beside }],
        [beside, Variant { text_h: LARGE_TEXT, ..beside }],
        [compact, Variant { text_h: LARGE_TEXT, ..compact }],
        [side_compact, Variant { text_h: LARGE_TEXT, ..side_compact }],
    ]
};
