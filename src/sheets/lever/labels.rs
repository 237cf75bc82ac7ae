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
        sub_inertia,
        sub_balancing,
        sub_resistance,
        sub_gas,
        inertia_table,
        reaction_table,
        balance_table,
    }
}

impl LeverLabels {
    /// A force symbol's subscript in the sheet's language: "i2" → "и2", "m" → "ур", "c5" →
    /// "пс5" on a Russian sheet; other symbols' subscripts as they are.
    pub fn force_sub(&self, main: &str, sub: &str) -> String {
        if !matches!(main, "P" | "M" | "P′" | "P″") {
            return sub.to_string();
        }
        let mut chars = sub.chars();
        let rest: String = chars.clone().skip(1).collect();
        match chars.next() {
            Some('i') => format!("{}{rest}", self.sub_inertia()),
            Some('m') if rest.is_empty() => self.sub_balancing().to_string(),
            Some('c') => format!("{}{rest}", self.sub_resistance()),
            Some('g') => format!("{}{rest}", self.sub_gas()),
            _ => sub.to_string(),
        }
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
        let ru = LeverLabels::get(Language::Ru);
        assert_eq!(
            [ru.force_sub("P", "i2"), ru.force_sub("P′", "m"), ru.force_sub("P", "c5"), ru.force_sub("M", "i4")],
            ["и2", "ур", "пс5", "и4"]
        );
        assert_eq!(ru.force_sub("R", "12"), "12", "reactions keep their link numbers");
        assert_eq!(LeverLabels::get(Language::En).force_sub("P", "m"), "m");
    }
}
