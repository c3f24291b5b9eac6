//! The typed forms of a scene's choices. A JSON scene gives a hole's shape, a law's parameters, a
//! boundary condition's place and load and a bolt group's layout as optional fields; each method
//! here turns them into the enum that says what is valid, or an error naming the field at `path`.
//! Validation calls them first, so a scene that loads has them all; setup matches on the enums and
//! is left nothing to assume.

use super::validate::{SceneError, invalid};
use super::{
    BoltLine, BoltPattern, BoltSpec, BoundaryCondition, Circle, CwfsSpec, Excavation, Fix,
    HoekBrownResidual, Horseshoe, Inclusion, JointLawKind, JointMaterial, Material, SofteningPoint,
    StressTensor, ZoneLawKind,
};

/// The outline of an excavation or inclusion.
#[derive(Debug, Clone, Copy)]
pub enum Shape<'a> {
    Circle(&'a Circle),
    /// Vertices, m.
    Polygon(&'a [[f64; 2]]),
    Horseshoe(&'a Horseshoe),
}

impl Excavation {
    /// Its one shape: `circle`, `polygon` or `horseshoe`.
    pub fn shape(&self, path: &str) -> Result<Shape<'_>, SceneError> {
        match (&self.circle, &self.polygon, &self.horseshoe) {
            (Some(c), None, None) => Ok(Shape::Circle(c)),
            (None, Some(p), None) => Ok(Shape::Polygon(p)),
            (None, None, Some(h)) => Ok(Shape::Horseshoe(h)),
            _ => Err(invalid(
                path,
                "give exactly one of `circle`, `polygon` and `horseshoe`",
            )),
        }
    }
}

impl Inclusion {
    /// Its one shape: `circle` or `polygon`.
    pub fn shape(&self, path: &str) -> Result<Shape<'_>, SceneError> {
        match (&self.circle, &self.polygon) {
            (Some(c), None) => Ok(Shape::Circle(c)),
            (None, Some(p)) => Ok(Shape::Polygon(p)),
            _ => Err(invalid(path, "give exactly one of `circle` and `polygon`")),
        }
    }
}

/// A zone material's law with the parameters it needs.
#[derive(Debug, Clone, Copy)]
pub enum ZoneLawSpec<'a> {
    Elastic,
    MohrCoulomb {
        /// Cohesion c, Pa.
        cohesion: f64,
        /// Friction angle φ, degrees.
        friction: f64,
        /// Dilation angle ψ, degrees.
        dilation: f64,
        /// Tensile strength σt, Pa (`None`: the cap c / tan φ).
        tensile_strength: Option<f64>,
        /// Strain-softening table.
        softening: &'a [SofteningPoint],
        /// Cohesion weakening and friction strengthening, instead of `softening`.
        cwfs: Option<CwfsSpec>,
    },
    HoekBrown {
        /// The intact rock's uniaxial compressive strength σci, Pa.
        sigma_ci: f64,
        /// Where mb, s and a come from.
        constants: HoekBrownConstants,
        /// Dilation angle ψ, degrees.
        dilation: f64,
        /// Tensile strength σt, Pa (`None`: the apex s σci / mb).
        tensile_strength: Option<f64>,
        /// Residual constants and the plastic shear strain where they hold.
        residual: Option<(HoekBrownConstants, f64)>,
    },
}

/// The Hoek–Brown constants as a scene gives them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HoekBrownConstants {
    /// From the geological strength index, mi and the disturbance factor D.
    Gsi { gsi: f64, mi: f64, disturbance: f64 },
    /// mb, s and a themselves.
    Given { mb: f64, s: f64, a: f64 },
}

impl HoekBrownConstants {
    /// (mb, s, a).
    pub fn values(self) -> (f64, f64, f64) {
        match self {
            HoekBrownConstants::Gsi {
                gsi,
                mi,
                disturbance,
            } => crate::law::hoek_brown_constants(gsi, mi, disturbance),
            HoekBrownConstants::Given { mb, s, a } => (mb, s, a),
        }
    }
}

