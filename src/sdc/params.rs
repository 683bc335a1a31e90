//! Scheme parameters: specification (name, default, admissible range) and the
//! resolved values a scheme instance runs with.

use crate::error::Error;
use crate::numeric::ParamValue;
use serde::Serialize;

#[derive(Clone, Debug, Serialize)]
pub struct ParamSpec {
    pub name: &'static str,
    /// default value; empty when the scheme's own rule applies (see description)
    pub default: &'static str,
    /// inclusive bounds of the admissible range
    pub min: f64,
    pub max: f64,
    pub description: &'static str,
}

#[derive(Clone, Debug, Default)]
pub struct Params {
    pub values: Vec<(String, ParamValue)>,
}

impl Params {
    /// The values as given (`name=text, ...`), for `Scheme::identity`.
    pub fn identity_text(&self) -> String {
        let given: Vec<String> = self.values.iter().map(|(k, v)| format!("{k}={}", v.text)).collect();
        given.join(", ")
    }
    pub fn get(&self, name: &str) -> Option<&ParamValue> {
        self.values.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    /// The value of the parameter `spec` describes. Schemes declare each
    /// parameter once as a `const ParamSpec` and look it up by that constant,
    /// so the name is written in one place and a typo cannot fall back
    /// silently to a default.
    pub fn of(&self, spec: &ParamSpec) -> Option<&ParamValue> {
        self.get(spec.name)
    }

    /// Defaults first, then the overrides. A spec whose default is empty has no
    /// single default value (the scheme applies its own rule, e.g. a formula in
    /// the valence) and is present only when given.
    pub fn resolve(scheme: &str, specs: &[ParamSpec], overrides: &[(String, String)]) -> Result<Params, Error> {
        let mut values = Vec::new();
        for spec in specs.iter().filter(|s| !s.default.is_empty()) {
            // a default is part of the program: failing to parse it is a bug, not an input error
            values.push((spec.name.to_string(), ParamValue::parse(spec.default)?));
        }
        for (name, text) in overrides {
            let Some(spec) = specs.iter().find(|s| s.name == name) else {
                let known: Vec<_> = specs.iter().map(|s| s.name).collect();
                return Err(Error::Input(if known.is_empty() {
                    format!("scheme '{scheme}' has no parameters (got '{name}')")
                } else {
                    format!("scheme '{scheme}' has no parameter '{name}'; its parameters: {}", known.join(", "))
                }));
            };
            let v = ParamValue::parse(text).map_err(|e| Error::Input(format!("parameter {name}: {e}")))?;
            // exact values are compared exactly with integer bounds (1.0000000000000001 > 1)
            let exact_outside = |bound: f64, below: bool| match (&v.exact, bound.fract() == 0.0 && bound.abs() < 1e15) {
                (Some(q), true) => {
                    let b = crate::numeric::Rational::from_integer((bound as i64).into());
                    if below {
                        *q < b
                    } else {
                        *q > b
                    }
                }
                _ => false,
            };
            if v.value < spec.min
                || v.value > spec.max
                || exact_outside(spec.min, true)
                || exact_outside(spec.max, false)
            {
                return Err(Error::Input(format!(
                    "parameter {name}={text} is out of range [{}, {}] for scheme '{scheme}'",
                    spec.min, spec.max
                )));
            }
            values.retain(|(n, _)| n != name);
            values.push((name.clone(), v));
        }
        Ok(Params { values })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> Vec<ParamSpec> {
        vec![ParamSpec { name: "a", default: "1/2", min: 0.0, max: 0.75, description: "test" }]
    }
    fn o(k: &str, v: &str) -> Vec<(String, String)> {
        vec![(k.into(), v.into())]
    }

    #[test]
    fn defaults_and_overrides() {
        let p = Params::resolve("s", &spec(), &[]).unwrap();
        assert_eq!(p.get("a").unwrap().value, 0.5);
        let p = Params::resolve("s", &spec(), &o("a", "3/8")).unwrap();
        assert_eq!(p.get("a").unwrap().value, 0.375);
    }

    #[test]
    fn out_of_range_nan_and_unknown_are_errors() {
        assert!(Params::resolve("s", &spec(), &o("a", "0.8")).unwrap_err().to_string().contains("out of range"));
        assert!(Params::resolve("s", &spec(), &o("a", "-1e-9")).unwrap_err().to_string().contains("out of range"));
        assert!(Params::resolve("s", &spec(), &o("a", "NaN")).unwrap_err().to_string().contains("not a finite number"));
        assert!(Params::resolve("s", &spec(), &o("b", "1")).unwrap_err().to_string().contains("no parameter 'b'"));
        // user input, typed as such (the CLI's exit status depends on it)
        assert!(matches!(Params::resolve("s", &spec(), &o("a", "0.8")), Err(Error::Input(_))));
    }
}
