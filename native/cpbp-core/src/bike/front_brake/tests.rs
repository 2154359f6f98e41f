use super::*;

#[test]
fn the_brake_lets_off_as_the_rear_tops_out() {
    let brake = FrontBrake::default();
    assert_eq!(brake.lift_off_share(0.039), 1.0);
    assert_eq!(brake.lift_off_share(0.0), 0.0);
    assert!((brake.lift_off_share(0.0185) - 0.5).abs() < 1e-12);
    assert_eq!(brake.lift_off_share(f64::NAN), 0.0);
}

#[test]
fn without_a_window_the_compression_lets_all_through() {
    let brake = FrontBrake {
        full_above: 0.0,
        none_below: 0.0,
        ..FrontBrake::default()
    };
    assert_eq!(brake.lift_off_share(0.0), 1.0);
    assert!(
        !brake.modulates(),
        "the reference's rules set it once a period"
    );
    assert!(!FrontBrake::default().modulates());
}

#[test]
fn the_tipping_limit_holds_the_brake_below_the_force_that_tips_the_bike() {
    let brake = FrontBrake {
        tipping_share: 0.95,
        ..FrontBrake::default()
    };
    assert!(brake.modulates());
    // 2200 N with b = h tips at 2200 N; 0.95 of that on a 0.3 m wheel is 627 N·m.
    let level = OverFrontTyre {
        behind: 0.6,
        height: 0.6,
        load: 2200.0,
        ..OverFrontTyre::default()
    };
    let share = brake.tipping_limit(&level, 0.3);
    assert!((share * brake.max_torque - 627.0).abs() < 1e-9, "{share}");
    // Far behind: the brake's full torque; over or ahead of the tyre: none.
    let far = OverFrontTyre {
        behind: 3.0,
        ..level
    };
    assert_eq!(brake.tipping_limit(&far, 0.3), 1.0);
    let over = OverFrontTyre {
        behind: -0.1,
        ..level
    };
    assert_eq!(brake.tipping_limit(&over, 0.3), 0.0);
    let flat = OverFrontTyre {
        height: 0.0,
        ..level
    };
    assert_eq!(brake.tipping_limit(&flat, 0.3), 0.0);
    let nan = OverFrontTyre {
        behind: f64::NAN,
        ..level
    };
    assert_eq!(brake.tipping_limit(&nan, 0.3), 0.0);
    // Off: no limit, whatever the geometry.
    assert_eq!(FrontBrake::default().tipping_limit(&over, 0.3), 1.0);
}

#[test]
fn the_tipping_limit_reads_ahead_at_the_weights_rate() {
    let brake = FrontBrake {
        tipping_share: 1.0,
        tipping_lookahead: 0.2,
        max_torque: 10_000.0,
        ..FrontBrake::default()
    };
    // Moving 0.5 m/s over the tyre and 0.1 m/s down: in 0.2 s b = 0.5, h = 0.58.
    let diving = OverFrontTyre {
        behind: 0.6,
        height: 0.6,
        behind_rate: -0.5,
        height_rate: -0.1,
        load: 2000.0,
    };
    let torque = brake.tipping_limit(&diving, 0.3) * brake.max_torque;
    assert!(
        (torque - 2000.0 * 0.5 / 0.58 * 0.3).abs() < 1e-9,
        "{torque}"
    );
}

#[test]
fn a_leaned_bike_brakes_less_with_cornering_abs() {
    assert_eq!(
        FrontBrake::default().cornering_share(0.5, 10.0),
        1.0,
        "not on the reference"
    );
    let brake = FrontBrake {
        cornering_lean: 45f64.to_radians(),
        ..FrontBrake::default()
    };
    assert_eq!(brake.cornering_share(0.0, 10.0), 1.0);
    let at_20 = brake.cornering_share(-20f64.to_radians(), 10.0);
    assert!(
        (at_20 - (1.0 - (20.0f64 / 45.0).powi(2))).abs() < 1e-12,
        "{at_20}"
    );
    assert_eq!(brake.cornering_share(50f64.to_radians(), 10.0), 0.0);
    assert_eq!(brake.cornering_share(f64::NAN, 10.0), 0.0);
    assert_eq!(
        brake.cornering_share(0.2, 1.0),
        1.0,
        "standing leaned on a foot"
    );
    assert_eq!(brake.cornering_share(0.2, f64::NAN), 1.0);
}

