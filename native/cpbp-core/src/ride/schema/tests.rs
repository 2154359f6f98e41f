use super::*;
use crate::settings::{Owner, Range, HORIZON_S};

#[test]
fn every_entry_is_a_value_it_may_have_and_names_are_unique() {
    let entries = all();
    for (i, setting) in entries.iter().enumerate() {
        setting
            .check(&Value::from(setting.default))
            .unwrap_or_else(|why| panic!("{why}"));
        assert!(!setting.label.is_empty() && !setting.description.is_empty());
        assert!(
            entries[..i].iter().all(|s| s.name != setting.name),
            "{} twice",
            setting.name
        );
        for offered in setting.offered {
            let r = setting.limit();
            assert!(
                (r.min..=r.max).contains(offered),
                "{} offers {offered}",
                setting.name
            );
        }
    }
}

#[test]
fn values_are_held_within_their_range_and_refuse_another_type() {
    let mut values = values_of(|s| s.owner.on_the_node());
    assert_eq!(values.number(&HORIZON_S), 1.2);
    assert!(values.set("horizon", Value::Float(9.0)).unwrap().is_some());
    assert_eq!(values.number(&HORIZON_S), 3.0);
    assert!(values
        .set("horizon", Value::Float(f64::NAN))
        .unwrap()
        .is_some());
    assert_eq!(values.number(&HORIZON_S), 1.2);
    assert_eq!(values.set("trajectories", Value::Float(9.6)), Ok(None));
    assert_eq!(values.get("trajectories"), Some(&Value::Int(10)));
    assert!(values.set("trajectories", Value::Bool(true)).is_err());
    assert!(
        values.set("camera", Value::Text("chase".into())).is_err(),
        "not the node's"
    );
}

#[test]
fn an_entry_added_at_run_time_reaches_every_reader() {
    let throwaway = Setting {
        name: "throwaway_rust_test",
        label: "Throwaway",
        description: "A test's.",
        default: DefaultValue::Float(0.5),
        range: Some(Range::new(0.0, 1.0, 0.1)),
        owner: Owner::Planner,
        player: true,
        menu: "Planner",
        player_default: None,
        unit: "",
        offered: &[],
        choices: &[],
    };
    extend(throwaway).unwrap();
    assert!(extend(throwaway).is_err(), "the name is taken");
    assert_eq!(find("throwaway_rust_test"), Some(throwaway));
    let values = values_of(|s| s.owner.on_the_node());
    assert_eq!(values.get("throwaway_rust_test"), Some(&Value::Float(0.5)));
    assert!(schema_json().contains("\"name\":\"throwaway_rust_test\""));
    let out_of_range = Setting {
        name: "throwaway_bad",
        default: DefaultValue::Float(2.0),
        ..throwaway
    };
    assert!(extend(out_of_range).is_err());
}

#[test]
fn a_name_with_choices_holds_only_one_of_them() {
    use crate::settings::GRAPHICS_QUALITY;
    assert!(GRAPHICS_QUALITY.check(&Value::Text("high".into())).is_ok());
    let why = GRAPHICS_QUALITY
        .check(&Value::Text("ultra".into()))
        .unwrap_err();
    assert!(why.contains("auto, low, medium, high"), "{why}");
    assert!(schema_json().contains("\"choices\":[\"auto\",\"low\",\"medium\",\"high\"]"));
    let number_with_choices = Setting {
        name: "throwaway_choices",
        choices: &["a", "b"],
        range: Some(Range::new(0.0, 1.0, 0.1)),
        ..crate::settings::BASE
    };
    assert!(
        extend(number_with_choices).is_err(),
        "only a name has choices"
    );
    let default_not_a_choice = Setting {
        name: "throwaway_choice_default",
        label: "Throwaway",
        description: "A test's.",
        default: DefaultValue::Text("c"),
        choices: &["a", "b"],
        ..crate::settings::BASE
    };
    assert!(extend(default_not_a_choice).is_err(), "its default is one");
}

#[test]
fn a_tool_parses_a_setting_from_text_and_refuses_what_does_not_fit() {
    assert_eq!(HORIZON_S.parse("0.6"), Ok(Value::Float(0.6)));
    assert!(
        HORIZON_S.parse("9").unwrap_err().contains("within"),
        "refused, not clamped"
    );
    assert!(HORIZON_S.parse("short").unwrap_err().contains("a number"));
    let trajectories = find("trajectories").unwrap();
    assert_eq!(trajectories.parse("12"), Ok(Value::Int(12)));
    assert!(trajectories.parse("1.5").is_err(), "a whole number");
    let waits = find("wait_for_every_plan").unwrap();
    assert_eq!(waits.parse("true"), Ok(Value::Bool(true)));
    assert!(waits.parse("yes").is_err());
    let quality = find("graphics_quality").unwrap();
    assert_eq!(quality.parse("low"), Ok(Value::Text("low".into())));
    assert!(quality.parse("ultra").is_err(), "not one of its choices");
}

#[test]
fn the_planners_settings_from_the_defaults_are_the_games_defaults() {
    use crate::control::learned::{LoadedPolicy, LoadedValue};
    use crate::physics::PhysicsModel;
    use crate::ride::PlannerSettings;

    let mut values = values_of(|s| s.owner.on_the_node());
    let physics = PhysicsModel::Exact;
    let (policy, value) = (LoadedPolicy::default(), LoadedValue::default());
    let from_values = PlannerSettings::from_values(&values, physics, policy.clone(), value.clone());
    let mut default = PlannerSettings::default();
    default.planning = default.planning.rolling_out_in(physics);
    // The default holds no planner parameters (each reads its default); the values hold
    // them all at their defaults, which plans the same.
    default.planning.parameters = values.clone();
    assert_eq!(from_values, default);
    values.set("horizon", Value::Float(0.6)).unwrap();
    let shorter = PlannerSettings::from_values(&values, physics, policy, value);
    assert_eq!(shorter.planning.horizon, 0.6);
}

#[test]
fn a_players_default_is_a_value_of_a_player_setting() {
    let start = |player_default, player| Setting {
        name: "throwaway_player_start",
        label: "Throwaway",
        description: "A test's.",
        default: DefaultValue::Float(0.5),
        player_default: Some(player_default),
        range: Some(Range::new(0.0, 1.0, 0.1)),
        player,
        ..crate::settings::BASE
    };
    let out_of_range = check_entry(&start(DefaultValue::Float(2.0), true)).unwrap_err();
    assert!(out_of_range.contains("within 0–1"), "{out_of_range}");
    assert!(check_entry(&start(DefaultValue::Bool(true), true)).is_err());
    let hidden = check_entry(&start(DefaultValue::Float(0.7), false)).unwrap_err();
    assert!(hidden.contains("only a player setting"), "{hidden}");
    let fine = start(DefaultValue::Float(0.7), true);
    assert!(check_entry(&fine).is_ok());
    assert_eq!(fine.player_start(), DefaultValue::Float(0.7));
    assert_eq!(
        crate::settings::BASE.player_start(),
        DefaultValue::Float(0.0)
    );
}
