//! Scene fields of the supports: fully grouted rock bolts (cable elements) and liners (beam
//! elements on an excavation's wall). Plane strain: the model is one metre thick, so every
//! property of one bolt or one steel set is divided by its spacing along the tunnel axis.

use serde::Deserialize;

/// A group of fully grouted bolts with the same properties: one along a line, or a pattern
/// around an excavation.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoltSpec {
    /// Name, used by a stage's `install`.
    pub name: String,
    /// Young's modulus of the bolt steel, Pa.
    pub young: f64,
    /// Cross-section area of one bolt, m².
    pub area: f64,
    /// Axial yield force of one bolt, N (in tension and in compression).
    pub(crate) yield_force: f64,
    /// Shear stiffness of the grout per length of bolt, N/m per m (Pa).
    pub grout_stiffness: f64,
    /// Bond strength of the grout per length of bolt, N/m.
    pub bond_strength: f64,
    /// Pretension of one bolt, N (default 0): an axial force in every segment from installation.
    #[serde(default)]
    pub(crate) pretension: f64,
    /// Spacing of the bolts along the tunnel axis, m (default 1).
    #[serde(default = "one")]
    pub out_of_plane_spacing: f64,
    /// Density of the steel, kg/m³ (default 7850; dynamic runs only).
    #[serde(default = "steel_density")]
    pub density: f64,
    /// Length of the cable segments, m (default `zoning.edge_at_excavation`).
    #[serde(default)]
    pub segment: Option<f64>,
    /// One bolt from `from` (its head) to `to`.
    #[serde(default)]
    pub line: Option<BoltLine>,
    /// Bolts normal to an excavation's wall.
    #[serde(default)]
    pub pattern: Option<BoltPattern>,
}

/// One bolt between two points.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoltLine {
    /// Head, m.
    pub from: [f64; 2],
    /// Toe, m.
    pub to: [f64; 2],
}

/// `count` bolts of length `length` normal to the wall of `excavation`, their heads `spacing`
/// apart along the wall, centred on the wall point seen from the excavation's centroid in the
/// direction `toward`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoltPattern {
    pub excavation: String,
    pub count: usize,
    /// Bolt length, m.
    pub length: f64,
    /// Distance between neighbouring heads along the wall, m.
    pub spacing: f64,
    /// Direction of the pattern's centre from the excavation's centroid, degrees counter-clockwise
    /// from +x (default 90: the crown).
    #[serde(default = "crown")]
    pub(crate) toward: f64,
}

/// A liner (shotcrete, steel sets) along the whole wall of an excavation: elastic beam elements
/// bonded to the wall (no slip).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinerSpec {
    /// Name, used by a stage's `install`.
    pub name: String,
    /// The excavation whose wall it lines.
    pub excavation: String,
    /// Young's modulus, Pa.
    pub young: f64,
    /// Poisson's ratio (default 0): a continuous shell bends in plane strain, E/(1 − ν²).
    #[serde(default)]
    pub poisson: f64,
    /// Cross-section area of one set, m² (a shotcrete shell of thickness t: t × 1 m).
    pub area: f64,
    /// Second moment of area of one set, m⁴ (shotcrete: t³/12 × 1 m).
    pub inertia: f64,
    /// Spacing of the sets along the tunnel axis, m (default 1; a continuous shell: 1).
    #[serde(default = "one")]
    pub out_of_plane_spacing: f64,
    /// Density, kg/m³ (default 2500; dynamic runs only).
    #[serde(default = "concrete_density")]
    pub density: f64,
    /// The strengths of its material: with them, each element's factor of safety against its
    /// thrust, moment and shear is reported (`support::liner_capacity`).
    #[serde(default)]
    pub capacity: Option<LinerCapacitySpec>,
}

/// A liner's material strengths, for its capacity (a rectangular section: depth √(12 I / A)).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinerCapacitySpec {
    /// Uniaxial compressive strength σc, Pa.
    pub compressive_strength: f64,
    /// Tensile strength σt, Pa.
    pub tensile_strength: f64,
}

fn one() -> f64 {
    1.0
}

fn steel_density() -> f64 {
    7850.0
}

fn concrete_density() -> f64 {
    2500.0
}

fn crown() -> f64 {
    90.0
}

use super::validate::{Num, SceneError, invalid};
use super::{BoltLayout, Scene};

fn positive(path: String, v: f64) -> Result<(), SceneError> {
    if v > 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(invalid(path, format!("must be positive, got {}", Num(v))))
    }
}

fn at_least_zero(path: String, v: f64) -> Result<(), SceneError> {
    if v >= 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(invalid(
            path,
            format!("must be zero or positive, got {}", Num(v)),
        ))
    }
}

