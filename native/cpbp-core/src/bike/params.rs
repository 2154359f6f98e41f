//! Dimensions and masses of the bike and rider, with where the numbers come from.
//!
//! Frame of the model ("bike frame"): x forward, y up, z to the rider's right; the origin
//! is on the ground midway between the two wheels' contact points, bike upright.
//!
//! **Motorcycle**: a light road bike of the 300–400 cc class (e.g. KTM 390 Duke, Honda
//! CB300R; manufacturers' published specifications): wheelbase 1.36–1.40 m, rake (caster)
//! 24.5–25°, trail 95–100 mm, 17-inch wheels (0.60 m tyre diameter), about 150 kg ready
//! to ride. Wheel, fork and frame shares of that mass follow typical component weights
//! (cast wheel with tyre and disc: front ≈ 10 kg, rear ≈ 14 kg; fork with bars ≈ 12 kg, of
//! which the lower legs with axle and caliper ≈ 4 kg slide; swingarm ≈ 6 kg). Suspension:
//! see `suspension.rs`.
//!
//! **Rider**: an adult of 75 kg and 1.75 m. Segment masses and lengths are the fractions of
//! Winter, *Biomechanics and Motor Control of Human Movement* (4th ed., 2009, table 4.1):
//! thigh 0.100 M and 0.245 H, shank 0.0465 M and 0.246 H, foot 0.0145 M, upper arm
//! 0.028 M and 0.186 H, forearm 0.016 M, hand 0.006 M, trunk with head and neck 0.578 M.
//! The model has one leg and one arm in the mid-plane (as in the thesis, §4.2), so they
//! carry the mass of both sides: legs 15.0 kg (thighs) and 9.15 kg (shanks and feet),
//! arms 4.2 kg (upper) and 3.3 kg (forearms and hands); torso with head 43.35 kg.

use super::engine::RearWheelDrive;
use super::feet::Feet;
use super::front_brake::FrontBrake;
use super::posture::Posture;
use super::suspension::Suspension;
use super::wheelie_control::WheelieControl;

/// Gravity the bike is set up for (m/s²): the suspension's preload carries its weight.
pub const GRAVITY: f64 = 9.81;

