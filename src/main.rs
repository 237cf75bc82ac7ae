//! `tmm`: builds the course project's drawing sheets. Thin: parse arguments, run, report.

fn main() -> std::process::ExitCode {
    match tmm_sheets::cli::run() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