#[test]
fn a_leaned_bike_keeps_the_speed_it_stands_up_at_with_the_righting_reserve() {
    // g·L / (tan δ·cos ε) of a 1.38 m bike with a 30° lock and 24° of rake: 25.7 m²/s².
    let full_lock = 9.81 * 1.38 / (30f64.to_radians().tan() * 24f64.to_radians().cos());
    assert_eq!(
        FrontBrake::default().righting_share(0.3, 5.0, full_lock),
        1.0,
        "not on the reference"
    );
    let brake = FrontBrake {
        righting_reserve: true,
        ..FrontBrake::default()
    };
    assert_eq!(brake.righting_share(0.0, 5.0, full_lock), 1.0, "upright");
    // Leaned 20° at 25 km/h the full-lock turn holds the lean at 3.0 m/s, so 1 − 3.0² /
    // 6.9² of the brake is left; either way round.
    let (lean, speed) = (20f64.to_radians(), 25.0 / 3.6);
    let expected = 1.0 - full_lock * lean.sin() / (speed * speed);
    for lean in [lean, -lean] {
        let share = brake.righting_share(lean, speed, full_lock);
        assert!((share - expected).abs() < 1e-12, "{share}");
    }
    assert!((0.8..0.82).contains(&expected), "{expected}");
    assert_eq!(
        brake.righting_share(lean, 2.9, full_lock),
        0.0,
        "below the speed it stands up at"
    );
    assert_eq!(
        brake.righting_share(lean, 1.0, full_lock),
        1.0,
        "walking pace"
    );
    assert_eq!(brake.righting_share(f64::NAN, 5.0, full_lock), 0.0);
    assert_eq!(brake.righting_share(lean, f64::NAN, full_lock), 1.0);
    assert!(brake.modulates(), "set before every physics step");
}

#[test]
fn at_walking_pace_the_reserve_waits_for_the_bar_to_come_straight() {
    let lock = 40f64.to_radians();
    let walking = FrontBrake::default().abs_above;
    assert_eq!(
        FrontBrake::default().walking_bar_share(1.0, lock, lock),
        1.0,
        "not on the reference"
    );
    let brake = FrontBrake {
        righting_reserve: true,
        ..FrontBrake::default()
    };
    assert_eq!(brake.walking_bar_share(1.0, 0.0, lock), 1.0, "straight");
    for steer in [lock, -lock, 1.2 * lock] {
        assert_eq!(
            brake.walking_bar_share(1.0, steer, lock),
            0.0,
            "at the lock"
        );
    }
    let halfway = brake.walking_bar_share(walking, -lock / 2.0, lock);
    assert!((halfway - 0.5).abs() < 1e-12, "{halfway}");
    assert_eq!(
        brake.walking_bar_share(walking + 0.1, lock, lock),
        1.0,
        "above walking pace the righting share rules"
    );
    assert_eq!(
        brake.walking_bar_share(-1.0, lock, lock),
        0.0,
        "rolling back"
    );
    assert_eq!(brake.walking_bar_share(1.0, f64::NAN, lock), 0.0);
    assert_eq!(brake.walking_bar_share(f64::NAN, lock, lock), 1.0);
}

#[test]
fn the_brake_eases_in_the_last_metre_when_asked() {
    assert_eq!(
        FrontBrake::default().eased(0.0),
        1.0,
        "not on the reference bike"
    );
    let brake = FrontBrake {
        ease_below: 2.0,
        ease_to: 0.4,
        ..FrontBrake::default()
    };
    assert_eq!(brake.eased(5.0), 1.0);
    assert!((brake.eased(1.0) - 0.7).abs() < 1e-12);
    assert!((brake.eased(-1.0) - 0.7).abs() < 1e-12, "rolling back too");
    assert!((brake.eased(0.0) - 0.4).abs() < 1e-12);
    assert_eq!(brake.eased(f64::NAN), 1.0);
}

#[test]
fn the_ramp_slows_the_rise_and_not_the_release() {
    let brake = FrontBrake {
        ramp_time: 0.2,
        ..FrontBrake::default()
    };
    // 700 N·m in 0.2 s: 29.17 N·m in a 1/120 s step.
    let step = brake.ramped(0.0, 700.0, 1.0 / 120.0);
    assert!((step - 700.0 / 24.0).abs() < 1e-9, "{step}");
    assert_eq!(
        brake.ramped(690.0, 700.0, 1.0 / 120.0),
        700.0,
        "reaches the lever"
    );
    assert_eq!(
        brake.ramped(700.0, 100.0, 1.0 / 120.0),
        100.0,
        "let off at once"
    );
    assert_eq!(FrontBrake::default().ramped(0.0, 700.0, 0.001), 700.0);
}

#[test]
fn abs_keeps_a_braked_wheel_turning_until_walking_pace() {
    let brake = FrontBrake::default();
    // 10 m/s on a 0.3 m wheel rolls at 33.3 rad/s: ABS keeps 30.
    assert!((brake.abs_floor(10.0, 0.3) - 30.0).abs() < 1e-9);
    assert_eq!(brake.abs_floor(1.0, 0.3), 0.0, "held still at walking pace");
    assert_eq!(brake.abs_floor(-3.0, 0.3), 0.0, "rolling back");
    assert_eq!(brake.abs_floor(f64::NAN, 0.3), 0.0);
}

#[test]
fn the_stoppie_hold_brakes_while_the_weight_is_behind() {
    let brake = FrontBrake::default();
    assert_eq!(brake.hold_share(-0.6, 0.0), 1.0);
    assert!(brake.hold_share(-0.1, 0.0) > 0.0);
    assert_eq!(brake.hold_share(0.05, 0.0), 0.0);
    assert_eq!(brake.hold_share(0.0, 0.5), 0.0);
    assert_eq!(brake.hold_share(f64::NAN, 0.0), 0.0);
}
