//! Embeds the catalogue (`catalogue/<folder>/{task.yaml, variants.csv, errata.csv}`): writes
//! `$OUT_DIR/catalogue.rs`, one `include_str!` triple per folder in name order, so that a
//! folder added to the catalogue needs no code.

use std::fmt::Write;
use std::path::Path;

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("catalogue");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut folders: Vec<String> = std::fs::read_dir(&root)
        .map(|dir| {
            dir.filter_map(Result::ok)
                .filter(|e| e.path().join("task.yaml").is_file())
                .filter_map(|e| e.file_name().into_string().ok())
                .collect()
        })
        .unwrap_or_default();
    folders.sort();
    let mut out = String::from("&[\n");
    for f in &folders {
        let dir = root.join(f);
        for file in ["task.yaml", "variants.csv", "errata.csv"] {
            println!("cargo:rerun-if-changed={}", dir.join(file).display());
        }
        let path = |file: &str| format!("{:?}", dir.join(file).display().to_string());
        let optional = |file: &str| {
            if dir.join(file).is_file() { format!("include_str!({})", path(file)) } else { "\"\"".to_string() }
        };
        writeln!(
            out,
            "    ({f:?}, include_str!({}), {}, {}),",
            path("task.yaml"),
            optional("variants.csv"),
            optional("errata.csv")
        )
        .unwrap();
    }
    out.push(']');
    let dest = Path::new(&std::env::var("OUT_DIR").unwrap()).join("catalogue.rs");
    std::fs::write(dest, out).unwrap();
}
