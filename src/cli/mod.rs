//! The `subdlab` command line. Every analysis command (`spectrum`,
//! `stencils`, `matrix`, `charmap`, `curvature`) takes the same scheme and
//! configuration flags ([`SchemeArgs`]: the scheme, `--valence N`, repeated
//! `--param NAME=VALUE`, `--faces`) and `--json`; the scheme is resolved once
//! (`front_door`) and its domain decides which analyses run on it. Errors are
//! one line on stderr with a non-zero exit.

mod args;
mod charmap_commands;
mod command_line;
mod commands;
mod curvature;
mod dispatch;
mod entry;
mod every_valence;
mod front_door;
mod lattice;
mod mesh_analysis;
mod mesh_commands;
mod shape_chart;
mod verify;

pub use args::{AnalysisArgs, FigureArgs, SchemeArgs, SweepArgs};
pub use command_line::{Cli, Command};
pub use entry::{main, run};
