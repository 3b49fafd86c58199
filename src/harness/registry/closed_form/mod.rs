//! The closed forms the rows compare with, one file a source's section:
//! the laterally confined column and the extreme suite on it
//! ([`column`]), the block on an inclined plane ([`sliding_block`]), the
//! paper slope's slip circle ([`slip_circle`]), and the rock-slope
//! mechanisms of Hoek & Bray and Goodman & Bray ([`rock_slopes`]).

pub mod column;
pub mod rock_slopes;
pub mod sliding_block;
pub mod slip_circle;

pub use column::*;
pub use rock_slopes::*;
pub use sliding_block::*;
pub use slip_circle::*;
