//! A small deterministic generator for the random data of the grid tests.

/// 64-bit linear congruential generator (Knuth's MMIX constants), top 53 bits as `f64`.
pub struct Lcg(pub u64);

impl Lcg {
    /// The next value in `[0, 1)`.
    #[allow(clippy::should_implement_trait)] // an infinite stream of f64, not an Option
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// The next value in `[−1, 1)`.
    pub fn signed(&mut self) -> f64 {
        2.0 * self.next() - 1.0
    }
    /// An index in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
    /// Shuffles `v` (Fisher–Yates).
    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            v.swap(i, self.below(i + 1));
        }
    }
    /// `count` parameters in `[0, 1]` including both ends.
    pub fn params(&mut self, count: usize) -> Vec<f64> {
        let mut ts: Vec<f64> = (0..count).map(|_| self.next()).collect();
        ts[0] = 0.0;
        if count > 1 {
            ts[count - 1] = 1.0;
        }
        ts
    }
}
