//! Checkpoints: what a long command has finished, written so that a run
//! killed at any instant can go on from it (`--resume DIR`) and give the same
//! bytes as a run that was never stopped.
//!
//! A checkpoint file is, in order: the magic `CDEMCKPT`, the format version
//! ([`FORMAT_VERSION`], u32 little-endian), the command's name (u8 length
//! and bytes), the digest of the scene and its mesh ([`scene_digest`], u64),
//! the payload's length (u64), the payload, and an FNV-1a 64 checksum of
//! everything before it (u64). Reading checks each in that order and refuses
//! the file with a [`CheckpointError`] naming what is wrong: never a
//! checkpoint of another scene, mesh, command or format version, nor a
//! truncated or corrupt one. Numbers are stored as their bits, so a state
//! read back is the state written, bit for bit.
//!
//! A checkpoint is written with [`crate::atomic::write_atomic`] (temporary
//! sibling, fsync, rename): killed while it writes, the previous checkpoint
//! stays whole. When it is written (every `--checkpoint-every` seconds of
//! wall time at the boundaries the command defines, and on SIGINT/SIGTERM)
//! never changes what it holds, only how much: the results depend on the
//! state, never on when it was saved.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::error::{CheckpointError, Error};
use crate::physics::joint::{JointState, JointStrength};
use crate::physics::mohr_coulomb::{MohrCoulomb, RockStrength, Yield};
use crate::physics::plastic::{CellPlastic, RockState, Screen, TetPlastic};
use crate::physics::spring::{SpringState, SpringStatus};
use crate::scene::Scene;
use crate::solver::State;
use crate::summary::EndState;

/// The checkpoint format this binary writes and reads (2: a joint's
/// strength is its law's tag and parameter list, for Barton-Bandis joints).
pub const FORMAT_VERSION: u32 = 2;
const MAGIC: &[u8; 8] = b"CDEMCKPT";
/// The checkpoint file's name in its directory.
pub const FILE_NAME: &str = "checkpoint.cdem";
/// The default of `--checkpoint-every` (s).
pub const DEFAULT_EVERY_S: f64 = 300.0;

/// FNV-1a, 64 bits.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// The digest of a scene (every value it was read into, its directory
/// left out) and its mesh file's bytes.
pub fn scene_digest(scene: &Scene) -> Result<u64, Error> {
    let mut s = scene.clone();
    let mesh = scene.mesh_path();
    s.base_dir = PathBuf::new();
    let mut bytes = format!("{s:?}").into_bytes();
    bytes.extend(std::fs::read(&mesh).map_err(|e| Error::io(&mesh, e))?);
    Ok(fnv1a(&bytes))
}

/// The digest of a state's displacements (bits).
pub fn state_digest(u: &[f64]) -> u64 {
    let bytes: Vec<u8> = u.iter().flat_map(|x| x.to_bits().to_le_bytes()).collect();
    fnv1a(&bytes)
}

/// How a command checkpoints: where, how often, and the signal flag the
/// command line sets (0: none; else the signal's number).
#[derive(Clone)]
pub struct Checkpointing {
    /// The directory the checkpoint is written into (the command's output
    /// directory).
    pub dir: PathBuf,
    /// The least wall time between two checkpoints (0: at every boundary).
    pub every: Duration,
    /// Read the checkpoint in this directory first and go on from it (none
    /// there: start from the beginning).
    pub resume: Option<PathBuf>,
    /// Set by the command line's signal handler to the signal's number.
    pub stop: Arc<AtomicUsize>,
}

impl Checkpointing {
    pub fn new(dir: &Path, every_s: f64, resume: Option<&Path>) -> Self {
        Self {
            dir: dir.to_path_buf(),
            every: Duration::from_secs_f64(if every_s.is_finite() { every_s.max(0.0) } else { 1e9 }),
            resume: resume.map(Path::to_path_buf),
            stop: Arc::new(AtomicUsize::new(0)),
        }
    }

    pub fn path(&self) -> PathBuf {
        self.dir.join(FILE_NAME)
    }

    /// The signal that asked the run to stop, if any.
    pub fn signal(&self) -> Option<i32> {
        match self.stop.load(Ordering::Relaxed) {
            0 => None,
            s => Some(s as i32),
        }
    }

    /// The error a run stopped by `signal` returns once its checkpoint is written.
    pub fn interrupted(&self, signal: i32) -> Error {
        let name = match signal {
            2 => "SIGINT",
            15 => "SIGTERM",
            _ => "signal",
        };
        Error::Interrupted { signal, name, checkpoint: self.path() }
    }

