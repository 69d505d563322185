//! The `profsubd` command-line tool; all logic lives in the library's `cli` module.

fn main() {
    std::process::exit(profsubd::cli::main());
}