/// Every number that shapes the bike and rider. `Default` is the reference bike.
#[derive(Clone, Debug, PartialEq)]
pub struct BikeParams {
    /// Distance between the wheels' ground contact points (m).
    pub wheelbase: f64,
    /// Wheel radius, tyre included (m).
    pub wheel_radius: f64,
    /// Radius of the tyre's round cross-section (m): 110–150 mm wide road tyres have a
    /// crown radius of about 50–75 mm. It decides where a leaning wheel touches the road.
    pub tyre_crown: f64,
    /// Angle of the steering axis from vertical (rad).
    pub rake: f64,
    /// Ground distance from the front contact point back to where the steering axis meets
    /// the ground (m); positive trail is what makes a bike self-aligning.
    pub trail: f64,
    pub rear_wheel_mass: f64,
    pub front_wheel_mass: f64,
    /// The steered fork above the sliders: stanchions, clamps, handlebar.
    pub fork_mass: f64,
    /// The fork's lower legs (sliders), axle and caliper: unsprung.
    pub fork_lower_mass: f64,
    pub frame_mass: f64,
    pub swingarm_mass: f64,
    /// Rider segments: lower leg, upper leg, torso with head, upper arm, lower arm (kg).
    pub rider_masses: [f64; 5],
    /// Where the rider sits: footpeg, seat, torso, grips (`Posture`).
    pub posture: Posture,
    /// How hard the rider braces the arms fore and aft while braking: the share
    /// of the arms' full strength reached at the full brake (`Bike::braced_arms`; 0: the
    /// arms as the physics model has them, the reference bike's).
    pub rider_brace: f64,
    /// Whether the rider's wrists turn with the bar: the wrist's motor turns about the
    /// steering axis and only damps the turn there, as a hand on a grip lets the bar turn
    /// in it, instead of holding the hand's pose at the bar within ±34°. Off, the
    /// reference bike's: held, the rider's sway about the peg drives a wrist to its stop
    /// and the rider's weight then holds the bar (on the sport 600's clip-ons arcade fell
    /// in 18 of 30 shoves, steering stuck at 11° while the lean ran to 62°; none with
    /// the wrists following, docs/bike-model.md, "The wrists follow the bar").
    pub rider_wrists_follow_bar: bool,
    /// Largest steering angle either way (rad).
    pub steer_limit: f64,
    /// The most torque (N·m) the rider turns the bar with: the reference bike's 60. At
    /// 60 km/h the street bike leaned past about 40° needs more to hold the lean: arcade
    /// asks the bar to turn at 50°/s, it moves at a fraction of a degree per second, and
    /// the lean creeps past the tyres' grip; with 80 it holds 45° within 0.5°, with 100
    /// exactly (issue 68).
    pub max_steer_torque: f64,
    /// The speed (m/s) the arcade controller's gains hold at; faster they shrink in
    /// proportion to it (`ArcadeGains::at_speed`); 0 keeps them at every speed, as on
    /// the reference bike, whose thesis tuned them at 25 km/h.
    pub arcade_tuned_speed: f64,
    /// Coulomb friction coefficient of tyres on the ground.
    pub tyre_friction: f64,
    /// Whether the tyres' friction acts along and across each wheel, so grip is the same
    /// at every heading (`World::set_tyre_friction_follows_wheel`). Off, the reference
    /// bike's: ODE's friction pyramid then takes world axes on level ground, and a tyre
    /// heading diagonally to them grips up to √2 times harder than one heading along one.
    pub tyre_friction_follows_wheel: bool,
    /// The deepest lean (rad) the turn command asks for (`TurnIntent::for_bike`): the
    /// reference bike's 30°, where the thesis's arcade controller, with the rider upright
    /// in the mid-plane, still holds long circles (it overshoots deeper leans and falls:
    /// 45° within seconds, 35° at 20 km/h).
    pub max_lean: f64,
    /// Whether the planners cost the frame's roll against the lean asked, as arcade, the
    /// HUD and `max_lean` measure a lean, instead of eq. 4.7's lean of the centre of mass
    /// over the support point. A round tyre touches the road inside the wheel's plane, so
    /// the centre of mass leans less than the frame: on the street bike 45° of frame roll
    /// is about 41° of it, and asked eq. 4.7's 45° a planner asks the tyres for μ = 1.00
    /// where the frame's 45° asks 0.87. Off, the reference plans as the thesis did.
    pub planners_cost_frame_roll: bool,
    /// The lean (rad, the frame's roll, leaned or asked) from which the planners' rollouts
    /// step as the master does (`SimulationConfig::substeps`) instead of the physics
    /// model's coarser `rollout_stepping`. Leaned deep at speed the coarse rollouts lose
    /// the master: on the street bike in a 45° bend at 60 km/h the model's drift 12.9° of
    /// roll in 0.5 s (its 100 N·m at the bar answers the coarse steps' errors harder),
    /// where the reference's 30° bend drifts 1.7°, every rollout of optimizer-10 then
    /// foresees a fall and it fell out of the bend (docs/benchmarks.md, "Rollout fidelity").
    /// The master's stepping costs about 3× the model's, in those leans only. 90° (the
    /// default) never: the reference plans as the thesis did.
    pub planners_exact_from_lean: f64,
    /// The tyres' sideways slide (m/s, `Bike::tyre_side_slide`) that costs the planners
    /// as much as the lean tolerance's error; 0 (the default) costs none, as the thesis.
    /// ODE's Coulomb friction grips as hard sliding as rolling, so a lean held in a slide
    /// costs eq. 4.7 nothing: in the street bike's 45° bend at 60 km/h optimizer-10, even
    /// with the master's rollouts, held the lean in a drift, the tyres 1.9–4.3 m/s sideways
    /// on average and the bar 6–18° against the bend (arcade's tyres 0.03 m/s). The street
    /// bike's 2 m/s takes the drift away (docs/bike-model.md, "The bikes").
    pub planners_slide_tolerance: f64,
    /// The share of the tyres' friction the planners' lean goal may ask of them in a
    /// steady turn: eq. 4.7's lean is held to tan⁻¹(share · μ) (`control::lean::
    /// grip_lean_limit`); 0 (the default) holds it to nothing, as the thesis. Eq. 4.7's
    /// 45° asks μ = 1.00, all the street tyres have, and the turn-in's overshoot asks more:
    /// in the street bike's 45° bend at 60 km/h optimizer-10 fell in 14 of 22 seeds, where
    /// held to 0.9 of μ (42°, its frame then at about 45°) it fell in 4 of 30 (docs/
    /// bike-model.md, "The bikes").
    pub planners_grip_share: f64,
    /// The planners' lean goal approaches the asked lean from where each plan starts, with
    /// the time scale of the bike's own fall (`control::lean::fall_time_scale`, about 0.25 s
    /// on the street bike), not at once, as a predictive controller's reference closes in
    /// on its set point; off (the thesis's goal, asked at once) on every bike. Tried on the
    /// street bike in the 45° bend at three headings: optimizer-10 fell in 6 of 90 against 9
    /// of 90 without (on the same seeds 6 to 9, McNemar p = 0.61), in the turn-in in 2
    /// against 5; the falls left come in the steady bend (docs/bike-model.md, "The bikes").
    pub planners_lean_reference: bool,
    /// The planners cost the lean where the bike's roll is taking it, its lean plus its
    /// roll rate times the time scale of its own fall (`control::lean::lean_ahead`), not
    /// where it is: a lean arriving at the goal still rolling costs the overshoot it is
    /// heading for. Off (the thesis's cost) by default; on for the street bike, whose
    /// optimizer overshot the 45° bend's turn-in into a slide (docs/bike-model.md).
    pub planners_lean_lookahead: bool,
    /// How firmly the planners hold the rider's weight in the riding pose while the
    /// player's weight stick is released (0–1, the stick's engagement it stands for,
    /// `bike::rider_position_cost`); 0 (the default) leaves the rider free to use the body
    /// for balance, as the thesis. The lean cost is eq. 4.7's centre of mass, so nothing
    /// else keeps the weight on the bike: the street bike's optimizer let it creep 20 cm
    /// inside the 45° bend until the centre of mass passed the grip; it holds it at 0.1.
    pub planners_rider_hold: f64,
    /// The forward speed (m/s) from which `planners_rider_hold` holds at full strength:
    /// below it the hold fades in proportion to the speed, none at rest, where the body
    /// balances the bike. 0 (the default) holds at every speed.
    pub planners_rider_hold_speed: f64,
    /// The drive and brake at the rear wheel (`RearWheelDrive`): the engine's torque and
    /// power, the rear brake's torque.
    pub rear_drive: RearWheelDrive,
    /// Fork and rear suspension; `None` builds the thesis's rigid frame and fork.
    pub suspension: Option<Suspension>,
    /// The drive's anti-wheelie, which reads the fork: only on a sprung bike.
    pub wheelie_control: Option<WheelieControl>,
    /// The rider's feet at a stop (`Feet`): on the game's bike; the rigid bike of the
    /// thesis has none.
    pub feet: Option<Feet>,
    /// The front brake (`FrontBrake`): on the game's bike; the thesis's braked the rear
    /// alone.
    pub front_brake: Option<FrontBrake>,
}

