//! Sheet 2's texts (`templates/labels/gears.yaml`).

use crate::drawing::labels::Wording;

/// Sheet 2's language with its words.
pub type GearWords = Wording<GearLabels>;

crate::label_set! {
    /// Every word of sheet 2 that is not shared with the other sheets.
    pub struct GearLabels = "gears.yaml" {
        sheet_name,
        sheet_name_pair,
        mesh_title(m, z1, z2),
        scale(s),
        contact_ratio_exact(e),
        contact_ratio_drawn(e, d),
        involute_note(dev),
        active_note,
        sliding_title,
        generation_title(w),
        datum_line,
        rolling_line,
        datum_rolling_line,
        arc_of_action,
        undercut_note(w, x, xmin),
        auto_shift_note(w, x, xmin),
        thin_tip_note(w, sa),
        low_ratio_note(e),
        interference_note(w, o, b),
        planetary_title(u, req, k),
        front_view,
        side_view,
        scheme_sun_planet_ring,
        scheme_double_planet,
        pair_table(n),
        pair_table_continued(n),
        planetary_table(n),
        conditions_table(n),
        wheel(w),
        pair_col,
        condition_col,
        value_col,
        limit_col,
        ok_col,
        yes,
        no,
        cond_ratio,
        cond_ratio_deviation(u),
        cond_coaxiality,
        cond_neighbours,
        cond_assembly,
        cond_no_undercut,
        cond_ring_teeth,
        cond_ring_planet_difference,
        integer,
        driver,
        sub_drawn,
        sub_required,
        linear_velocities,
        angular_velocities,
        graphic_ratio(s1, sh, u),
        graphic_ratio_note(u, d),
        graphic_ratio_unreadable,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::labels::Language;

    #[test]
    fn the_gear_set_loads_in_every_language() {
        for lang in Language::ALL {
            GearLabels::load(lang).unwrap();
        }
        assert_eq!(GearLabels::get(Language::Ru).wheel("1"), "Колесо 1");
    }
}
