//! The rollout's cost terms, each against the same rollout without it.

use super::*;
use crate::bike::{BikeParams, Part, Placement};
use crate::control::lean::lean_on_the_way;
use crate::simulation::{Simulation, SimulationConfig};
use crate::terrain::Terrain;

/// A rollout of `bike` standing on ice (friction 0.1), its wheels down, with every
/// body sliding at 2 m/s across its heading, as a bike does once its tyres let go.
fn sliding_rollout(bike: BikeParams) -> BikeRollout {
    let mut rollout = standing_rollout(BikeParams {
        tyre_friction: 0.1,
        ..bike
    });
    let across = rollout
        .bike
        .heading(&rollout.world, rollout.up)
        .cross(rollout.up);
    for body in 0..rollout.world.body_count() {
        let id = crate::ode::BodyId(body);
        rollout.world.set_body_linear_velocity(id, across * 2.0);
    }
    rollout
}

/// A rollout of `bike` standing upright on flat ground, its wheels down.
fn standing_rollout(bike: BikeParams) -> BikeRollout {
    let config = SimulationConfig {
        bike,
        ..SimulationConfig::default()
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        ..Placement::IDENTITY
    };
    let mut sim = Simulation::new(config, Arc::new(Terrain::flat()), spawn);
    // A few steps to set the tyres on the ground.
    for _ in 0..6 {
        sim.step();
    }
    let mut rollout = BikeRollout {
        world: sim.new_world(),
        bike: sim.bike().clone(),
        gravity: sim.config().gravity,
        up: sim.up(),
        step_dt: sim.config().control_dt,
        stepping: RolloutStepping::uniform(sim.config().substeps),
        goal: Goal::default(),
        tolerances: CostTolerances::default(),
        policy: None,
        start: PlanStart::default(),
        value: None,
        fallen: false,
    };
    rollout.restore(&sim.world().snapshot());
    rollout
}

/// The costs of two rollouts' first steps with the controls at rest. A cost term never
/// touches the physics: both worlds end the step alike.
fn first_step_of_both(a: &mut BikeRollout, b: &mut BikeRollout) -> (f64, f64) {
    let u = [0.0; CONTROL_DIM];
    let costs = (
        a.step(&u, 0).expect("the bike steps"),
        b.step(&u, 0).expect("the bike steps"),
    );
    let frame = a.bike.body(Part::Frame);
    assert_eq!(a.world.body_position(frame), b.world.body_position(frame));
    costs
}

#[test]
fn a_slide_tolerance_costs_the_tyres_sideways_slide_in_tolerances_squared() {
    let tolerance = 0.5;
    let mut plain = sliding_rollout(BikeParams::default());
    let mut costed = sliding_rollout(BikeParams {
        planners_slide_tolerance: tolerance,
        ..BikeParams::default()
    });
    let (without, with) = first_step_of_both(&mut plain, &mut costed);
    let slide = costed.bike.tyre_side_slide(&costed.world, costed.up);
    assert!(
        slide.abs() > 0.5,
        "the tyres still slide after one step: {slide}"
    );
    let expected = (slide / tolerance).powi(2);
    assert!(
        (with - without - expected).abs() < 1e-9,
        "{with} − {without} ≠ {expected}"
    );
}

#[test]
fn the_lean_reference_asks_the_first_steps_for_a_lean_on_the_way_from_the_start() {
    let asked = 0.7;
    let goal = Goal {
        lean: asked,
        ..Goal::default()
    };
    let mut thesis = standing_rollout(BikeParams::default());
    let mut referenced = standing_rollout(BikeParams {
        planners_lean_reference: true,
        ..BikeParams::default()
    });
    thesis.goal = goal;
    referenced.goal = goal;
    let (at_once, on_the_way) = first_step_of_both(&mut thesis, &mut referenced);
    let start = referenced.start;
    assert!(
        start.lean.abs() < 0.02,
        "it started upright: {}",
        start.lean
    );
    // The reference bike's centre of mass stands about 0.6 m over its contact line.
    assert!((0.2..0.3).contains(&start.fall_time), "{}", start.fall_time);
    let first = lean_on_the_way(start.lean, asked, thesis.step_dt, start.fall_time);
    assert_eq!(referenced.goal_lean(0), first);
    assert!(first < asked / 2.0, "one step in, not half way: {first}");
    assert!(on_the_way < at_once / 2.0, "{on_the_way} against {at_once}");
    // A later step of the same plan asks from the same start, closer to the goal.
    assert!(referenced.goal_lean(20) > 0.9 * asked);
}

/// A rollout of `bike` standing upright with every body turning at `rate` rad/s about
/// the tyres' contact line (the heading at the ground), as a bike starts to fall.
fn rolling_rollout(bike: BikeParams, rate: f64) -> BikeRollout {
    let mut rollout = standing_rollout(bike);
    let heading = rollout.bike.heading(&rollout.world, rollout.up);
    let spin = heading * rate;
    for body in 0..rollout.world.body_count() {
        let id = crate::ode::BodyId(body);
        let from_line = rollout.world.body_position(id).reject_from(heading);
        rollout.world.set_body_angular_velocity(id, spin);
        rollout
            .world
            .set_body_linear_velocity(id, spin.cross(from_line));
    }
    rollout
}

