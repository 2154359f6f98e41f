//! Godot's `RandomNumberGenerator`, number for number: the test level's logs were laid by
//! it before the core laid them, and every committed experiment ride met those logs, so
//! the core draws the same numbers from the same seed.
//!
//! Godot's generator is PCG32 (XSH RR, 64-bit state) seeded by `pcg32_srandom_r` with
//! Godot's default stream, which is `rand_pcg::Pcg32::new(seed, stream)` exactly. On top
//! of it Godot builds its own floats (`RandomPCG::randf`, core/math/random_pcg.h): the
//! exponent from the leading zeros of one draw, the mantissa from a second, in single
//! precision, as `randf_range` returns them in the engine's single-precision build.

use rand::Rng;
use rand_pcg::Pcg32;

/// Godot's default PCG stream (`PCG_DEFAULT_INC_64`), which every `RandomNumberGenerator`
/// uses.
const GODOT_STREAM: u64 = 1_442_695_040_888_963_407;

/// The numbers a Godot `RandomNumberGenerator` with `seed` set gives.
pub struct GodotRandom {
    pcg: Pcg32,
}

impl GodotRandom {
    /// As `RandomNumberGenerator.seed = seed` (GDScript's negative ints wrap as Godot's do).
    pub fn new(seed: i64) -> Self {
        Self {
            pcg: Pcg32::new(seed as u64, GODOT_STREAM),
        }
    }

    /// As `randi()`.
    pub fn randi(&mut self) -> u32 {
        self.pcg.next_u32()
    }

    /// As `randf()`: in [0, 1], the fraction's exponent drawn as a run of zero bits.
    pub fn randf(&mut self) -> f32 {
        let exponent_draw = self.randi();
        if exponent_draw == 0 {
            return 0.0;
        }
        let mantissa = (self.randi() | 0x8000_0001) as f32;
        let exponent = -32 - exponent_draw.leading_zeros() as i32;
        // A power of two times an f32 is exact here (no underflow above 2^-64), as ldexpf.
        mantissa * 2f32.powi(exponent)
    }

    /// As `randf_range(from, to)`, in single precision as the engine computes it.
    pub fn randf_range(&mut self, from: f32, to: f32) -> f32 {
        self.randf() * (to - from) + from
    }
}

#[cfg(test)]
mod tests {
    use super::GodotRandom;

    /// Numbers Godot 4.6.3 printed for these seeds (`RandomNumberGenerator`, `var_to_str`):
    /// the GDScript suite checks the same against the running engine.
    #[test]
    fn draws_what_godot_draws() {
        let mut rng = GodotRandom::new(1);
        let raw: Vec<u32> = (0..4).map(|_| rng.randi()).collect();
        assert_eq!(raw, [1811587497, 683407368, 2033395789, 2375931748]);
        let cases: [(i64, [f32; 6]); 3] = [
            (
                1,
                [
                    -2.3861728, -3.1276722, 0.13733482, 3.3883038, 0.3341856, -6.3356495,
                ],
            ),
            (
                1042,
                [
                    -5.91199, -4.02702, -1.350215, -3.4115083, -5.220774, 0.59023476,
                ],
            ),
            (
                -5,
                [
                    -1.730042, 1.404069, -2.9429822, 3.1128607, 5.328577, -5.1634865,
                ],
            ),
        ];
        for (seed, expected) in cases {
            let mut rng = GodotRandom::new(seed);
            let drawn: Vec<f32> = (0..6).map(|_| rng.randf_range(-7.0, 7.0)).collect();
            assert_eq!(drawn, expected, "seed {seed}");
        }
    }
}