    /// Writes `payload` as the checkpoint of `command` for `digest`.
    pub fn write(&self, command: &str, digest: u64, payload: &[u8]) -> Result<(), Error> {
        std::fs::create_dir_all(&self.dir).map_err(|e| Error::io(&self.dir, e))?;
        let bytes = frame(command, digest, payload);
        let path = self.path();
        match stall() {
            // Tests only: write half the bytes, wait, then the rest, so that
            // a kill can land inside a checkpoint's write.
            Some(ms) => write_stalled(&path, &bytes, ms),
            None => crate::atomic::write_atomic(&path, &bytes).map_err(|e| Error::io(&path, e)),
        }
    }

    /// The payload of the checkpoint of `command` for `digest` in the
    /// `resume` directory; None if there is none (or no `resume`).
    pub fn read(&self, command: &str, digest: u64) -> Result<Option<Vec<u8>>, Error> {
        let Some(dir) = &self.resume else { return Ok(None) };
        let path = dir.join(FILE_NAME);
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(Error::io(&path, e)),
        };
        unframe(&bytes, command, digest).map(Some).map_err(|source| Error::Checkpoint { path, source })
    }

    /// Removes the checkpoint (the command finished and wrote its files).
    pub fn remove(&self) {
        let _ = std::fs::remove_file(self.path());
    }
}

/// `CDEM_TEST_CHECKPOINT_STALL_MS`: tests only (see [`Checkpointing::write`]).
fn stall() -> Option<u64> {
    std::env::var("CDEM_TEST_CHECKPOINT_STALL_MS").ok().and_then(|v| v.parse().ok())
}

fn write_stalled(path: &Path, bytes: &[u8], ms: u64) -> Result<(), Error> {
    use std::io::Write;
    let tmp = crate::atomic::partial_path(path);
    let mut f = std::fs::File::create(&tmp).map_err(|e| Error::io(&tmp, e))?;
    let half = bytes.len() / 2;
    f.write_all(&bytes[..half]).and_then(|_| f.flush()).map_err(|e| Error::io(&tmp, e))?;
    std::thread::sleep(Duration::from_millis(ms));
    f.write_all(&bytes[half..]).and_then(|_| f.sync_all()).map_err(|e| Error::io(&tmp, e))?;
    drop(f);
    crate::atomic::commit(&tmp, path).map_err(|e| Error::io(path, e))
}

/// The whole file of a checkpoint (see the module doc).
pub fn frame(command: &str, digest: u64, payload: &[u8]) -> Vec<u8> {
    let mut b = Vec::with_capacity(payload.len() + 64);
    b.extend_from_slice(MAGIC);
    b.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    b.push(command.len() as u8);
    b.extend_from_slice(command.as_bytes());
    b.extend_from_slice(&digest.to_le_bytes());
    b.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    b.extend_from_slice(payload);
    let sum = fnv1a(&b);
    b.extend_from_slice(&sum.to_le_bytes());
    b
}

/// The payload of a checkpoint file, checked (see the module doc).
pub fn unframe(bytes: &[u8], command: &str, digest: u64) -> Result<Vec<u8>, CheckpointError> {
    let n = bytes.len() as u64;
    if bytes.len() < MAGIC.len() || &bytes[..MAGIC.len()] != MAGIC {
        return Err(if MAGIC.starts_with(bytes) && !bytes.is_empty() {
            CheckpointError::Truncated { found: n, expected: MAGIC.len() as u64 }
        } else {
            CheckpointError::NotACheckpoint
        });
    }
    let u64_at =
        |at: usize| -> Option<u64> { bytes.get(at..at + 8).map(|s| u64::from_le_bytes(s.try_into().unwrap())) };
    let short = |expected: usize| CheckpointError::Truncated { found: n, expected: expected as u64 };
    let version = bytes.get(8..12).ok_or(short(12))?;
    let version = u32::from_le_bytes(version.try_into().unwrap());
    if version != FORMAT_VERSION {
        return Err(CheckpointError::Version { found: version, expected: FORMAT_VERSION });
    }
    let len = *bytes.get(12).ok_or(short(13))? as usize;
    let name = bytes.get(13..13 + len).ok_or(short(13 + len))?;
    let mut at = 13 + len;
    let found_digest = u64_at(at).ok_or(short(at + 8))?;
    at += 8;
    let payload_len = u64_at(at).ok_or(short(at + 8))?;
    at += 8;
    let total = (at as u64).saturating_add(payload_len).saturating_add(8);
    if n != total {
        return Err(CheckpointError::Truncated { found: n, expected: total });
    }
    let body = bytes.len() - 8;
    let (found, computed) = (u64_at(body).unwrap_or(0), fnv1a(&bytes[..body]));
    if found != computed {
        return Err(CheckpointError::Corrupt { found, computed });
    }
    if name != command.as_bytes() {
        return Err(CheckpointError::Command {
            found: String::from_utf8_lossy(name).into_owned(),
            expected: command.to_string(),
        });
    }
    if found_digest != digest {
        return Err(CheckpointError::Foreign { found: found_digest, expected: digest });
    }
    Ok(bytes[at..body].to_vec())
}

