//! The entries themselves. Each constant is one setting; `ENTRIES` lists them in the order
//! menus and the inspector show them. The core's own defaults (`PlanningConfig`,
//! `SimulationConfig`, the ride's clamps) read their constant here.

use super::{DefaultValue as D, Owner, Range, Setting};

/// What an entry is unless it says otherwise: a planner's number, hidden from players.
/// A planner's own parameters (declared with its `PlannerSpec`) start from this too.
pub const BASE: Setting = Setting {
    name: "",
    label: "",
    description: "",
    unit: "",
    default: D::Float(0.0),
    player_default: None,
    range: None,
    offered: &[],
    choices: &[],
    owner: Owner::Planner,
    player: false,
    menu: "",
};

// The ride: what the pedals drive and how the master simulation steps.

pub const MAX_SPEED_KMH: Setting = Setting {
    name: "max_speed_kmh",
    label: "Top speed",
    description: "Speed full throttle drives towards.",
    unit: "km/h",
    // The drive reads both: its default input and the bound every input is held to
    // (`bike::DEFAULT_MAX_SPEED_KMH`, `bike::TOP_SPEED_KMH`).
    default: D::Float(40.0),
    range: Some(Range::new(1.0, 90.0, 1.0)),
    owner: Owner::Ride,
    player: true,
    menu: "Riding",
    ..BASE
};
pub const MOTOR_FORCE: Setting = Setting {
    name: "motor_force",
    label: "Motor force",
    description: "Share of the rear motor's torque that full throttle uses (the brake \
                  trigger gives the bike's whole brake).",
    unit: "share",
    default: D::Float(0.6),
    range: Some(Range::new(0.1, 1.0, 0.05)),
    owner: Owner::Ride,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const SUBSTEPS: Setting = Setting {
    name: "substeps",
    label: "Substeps",
    description: "ODE steps per control step (more: stiffer joints, slower); read when the \
                  ride is built.",
    default: D::Int(4),
    range: Some(Range::new(1.0, 16.0, 1.0)),
    owner: Owner::Ride,
    ..BASE
};
pub const PLAN_WAIT_MS: Setting = Setting {
    name: "plan_wait_ms",
    label: "Plan wait",
    description: "Longest the game waits at a control step for the planning thread; a \
                  later plan is taken over at a later step while the last best trajectory \
                  plays on.",
    unit: "ms",
    default: D::Float(12.0),
    range: Some(Range::new(0.0, 1000.0, 1.0)),
    owner: Owner::Ride,
    ..BASE
};
pub const WAIT_FOR_EVERY_PLAN: Setting = Setting {
    name: "wait_for_every_plan",
    label: "Wait for every plan",
    description: "Wait at every control step until its plan comes (headless tests and \
                  experiments), so a ride repeats exactly for its seed on a loaded machine \
                  too. Off in the game, where a slow plan must not stall.",
    default: D::Bool(false),
    owner: Owner::Ride,
    ..BASE
};
pub const WAIT_FOR_THROTTLE: Setting = Setting {
    name: "wait_for_throttle",
    label: "Wait for throttle",
    description: "The ride starts with the first throttle (and again after each reset); a \
                  bike with feet stands on them until then, one without is held.",
    default: D::Bool(false),
    owner: Owner::Ride,
    ..BASE
};

// The planners.

pub const TRAJECTORIES: Setting = Setting {
    name: "trajectories",
    label: "Trajectories",
    description: "Trajectories a planner simulates each control step (N); with \
                  auto_trajectories, the N it starts from.",
    default: D::Int(15),
    range: Some(Range::new(1.0, 256.0, 1.0)),
    offered: &[5.0, 10.0, 15.0, 32.0, 64.0, 128.0],
    player: true,
    ..BASE
};
/// Not a setting of its own: the range the automatic choice moves N in.
pub const AUTO_TRAJECTORY_RANGE: Range = Range::new(5.0, 64.0, 1.0);
pub const AUTO_TRAJECTORIES: Setting = Setting {
    name: "auto_trajectories",
    label: "Auto trajectories",
    description: "Move N while riding to what this machine plans in time: fewer when plans \
                  come late, more after a calm spell. Ignored with wait_for_every_plan.",
    default: D::Bool(true),
    player: true,
    ..BASE
};
pub const HORIZON_S: Setting = Setting {
    name: "horizon",
    label: "Horizon",
    description: "How far ahead the planners plan; the thesis used 1.2 s.",
    unit: "s",
    default: D::Float(1.2),
    range: Some(Range::new(0.2, 3.0, 0.1)),
    ..BASE
};
pub const TERMINAL_VALUE: Setting = Setting {
    name: "terminal_value",
    label: "Learned cost-to-go",
    description: "Plan the value horizon and cost the rest of the horizon with the bike's \
                  learned cost-to-go (models/value-<bike>): less to simulate, so more \
                  trajectories in time. Without the network the planners plan the whole \
                  horizon and say so.",
    // Off for the tools and their rows (the thesis's planner, bit-exact), on in the game:
    // the savings become trajectories (the auto N). It came on once the bot's wheelie onto
    // the skate park's platform (tests/levels/test_bot_rides.gd) rode with it: that took
    // wheelies in the cost-to-go's training and plans without it while the rider asks
    // for a wheelie or a stoppie (`BikeRollout::terminal_cost`).
    default: D::Bool(false),
    player_default: Some(D::Bool(true)),
    player: true,
    menu: "Lab",
    ..BASE
};
pub const VALUE_HORIZON_S: Setting = Setting {
    name: "value_horizon",
    label: "Value horizon",
    description: "How far ahead the planners simulate when the learned cost-to-go costs \
                  the rest of the horizon.",
    unit: "s",
    default: D::Float(0.6),
    range: Some(Range::new(0.1, 3.0, 0.1)),
    ..BASE
};
pub const LEAN_TOLERANCE_DEG: Setting = Setting {
    name: "lean_tolerance_deg",
    label: "Lean tolerance",
    description: "Lean error that costs as much as one unit (eq. 4.7's s): smaller tracks \
                  the requested lean more strictly.",
    unit: "°",
    default: D::Float(5.0),
    range: Some(Range::new(1.0, 30.0, 0.5)),
    ..BASE
};
pub const RIDER_TOLERANCE_CM: Setting = Setting {
    name: "rider_tolerance_cm",
    label: "Rider tolerance",
    description: "Rider position error that costs as much as one unit at full stick.",
    unit: "cm",
    default: D::Float(3.0),
    range: Some(Range::new(1.0, 20.0, 0.5)),
    ..BASE
};
pub const ROLLOUT_SUBSTEPS: Setting = Setting {
    name: "rollout_substeps",
    label: "Rollout substeps",
    description: "ODE steps per planning step in the rollouts; 0 takes the physics model's \
                  own. Fewer plan faster but predict a different bike.",
    default: D::Int(0),
    range: Some(Range::new(0.0, 8.0, 1.0)),
    ..BASE
};
pub const PLANNING_THREADS: Setting = Setting {
    name: "planning_threads",
    label: "Planning threads",
    description: "Threads that simulate the trajectories (0: one per core).",
    default: D::Int(0),
    range: Some(Range::new(0.0, 64.0, 1.0)),
    ..BASE
};
pub const PLANNER_SEED: Setting = Setting {
    name: "planner_seed",
    label: "Planner seed",
    description: "Seed of the planners' random draws: the same seed, start and inputs give \
                  the same ride.",
    // The year of the thesis; every planner's config reads it (`cpbp::DEFAULT_SEED`).
    default: D::Int(2015),
    range: Some(Range::new(i64::MIN as f64, i64::MAX as f64, 1.0)),
    ..BASE
};

// The game's own.

pub const ABS: Setting = Setting {
    name: "abs",
    label: "ABS",
    description: "The brakes keep the wheels turning under a hard brake; off, a wheel braked \
                  too hard locks and slides, the front's as the rear's.",
    default: D::Bool(true),
    owner: Owner::Ride,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const LEAN_SHARE: Setting = Setting {
    name: "lean_share",
    label: "Lean the stick may ask",
    description: "The share of the bike's lean a full turn of the stick asks for.",
    unit: "share",
    default: D::Float(1.0),
    range: Some(Range::new(0.5, 1.0, 0.05)),
    owner: Owner::Ride,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const ASSIST: Setting = Setting {
    name: "assist",
    label: "Assist",
    description: "How much the game helps you ride: who balances the bike, ABS, how far \
                  the stick leans it (the table in the README says what each level does).",
    default: D::Text("full"),
    // From the most help to the least; the game's Assists table says what each sets.
    choices: &["learner", "full", "standard", "pro"],
    owner: Owner::Game,
    player: true,
    menu: "Riding",
    ..BASE
};
pub const CONTROLLER: Setting = Setting {
    name: "controller",
    label: "Controller",
    description: "Who balances and steers, by the controller registry's name.",
    default: D::Text("combined"),
    owner: Owner::Game,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const AUTO_SPEED_KMH: Setting = Setting {
    name: "auto_speed_kmh",
    label: "Auto-accelerate speed",
    description: "Speed auto-accelerate holds; the thesis tested 10, 15, 20 and 25 km/h.",
    unit: "km/h",
    default: D::Int(15),
    range: Some(Range::new(5.0, 60.0, 1.0)),
    offered: &[10.0, 15.0, 20.0, 25.0],
    choices: &[],
    owner: Owner::Game,
    player: true,
    menu: "Riding",
    ..BASE
};
pub const AUTO_ACCELERATE: Setting = Setting {
    name: "auto_accelerate",
    label: "Auto-accelerate",
    description: "Hold the auto-accelerate speed without the triggers.",
    default: D::Bool(false),
    owner: Owner::Game,
    player: true,
    ..BASE
};
pub const LEVEL: Setting = Setting {
    name: "level",
    label: "Level",
    description: "The level the start menu offers first.",
    // The levels, each a scene in a folder of the same name under scenes/levels/
    // (scenes/levels/track/track.tscn); the start menu offers them in this order and names
    // each by its scene's title. A new level is its scene and one name here.
    default: D::Text("test_level"),
    choices: &["test_level", "track", "skate_park"],
    owner: Owner::Game,
    player: true,
    ..BASE
};
pub const BIKE: Setting = Setting {
    name: "bike",
    label: "Bike",
    description: "The bike you ride.",
    // The bikes a player chooses from, by their files' names in scenes/bike/bikes/ (the
    // thesis's street_350 there is the research's reference, not a choice); the start
    // menu offers them in this order.
    default: D::Text("street_390"),
    choices: &["street_390", "dirt_125", "sport_600"],
    owner: Owner::Game,
    player: true,
    ..BASE
};
pub const CAMERA: Setting = Setting {
    name: "camera",
    label: "Camera",
    description: "The follow camera's mode: chase, low side or helmet.",
    default: D::Text("chase"),
    // The follow camera's modes, in the order its key cycles them.
    choices: &["chase", "low_side", "helmet"],
    owner: Owner::Display,
    player: true,
    ..BASE
};
pub const SHOW_TRAJECTORIES: Setting = Setting {
    name: "show_trajectories",
    label: "Show trajectories",
    description: "Draw the planners' trajectories over the road.",
    default: D::Bool(true),
    owner: Owner::Display,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const PHYSICAL_MODEL: Setting = Setting {
    name: "physical_model",
    label: "Show physical bodies",
    description: "Show the simulated bodies instead of the bike's and rider's looks.",
    default: D::Bool(false),
    owner: Owner::Display,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const GRAPHICS_QUALITY: Setting = Setting {
    name: "graphics_quality",
    label: "Graphics",
    description: "How richly the world is drawn: low keeps a software renderer's frame time, \
                  high spends what a graphics card affords; auto picks from the frame time.",
    default: D::Text("auto"),
    choices: &["auto", "low", "medium", "high"],
    owner: Owner::Display,
    player: true,
    menu: "View",
    ..BASE
};
pub const UI_SCALE: Setting = Setting {
    name: "ui_scale",
    label: "Text and HUD size",
    description: "How large the menus, the HUD and their text are drawn.",
    unit: "%",
    default: D::Float(100.0),
    // Up to 125 % the HUD still fits the game's smallest canvas (1280 × 720 at 100 %,
    // 1024 × 576 at 125 %) with its longest texts and no label over another
    // (tests/scenes/test_hud_layout.gd); at 150 % its dial and the telemetry no longer do.
    range: Some(Range::new(75.0, 125.0, 5.0)),
    offered: &[75.0, 90.0, 100.0, 110.0, 125.0],
    owner: Owner::Display,
    player: true,
    menu: "View",
    ..BASE
};
pub const TELEMETRY: Setting = Setting {
    name: "telemetry",
    label: "Planner telemetry",
    description: "Show the controller's and the planners' numbers over the HUD (the \
                  controller, trajectories, planning time, late plans, the planner's own).",
    default: D::Bool(false),
    owner: Owner::Display,
    player: true,
    menu: "Lab",
    ..BASE
};
pub const RUMBLE: Setting = Setting {
    name: "rumble",
    label: "Rumble",
    description: "Shake the gamepad on landings and crashes.",
    default: D::Bool(true),
    owner: Owner::Game,
    player: true,
    menu: "Riding",
    ..BASE
};
pub const MASTER_VOLUME: Setting = Setting {
    name: "master_volume",
    label: "Volume",
    description: "Loudness of everything the game plays (0: silent).",
    unit: "share",
    default: D::Float(0.8),
    range: Some(Range::new(0.0, 1.0, 0.05)),
    owner: Owner::Sound,
    player: true,
    menu: "Sound",
    ..BASE
};
pub const ENGINE_VOLUME: Setting = Setting {
    name: "engine_volume",
    label: "Engine",
    description: "Loudness of the engine against the rest.",
    unit: "share",
    default: D::Float(1.0),
    range: Some(Range::new(0.0, 1.0, 0.05)),
    owner: Owner::Sound,
    player: true,
    menu: "Sound",
    ..BASE
};

/// Every compiled entry, in the order menus and the inspector show them.
pub const ENTRIES: &[Setting] = &[
    SHOW_TRAJECTORIES,
    PHYSICAL_MODEL,
    GRAPHICS_QUALITY,
    UI_SCALE,
    TELEMETRY,
    ASSIST,
    CONTROLLER,
    ABS,
    LEAN_SHARE,
    MAX_SPEED_KMH,
    MOTOR_FORCE,
    AUTO_SPEED_KMH,
    AUTO_ACCELERATE,
    RUMBLE,
    MASTER_VOLUME,
    ENGINE_VOLUME,
    LEVEL,
    BIKE,
    CAMERA,
    TRAJECTORIES,
    AUTO_TRAJECTORIES,
    HORIZON_S,
    TERMINAL_VALUE,
    VALUE_HORIZON_S,
    LEAN_TOLERANCE_DEG,
    RIDER_TOLERANCE_CM,
    ROLLOUT_SUBSTEPS,
    PLANNING_THREADS,
    PLANNER_SEED,
    SUBSTEPS,
    PLAN_WAIT_MS,
    WAIT_FOR_EVERY_PLAN,
    WAIT_FOR_THROTTLE,
];
