//! The wheelie family's draws (`Family::Wheelies`): up to 5–15 km/h, then the rider's
//! weight back with the throttle open, then riding on, again and again, mostly over a row
//! of platforms, so the planner's cost-to-go learns what a wheelie asked for costs, on the
//! flat and with a wheel climbing a step.

use cpbp_core::bike::{DriveInput, RiderPosition};
use rand::RngExt;
use rand_pcg::Pcg64;

use crate::episode::{Ground, Segment};
use crate::family::{heading, up_to_speed, Drawn};

/// The steps (at 30 a second) of one wheelie: 0.4–1.2 s, about the bot's onto the skate
/// park's platform (from 2 m before its edge to the front wheel over it, 0.8 s). Longer
/// ones at a wide-open throttle ran the street 390 up to 60 km/h and more.
const WHEELIE_STEPS: std::ops::Range<usize> = 12..36;
/// The steps riding on between two: 0.7–2.5 s.
const RIDING_STEPS: std::ops::Range<usize> = 20..75;

pub fn draw_wheelies(rng: &mut Pcg64, steps: usize) -> Drawn {
    // Seven in ten over platforms up to 0.12–0.30 m, the rest on the flat.
    let ground = if rng.random::<f64>() < 0.7 {
        Ground::Platforms(rng.random_range(0.12..0.30))
    } else {
        Ground::Flat
    };
    let (drive, mut segments, mut start) = up_to_speed(rng, 0.4..1.0, 5.0..15.0);
    while start < steps {
        // The pedal well down, towards a speed above the one held (the game's is the
        // player's top speed, 40 km/h by default).
        let wheelie = DriveInput {
            throttle: rng.random_range(0.6..1.0),
            brake: 0.0,
            max_speed: drive.max_speed + rng.random_range(5.0..25.0) / 3.6,
        };
        let rider = RiderPosition {
            forward: -rng.random_range(0.6..1.0),
            right: rng.random_range(-0.2..0.2),
        };
        segments.push(Segment {
            start,
            drive: wheelie,
            rider,
            ..Segment::STRAIGHT
        });
        start += rng.random_range(WHEELIE_STEPS);
        if start < steps {
            // Half the time a light brake, so the speed the wheelies add is shed again
            // (a stop now and then, and a wheelie from a standstill after it).
            let riding = if rng.random::<f64>() < 0.5 {
                DriveInput {
                    throttle: 0.0,
                    brake: rng.random_range(0.2..0.5),
                    ..drive
                }
            } else {
                drive
            };
            segments.push(Segment {
                start,
                drive: riding,
                ..Segment::STRAIGHT
            });
            start += rng.random_range(RIDING_STEPS);
        }
    }
    (ground, segments, heading(rng))
}

#[cfg(test)]
mod tests {
    use cpbp_core::bike::{pitch_request, BikeParams};
    use cpbp_core::terrain::TerrainShape;
    use glam::DQuat;

    use super::*;
    use crate::episode::{Episode, ExpertSettings, Family};
    use crate::grounds::platform_pieces;

    fn settings() -> ExpertSettings {
        ExpertSettings {
            family: Family::Wheelies,
            ..ExpertSettings::default()
        }
    }

    #[test]
    fn a_wheelie_episode_asks_for_wheelies_between_stretches_of_riding_on() {
        let mut grounds = Vec::new();
        for seed in [1, 2, 3, 4, 5, 30_001] {
            let episode = Episode::draw(seed, &settings());
            assert_eq!(episode, Episode::draw(seed, &settings()));
            grounds.push(episode.ground);
            let first = episode.segments[0];
            assert_eq!((first.start, first.rider), (0, RiderPosition::NEUTRAL));
            assert!((5.0..15.0).contains(&(first.drive.max_speed * 3.6)));
            let ends = episode.segments.iter().skip(1).map(|s| s.start);
            let stretches: Vec<_> = episode.segments[1..]
                .iter()
                .zip(ends.skip(1).chain([episode.steps]))
                .collect();
            assert!(
                stretches.len() >= 6,
                "{} stretches in 12 s",
                stretches.len()
            );
            for (k, (segment, end)) in stretches.into_iter().enumerate() {
                let (steps, drive) = (end - segment.start, segment.drive);
                assert!(segment.stick == 0.0 && segment.lean.is_none() && segment.push == 0.0);
                if k % 2 == 0 {
                    // Back and the throttle open: the game's wheelie (pitch_request's lift).
                    let lift = pitch_request(&segment.rider, &drive).lift;
                    assert!(lift >= 0.36, "{segment:?}");
                    assert!(drive.max_speed > first.drive.max_speed && drive.brake == 0.0);
                    assert!(steps < WHEELIE_STEPS.end, "{steps}");
                } else {
                    assert_eq!(segment.rider, RiderPosition::NEUTRAL);
                    assert!(drive == first.drive || (drive.throttle == 0.0 && drive.brake > 0.0));
                    assert!(steps < RIDING_STEPS.end, "{steps}");
                }
            }
            assert!(
                episode
                    .simulation(&BikeParams::default())
                    .crashed()
                    .is_none(),
                "it starts upright, clear of the platforms"
            );
        }
        assert!(grounds.contains(&Ground::Flat), "{grounds:?}");
        assert!(grounds.iter().any(|g| matches!(g, Ground::Platforms(_))));
    }

    #[test]
    fn the_platforms_stand_ahead_in_a_row_no_taller_than_drawn() {
        let heading = DQuat::from_rotation_y(0.7);
        let pieces = platform_pieces(9, heading, 0.28);
        assert_eq!(
            pieces,
            platform_pieces(9, heading, 0.28),
            "drawn from the seed"
        );
        let boxes = &pieces[1..];
        assert!(boxes.len() >= 8, "{} platforms over 72 m", boxes.len());
        let mut behind = 8.0;
        for piece in boxes {
            let TerrainShape::Cuboid { size } = piece.shape else {
                panic!("{:?}", piece.shape);
            };
            assert!((0.1..=0.28).contains(&size.y) && (2.0..6.0).contains(&size.x));
            // Along the heading, resting on the ground, after the one before and a gap.
            let along = heading.inverse() * piece.placement.position;
            assert!((along.y - size.y / 2.0).abs() < 1e-9 && along.z.abs() < 1e-9);
            let from = along.x - size.x / 2.0;
            assert!(from >= behind - 1e-9, "{from} before {behind}");
            behind = along.x + size.x / 2.0 + 2.0;
        }
    }
}
