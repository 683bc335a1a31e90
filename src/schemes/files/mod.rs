//! Scheme files of the lattice (Z²) and curve (Z) families, and the routing
//! of a scheme file to its family's loader.
//!
//! A file says which family it belongs to with a top-level key
//! `domain = "lattice"` or `domain = "curve"`. Mesh scheme files (`user`) have
//! no such key (they name a `topology`), and `user` rejects keys it does not
//! know; so the router peeks at the TOML's keys first and hands the text to
//! the loader of its family, which then parses it strictly.
//!
//! Both formats share: `name` (not a built-in name), `description`, `affine`
//! (default true: every rule's weights sum to 1), `[params.NAME]` tables with
//! `default`, `min`, `max`, `description` (as in mesh scheme files), and
//! weights as expressions of the project's expression language
//! (`numeric::expr`) in the parameters. Offsets are table keys: `"r,s"` on the
//! lattice, `"o"` on the line. Every error names the file, the line and the
//! field.
//!
//! What the formats share is in `shared_format` (which imports no format);
//! this file routes a file to its format's loader.

pub mod curve;
pub mod lattice;
// the caps, header, expressions and errors every format shares
pub mod shared_format;

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use crate::error::Error;
use crate::schemes::entry::{Built, Family};
use shared_format::{line_of, read_scheme_file, Term, UserParam};
pub use shared_format::{Head, WeightSite, MAX_EXPR_CHARS, MAX_FILE_BYTES, MAX_OFFSET};

/// The family a file's text declares. Text that is not TOML, or whose
/// `domain` is not a string, goes to the mesh loader, whose parser reports the
/// problem with its line.
fn family_of_text(text: &str, file: &str) -> Result<Family, Error> {
    /// Only the `domain` key; every other key is left to the family's loader.
    #[derive(Deserialize)]
    struct Peek {
        domain: Option<Spanned<toml::Value>>,
    }
    let Ok(Peek { domain: Some(domain) }) = toml::from_str::<Peek>(text) else { return Ok(Family::Mesh) };
    match domain.get_ref().as_str() {
        Some("lattice") => Ok(Family::Lattice),
        Some("curve") => Ok(Family::Curve),
        other => Err(Error::File(format!(
            "{file} line {}, field domain: {} is not a domain; use \"lattice\" or \"curve\" (mesh scheme files have \
             no domain key: they name a topology)",
            line_of(text, domain.span().start),
            other.map(|d| format!("'{d}'")).unwrap_or_else(|| "a non-string value".into())
        ))),
    }
}

/// The family of a scheme file, from its `domain` key.
pub fn family(path: &Path) -> Result<Family, Error> {
    family_of_text(&read_scheme_file(path)?, &path.display().to_string())
}

/// Load a scheme file of any family with `name=value` parameter overrides.
pub fn load(path: &Path, overrides: &[(String, String)]) -> Result<Built, Error> {
    let text = read_scheme_file(path)?;
    let file = path.display().to_string();
    Ok(match family_of_text(&text, &file)? {
        Family::Mesh => Built::Mesh(super::user::load(path, overrides)?),
        Family::Lattice => Built::Lattice(Box::new(lattice::LatticeFileDef::parse(&text, &file)?.build(overrides)?)),
        Family::Curve => Built::Curve(Box::new(curve::CurveFileDef::parse(&text, &file)?.build(overrides)?)),
    })
}