impl Material {
    /// Its law: Mohr–Coulomb needs `cohesion` and `friction`, Hoek–Brown `sigma_ci` and either
    /// `gsi` and `mi` or `mb`, `s` and `a`; a field of another law than the material's is an
    /// error (it could not act), as is any strength with the elastic law.
    pub fn law_spec(&self, path: &str) -> Result<ZoneLawSpec<'_>, SceneError> {
        let mohr_coulomb = [
            ("cohesion", self.cohesion.is_some()),
            ("friction", self.friction.is_some()),
            ("softening", !self.softening.is_empty()),
            ("cwfs", self.cwfs.is_some()),
        ];
        let hoek_brown = [
            ("sigma_ci", self.sigma_ci.is_some()),
            ("gsi", self.gsi.is_some()),
            ("mi", self.mi.is_some()),
            ("disturbance", self.disturbance.is_some()),
            ("mb", self.mb.is_some()),
            ("s", self.s.is_some()),
            ("a", self.a.is_some()),
            ("residual", self.residual.is_some()),
        ];
        let shared = [
            ("dilation", self.dilation != 0.0),
            ("tensile_strength", self.tensile_strength.is_some()),
        ];
        let foreign = |fields: &[(&str, bool)], law: &str| match fields.iter().find(|f| f.1) {
            Some((name, _)) => Err(invalid(
                format!("{path}.{name}"),
                format!("belongs to `law: {law}`, not this material's law"),
            )),
            None => Ok(()),
        };
        match self.law {
            ZoneLawKind::Elastic => {
                foreign(&mohr_coulomb, "mohr_coulomb")?;
                foreign(&shared, "mohr_coulomb` or `law: hoek_brown")?;
                foreign(&hoek_brown, "hoek_brown")?;
                Ok(ZoneLawSpec::Elastic)
            }
            ZoneLawKind::MohrCoulomb => {
                foreign(&hoek_brown, "hoek_brown")?;
                let (Some(cohesion), Some(friction)) = (self.cohesion, self.friction) else {
                    return Err(invalid(
                        path,
                        "`law: mohr_coulomb` needs `cohesion` and `friction`",
                    ));
                };
                if self.cwfs.is_some() && !self.softening.is_empty() {
                    return Err(invalid(
                        format!("{path}.cwfs"),
                        "give `cwfs` or a `softening` table, not both (`cwfs` makes the table)",
                    ));
                }
                Ok(ZoneLawSpec::MohrCoulomb {
                    cohesion,
                    friction,
                    dilation: self.dilation,
                    tensile_strength: self.tensile_strength,
                    softening: &self.softening,
                    cwfs: self.cwfs,
                })
            }
            ZoneLawKind::HoekBrown => {
                foreign(&mohr_coulomb, "mohr_coulomb")?;
                let Some(sigma_ci) = self.sigma_ci else {
                    return Err(invalid(path, "`law: hoek_brown` needs `sigma_ci`"));
                };
                let constants = match (self.gsi, self.mi, self.mb, self.s, self.a) {
                    (Some(gsi), Some(mi), None, None, None) => HoekBrownConstants::Gsi {
                        gsi,
                        mi,
                        disturbance: self.disturbance.unwrap_or(0.0),
                    },
                    (None, None, Some(mb), Some(s), Some(a)) if self.disturbance.is_none() => {
                        HoekBrownConstants::Given { mb, s, a }
                    }
                    _ => {
                        return Err(invalid(
                            path,
                            "`law: hoek_brown` needs either `gsi` and `mi` (with `disturbance`, \
                             default 0) or `mb`, `s` and `a`, not both",
                        ));
                    }
                };
                let residual = match self.residual {
                    None => None,
                    Some(r) => Some((residual_constants(&r, constants, path)?, r.plastic_strain)),
                };
                Ok(ZoneLawSpec::HoekBrown {
                    sigma_ci,
                    constants,
                    dilation: self.dilation,
                    tensile_strength: self.tensile_strength,
                    residual,
                })
            }
        }
    }
}

