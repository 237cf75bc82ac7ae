//! Sheet 1's texts (`templates/labels/lever.yaml`).

use crate::drawing::labels::Wording;
use crate::report::ForceKind;

/// Sheet 1's language with its words.
pub type LeverWords = Wording<LeverLabels>;

crate::label_set! {
    /// Every word of sheet 1 that is not shared with the other sheets.
    pub struct LeverLabels = "lever.yaml" {
        sheet_name,
        sheet_name_forces,
        positions_title,
        velocity_plans,
        acceleration_plans,
        position(k),
        velocity_table(n),
        acceleration_table(n),
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
        from_power_balance,
        sub_inertia,
        sub_balancing,
        sub_resistance,
        sub_gas,
        inertia_table(n),
        reaction_table(n),
        balance_table(n),
        balance_table_signed(n),
    }
}

impl LeverLabels {
    /// A force's subscript in the sheet's language: its kind's letter and the link number
    /// ("и2" for the inertia force of link 2 on a Russian sheet, "ур" for the balancing one).
    pub fn force(&self, kind: ForceKind, link: &str) -> String {
        let letter = match kind {
            ForceKind::Inertia => self.sub_inertia(),
            ForceKind::Balancing => self.sub_balancing(),
            ForceKind::Resistance => self.sub_resistance(),
            ForceKind::Gas => self.sub_gas(),
        };
        format!("{letter}{link}")
    }
}

/// Letters that name the sheet's enlarged details (GOST 2.305 names a detail by a capital
/// letter), none a symbol of the course's quantities: the force polygons' insets take them
/// from the front, the crank's detail the last free one, so that two details never share
/// a letter.
pub const DETAIL_LETTERS: &str = "KLTUVWXYZ";

/// [`DETAIL_LETTERS`] that begin no point's name, in order: the last is the crank
/// detail's, the rest the insets' (none if every one names a point).
pub fn free_detail_letters(point_names: &[String]) -> Vec<String> {
    let used: Vec<char> = point_names.iter().filter_map(|n| n.chars().next()).collect();
    DETAIL_LETTERS.chars().filter(|c| !used.contains(c)).map(String::from).collect()
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
        let ru = LeverLabels::get(Language::Ru);
        use ForceKind::*;
        assert_eq!(
            [ru.force(Inertia, "2"), ru.force(Balancing, ""), ru.force(Resistance, "5"), ru.force(Gas, "3")],
            ["и2", "ур", "пс5", "г3"]
        );
        assert_eq!(LeverLabels::get(Language::En).force(Balancing, ""), "b");
    }
}
