//! Sheet 3's texts (`templates/labels/cam.yaml`).

use crate::cams::laws::Standard;
use crate::drawing::labels::Wording;

/// Sheet 3's language with its words.
pub type CamWords = Wording<CamLabels>;

crate::label_set! {
    /// Every word of sheet 3 that is not shared with the other sheets.
    pub struct CamLabels = "cam.yaml" {
        sheet_name,
        laws_title(law),
        laws_title_rocker(law),
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
        law_custom_note(name, corners),
        law_custom_return,
        unit_deg_per_mm,
        unit_rad_per_mm,
        unit_per_mm,
        unit_deg,
        phases(rise, dwell, ret, work),
        integration_note(n, q, dq, es, ev),
        integration_note_chords(n, k, q, dq, es, ev),
        nomogram_title,
        nomogram_note(a),
        angles_two(rise, ret),
        zone,
        profile_title,
        pressure_title,
        pitch_profile,
        working_profile,
        knife_profile,
        base_circle,
        profile_note(dev),
        knife_note,
        knife_note_rocker,
        roller_reduced(r, rho),
        roller_outside(r, k, lo, hi),
        roller_near_curvature(r, lim),
        law_table(n, phase),
        profile_table(n, phase),
        results_table(n),
        phase_rise,
        phase_return,
        sub_pitch,
        sub_work,
        sub_rise,
        sub_return,
        sub_far_dwell,
        sub_working_angle,
        sub_min,
        sub_roller,
        sub_allowed_rise,
        sub_allowed_return,
        sub_max_rise,
        sub_max_return,
        follower_translating,
        follower_rocker,
    }
}

impl CamLabels {
    /// A built-in law's name in the sheet's language.
    pub fn law(&self, law: Standard) -> &str {
        match law {
            Standard::UniformAcceleration => self.law_uniform_acceleration(),
            Standard::LinearlyDecreasing => self.law_linearly_decreasing(),
            Standard::Cosine => self.law_cosine(),
            Standard::Sine => self.law_sine(),
            Standard::Triangular => self.law_triangular(),
            Standard::Trapezoid => self.law_trapezoid(),
            Standard::Polynomial345 => self.law_polynomial_345(),
            Standard::ModifiedTrapezoid => self.law_modified_trapezoid(),
            Standard::ModifiedSine => self.law_modified_sine(),
        }
    }
}
