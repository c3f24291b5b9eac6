//! The material catalogues a scene sets up: zone laws (the scene's materials, then the null law of
//! excavated zones) and joint laws (the scene's joint materials, then the glued interfaces of
//! staged fills and inclusions), with the material of each block, joint feature and hole wall.

use crate::contact::detect::NO_MATERIAL;
use crate::joint::{
    BartonBandis, ContinuouslyYielding, CoulombSlip, Glued, JointLaw, Roughness, tan_deg,
};
use crate::law::{
    Elastic, HoekBrown, Matrix, MohrCoulomb, Null, Residual, UbiquitousJoint, ZoneLaw,
};
use crate::model::MaterialId;
use crate::scene::{JointLawSpec, JointMaterial, Material, Scene, SceneError, ZoneLawSpec};

use super::geometry::{Meshed, NOT_FILL};

/// The zone law of material `m` (scene field `path`): its law, inside ubiquitous joints when it
/// has a weak plane.
pub fn zone_law(m: &Material, path: &str) -> Result<Box<dyn ZoneLaw>, SceneError> {
    let matrix = matrix_law(m, path)?;
    Ok(match m.weak_plane {
        None => matrix.into_law(),
        Some(w) => Box::new(UbiquitousJoint::new(
            matrix,
            w.dip,
            w.cohesion,
            (w.friction, w.dilation),
            w.tensile_strength.unwrap_or(f64::INFINITY),
        )),
    })
}

/// The law of material `m` (scene field `path`) without its weak plane.
pub fn matrix_law(m: &Material, path: &str) -> Result<Matrix, SceneError> {
    let elastic = Elastic::from_young(m.young, m.poisson, m.density);
    Ok(match m.law_spec(path)? {
        ZoneLawSpec::Elastic => Matrix::Elastic(elastic),
        ZoneLawSpec::MohrCoulomb {
            cohesion,
            friction,
            dilation,
            tensile_strength,
            softening,
            cwfs,
        } => {
            let tension = tensile_strength.unwrap_or(f64::INFINITY);
            let mut law = MohrCoulomb::new(elastic, cohesion, friction, dilation, tension);
            let table = match cwfs {
                Some(cwfs) => cwfs.table(cohesion, friction),
                None => (softening.iter())
                    .map(|p| (p.plastic_strain, p.cohesion, p.friction))
                    .collect(),
            };
            law.softening = (table.into_iter())
                .map(|(e, c, phi)| (e, c, phi.to_radians()))
                .collect();
            Matrix::MohrCoulomb(law)
        }
        ZoneLawSpec::HoekBrown {
            sigma_ci,
            constants,
            dilation,
            tensile_strength,
            residual,
        } => {
            let law = HoekBrown::new(
                elastic,
                sigma_ci,
                constants.values(),
                dilation,
                tensile_strength.unwrap_or(f64::INFINITY),
            );
            Matrix::HoekBrown(match residual {
                None => law,
                Some((constants, strain)) => {
                    let (mb, s, a) = constants.values();
                    law.with_residual(Residual { mb, s, a, strain })
                }
            })
        }
    })
}

/// The joint law of joint material `j` (scene field `path`).
pub fn joint_law(j: &JointMaterial, path: &str) -> Result<Box<dyn JointLaw>, SceneError> {
    let (normal_stiffness, shear_stiffness) = (j.normal_stiffness, j.shear_stiffness);
    Ok(match j.law_spec(path)? {
        JointLawSpec::Glued => Box::new(Glued {
            normal_stiffness,
            shear_stiffness,
        }),
        JointLawSpec::Coulomb => Box::new(CoulombSlip {
            normal_stiffness,
            shear_stiffness,
            tan_friction: tan_deg(j.friction),
            cohesion: j.cohesion,
            residual_cohesion: j.residual_cohesion,
            tensile_strength: j.tensile_strength,
            tan_dilation: tan_deg(j.dilation),
        }),
        JointLawSpec::ContinuouslyYielding {
            roughness,
            initial_friction,
        } => Box::new(ContinuouslyYielding {
            normal_stiffness,
            shear_stiffness,
            friction: j.friction.to_radians(),
            initial_friction: initial_friction.to_radians(),
            roughness,
            strength_factor: 1.0,
        }),
        JointLawSpec::BartonBandis {
            jrc,
            jcs,
            max_closure,
            max_normal_stiffness,
            sample_length,
            block_size,
            dilation_divisor,
        } => {
            let law = BartonBandis::new(
                (normal_stiffness, max_closure),
                shear_stiffness,
                Roughness {
                    jrc,
                    jcs,
                    sample_length,
                    block_size,
                },
                j.friction,
                dilation_divisor,
            );
            Box::new(match max_normal_stiffness {
                Some(k) => law.with_max_normal_stiffness(k),
                None => law,
            })
        }
    })
}

/// Where `name` is in `names`, as an id; else an error naming the field `path`.
pub(super) fn position(names: &[String], name: &str, path: &str) -> anyhow::Result<u32> {
    let i = names.iter().position(|n| n == name);
    i.map(|i| i as u32)
        .ok_or_else(|| anyhow::anyhow!("{path}: no material named '{name}'"))
}

/// The zone laws by `MaterialId`: the scene's materials in order, then (with stages) the null law
/// excavated zones take.
pub(super) struct ZoneCatalogue {
    pub names: Vec<String>,
    pub(crate) laws: Vec<Box<dyn ZoneLaw>>,
    /// The null law's id (staged scenes only).
    pub null: Option<MaterialId>,
    /// Poisson's ratio of each of the scene's materials.
    pub poisson: Vec<f64>,
    /// Young's modulus of each of the scene's materials, Pa.
    pub young: Vec<f64>,
    /// The region's material.
    pub region: MaterialId,
    /// The material of each inclusion.
    pub inclusion: Vec<MaterialId>,
}

