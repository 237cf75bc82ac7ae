//! `tmm`: builds the course project's drawing sheets. Thin: parse arguments, run, report.

fn main() -> std::process::ExitCode {
    tmm_sheets::cli::run()
}
