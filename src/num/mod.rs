//! Numerical ground rules shared by every domain: the limits of accepted input, named
//! tolerances with their units (and [`Near`] with `assert_near!` for the tests), the one
//! root finder, the sense of rotation, the mathematical functions whose results reach an output
//! (platform-independent), and the counts of the costly steps a build takes ([`work`]).

pub mod bezier;
pub mod digits;
pub mod limits;
pub mod math;
pub mod near;
pub mod roots;
pub mod sense;
pub mod tol;
pub mod units;
pub mod work;

pub use near::Near;
pub use sense::Sense;

/// Levenshtein distance, by characters (close names suggested for a misspelt key or id).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