impl Default for BikeParams {
    fn default() -> Self {
        Self {
            wheelbase: 1.39,
            wheel_radius: 0.30,
            tyre_crown: 0.06,
            rake: 25f64.to_radians(),
            trail: 0.095,
            rear_wheel_mass: 14.0,
            front_wheel_mass: 10.0,
            fork_mass: 8.0,
            fork_lower_mass: 4.0,
            frame_mass: 108.0,
            swingarm_mass: 6.0,
            rider_masses: [9.15, 15.0, 43.35, 4.2, 3.3],
            posture: Posture::default(),
            rider_brace: 0.0,
            rider_wrists_follow_bar: false,
            steer_limit: 35f64.to_radians(),
            max_steer_torque: 60.0,
            arcade_tuned_speed: 0.0,
            tyre_friction: 1.0,
            tyre_friction_follows_wheel: false,
            max_lean: 30f64.to_radians(),
            planners_cost_frame_roll: false,
            planners_exact_from_lean: 90f64.to_radians(),
            planners_slide_tolerance: 0.0,
            planners_grip_share: 0.0,
            planners_lean_reference: false,
            planners_lean_lookahead: false,
            planners_rider_hold: 0.0,
            planners_rider_hold_speed: 0.0,
            rear_drive: RearWheelDrive::default(),
            suspension: Some(Suspension::default()),
            wheelie_control: Some(WheelieControl::default()),
            feet: Some(Feet::default()),
            front_brake: Some(FrontBrake::default()),
        }
    }
}