/// The residual constants `r` of a Hoek–Brown material whose peak constants are `peak`: a
/// residual GSI takes the peak's mi and D.
fn residual_constants(
    r: &HoekBrownResidual,
    peak: HoekBrownConstants,
    path: &str,
) -> Result<HoekBrownConstants, SceneError> {
    match (r.gsi, r.mb, r.s, r.a, peak) {
        (
            Some(gsi),
            None,
            None,
            None,
            HoekBrownConstants::Gsi {
                mi, disturbance, ..
            },
        ) => Ok(HoekBrownConstants::Gsi {
            gsi,
            mi,
            disturbance,
        }),
        (None, Some(mb), Some(s), Some(a), _) => Ok(HoekBrownConstants::Given { mb, s, a }),
        _ => Err(invalid(
            format!("{path}.residual"),
            "give `gsi` (with the peak's `gsi` and `mi`, whose mi and D it takes) or `mb`, `s` \
             and `a`",
        )),
    }
}

/// A joint material's law with the parameters only it needs (the stiffnesses, friction, cohesion,
/// tensile strength and dilation are common fields).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointLawSpec {
    Glued,
    Coulomb,
    ContinuouslyYielding {
        /// Roughness parameter R, m.
        roughness: f64,
        /// Initial friction angle, degrees (default: the friction angle).
        initial_friction: f64,
    },
    BartonBandis {
        /// JRC0 of the sample.
        jrc: f64,
        /// JCS0 of the sample, Pa.
        jcs: f64,
        /// Maximum closure Vm, m.
        max_closure: f64,
        /// Kmax, Pa/m (default: the tangent at JCS).
        max_normal_stiffness: Option<f64>,
        /// Sample length L0, m.
        sample_length: f64,
        /// Block size Ln to scale to, m.
        block_size: Option<f64>,
        /// Divisor M of the mobilized dilation angle.
        dilation_divisor: f64,
    },
}

impl JointMaterial {
    /// Its law: the continuously yielding law needs `roughness`, the Barton–Bandis law `jrc`,
    /// `jcs` and `max_closure`; each law's own fields belong to it alone, and the Barton–Bandis
    /// law, whose strength and dilation come from its roughness, takes no `cohesion`,
    /// `tensile_strength` or `dilation`.
    pub fn law_spec(&self, path: &str) -> Result<JointLawSpec, SceneError> {
        let barton_bandis = [
            ("jrc", self.jrc),
            ("jcs", self.jcs),
            ("max_closure", self.max_closure),
            ("max_normal_stiffness", self.max_normal_stiffness),
            ("sample_length", self.sample_length),
            ("block_size", self.block_size),
            ("dilation_divisor", self.dilation_divisor),
        ];
        if self.law == JointLawKind::BartonBandis {
            return self.barton_bandis_spec(path);
        }
        if let Some((field, _)) = barton_bandis.iter().find(|(_, v)| v.is_some()) {
            return Err(invalid(
                format!("{path}.{field}"),
                "belongs to the Barton–Bandis law (`law: barton_bandis`)",
            ));
        }
        match self.law {
            JointLawKind::ContinuouslyYielding => self.refuse_coulomb_strength(
                path,
                "the continuously yielding law (its strength is |σn| tan φm, its dilation \
                 tan(φm − φ), and it carries no tension)",
            )?,
            JointLawKind::Glued => {
                self.refuse_coulomb_strength(path, "a glued joint (it never slips or opens)")?
            }
            JointLawKind::Coulomb | JointLawKind::BartonBandis => {}
        }
        match self.law {
            JointLawKind::ContinuouslyYielding => match self.roughness {
                Some(roughness) => Ok(JointLawSpec::ContinuouslyYielding {
                    roughness,
                    initial_friction: self.initial_friction.unwrap_or(self.friction),
                }),
                None => Err(invalid(
                    format!("{path}.roughness"),
                    "required by the continuously yielding law",
                )),
            },
            _ if self.roughness.is_some() || self.initial_friction.is_some() => Err(invalid(
                path,
                "`roughness` and `initial_friction` belong to the continuously yielding law",
            )),
            JointLawKind::Glued => Ok(JointLawSpec::Glued),
            JointLawKind::Coulomb => Ok(JointLawSpec::Coulomb),
            JointLawKind::BartonBandis => unreachable!("returned above"),
        }
    }

