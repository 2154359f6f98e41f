//! Values of some of the schema's settings, each held within its entry's range: the game
//! node keeps its own (the ride's and the planners') in one of these.

use super::{DefaultValue, Setting};

/// A setting's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Bool(bool),
    Int(i64),
    Float(f64),
    Text(String),
}

impl From<DefaultValue> for Value {
    fn from(default: DefaultValue) -> Self {
        match default {
            DefaultValue::Bool(on) => Value::Bool(on),
            DefaultValue::Int(n) => Value::Int(n),
            DefaultValue::Float(x) => Value::Float(x),
            DefaultValue::Text(name) => Value::Text(name.to_owned()),
        }
    }
}

impl Value {
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Bool(_) => "a switch (true or false)",
            Value::Int(_) => "a whole number",
            Value::Float(_) => "a number",
            Value::Text(_) => "a name",
        }
    }

    /// The value as a number (0 for a name, 1 for true).
    pub fn number(&self) -> f64 {
        match self {
            Value::Bool(on) => f64::from(u8::from(*on)),
            Value::Int(n) => *n as f64,
            Value::Float(x) => *x,
            Value::Text(_) => 0.0,
        }
    }
}

/// The values of the settings a filter chose, starting at their defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct SettingValues {
    entries: Vec<(Setting, Value)>,
}

impl SettingValues {
    /// `settings`, each at its default (the whole schema's are `ride::schema::values_of`).
    pub fn holding(settings: impl IntoIterator<Item = Setting>) -> Self {
        let entries = settings
            .into_iter()
            .map(|s| (s, Value::from(s.default)))
            .collect();
        Self { entries }
    }

    /// None held: every reader gets the defaults.
    pub fn none() -> Self {
        Self {
            entries: Vec::new(),
        }
    }

    /// Holds `settings` too (at their defaults), those it does not hold yet.
    pub fn include(&mut self, settings: &[Setting]) {
        for setting in settings {
            if self.get(setting.name).is_none() {
                self.entries.push((*setting, Value::from(setting.default)));
            }
        }
    }

    /// The settings held, in the schema's order.
    pub fn settings(&self) -> impl Iterator<Item = &Setting> {
        self.entries.iter().map(|(s, _)| s)
    }

    pub fn get(&self, name: &str) -> Option<&Value> {
        self.entries
            .iter()
            .find(|(s, _)| s.name == name)
            .map(|(_, v)| v)
    }

    /// Sets setting `name`. A whole number is taken for a number and a number for a
    /// whole number (rounded); a number out of range is clamped into it and one that is
    /// not a number leaves the default; each of those returns a warning to show. A value
    /// of another type, or a name this set does not hold, is refused.
    pub fn set(&mut self, name: &str, value: Value) -> Result<Option<String>, String> {
        let Some((setting, held)) = self.entries.iter_mut().find(|(s, _)| s.name == name) else {
            return Err(format!("no setting here is called {name}"));
        };
        let (value, warning) = fitted(setting, value)?;
        *held = value;
        Ok(warning)
    }

    /// The number `setting` holds (its default if it is not held here).
    pub fn number(&self, setting: &Setting) -> f64 {
        self.get(setting.name)
            .map_or(setting.default_number(), Value::number)
    }

    /// A whole-number setting, exactly.
    pub fn integer(&self, setting: &Setting) -> i64 {
        match self.get(setting.name) {
            Some(Value::Int(n)) => *n,
            other => other.map_or(setting.default_number(), Value::number) as i64,
        }
    }

    /// A whole-number setting as a count.
    pub fn count(&self, setting: &Setting) -> usize {
        self.number(setting).max(0.0) as usize
    }

    pub fn flag(&self, setting: &Setting) -> bool {
        self.number(setting) != 0.0
    }
}

/// `value` as `setting` may hold it, with the warning its fitting deserves.
fn fitted(setting: &Setting, value: Value) -> Result<(Value, Option<String>), String> {
    let default = Value::from(setting.default);
    if let (Value::Int(_), Value::Int(n), Some(range)) = (&default, &value, setting.range) {
        // Whole numbers stay exact (a seed may be wider than a double's mantissa).
        if (range.min..=range.max).contains(&(*n as f64)) {
            return Ok((value, None));
        }
    }
    let number = match (&default, &value) {
        (Value::Int(_) | Value::Float(_), Value::Int(_) | Value::Float(_)) => value.number(),
        _ if std::mem::discriminant(&default) == std::mem::discriminant(&value) => {
            return Ok((value, None))
        }
        _ => {
            return Err(format!(
                "{} takes {}, not {value:?}",
                setting.name,
                default.type_name()
            ))
        }
    };
    let Some(range) = setting.range else {
        return Ok((value, None));
    };
    let mut warning = None;
    let fitted = if !number.is_finite() {
        warning = Some(format!(
            "{} = {number} is not a number; using the default",
            setting.name
        ));
        default.number()
    } else if !(range.min..=range.max).contains(&number) {
        let clamped = number.clamp(range.min, range.max);
        warning = Some(format!(
            "{} = {number} is outside {}–{}; using {clamped}",
            setting.name, range.min, range.max
        ));
        clamped
    } else {
        number
    };
    let value = match default {
        Value::Int(_) => Value::Int(fitted.round() as i64),
        _ => Value::Float(fitted),
    };
    Ok((value, warning))
}
