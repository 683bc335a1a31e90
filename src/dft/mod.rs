//! Block diagonalisation of rotation-symmetric local matrices by the discrete
//! Fourier transform over the sector rotation group.

pub mod blocks;

pub use blocks::{fourier_blocks, fourier_blocks_from_rows, lazy_full_by_rotation, omega_pow, FourierBlock, Orbits};
