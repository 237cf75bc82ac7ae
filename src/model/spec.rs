//! The project file as the user writes it (YAML), in the course's own terms.
//!
//! Every struct denies unknown keys, so a misspelt key is reported with its line and
//! column. Numbers that must be positive are validated while parsing for the same reason.

use serde::{Deserialize, Deserializer};
use serde_saphyr::Spanned;

/// A point name as written, with where it was written.
pub type Name = Spanned<String>;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProjectFile {
    pub project: ProjectInfo,
    pub mechanism: MechanismSpec,
    #[serde(default)]
    pub analysis: AnalysisSpec,
    /// The force analysis at φ1 (`analysis.assigned_deg`); absent: sheet 1 has kinematics only.
    #[serde(default)]
    pub forces: Option<Spanned<ForcesSpec>>,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    #[default]
    Uz,
    Ru,
    En,
}

#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProjectInfo {
    pub title: String,
    #[serde(default)]
    pub designation: String,
    #[serde(default)]
    pub student: String,
    #[serde(default)]
    pub group: String,
    #[serde(default)]
    pub supervisor: String,
    #[serde(default)]
    pub institution: String,
    #[serde(default)]
    pub language: Language,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// Fixed points of the frame, [x, y] in metres.
    pub frame: Vec<FramePoint>,
    pub crank: CrankSpec,
    pub groups: Vec<Spanned<GroupSpec>>,
    #[serde(default)]
    pub points: Vec<PointSpec>,
    /// The slider point whose extreme positions define position 0 (default: the last group's).
    #[serde(default)]
    pub output_point: Option<Name>,
    /// Or the rocker link whose extreme angles define position 0.
    #[serde(default)]
    pub output_link: Option<Spanned<u32>>,
    /// Free text printed on the sheet: what was assumed where the figure was lost.
    #[serde(default)]
    pub assumptions: Vec<String>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FramePoint {
    pub name: Name,
    pub at: [Finite; 2],
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Sense {
    /// Counter-clockwise.
    Ccw,
    /// Clockwise.
    Cw,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrankSpec {
    pub pivot: Name,
    pub pin: Name,
    pub length: Positive,
    /// n1, rev/min.
    pub rpm: Positive,
    pub sense: Sense,
    #[serde(default = "one")]
    pub link: u32,
}

fn one() -> u32 {
    1
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Left,
    Right,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Along {
    Forward,
    Backward,
}

/// An Assur group, in order of formation.
#[derive(Debug, Clone, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum GroupSpec {
    /// Two links, three revolute pairs: `point` joined to `joints[0]` by a link of
    /// `lengths[0]` and to `joints[1]` by a link of `lengths[1]`.
    Rrr(RrrSpec),
    /// Rod and slider: `point` on the guide, joined to `joint` by a rod of `length`.
    Rrp(RrpSpec),
    /// Kulisa: a block pinned at `block_at` slides along a kulisa turning about `pivot`.
    Rpr(RprSpec),
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RrrSpec {
    pub links: [u32; 2],
    pub joints: [Name; 2],
    pub point: Name,
    pub lengths: [Positive; 2],
    /// Side of the directed line joints[0] → joints[1] on which `point` lies.
    pub branch: Side,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RrpSpec {
    pub links: [u32; 2],
    pub joint: Name,
    pub point: Name,
    pub length: Positive,
    pub guide: GuideSpec,
    /// Whether the slider lies ahead of (forward) or behind the joint along the guide.
    pub branch: Along,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GuideSpec {
    /// A point of the guide line, [x, y] in metres.
    pub through: [Finite; 2],
    /// Direction of the guide, degrees counter-clockwise from the x axis.
    pub angle_deg: Finite,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RprSpec {
    /// [block, kulisa].
    pub links: [u32; 2],
    pub block_at: Name,
    pub pivot: Name,
    /// Name of the kulisa's point under the block (default: the block point + "3").
    #[serde(default)]
    pub image: Option<Name>,
    /// Drawn length of the kulisa from its pivot, metres (default: its longest reach).
    #[serde(default)]
    pub length: Option<Positive>,
}

/// A point fixed to a link, e.g. a centre of mass.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    pub name: Name,
    pub link: Spanned<u32>,
    pub from: Name,
    /// Direction point on the same link; absent: the point coincides with `from`.
    #[serde(default)]
    pub toward: Option<Name>,
    /// Fraction of the distance from → toward.
    #[serde(default)]
    pub ratio: Option<Finite>,
    /// Or an absolute distance from `from`, metres.
    #[serde(default)]
    pub distance: Option<Finite>,
    /// Turn of the direction, degrees counter-clockwise (ternary links).
    #[serde(default)]
    pub angle_deg: Option<Finite>,
    #[serde(default)]
    pub mass_centre: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum StartExtreme {
    /// The output's smallest coordinate along its guide (or smallest rocker angle).
    #[default]
    Min,
    Max,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalysisSpec {
    /// 12 (every 30°) or 8 (every 45°).
    #[serde(default = "twelve")]
    pub positions: Spanned<u32>,
    #[serde(default)]
    pub start: StartExtreme,
    /// Fixes position 0 at this absolute crank angle instead (degrees from +x, ccw).
    #[serde(default)]
    pub start_deg: Option<Finite>,
    /// Course crank angle φ1 of the assigned (thick) position, degrees from position 0.
    #[serde(default)]
    pub assigned_deg: Option<Spanned<Finite>>,
    /// Positions that get acceleration plans (default: four, evenly spread).
    #[serde(default)]
    pub acceleration_plans: Option<Spanned<Vec<u32>>>,
}

fn twelve() -> Spanned<u32> {
    Spanned::new(12, serde_saphyr::Location::UNKNOWN, serde_saphyr::Location::UNKNOWN)
}

impl Default for AnalysisSpec {
    fn default() -> Self {
        AnalysisSpec { positions: twelve(), start: StartExtreme::Min, start_deg: None, assigned_deg: None, acceleration_plans: None }
    }
}

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
                if x.is_finite() && x >= 0.0 { Ok(Inertia::Value(x)) } else { Err(E::custom(format!("expected a moment of inertia ≥ 0, got {x}"))) }
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

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResistanceSpec {
    pub point: Name,
    /// Direction of the working stroke along the slider's guide.
    pub working: Along,
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

/// A finite number (YAML's .nan and .inf are refused where they are written).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finite(pub f64);

impl<'de> Deserialize<'de> for Finite {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = f64::deserialize(d)?;
        if !x.is_finite() {
            return Err(serde::de::Error::custom(format!("expected a finite number, got {x}")));
        }
        Ok(Finite(x))
    }
}

/// A finite number ≥ 0 (masses, forces that may vanish).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonNegative(pub f64);

impl<'de> Deserialize<'de> for NonNegative {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = f64::deserialize(d)?;
        if !(x.is_finite() && x >= 0.0) {
            return Err(serde::de::Error::custom(format!("expected a number ≥ 0, got {x}")));
        }
        Ok(NonNegative(x))
    }
}

/// A strictly positive finite number (lengths, speeds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Positive(pub f64);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = f64::deserialize(d)?;
        if !(x.is_finite() && x > 0.0) {
            return Err(serde::de::Error::custom(format!("expected a positive number, got {x}")));
        }
        Ok(Positive(x))
    }
}
