//! The `forces` section: masses and moments of inertia of the links and the loads on the
//! sliders, for the force analysis at φ1.

use super::values::{Finite, Name, NonNegative, Positive};
use crate::num::digits::{sig, written};
use crate::num::limits::INPUT_MAX;
use serde::{Deserialize, Deserializer};
use serde_saphyr::Spanned;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForcesSpec {
    /// Gravity, m/s² (default 9.81).
    #[serde(default)]
    pub g: Option<Positive>,
    /// Mass and moment of inertia of every moving link (the crank may be left out).
    pub links: Vec<LinkMassSpec>,
    #[serde(default)]
    pub loads: Vec<Spanned<LoadSpec>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinkMassSpec {
    pub link: Spanned<u32>,
    /// kg
    #[serde(default)]
    pub mass: Option<NonNegative>,
    /// Mass per metre, kg/m, for tasks that give m = q·l.
    #[serde(default)]
    pub q: Option<Positive>,
    /// J_S, kg·m², or `rod` for J = m·l²/12 (default: `rod` with `q`, else 0).
    #[serde(default)]
    pub inertia: Option<Inertia>,
}

/// A moment of inertia: a number, or the rule for a uniform rod.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Inertia {
    Value(f64),
    Rod,
}

impl<'de> Deserialize<'de> for Inertia {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = Inertia;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a moment of inertia ≥ 0 in kg·m², or `rod` for m·l²/12")
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Inertia, E> {
                if x.is_finite() && (0.0..=INPUT_MAX).contains(&x) {
                    Ok(Inertia::Value(x))
                } else {
                    Err(E::custom(format!(
                        "expected a moment of inertia from 0 to {} kg·m², got {}",
                        sig(INPUT_MAX, 3),
                        written(x)
                    )))
                }
            }
            fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<Inertia, E> {
                self.visit_f64(x as f64)
            }
            fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<Inertia, E> {
                self.visit_f64(x as f64)
            }
            fn visit_str<E: serde::de::Error>(self, x: &str) -> Result<Inertia, E> {
                match x {
                    "rod" => Ok(Inertia::Rod),
                    _ => Err(E::custom(format!("expected a number or `rod`, got `{x}`"))),
                }
            }
        }
        d.deserialize_any(V)
    }
}

/// A load on a slider, along its guide.
#[derive(Debug, Clone, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadSpec {
    /// Useful resistance against the motion on the working stroke (presses, machine tools).
    Resistance(ResistanceSpec),
    /// Gas pressure on a piston from an indicator diagram (compressors, engines).
    Gas(Box<GasSpec>),
}

/// A diagram as written: [stroke fraction, value] rows.
pub type DiagramSpec = Spanned<Vec<[Finite; 2]>>;

/// The working stroke's way: along a slider's guide, or a rocker's sense of rotation (for a
/// point on a link turning about a frame pivot: a jaw crusher's jaw).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Working {
    Forward,
    Backward,
    Cw,
    Ccw,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResistanceSpec {
    pub point: Name,
    /// The working stroke's way: `forward`/`backward` along a slider's guide, `cw`/`ccw`
    /// for a point on a rocker (the force then acts square to its radius from the pivot).
    pub working: Working,
    /// Largest resistance on the working stroke, N.
    pub force: Positive,
    /// Fraction of the working stroke → fraction of `force` (default: constant).
    #[serde(default)]
    pub diagram: Option<DiagramSpec>,
    /// Resistance on the return stroke, N (default 0).
    #[serde(default)]
    pub idle_force: Option<NonNegative>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum IndicatorName {
    /// The guide's appendix 1, stage I.
    #[serde(rename = "compressor-stage-1")]
    CompressorStage1,
    /// The guide's appendix 1, stage II.
    #[serde(rename = "compressor-stage-2")]
    CompressorStage2,
    /// The guide's appendix 2, four-stroke engine.
    Engine,
    /// Given in `table`.
    Table,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GasSpec {
    pub point: Name,
    /// Cylinder bore d, m; with `pressure` the force is p·πd²/4.
    #[serde(default)]
    pub bore: Option<Positive>,
    /// Largest pressure, Pa.
    #[serde(default)]
    pub pressure: Option<Positive>,
    /// Or the largest force itself, N.
    #[serde(default)]
    pub force: Option<Positive>,
    pub indicator: Spanned<IndicatorName>,
    /// For `indicator: table`: pressure fractions against S/H measured from the head.
    #[serde(default)]
    pub table: Option<IndicatorTable>,
    /// For the engine: 1 = expansion and exhaust strokes (default), 2 = intake and compression.
    #[serde(default)]
    pub revolution: Option<Spanned<u32>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IndicatorTable {
    pub toward_head: DiagramSpec,
    pub away_from_head: DiagramSpec,
}
