//! The `cagd` command line.

fn main() {
    println!("cagd");
}
