//! The catalogue's own words in the three languages (templates/labels/catalogue.yaml).

use crate::drawing::labels::{Common, Language};

crate::label_set! {
    /// What `tmm list`, `tmm init` and the batch summary write around the guide's data.
    pub struct CatalogueWords = "catalogue.yaml" {
        guide,
        manual,
        header_task(source, task, variant, name),
        header_practice(source, table, variant, name),
        header_written(command),
        header_errata,
        cell_source(table, variant),
        corrected(printed, reason),
        restored(reason),
        computed(expression, value),
        incomplete(task, variant, columns),
        list_heading,
        list_practice,
        col_task,
        col_machine,
        col_kind,
        col_variants,
        col_incomplete,
        col_variant,
        col_table,
        none,
        list_hint,
        constants,
        left_out(names),
        partial(sections),
        col_partial,
        refused_as_printed,
        left_out_with_mechanism,
        col_status,
        unit_rev_per_min,
        unit_kg_per_m,
        unit_kn,
        unit_mpa,
        unit_m,
    }
}

/// A unit as a task's columns print it (in English) in `lang`: the sheets' own units from
/// [`Common::si_unit`], the guide's others from the catalogue's words.
pub fn unit(unit: &str, lang: Language) -> String {
    let w = CatalogueWords::get(lang);
    match unit.trim() {
        "rev/min" => w.unit_rev_per_min(),
        "kg/m" => w.unit_kg_per_m(),
        "kN" => w.unit_kn(),
        "MPa" => w.unit_mpa(),
        "m" => w.unit_m(),
        other => Common::get(lang).si_unit(other),
    }
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_words_load_in_every_language() {
        for lang in Language::ALL {
            CatalogueWords::load(lang).unwrap();
        }
    }
}