#[test]
fn looking_ahead_costs_the_lean_the_roll_is_heading_for() {
    let mut thesis = rolling_rollout(BikeParams::default(), 1.0);
    let mut ahead = rolling_rollout(
        BikeParams {
            planners_lean_lookahead: true,
            ..BikeParams::default()
        },
        1.0,
    );
    let (now, looking) = first_step_of_both(&mut thesis, &mut ahead);
    let costed = ahead.costed_lean();
    let rate = ahead.bike.lean_rate(&ahead.world, ahead.up);
    assert!(rate > 0.8, "still rolling right after one step: {rate}");
    let expected = ((costed.lean + rate * costed.fall_time) / ahead.tolerances.lean).powi(2);
    assert!((looking - expected).abs() < 1e-9, "{looking} ≠ {expected}");
    // Nearly upright and falling away from an upright goal, looking ahead costs the lean
    // a quarter of a second on, many times today's cost of where the bike is.
    assert!(looking > 4.0 * now, "{looking} against {now}");
}

#[test]
fn a_bike_that_holds_the_rider_costs_a_released_riders_weight_off_the_riding_pose() {
    let hold = 0.1;
    let mut free = standing_rollout(BikeParams::default());
    let mut held = standing_rollout(BikeParams {
        planners_rider_hold: hold,
        ..BikeParams::default()
    });
    assert_eq!(held.goal.rider.engagement(), 0.0, "the stick is released");
    let (without, with) = first_step_of_both(&mut free, &mut held);
    let expected = hold * off_the_riding_pose(&held);
    assert!(
        expected > 0.0,
        "the standing rider sits off the riding pose"
    );
    assert!(
        (with - without - expected).abs() < 1e-9,
        "{with} − {without} ≠ {expected}"
    );
}

#[test]
fn the_rider_hold_fades_out_towards_rest() {
    let bike = BikeParams {
        planners_rider_hold: 0.1,
        planners_rider_hold_speed: 4.0,
        ..BikeParams::default()
    };
    assert_eq!(bike.planners_rider_hold_at(8.0), 0.1);
    assert!((bike.planners_rider_hold_at(1.0) - 0.025).abs() < 1e-15);
    assert_eq!(bike.planners_rider_hold_at(0.0), 0.0);
    assert_eq!(bike.planners_rider_hold_at(-2.0), 0.0, "backwards: none");
    // A bike standing still holds its rider a speed's worth: next to nothing.
    let mut free = standing_rollout(BikeParams::default());
    let mut held = standing_rollout(bike.clone());
    let (without, with) = first_step_of_both(&mut free, &mut held);
    let speed = held.bike.forward_speed(&held.world, held.up);
    assert!(speed.abs() < 0.1, "standing: {speed} m/s");
    let faded = bike.planners_rider_hold_at(speed);
    assert!(faded < 0.03 * 0.1, "faded to under 3 % at rest: {faded}");
    let expected = faded * off_the_riding_pose(&held);
    assert!(
        (with - without - expected).abs() < 1e-9,
        "{with} − {without} ≠ {expected}"
    );
}

/// How far the rollout's rider sits off the riding pose, fore/aft and sideways, squared in
/// units of the rider tolerance: what a full stick's firmness costs.
fn off_the_riding_pose(rollout: &BikeRollout) -> f64 {
    let off = rollout.bike.rider_offset(&rollout.world);
    let tolerance = rollout.tolerances.rider;
    (off.x * off.x + off.z * off.z) / (tolerance * tolerance)
}

#[test]
fn a_plan_made_while_the_rider_asks_for_a_wheelie_or_a_stoppie_has_no_cost_to_go() {
    use crate::bike::{DriveInput, RiderPosition};
    use crate::control::learned::{NetworkParts, ValueNetwork, VALUE_INPUT_COUNT};
    // A network that answers ln(1 + cost) = 1 wherever it is asked.
    let network = ValueNetwork::new(NetworkParts {
        input_mean: vec![0.0; VALUE_INPUT_COUNT],
        input_std: vec![1.0; VALUE_INPUT_COUNT],
        layers: vec![(vec![0.0; VALUE_INPUT_COUNT], vec![1.0])],
        output_mean: vec![0.0],
        output_std: vec![1.0],
        training: "by hand".into(),
        bike: BikeParams::default().identity(),
    })
    .unwrap();
    let mut rollout = standing_rollout(BikeParams::default());
    rollout.value = Some(TerminalValue {
        network: Arc::new(network),
        remaining_s: 0.6,
    });
    let drive = |throttle: f64, brake: f64| DriveInput {
        throttle,
        brake,
        max_speed: 5.0,
    };
    let rider = |forward: f64| RiderPosition {
        forward,
        right: 0.0,
    };
    let mut asked = |drive: DriveInput, rider: RiderPosition| {
        rollout.goal = Goal {
            lean: 0.0,
            drive,
            rider,
        };
        rollout.terminal_cost()
    };
    let riding = asked(drive(0.6, 0.0), rider(0.0)).expect("costed riding on");
    assert!((riding - (1f64.exp() - 1.0)).abs() < 1e-9, "{riding}");
    // The weight back with no throttle, or forward with no brake, asks no pitch.
    assert!(asked(drive(0.0, 0.0), rider(-1.0)).is_some());
    assert!(asked(drive(0.0, 0.0), rider(1.0)).is_some());
    assert_eq!(asked(drive(0.6, 0.0), rider(-1.0)), None, "a wheelie");
    assert_eq!(asked(drive(0.0, 0.8), rider(1.0)), None, "a stoppie");
}