    /// The Coulomb law's `cohesion`, `tensile_strength` and `dilation` refused where they
    /// cannot act, in `law` (words).
    fn refuse_coulomb_strength(&self, path: &str, law: &str) -> Result<(), SceneError> {
        for (field, v) in [
            ("cohesion", self.cohesion),
            ("tensile_strength", self.tensile_strength),
            ("dilation", self.dilation),
        ] {
            if v != 0.0 {
                return Err(invalid(
                    format!("{path}.{field}"),
                    format!("cannot act in {law}"),
                ));
            }
        }
        Ok(())
    }

    /// The Barton–Bandis law's fields (`friction` is its residual friction angle φr).
    fn barton_bandis_spec(&self, path: &str) -> Result<JointLawSpec, SceneError> {
        let required = |field: &str, v: Option<f64>| {
            v.ok_or_else(|| {
                invalid(
                    format!("{path}.{field}"),
                    "required by the Barton–Bandis law",
                )
            })
        };
        self.refuse_coulomb_strength(
            path,
            "the Barton–Bandis law (its strength and dilation come from `jrc` and `jcs`, and it \
             carries no tension)",
        )?;
        if self.roughness.is_some() || self.initial_friction.is_some() {
            return Err(invalid(
                path,
                "`roughness` and `initial_friction` belong to the continuously yielding law",
            ));
        }
        Ok(JointLawSpec::BartonBandis {
            jrc: required("jrc", self.jrc)?,
            jcs: required("jcs", self.jcs)?,
            max_closure: required("max_closure", self.max_closure)?,
            max_normal_stiffness: self.max_normal_stiffness,
            sample_length: self.sample_length.unwrap_or(0.1),
            block_size: self.block_size,
            dilation_divisor: self.dilation_divisor.unwrap_or(2.0),
        })
    }
}

/// Where a boundary condition acts, and what it does there.
#[derive(Debug, Clone, Copy)]
pub enum Condition<'a> {
    /// The boundary node nearest to `at` (m) has the components `fix` held.
    Point { at: [f64; 2], fix: Fix },
    /// Every node of the boundary part `name` has the components `fix` held and the edges of the
    /// part carry `load`.
    Part {
        name: &'a str,
        fix: Option<Fix>,
        load: Option<Load>,
    },
}

/// A traction on a boundary part.
#[derive(Debug, Clone, Copy)]
pub enum Load {
    /// σ·n of a given stress tensor, Pa.
    Stress(StressTensor),
    /// σ·n of the in-situ stress (with its gradient).
    InSitu,
    /// A normal and a shear stress, Pa (tension positive; shear along t = (−n_y, n_x)).
    NormalShear { normal: f64, shear: f64 },
}

impl BoundaryCondition {
    /// The components it holds: its `fix`, and its `motion`'s direction (which the motion
    /// drives).
    pub fn held(&self) -> Option<Fix> {
        let motion = self.motion.as_ref().map(|m| match m.direction {
            super::Axis::X => Fix::X,
            super::Axis::Y => Fix::Y,
        });
        match (self.fix, motion) {
            (Some(a), Some(b)) if a != b => Some(Fix::XY),
            (a, b) => a.or(b),
        }
    }