/// Every weight a scheme file of any family defines, at its default
/// parameters: for mesh files at each valence in `valences` (or the rule's
/// fixed one), every index j the rule asks for and, for face-corner fields,
/// every corner count m in `valences`; for lattice and curve files each mask
/// term and common factor. For checking that every arithmetic reads a file
/// alike.
pub fn weight_sites(path: &Path, valences: std::ops::RangeInclusive<i64>) -> Result<Vec<WeightSite>, Error> {
    let text = read_scheme_file(path)?;
    let file = path.display().to_string();
    let terms = |head: &Head, rules: Vec<(&[Term<()>], Option<&Term<()>>)>| -> Result<Vec<WeightSite>, Error> {
        let (env, _) = head.values(&[])?;
        let site = |t: &Term<()>| WeightSite { field: t.field.clone(), expr: t.expr.clone(), env: env.clone() };
        Ok(rules.into_iter().flat_map(|(ts, scale)| ts.iter().chain(scale).map(site).collect::<Vec<_>>()).collect())
    };
    match family_of_text(&text, &file)? {
        Family::Mesh => super::user::UserSchemeDef::parse(&text, &file)?.weight_sites(valences),
        Family::Lattice => {
            let d = lattice::LatticeFileDef::parse(&text, &file)?;
            let masks = d.terms();
            terms(&d.head, masks.iter().map(|(t, s)| (t.as_slice(), s.as_ref())).collect())
        }
        Family::Curve => {
            let d = curve::CurveFileDef::parse(&text, &file)?;
            let rules = d.terms();
            terms(&d.head, rules.iter().map(|(t, s)| (t.as_slice(), s.as_ref())).collect())
        }
    }
}

/// What `subdlab schemes FILE` shows of a file of any family.
pub struct Described {
    pub name: String,
    pub description: String,
    /// the topology a mesh file names, or the domain of a lattice or curve file
    pub topology: &'static str,
    pub params: Vec<UserParam>,
}

/// Parse a scheme file of any family for its name, description and parameters.
pub fn describe(path: &Path) -> Result<Described, Error> {
    let text = read_scheme_file(path)?;
    let file = path.display().to_string();
    Ok(match family_of_text(&text, &file)? {
        Family::Mesh => {
            let d = super::user::UserSchemeDef::parse(&text, &file)?;
            Described { topology: d.topology_name(), name: d.name, description: d.description, params: d.params }
        }
        Family::Lattice => {
            let d = lattice::LatticeFileDef::parse(&text, &file)?;
            Described { topology: "lattice", name: d.head.name, description: d.head.description, params: d.head.params }
        }
        Family::Curve => {
            let d = curve::CurveFileDef::parse(&text, &file)?;
            Described { topology: "curve", name: d.head.name, description: d.head.description, params: d.head.params }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::shared_format::offset_key;
    use super::*;

    #[test]
    fn domain_routing() {
        assert_eq!(family_of_text("name = \"x\"\ntopology = \"primal-quad\"\n", "f").unwrap(), Family::Mesh);
        assert_eq!(family_of_text("domain = \"curve\"\n", "f").unwrap(), Family::Curve);
        assert_eq!(family_of_text("domain = \"lattice\"\n", "f").unwrap(), Family::Lattice);
        let e = family_of_text("name = \"x\"\ndomain = \"torus\"\n", "f.toml").unwrap_err();
        assert!(matches!(e, Error::File(_)), "{e:?}");
        let e = e.to_string();
        assert!(e.starts_with("f.toml line 2, field domain:"), "{e}");
        // nested tables elsewhere in the file do not hide the key
        let nested = "domain = \"curve\"\n[params.w]\ndefault = \"1/16\"\n[odd]\n\"0\" = \"-w\"\n";
        assert_eq!(family_of_text(nested, "f").unwrap(), Family::Curve);
        // not TOML: the mesh loader reports it with its line
        assert_eq!(family_of_text("name = = 1", "f").unwrap(), Family::Mesh);
    }

    #[test]
    fn offsets() {
        assert_eq!(offset_key("-1, 2", 2).unwrap(), vec![-1, 2]);
        assert_eq!(offset_key("3", 1).unwrap(), vec![3]);
        assert!(offset_key("1", 2).unwrap_err().to_string().contains("not an offset"));
        assert!(offset_key("x", 1).unwrap_err().to_string().contains("not an integer offset"));
        assert!(offset_key("99", 1).unwrap_err().to_string().contains("beyond"));
    }
}
