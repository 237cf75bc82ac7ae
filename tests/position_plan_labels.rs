//! Labels near their points where the thin lines of many positions crowd them (issue 22's
//! review: the crank's pivot "O" 20–35 mm below its pivot on most fixtures, a cam's "8≡9"
//! on a 45 mm leader): they stand on those lines, interrupted for them.

mod common;

use common::{fixture, fixture_names};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::scene::Item;
use tmm_sheets::num::math::Norm;
use tmm_sheets::pipeline;

/// No label of the position plan hangs off its point on a long leader (the review found the
/// crank's pivot "O" 20–35 mm below its pivot, ω1 25 mm from its arrow, on most fixtures):
/// where the nearest free spots are all far, a label stands beside its point on the other
/// positions' thin lines, interrupted for it. Every leader (and the legend's sample line) of
/// the mechanism's drawing is at most 18 mm on every fixture in every language (up to 36
/// before).
#[test]
fn the_position_plans_labels_stand_near_their_points() {
    for name in fixture_names() {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            assert_leaders_within(&p, (1, "mechanism"), 18.0, &format!("{name} {lang:?}"));
        }
    }
}

/// The cam's profile names its follower's positions and pivots near their points, on the
/// positions' thin lines interrupted for them where they crowd (knife-rocker's "8≡9" hung on
/// a 45.6 mm leader parallel to the rocker's lines, the worked example's A₁₃ on 36 mm): every
/// leader of the profile's drawing is at most 30 mm (a profile's name, set where the
/// profile runs clear, is the longest) on every cam fixture and the worked example, in every
/// language.
#[test]
fn the_cam_profiles_labels_stand_near_their_points() {
    for f in cam_projects() {
        for lang in Language::ALL {
            let mut p = pipeline::load(&std::fs::read_to_string(&f).unwrap()).unwrap();
            p.info.language = lang;
            assert_leaders_within(&p, (3, "profile"), 30.0, &format!("{f:?} {lang:?}"));
        }
    }
}

/// Every leader (every line of the writing) of the drawing `group` of sheet `sheet` of `p`
/// is at most `most` mm long.
fn assert_leaders_within(p: &tmm_sheets::project::Project, (sheet, group): (u32, &str), most: f64, what: &str) {
    let out = pipeline::build(p, &[sheet]).unwrap().remove(0).output;
    let g = out.scene.groups.iter().find(|g| g.id == group).expect("the drawing");
    for &k in &g.writing {
        let Item::Path { path, .. } = &g.items[k] else { continue };
        let long = (path.end() - path.start).norm();
        assert!(long <= most, "{what}: a {long:.1} mm leader from {:?}", path.start);
    }
}

/// The nomogram's r_min stands along its radius and the zone's name in two lines inside the
/// zone: a level r_min hung 22–35 mm off on a leader between the limiting lines
/// (custom-laws, translating-offset-auto), the zone's name in one line 36 mm off. Every
/// leader of the nomogram is at most 20 mm on every cam fixture and the worked example, in
/// every language.
#[test]
fn the_nomograms_labels_stand_near_what_they_name() {
    for f in cam_projects() {
        for lang in Language::ALL {
            let mut p = pipeline::load(&std::fs::read_to_string(&f).unwrap()).unwrap();
            p.info.language = lang;
            assert_leaders_within(&p, (3, "nomogram"), 20.0, &format!("{f:?} {lang:?}"));
        }
    }
}

/// The cam fixtures and the worked example's project file.
fn cam_projects() -> Vec<std::path::PathBuf> {
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(common::root().join("fixtures/cams"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    files.sort();
    files.push(common::root().join("fixtures/worked-example.yaml"));
    files
}