    /// Its typed form: exactly one of `part` and `at`; at most one kind of load; a point condition
    /// only fixes; something is fixed or loaded.
    pub fn condition(&self, path: &str) -> Result<Condition<'_>, SceneError> {
        let mut loads = Vec::with_capacity(1);
        if let Some(s) = self.stress {
            loads.push(Load::Stress(s));
        }
        if self.in_situ_traction {
            loads.push(Load::InSitu);
        }
        if self.normal_stress.is_some() || self.shear_stress.is_some() {
            loads.push(Load::NormalShear {
                normal: self.normal_stress.unwrap_or(0.0),
                shear: self.shear_stress.unwrap_or(0.0),
            });
        }
        match (&self.part, self.at) {
            (Some(_), None) | (None, Some(_)) => {}
            _ => return Err(invalid(path, "give exactly one of `part` and `at`")),
        }
        if self.at.is_some() && !loads.is_empty() {
            return Err(invalid(
                path,
                "a point condition (`at`) can only fix velocities",
            ));
        }
        if loads.len() > 1 {
            return Err(invalid(
                path,
                "give at most one of `stress`, `in_situ_traction`, `normal_stress`/`shear_stress`",
            ));
        }
        let load = loads.pop();
        match (&self.part, self.at, self.held()) {
            (None, Some(at), Some(fix)) => Ok(Condition::Point { at, fix }),
            (Some(name), None, fix) if fix.is_some() || load.is_some() || self.quiet => {
                Ok(Condition::Part { name, fix, load })
            }
            _ => Err(invalid(path, "neither a fixity nor a load is given")),
        }
    }
}

