//! The `profsubd` command-line tool; all logic lives in [`profsubd::cli`].

fn main() {
    std::process::exit(profsubd::cli::main());
}
