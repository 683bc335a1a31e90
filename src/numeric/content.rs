//! The content (gcd of all coefficients) of an integer vector, the step that
//! keeps exact polynomial recursions (Schur–Cohn, subresultants, Sturm) at
//! the size of their minors.
//!
//! Why not a fold of `Integer::gcd`: num-bigint's gcd is Stein's binary
//! algorithm, one multi-word shift per bit, and a fold calls it once per
//! coefficient with the running gcd — which by then is usually the content
//! already, so every call re-derives it bit by bit from a thousand-bit
//! coefficient that it divides (a Schur–Cohn disc test at degree 60 spent a
//! third of its time shifting). Here each coefficient is first reduced modulo
//! the running gcd (one division; a multiple leaves 0 and costs nothing
//! more), and the binary gcd runs only on what is left, below the running
//! gcd. gcd(g, c) = gcd(g, c mod g), so the result is the same number.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// gcd(c_0, c_1, ...) ≥ 0 (0 for no or only zero coefficients).
pub fn content<'a>(coefficients: impl IntoIterator<Item = &'a BigInt>) -> BigInt {
    let mut rest = coefficients.into_iter();
    let mut g = BigInt::zero();
    while let Some(c) = rest.next() {
        if g.is_one() {
            break;
        }
        if g.is_zero() {
            g = c.abs();
        } else {
            let r = c.mod_floor(&g);
            if !r.is_zero() {
                g = g.gcd(&r);
            }
        }
        // once the running gcd fits a machine word, the rest is word
        // arithmetic (a BigInt per step allocates; most denominators of a
        // subdivision matrix's exact rows are words from the start)
        if let Some(w) = g.to_u64().filter(|&w| w > 1) {
            let mut w = w;
            for c in rest.by_ref() {
                if w == 1 {
                    break;
                }
                let r = (c.magnitude() % w).to_u64().expect("a remainder modulo a word is a word");
                w = w.gcd(&r);
            }
            return BigInt::from(w);
        }
    }
    g
}

#[cfg(test)]
mod tests {
    use super::content;
    use num_bigint::BigInt;
    use num_integer::Integer;
    use num_traits::{One, Zero};

    /// The content equals the fold of the binary gcd over every coefficient,
    /// on vectors built to exercise each path: zeros first, negative
    /// coefficients, multiples of a large common factor (the remainder is
    /// 0), a factor that shrinks below a word, and unit content.
    #[test]
    fn content_equals_the_fold_of_gcds() {
        let big = |s: &str| s.parse::<BigInt>().unwrap();
        let p = big("340282366920938463463374607431768211507"); // a prime above 2^128
        let q = big("18446744073709551629"); // a prime above 2^64
        let cases: Vec<Vec<BigInt>> = vec![
            vec![],
            vec![BigInt::zero(), BigInt::zero()],
            vec![BigInt::zero(), -&p * 6, &p * 10, &p * &q * 14],
            vec![&p * &q * 3, -&p * &q * 5 * 7, &p * 4],
            vec![&p * 12, &q * 18, BigInt::from(30)],
            vec![&p * &q, &p * &q * 2 + 1],
            vec![BigInt::from(-12), BigInt::from(18), &p * 24],
            vec![&q * (BigInt::one() << 70u32), &q * (BigInt::one() << 65u32) * 3, -(&q * (BigInt::one() << 66u32))],
        ];
        for cs in cases {
            let want = cs.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
            assert_eq!(content(&cs), want, "{cs:?}");
        }
    }

    /// The same on pseudo-random vectors: a random common factor of 0 to 4
    /// words times random cofactors of 0 to 4 words, signs mixed, zeros
    /// among them (a fixed linear congruential generator: reproducible).
    #[test]
    fn content_equals_the_fold_on_random_vectors() {
        fn next(state: &mut u64) -> u64 {
            *state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            *state
        }
        fn random_big(words: u64, state: &mut u64) -> BigInt {
            (0..words).fold(BigInt::zero(), |acc, _| (acc << 64u32) + BigInt::from(next(state)))
        }
        let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
        for _ in 0..300 {
            let factor_words = next(&mut state) % 5;
            let factor: BigInt = random_big(factor_words, &mut state) + BigInt::one();
            let len = (next(&mut state) % 8) as usize;
            let mut cs: Vec<BigInt> = Vec::new();
            for _ in 0..len {
                let words = next(&mut state) % 5;
                let c: BigInt = &factor * random_big(words, &mut state);
                cs.push(if next(&mut state) % 2 == 0 { -c } else { c });
            }
            let want = cs.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
            assert_eq!(content(&cs), want, "{cs:?}");
        }
    }
}
