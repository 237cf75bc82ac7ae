//! Sheet 1's texts (`templates/labels/lever.yaml`).

crate::label_set! {
    /// Every word of sheet 1 that is not shared with the other sheets.
    pub struct LeverLabels = "lever.yaml" {
        sheet_name,
        sheet_name_forces,
        positions_title,
        velocity_plans,
        acceleration_plans,
        own_scales,
        position(k),
        velocity_table,
        acceleration_table,
        structure,
        trajectories,
        exact_note,
        forces_title(phi),
        group(g),
        driving_link,
        lever_title,
        load_title(n),
        stroke_working,
        stroke_idle,
        stroke_toward_head,
        stroke_away_from_head,
        stroke_expansion,
        stroke_exhaust,
        stroke_intake,
        stroke_compression,
        short_arrow(len),
        inertia_table,
        reaction_table,
        balance_table,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::labels::Language;

    #[test]
    fn the_lever_set_loads_in_every_language() {
        for lang in Language::ALL {
            LeverLabels::load(lang).unwrap();
        }
        assert_eq!(LeverLabels::get(Language::Uz).position("4′"), "4′-holat");
    }
}