impl BikeParams {
    /// How firmly the planners hold a released rider at `forward_speed` (m/s): the full
    /// `planners_rider_hold` from `planners_rider_hold_speed` up, less in proportion
    /// below it, none at rest or backwards.
    pub fn planners_rider_hold_at(&self, forward_speed: f64) -> f64 {
        let full_from = self.planners_rider_hold_speed;
        if full_from <= 0.0 {
            return self.planners_rider_hold;
        }
        self.planners_rider_hold * (forward_speed / full_from).clamp(0.0, 1.0)
    }

    /// Takes ABS away, as a bike without it brakes (the players' Pro assist): no wheel
    /// kept turning (`FrontBrake::abs_above` beyond any speed), so a braked wheel may lock,
    /// the front's as the rear's; no rear-lift mitigation (`tipping_share`), so the full
    /// brake may tip the bike over its front tyre; no cornering ABS (`cornering_lean`).
    pub fn without_abs(&mut self) {
        if let Some(brake) = self.front_brake.as_mut() {
            brake.abs_above = f64::INFINITY;
            brake.tipping_share = 0.0;
            brake.cornering_lean = 0.0;
        }
    }

    /// The same bike without suspension: lower legs fixed to the fork, swingarm to the
    /// frame (and no anti-wheelie, which reads the fork, and no feet: the thesis's bike).
    pub fn rigid(&self) -> Self {
        Self {
            suspension: None,
            wheelie_control: None,
            feet: None,
            front_brake: None,
            ..self.clone()
        }
    }

    /// Bike without rider (kg).
    pub fn bike_mass(&self) -> f64 {
        self.rear_wheel_mass
            + self.front_wheel_mass
            + self.fork_mass
            + self.fork_lower_mass
            + self.frame_mass
            + self.swingarm_mass
    }

    /// Rider (kg).
    pub fn rider_mass(&self) -> f64 {
        self.rider_masses.iter().sum()
    }

    /// A short name for exactly these numbers (16 hex digits of an FNV-1a hash): what a
    /// learned model records of the bike it was trained on. It hashes, by name, the
    /// fields (`FIELDS`) whose value differs from the reference bike's, in their exact
    /// notation, so a field added to the model at the reference's value changes no
    /// bike's identity and the reference's own is the hash of nothing.
    pub fn identity(&self) -> String {
        let reference = BikeParams::default();
        let mut fields: Vec<_> = super::FIELDS.iter().collect();
        fields.sort_by_key(|f| f.name);
        let bits = |value: Option<f64>| value.map(f64::to_bits);
        let text: String = fields
            .into_iter()
            .filter(|f| bits(f.value(self)) != bits(f.value(&reference)))
            .map(|f| format!("{}={:?}\n", f.name, f.value(self)))
            .collect();
        let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        });
        format!("{hash:016x}")
    }

    /// Distance from the front axle to the steering axis (m), from rake, trail and radius.
    pub fn fork_offset(&self) -> f64 {
        self.wheel_radius * self.rake.sin() - self.trail * self.rake.cos()
    }
}