impl Scene {
    /// Bolts and liners: properties in range, one placement per bolt group, known excavations,
    /// unique names.
    pub(super) fn validate_supports(&self) -> Result<(), SceneError> {
        let mut names: Vec<&str> = Vec::new();
        let excavation = |p: String, name: &str| {
            if self.excavations.iter().any(|e| e.name == name) {
                Ok(())
            } else {
                Err(invalid(p, format!("no excavation named '{name}'")))
            }
        };
        for (i, b) in self.bolts.iter().enumerate() {
            let p = format!("bolts[{i}]");
            if names.contains(&b.name.as_str()) {
                return Err(invalid(
                    format!("{p}.name"),
                    format!("'{}' is used twice", b.name),
                ));
            }
            names.push(&b.name);
            for (f, v) in [
                ("young", b.young),
                ("area", b.area),
                ("yield_force", b.yield_force),
                ("grout_stiffness", b.grout_stiffness),
                ("bond_strength", b.bond_strength),
                ("out_of_plane_spacing", b.out_of_plane_spacing),
                ("density", b.density),
            ] {
                positive(format!("{p}.{f}"), v)?;
            }
            at_least_zero(format!("{p}.pretension"), b.pretension)?;
            if b.pretension > b.yield_force {
                return Err(invalid(
                    format!("{p}.pretension"),
                    "must not exceed yield_force",
                ));
            }
            if let Some(s) = b.segment {
                positive(format!("{p}.segment"), s)?;
            }
            match b.layout(&p)? {
                BoltLayout::Line(l) => {
                    if l.from == l.to {
                        return Err(invalid(format!("{p}.line"), "`from` and `to` coincide"));
                    }
                }
                BoltLayout::Pattern(pat) => {
                    excavation(format!("{p}.pattern.excavation"), &pat.excavation)?;
                    self.installed_after_its_wall(&format!("{p}.name"), &b.name, &pat.excavation)?;
                    positive(format!("{p}.pattern.length"), pat.length)?;
                    if pat.count == 0 {
                        return Err(invalid(format!("{p}.pattern.count"), "must be at least 1"));
                    }
                    if pat.count > 1 {
                        positive(format!("{p}.pattern.spacing"), pat.spacing)?;
                    }
                }
            }
        }
        for (i, l) in self.liners.iter().enumerate() {
            let p = format!("liners[{i}]");
            if names.contains(&l.name.as_str()) {
                return Err(invalid(
                    format!("{p}.name"),
                    format!("'{}' is used twice", l.name),
                ));
            }
            names.push(&l.name);
            excavation(format!("{p}.excavation"), &l.excavation)?;
            self.installed_after_its_wall(&format!("{p}.name"), &l.name, &l.excavation)?;
            for (f, v) in [
                ("young", l.young),
                ("area", l.area),
                ("inertia", l.inertia),
                ("out_of_plane_spacing", l.out_of_plane_spacing),
                ("density", l.density),
            ] {
                positive(format!("{p}.{f}"), v)?;
            }
            if let Some(c) = l.capacity {
                positive(
                    format!("{p}.capacity.compressive_strength"),
                    c.compressive_strength,
                )?;
                positive(format!("{p}.capacity.tensile_strength"), c.tensile_strength)?;
            }
            if !(-1.0 < l.poisson && l.poisson < 0.5) {
                return Err(invalid(
                    format!("{p}.poisson"),
                    format!("must be in (−1, 0.5), got {}", Num(l.poisson)),
                ));
            }
        }
        Ok(())
    }

    /// A support `name` (path `p`) on the wall of excavation `wall`: if a stage makes that wall,
    /// a stage must install the support (one that no stage installs is there from the start,
    /// and would carry load in the rock before its wall exists).
    fn installed_after_its_wall(&self, p: &str, name: &str, wall: &str) -> Result<(), SceneError> {
        let Some(made) = self
            .stages
            .iter()
            .find(|s| s.excavate.iter().any(|x| x == wall))
        else {
            return Ok(());
        };
        if self
            .stages
            .iter()
            .any(|s| s.install.iter().any(|n| n == name))
        {
            return Ok(());
        }
        Err(invalid(
            p,
            format!(
                "'{name}' is on the wall of '{wall}', which stage '{}' excavates, but no stage \
                 installs it: name it in the `install` of that stage or a later one",
                made.name
            ),
        ))
    }

    /// A stage's `install` entry `name` (path `p`), with `excavated` the excavations made by this
    /// stage and the ones before: a known support, installed once, on a wall that exists.
    pub(super) fn validate_install(
        &self,
        p: &str,
        name: &str,
        excavated: &[&str],
    ) -> Result<(), SceneError> {
        let installs = self
            .stages
            .iter()
            .flat_map(|s| &s.install)
            .filter(|n| *n == name)
            .count();
        if installs > 1 {
            return Err(invalid(p, format!("'{name}' is installed twice")));
        }
        let wall = if let Some(b) = self.bolts.iter().find(|b| b.name == name) {
            b.pattern.as_ref().map(|pat| pat.excavation.as_str())
        } else if let Some(l) = self.liners.iter().find(|l| l.name == name) {
            Some(l.excavation.as_str())
        } else {
            return Err(invalid(p, format!("no bolt group or liner named '{name}'")));
        };
        if let Some(e) = wall {
            let staged = self
                .stages
                .iter()
                .any(|s| s.excavate.iter().any(|x| x == e));
            if staged && !excavated.contains(&e) {
                return Err(invalid(
                    p,
                    format!("'{name}' is installed on the wall of '{e}' before it is excavated"),
                ));
            }
        }
        Ok(())
    }
}