/// A deadline for the next checkpoint.
pub struct Clock {
    last: Instant,
    every: Duration,
}

impl Clock {
    pub fn new(every: Duration) -> Self {
        Self { last: Instant::now(), every }
    }
    /// Whether a checkpoint is due; if so the clock starts again.
    pub fn due(&mut self) -> bool {
        let due = self.last.elapsed() >= self.every;
        if due {
            self.last = Instant::now();
        }
        due
    }
}

/// The writer of a payload.
#[derive(Default)]
pub struct Enc(pub Vec<u8>);

/// The reader of a payload.
pub struct Dec<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Dec<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, at: 0 }
    }
    fn take(&mut self, n: usize) -> Result<&'a [u8], CheckpointError> {
        let s = self.bytes.get(self.at..self.at.saturating_add(n)).ok_or_else(|| self.bad("past the end"))?;
        self.at += n;
        Ok(s)
    }
    pub fn bad(&self, reason: &str) -> CheckpointError {
        CheckpointError::Content { offset: self.at, reason: reason.to_string() }
    }
    /// The payload has been read to its end.
    pub fn finish(&self) -> Result<(), CheckpointError> {
        if self.at == self.bytes.len() {
            Ok(())
        } else {
            Err(self.bad("bytes left over"))
        }
    }
}

/// A value a checkpoint holds, bit for bit.
pub trait Codec: Sized {
    fn put(&self, w: &mut Enc);
    fn get(r: &mut Dec) -> Result<Self, CheckpointError>;
}

impl Codec for u64 {
    fn put(&self, w: &mut Enc) {
        w.0.extend_from_slice(&self.to_le_bytes());
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        Ok(u64::from_le_bytes(r.take(8)?.try_into().unwrap()))
    }
}

impl Codec for usize {
    fn put(&self, w: &mut Enc) {
        (*self as u64).put(w)
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        let v = u64::get(r)?;
        usize::try_from(v).map_err(|_| r.bad("a count too large"))
    }
}

impl Codec for f64 {
    fn put(&self, w: &mut Enc) {
        self.to_bits().put(w)
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        u64::get(r).map(f64::from_bits)
    }
}

impl Codec for u8 {
    fn put(&self, w: &mut Enc) {
        w.0.push(*self)
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        Ok(r.take(1)?[0])
    }
}

impl Codec for bool {
    fn put(&self, w: &mut Enc) {
        (*self as u8).put(w)
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        match u8::get(r)? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(r.bad("a flag that is neither 0 nor 1")),
        }
    }
}

impl<T: Codec> Codec for Option<T> {
    fn put(&self, w: &mut Enc) {
        match self {
            None => 0u8.put(w),
            Some(v) => {
                1u8.put(w);
                v.put(w)
            }
        }
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        Ok(if bool::get(r)? { Some(T::get(r)?) } else { None })
    }
}

impl<T: Codec> Codec for Vec<T> {
    fn put(&self, w: &mut Enc) {
        self.len().put(w);
        for v in self {
            v.put(w);
        }
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        let n = usize::get(r)?;
        // Every value takes at least one byte: a length past the payload is corrupt.
        if n > r.bytes.len() - r.at {
            return Err(r.bad("a length past the end"));
        }
        (0..n).map(|_| T::get(r)).collect()
    }
}

impl<T: Codec + Copy + Default, const N: usize> Codec for [T; N] {
    fn put(&self, w: &mut Enc) {
        for v in self {
            v.put(w);
        }
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        let mut out = [T::default(); N];
        for v in &mut out {
            *v = T::get(r)?;
        }
        Ok(out)
    }
}