/// How a bolt group is laid out.
#[derive(Debug, Clone, Copy)]
pub enum BoltLayout<'a> {
    Line(&'a BoltLine),
    Pattern(&'a BoltPattern),
}

impl BoltSpec {
    /// Its layout: exactly one of `line` and `pattern`.
    pub fn layout(&self, path: &str) -> Result<BoltLayout<'_>, SceneError> {
        match (&self.line, &self.pattern) {
            (Some(l), None) => Ok(BoltLayout::Line(l)),
            (None, Some(p)) => Ok(BoltLayout::Pattern(p)),
            _ => Err(invalid(path, "give exactly one of `line` and `pattern`")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn condition(json: &str) -> Result<(), String> {
        let bc: BoundaryCondition = serde_json::from_str(json).unwrap();
        bc.condition("b").map(|_| ()).map_err(|e| e.to_string())
    }

    #[test]
    fn a_boundary_condition_is_a_point_fixity_or_a_part_with_a_fixity_or_one_load() {
        assert!(matches!(
            serde_json::from_str::<BoundaryCondition>(r#"{ "at": [1, 2], "fix": "x" }"#)
                .unwrap()
                .condition("b"),
            Ok(Condition::Point {
                at: [1.0, 2.0],
                fix: Fix::X
            })
        ));
        let part: BoundaryCondition =
            serde_json::from_str(r#"{ "part": "top", "normal_stress": -1e6 }"#).unwrap();
        match part.condition("b") {
            Ok(Condition::Part {
                name: "top",
                fix: None,
                load: Some(Load::NormalShear { normal, shear }),
            }) => assert_eq!((normal, shear), (-1e6, 0.0)),
            other => panic!("{other:?}"),
        }
        for (json, reason) in [
            (
                r#"{ "part": "top", "at": [0, 0], "fix": "x" }"#,
                "exactly one of `part` and `at`",
            ),
            (r#"{ "fix": "x" }"#, "exactly one of `part` and `at`"),
            (
                r#"{ "at": [0, 0], "normal_stress": 1 }"#,
                "can only fix velocities",
            ),
            (r#"{ "at": [0, 0] }"#, "neither a fixity nor a load"),
            (r#"{ "part": "top" }"#, "neither a fixity nor a load"),
            (
                r#"{ "part": "top", "in_situ_traction": true, "shear_stress": 1 }"#,
                "at most one of",
            ),
        ] {
            let msg = condition(json).unwrap_err();
            assert!(
                msg.starts_with("b: ") && msg.contains(reason),
                "{json}: {msg}"
            );
        }
    }

    #[test]
    fn a_law_takes_exactly_the_parameters_it_needs() {
        let m = |json: &str| serde_json::from_str::<Material>(json).unwrap();
        let base = r#""density": 2500, "young": 1e9, "poisson": 0.2"#;
        let mc = m(&format!(
            r#"{{ {base}, "law": "mohr_coulomb", "cohesion": 1e6, "friction": 30 }}"#
        ));
        assert!(matches!(
            mc.law_spec("m"),
            Ok(ZoneLawSpec::MohrCoulomb {
                cohesion: 1e6,
                friction: 30.0,
                tensile_strength: None,
                ..
            })
        ));
        let no_friction = m(&format!(
            r#"{{ {base}, "law": "mohr_coulomb", "cohesion": 1e6 }}"#
        ));
        assert!(
            no_friction
                .law_spec("m")
                .unwrap_err()
                .to_string()
                .contains("needs")
        );
        let elastic_with_strength = m(&format!(r#"{{ {base}, "cohesion": 1e6 }}"#));
        assert!(elastic_with_strength.law_spec("m").is_err());

        let j = |json: &str| serde_json::from_str::<JointMaterial>(json).unwrap();
        let k = r#""normal_stiffness": 1e10, "shear_stiffness": 1e9, "friction": 30"#;
        let cy = j(&format!(
            r#"{{ {k}, "law": "continuously_yielding", "roughness": 1e-3 }}"#
        ));
        assert_eq!(
            cy.law_spec("j").unwrap(),
            JointLawSpec::ContinuouslyYielding {
                roughness: 1e-3,
                initial_friction: 30.0
            }
        );
        let cy_bare = j(&format!(r#"{{ {k}, "law": "continuously_yielding" }}"#));
        assert!(
            cy_bare
                .law_spec("j")
                .unwrap_err()
                .to_string()
                .starts_with("j.roughness")
        );
        let coulomb_rough = j(&format!(r#"{{ {k}, "roughness": 1e-3 }}"#));
        assert!(coulomb_rough.law_spec("j").is_err());
        // Strength fields that cannot act are refused.
        let cy_cohesive = j(&format!(
            r#"{{ {k}, "law": "continuously_yielding", "roughness": 1e-3, "cohesion": 1e5 }}"#
        ));
        assert!((cy_cohesive.law_spec("j").unwrap_err().to_string()).starts_with("j.cohesion"));
        let glued_dilating = j(&format!(r#"{{ {k}, "law": "glued", "dilation": 5 }}"#));
        assert!((glued_dilating.law_spec("j").unwrap_err().to_string()).starts_with("j.dilation"));

        let bb = r#""law": "barton_bandis", "jrc": 10, "jcs": 100e6, "max_closure": 5e-4"#;
        assert_eq!(
            j(&format!("{{ {k}, {bb} }}")).law_spec("j").unwrap(),
            JointLawSpec::BartonBandis {
                jrc: 10.0,
                jcs: 100e6,
                max_closure: 5e-4,
                max_normal_stiffness: None,
                sample_length: 0.1,
                block_size: None,
                dilation_divisor: 2.0
            }
        );
        let err = |json: String| j(&json).law_spec("j").unwrap_err().to_string();
        assert!(
            err(format!(
                r#"{{ {k}, "law": "barton_bandis", "jrc": 10, "jcs": 100e6 }}"#
            ))
            .starts_with("j.max_closure")
        );
        assert!(err(format!(r#"{{ {k}, {bb}, "cohesion": 1e5 }}"#)).starts_with("j.cohesion"));
        assert!(err(format!(r#"{{ {k}, {bb}, "dilation": 5 }}"#)).starts_with("j.dilation"));
        assert!(err(format!(r#"{{ {k}, "jrc": 10 }}"#)).starts_with("j.jrc"));
    }
}
