//! Long work in chunks, between which the caller may stop it (Octave's Ctrl-C): the
//! evaluations of this layer ask an [`Interrupt`] every few milliseconds of work.

use super::error::{NurbsError, Result};

/// The work between two questions, in operations of one `f64` each: a few milliseconds.
pub const CHECK_WORK: u128 = 1 << 22;

/// Most items (parameters, points) between two questions, however cheap each is.
const MOST_ITEMS: u128 = 4096;

/// Whether the caller asked to stop, asked between chunks of about [`CHECK_WORK`]
/// operations; when it answers `true` the work stops with [`NurbsError::Interrupted`].
///
/// ```
/// use cagd_octave::octave_nurbs::{Interrupt, NurbsError};
/// assert!(Interrupt::never().check().is_ok());
/// let stop = || true;
/// assert_eq!(Interrupt::new(&stop).check(), Err(NurbsError::Interrupted));
/// // A point of a million operations is asked about every 4 points, a cheap one every 4096.
/// assert_eq!((Interrupt::chunk(1_000_000), Interrupt::chunk(10)), (4, 4096));
/// ```
#[derive(Clone, Copy)]
pub struct Interrupt<'a> {
    asked: &'a (dyn Fn() -> bool + Sync),
}

impl std::fmt::Debug for Interrupt<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Interrupt")
    }
}

/// The question of work nobody interrupts.
fn never() -> bool {
    false
}

impl<'a> Interrupt<'a> {
    /// Asks `asked`.
    pub fn new(asked: &'a (dyn Fn() -> bool + Sync)) -> Self {
        Interrupt { asked }
    }

    /// Never stops.
    pub fn never() -> Interrupt<'static> {
        Interrupt { asked: &never }
    }

    /// Stops with [`NurbsError::Interrupted`] if the caller asked to.
    ///
    /// # Errors
    /// [`NurbsError::Interrupted`].
    pub fn check(&self) -> Result<()> {
        if (self.asked)() {
            return Err(NurbsError::Interrupted);
        }
        Ok(())
    }

    /// The items of `per_item` operations each to do between two questions: about
    /// [`CHECK_WORK`] operations, at least 1, at most 4096.
    pub fn chunk(per_item: u128) -> usize {
        (CHECK_WORK / per_item.max(1)).clamp(1, MOST_ITEMS) as usize
    }

    /// The questions of a loop over `items` items of `per_item()` operations each: after
    /// every [`chunk`](Self::chunk) of them, none for [`FEW_ITEMS`] or fewer (a call for one
    /// point neither asks nor estimates).
    pub fn poll(self, items: usize, per_item: impl FnOnce() -> u128) -> Poll<'a> {
        let chunk = if items > FEW_ITEMS {
            Self::chunk(per_item())
        } else {
            usize::MAX
        };
        Poll {
            interrupt: self,
            chunk,
            next: chunk,
        }
    }
}

/// Loops over this many items or fewer do not ask (at most a few milliseconds even for items
/// of a million operations each, a point of degree 1000).
pub const FEW_ITEMS: usize = 16;

/// The questions of one loop ([`Interrupt::poll`]).
///
/// ```
/// use cagd_octave::octave_nurbs::{Interrupt, NurbsError};
/// let stop = || true;
/// let mut poll = Interrupt::new(&stop).poll(10_000, || 1_000_000);
/// // Asked after every 4 items of a million operations: item 4 is the first to stop.
/// assert!((0..4).all(|k| poll.at(k).is_ok()));
/// assert_eq!(poll.at(4), Err(NurbsError::Interrupted));
/// let mut few = Interrupt::new(&stop).poll(16, || 1_000_000);
/// assert!((0..16).all(|k| few.at(k).is_ok()));
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Poll<'a> {
    interrupt: Interrupt<'a>,
    chunk: usize,
    next: usize,
}

impl Poll<'_> {
    /// Before item `k` (counted from 0, increasing): asks at the end of each chunk.
    ///
    /// # Errors
    /// [`NurbsError::Interrupted`].
    #[inline]
    pub fn at(&mut self, k: usize) -> Result<()> {
        if k < self.next {
            return Ok(());
        }
        self.next = k.saturating_add(self.chunk);
        self.interrupt.check()
    }
}