/// A fieldless enum as its index.
macro_rules! enum_codec {
    ($t:ty, $($v:path),+) => {
        impl Codec for $t {
            fn put(&self, w: &mut Enc) {
                let all = [$($v),+];
                (all.iter().position(|v| v == self).expect("every variant listed") as u8).put(w)
            }
            fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
                let all = [$($v),+];
                let i = u8::get(r)? as usize;
                all.get(i).copied().ok_or_else(|| r.bad(concat!("an unknown ", stringify!($t))))
            }
        }
    };
}

enum_codec!(SpringStatus, SpringStatus::Intact, SpringStatus::Tension, SpringStatus::Shear);
enum_codec!(Yield, Yield::Elastic, Yield::Shear, Yield::Tension);
enum_codec!(EndState, EndState::Equilibrium, EndState::GlobalSliding, EndState::Undecided);

/// A struct field by field; the destructuring fails to compile when the
/// struct gains a field the checkpoint does not hold.
macro_rules! struct_codec {
    ($t:ident { $($f:ident),+ }) => {
        impl Codec for $t {
            fn put(&self, w: &mut Enc) {
                let $t { $($f),+ } = self;
                $($f.put(w);)+
            }
            fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
                Ok($t { $($f: Codec::get(r)?),+ })
            }
        }
    };
}

/// A joint's strength: its law's tag and [`JointStrength::words`].
impl Codec for JointStrength {
    fn put(&self, w: &mut Enc) {
        let (tag, words) = self.words();
        tag.put(w);
        words.put(w);
    }
    fn get(r: &mut Dec) -> Result<Self, CheckpointError> {
        let tag = u8::get(r)?;
        let words = Vec::<f64>::get(r)?;
        JointStrength::from_words(tag, &words).ok_or_else(|| r.bad("a joint strength of an unknown law or shape"))
    }
}
struct_codec!(JointState { strength });
struct_codec!(SpringState { slip, status });
struct_codec!(RockStrength { cohesion, tan_phi, tensile, tan_psi });
struct_codec!(MohrCoulomb { k, sin_phi, sin_psi, tensile });
struct_codec!(TetPlastic { eps_p, now, ever, ever_tension });
struct_codec!(Screen { u_check, offset, radius2 });
struct_codec!(CellPlastic { stress, yielding, yielded, yielding_tension, yielded_tension, plastic_shear });
struct_codec!(RockState {
    given,
    surface,
    history,
    volumetric,
    pressure,
    vertex_strain,
    vertex_pressure,
    smoothing,
    cell_strain,
    used_strain,
    cell_stress,
    vertex_dev_strain,
    vertex_dev_stress,
    screen
});
struct_codec!(State { u, v, f_int, springs, joints, rock, step, time });

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_reads_back_and_each_damage_is_named() {
        let payload: Vec<u8> = (0..100u8).collect();
        let f = frame("srm", 7, &payload);
        assert_eq!(unframe(&f, "srm", 7).unwrap(), payload);
        assert!(matches!(unframe(&f[..f.len() - 1], "srm", 7), Err(CheckpointError::Truncated { .. })));
        assert!(matches!(unframe(&f[..5], "srm", 7), Err(CheckpointError::Truncated { .. })));
        let mut bad = f.clone();
        bad[40] ^= 1;
        assert!(matches!(unframe(&bad, "srm", 7), Err(CheckpointError::Corrupt { .. })));
        assert!(matches!(unframe(&f, "srm", 8), Err(CheckpointError::Foreign { found: 7, expected: 8 })));
        assert!(matches!(unframe(&f, "run", 7), Err(CheckpointError::Command { .. })));
        assert_eq!(unframe(b"hello world, not a checkpoint", "srm", 7), Err(CheckpointError::NotACheckpoint));
        let mut v2 = f.clone();
        v2[8] = 1;
        assert_eq!(unframe(&v2, "srm", 7), Err(CheckpointError::Version { found: 1, expected: FORMAT_VERSION }));
    }

    #[test]
    fn numbers_come_back_bit_for_bit() {
        let xs = vec![0.1, -0.0, f64::INFINITY, f64::NAN, f64::MIN_POSITIVE / 3.0];
        let mut w = Enc::default();
        xs.put(&mut w);
        Some(SpringStatus::Shear).put(&mut w);
        let mut r = Dec::new(&w.0);
        let back = Vec::<f64>::get(&mut r).unwrap();
        assert!(xs.iter().zip(&back).all(|(a, b)| a.to_bits() == b.to_bits()));
        assert_eq!(Option::<SpringStatus>::get(&mut r).unwrap(), Some(SpringStatus::Shear));
        r.finish().unwrap();
    }
}
