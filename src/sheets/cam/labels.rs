//! Sheet 3's texts (`templates/labels/cam.yaml`).

use crate::cams::laws::Law;

crate::label_set! {
    /// Every word of sheet 3 that is not shared with the other sheets.
    pub struct CamLabels = "cam.yaml" {
        sheet_name,
        laws_title(law),
        laws_title_two(rise, ret),
        law_uniform_acceleration,
        law_linearly_decreasing,
        law_cosine,
        law_sine,
        law_triangular,
        law_trapezoid,
        law_polynomial_345,
        law_modified_trapezoid,
        law_modified_sine,
        unit_deg_per_mm,
        unit_rad_per_mm,
        unit_per_mm,
        unit_deg,
        phases(rise, dwell, ret, work),
        integration_note(n, q, dq, es, ev),
        nomogram_title,
        nomogram_note(a),
        zone,
        profile_title,
        pitch_profile,
        working_profile,
        base_circle,
        profile_note(dev),
        knife_note,
        roller_reduced(r, rho),
        law_table,
        profile_table,
        results_table,
        sub_pitch,
        sub_work,
        sub_rise,
        sub_return,
        sub_min,
        sub_roller,
        follower_translating,
        follower_rocker,
    }
}

impl CamLabels {
    /// A law's name in the sheet's language.
    pub fn law(&self, law: Law) -> &str {
        match law {
            Law::UniformAcceleration => self.law_uniform_acceleration(),
            Law::LinearlyDecreasing => self.law_linearly_decreasing(),
            Law::Cosine => self.law_cosine(),
            Law::Sine => self.law_sine(),
            Law::Triangular => self.law_triangular(),
            Law::Trapezoid => self.law_trapezoid(),
            Law::Polynomial345 => self.law_polynomial_345(),
            Law::ModifiedTrapezoid => self.law_modified_trapezoid(),
            Law::ModifiedSine => self.law_modified_sine(),
        }
    }

    /// A table subscript in the sheet's language.
    pub fn sub<'a>(&'a self, sub: &'a str) -> &'a str {
        match sub {
            "pitch" => self.sub_pitch(),
            "work" => self.sub_work(),
            "rise" => self.sub_rise(),
            "return" => self.sub_return(),
            "roller" => self.sub_roller(),
            other => other,
        }
    }
}
