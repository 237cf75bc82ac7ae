//! The catalogue's own words in the three languages (templates/labels/catalogue.yaml).

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
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::labels::Language;

    #[test]
    fn the_catalogue_words_load_in_every_language() {
        for lang in Language::ALL {
            CatalogueWords::load(lang).unwrap();
        }
    }
}
