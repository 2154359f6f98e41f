//! The game's automatic N under load, measured (issue 69; a test until then, whose
//! verdict a busy machine could flip): riding in real time as the game does (a control
//! step every 1/30 s, waiting at most the game's wait for a plan), busy loops on every
//! core make plans late and the automatic choice lowers N until they arrive in time; once
//! the load goes it raises N again. What the rule does with given plan times is tested
//! on injected times (`ride::auto_trajectories`' tests); this is how it fares on this
//! machine, as a figure.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{limits, ControllerKind, Intent, Ride, GAME_PLAN_WAIT};
use cpbp_core::terrain::Terrain;

/// Each loop's duty: busy, then idle, over and over. Another program at full tilt on
/// every core leaves two cores nothing to plan with at any N (N = 5 went late at 47 ms
/// plans); a busy half is the load of a second game or a video call.
const BUSY: Duration = Duration::from_millis(6);
const IDLE: Duration = Duration::from_millis(4);
const LCG: u64 = 6_364_136_223_846_793_005;
/// Each spell's length (s), and the steps at its end whose late plans are counted.
const SPELL_SECONDS: f64 = 10.0;
const SETTLED_STEPS: usize = 60;

/// Prints N under load and after it, riding combined from the most N the automatic
/// choice allows (too many for two cores even unloaded).
pub fn under_load() {
    let mut ride = Ride::new(
        super::rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default()),
        ControllerKind::COMBINED,
    );
    ride.planner.planning.trajectories = limits::AUTO_TRAJECTORIES.max as usize;
    ride.planner.wait = PlanWait::AtMost(GAME_PLAN_WAIT);
    ride.planner.auto_trajectories = true;
    ride.set_intent(Intent::cruise(15.0));
    let loaded = {
        let _load = Load::on_every_core();
        ride_in_real_time(&mut ride)
    };
    let unloaded = ride_in_real_time(&mut ride);
    println!();
    println!(
        "Automatic N ({} physics, combined from N = {}, {SPELL_SECONDS} s spells in real time; \
         the load: busy loops on every core, {} ms of every {}):",
        PhysicsModel::default().name(),
        limits::AUTO_TRAJECTORIES.max,
        BUSY.as_millis(),
        (BUSY + IDLE).as_millis()
    );
    println!(
        "{:<14} {:>8} {:>8} {:>22}",
        "spell", "N", "lowest", "late, last 2 s (steps)"
    );
    for (name, spell) in [("under load", loaded), ("load gone", unloaded)] {
        println!(
            "{name:<14} {:>8} {:>8} {:>22}",
            spell.trajectories, spell.lowest, spell.late_at_the_end
        );
    }
    if let Some(cause) = ride.sim().crashed() {
        println!("the bike fell while N moved: {cause:?}");
    }
}

/// What a spell of real-time riding showed: N at its end, the lowest N it went to, and
/// the late steps in its last `SETTLED_STEPS` steps.
struct Spell {
    trajectories: usize,
    late_at_the_end: u64,
    lowest: usize,
}

fn ride_in_real_time(ride: &mut Ride) -> Spell {
    let period = Duration::from_secs_f64(ride.sim().config().control_dt);
    let steps = (SPELL_SECONDS / period.as_secs_f64()).round() as usize;
    let mut boundary = Instant::now();
    let (mut late_at_the_end, mut lowest) = (0, usize::MAX);
    for step in 0..steps {
        let late_before = ride.late_plans();
        ride.step();
        if step + SETTLED_STEPS >= steps {
            late_at_the_end += ride.late_plans() - late_before;
        }
        lowest = lowest.min(ride.trajectories().unwrap_or(usize::MAX));
        boundary += period;
        std::thread::sleep(boundary.saturating_duration_since(Instant::now()));
    }
    Spell {
        trajectories: ride.trajectories().expect("a planner rides"),
        late_at_the_end,
        lowest,
    }
}

/// Busy loops on every core until dropped.
struct Load {
    running: Arc<AtomicBool>,
    threads: Vec<std::thread::JoinHandle<()>>,
}

impl Load {
    fn on_every_core() -> Self {
        let running = Arc::new(AtomicBool::new(true));
        let threads = (0..super::threads())
            .map(|_| {
                let running = Arc::clone(&running);
                std::thread::spawn(move || {
                    let mut x = 1u64;
                    while running.load(Ordering::Relaxed) {
                        let busy = Instant::now();
                        while busy.elapsed() < BUSY {
                            x = std::hint::black_box(x.wrapping_mul(LCG).wrapping_add(1));
                        }
                        std::thread::sleep(IDLE);
                    }
                })
            })
            .collect();
        Self { running, threads }
    }
}

impl Drop for Load {
    fn drop(&mut self) {
        self.running.store(false, Ordering::Relaxed);
        for thread in self.threads.drain(..) {
            let _ = thread.join();
        }
    }
}
