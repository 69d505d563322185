//! The `profsubd` command-line tool (under construction).

/// Run the CLI with the process arguments; returns the exit code.
pub fn main() -> i32 {
    0
}