impl ZoneCatalogue {
    pub fn of(scene: &Scene) -> anyhow::Result<ZoneCatalogue> {
        let mut names: Vec<String> = scene.materials.keys().cloned().collect();
        let mut laws: Vec<Box<dyn ZoneLaw>> = Vec::with_capacity(names.len() + 1);
        for (name, m) in &scene.materials {
            laws.push(zone_law(m, &format!("materials.{name}"))?);
        }
        let region = MaterialId(position(&names, &scene.region.material, "region.material")?);
        let mut inclusion = Vec::with_capacity(scene.inclusions.len());
        for (i, inc) in scene.inclusions.iter().enumerate() {
            let path = format!("inclusions[{i}].material");
            inclusion.push(MaterialId(position(&names, &inc.material, &path)?));
        }
        // Excavated zones take the null law (the last material).
        let null = (!scene.stages.is_empty()).then(|| {
            names.push("excavated".into());
            laws.push(Box::new(Null));
            MaterialId((laws.len() - 1) as u32)
        });
        Ok(ZoneCatalogue {
            names,
            laws,
            null,
            poisson: scene.materials.values().map(|m| m.poisson).collect(),
            young: scene.materials.values().map(|m| m.young).collect(),
            region,
            inclusion,
        })
    }

    /// The id of the material `name` (scene field `path`).
    pub fn id(&self, name: &str, path: &str) -> anyhow::Result<MaterialId> {
        position(&self.names, name, path).map(MaterialId)
    }

    /// Each block's material: the region's, or its inclusion's.
    pub fn of_blocks(&self, meshed: &Meshed) -> Vec<MaterialId> {
        let of_block = |i: u32| {
            self.inclusion
                .get(i as usize)
                .copied()
                .unwrap_or(self.region)
        };
        meshed.inclusion.iter().map(|&i| of_block(i)).collect()
    }
}

/// The joint laws by joint material id, and which of them each joint feature and hole wall takes.
pub(super) struct JointCatalogue {
    pub names: Vec<String>,
    pub(crate) laws: Vec<Box<dyn JointLaw>>,
    /// Joint material of each joint feature (`EdgeKind::Joint(k)`: sets first, then explicit
    /// joints, then Voronoi grain boundaries).
    pub feature: Vec<u32>,
    /// Joint material of each hole's wall: a staged excavation's fill, an inclusion's interface,
    /// `NO_MATERIAL` for a hole from the start.
    pub hole: Vec<u32>,
}

impl JointCatalogue {
    pub fn of(
        scene: &Scene,
        meshed: &Meshed,
        zones: &ZoneCatalogue,
    ) -> anyhow::Result<JointCatalogue> {
        let mut names: Vec<String> = scene.joint_materials.keys().cloned().collect();
        let mut laws: Vec<Box<dyn JointLaw>> = Vec::with_capacity(names.len() + 2);
        for (name, j) in &scene.joint_materials {
            laws.push(joint_law(j, &format!("joint_materials.{name}"))?);
        }
        let mut feature = Vec::new();
        for (i, s) in scene.joint_sets.iter().enumerate() {
            feature.push(position(
                &names,
                &s.material,
                &format!("joint_sets[{i}].material"),
            )?);
        }
        for (i, j) in scene.joints.iter().enumerate() {
            feature.push(position(
                &names,
                &j.material,
                &format!("joints[{i}].material"),
            )?);
        }
        if let Some(v) = &scene.voronoi {
            feature.push(position(&names, &v.material, "voronoi.material")?);
        }
        // The rock filling a staged excavation is glued to its surroundings until it is removed,
        // with the stiffness of the stiffest joint material, or of the rock over a wall zone (E/h)
        // if there is none (so that filling adds nothing stiffer than the model already has).
        let fill = meshed.fill.iter().any(|&f| f != NOT_FILL).then(|| {
            let (kn, ks) = laws
                .iter()
                .map(|l| l.stiffness())
                .fold(None, |m: Option<(f64, f64)>, k| {
                    Some(m.map_or(k, |m| (m.0.max(k.0), m.1.max(k.1))))
                })
                .unwrap_or_else(|| {
                    let e = zones.young[zones.region.0 as usize];
                    let k = e / scene.zoning.edge_at_excavation;
                    (k, 0.5 * k)
                });
            names.push("excavation fill".into());
            laws.push(Box::new(Glued {
                normal_stiffness: kn,
                shear_stiffness: ks,
            }));
            (laws.len() - 1) as u32
        });
        // Inclusions are bonded to the rock around: glued, kn = (largest E of the rock and the
        // inclusions) / h at the excavation, so the interface is stiffer than a zone of either
        // side.
        let inclusion = (!scene.inclusions.is_empty()).then(|| {
            let e = (zones.inclusion.iter())
                .chain([&zones.region])
                .map(|m| zones.young[m.0 as usize])
                .fold(0.0, f64::max);
            let k = e / scene.zoning.edge_at_excavation;
            names.push("inclusion interface".into());
            laws.push(Box::new(Glued {
                normal_stiffness: k,
                shear_stiffness: 0.5 * k,
            }));
            (laws.len() - 1) as u32
        });
        let hole: Vec<u32> = (0..meshed.domain.holes.len())
            .map(|j| match scene.excavations.get(j) {
                Some(e) if scene.is_staged(&e.name) => fill,
                Some(_) => None,
                None => inclusion,
            })
            .map(|m| m.unwrap_or(NO_MATERIAL))
            .collect();
        Ok(JointCatalogue {
            names,
            laws,
            feature,
            hole,
        })
    }
}
