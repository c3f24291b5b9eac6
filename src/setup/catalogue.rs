//! The material catalogues a scene sets up: zone laws (the scene's materials, then the null law of
//! excavated zones) and joint laws (the scene's joint materials, then the glued interfaces of
//! staged fills and inclusions), with the material of each block, joint feature and hole wall.

use crate::contact::detect::NO_MATERIAL;
use crate::joint::{ContinuouslyYielding, CoulombSlip, Glued, JointLaw, tan_deg};
use crate::law::{Elastic, MohrCoulomb, Null, ZoneLaw};
use crate::model::MaterialId;
use crate::scene::{JointLawKind, JointMaterial, Material, Scene, ZoneLawKind};

use super::geometry::{Meshed, NOT_FILL};

/// The zone law of a material (scene-validated).
pub fn zone_law(m: &Material) -> Box<dyn ZoneLaw> {
    let elastic = Elastic::from_young(m.young, m.poisson, m.density);
    match m.law {
        ZoneLawKind::Elastic => Box::new(elastic),
        ZoneLawKind::MohrCoulomb => {
            let c = m.cohesion.expect("validated");
            let phi = m.friction.expect("validated");
            let tension = m.tensile_strength.unwrap_or(f64::INFINITY);
            let mut law = MohrCoulomb::new(elastic, c, phi, m.dilation, tension);
            law.softening = m
                .softening
                .iter()
                .map(|p| (p.plastic_strain, p.cohesion, p.friction.to_radians()))
                .collect();
            Box::new(law)
        }
    }
}

/// The joint law of a joint material (scene-validated).
pub fn joint_law(j: &JointMaterial) -> Box<dyn JointLaw> {
    let (normal_stiffness, shear_stiffness) = (j.normal_stiffness, j.shear_stiffness);
    match j.law {
        JointLawKind::Glued => Box::new(Glued {
            normal_stiffness,
            shear_stiffness,
        }),
        JointLawKind::Coulomb => Box::new(CoulombSlip {
            normal_stiffness,
            shear_stiffness,
            tan_friction: tan_deg(j.friction),
            cohesion: j.cohesion,
            tensile_strength: j.tensile_strength,
            tan_dilation: tan_deg(j.dilation),
        }),
        JointLawKind::ContinuouslyYielding => Box::new(ContinuouslyYielding {
            normal_stiffness,
            shear_stiffness,
            friction: j.friction.to_radians(),
            initial_friction: j.initial_friction.unwrap_or(j.friction).to_radians(),
            roughness: j.roughness.expect("validated"),
        }),
    }
}

/// The zone laws by `MaterialId`: the scene's materials in order, then (with stages) the null law
/// excavated zones take.
pub(super) struct ZoneCatalogue {
    pub names: Vec<String>,
    pub laws: Vec<Box<dyn ZoneLaw>>,
    /// The null law's id (staged scenes only).
    pub null: Option<MaterialId>,
    /// Poisson's ratio of each of the scene's materials.
    pub poisson: Vec<f64>,
    /// The region's material.
    pub region: MaterialId,
}

impl ZoneCatalogue {
    pub fn of(scene: &Scene) -> ZoneCatalogue {
        let mut names: Vec<String> = scene.materials.keys().cloned().collect();
        let mut laws: Vec<Box<dyn ZoneLaw>> = scene.materials.values().map(zone_law).collect();
        let region = names
            .iter()
            .position(|n| *n == scene.region.material)
            .expect("validated");
        // Excavated zones take the null law (the last material).
        let null = (!scene.stages.is_empty()).then(|| {
            names.push("excavated".into());
            laws.push(Box::new(Null));
            MaterialId((laws.len() - 1) as u32)
        });
        ZoneCatalogue {
            names,
            laws,
            null,
            poisson: scene.materials.values().map(|m| m.poisson).collect(),
            region: MaterialId(region as u32),
        }
    }

    /// The id of the material `name`.
    pub fn id(&self, name: &str) -> MaterialId {
        MaterialId(
            self.names
                .iter()
                .position(|n| n == name)
                .expect("validated") as u32,
        )
    }

    /// Each block's material: the region's, or its inclusion's.
    pub fn of_blocks(&self, scene: &Scene, meshed: &Meshed) -> Vec<MaterialId> {
        meshed
            .inclusion
            .iter()
            .map(|&i| match scene.inclusions.get(i as usize) {
                Some(inc) => self.id(&inc.material),
                None => self.region,
            })
            .collect()
    }
}

/// The joint laws by joint material id, and which of them each joint feature and hole wall takes.
pub(super) struct JointCatalogue {
    pub names: Vec<String>,
    pub laws: Vec<Box<dyn JointLaw>>,
    /// Joint material of each joint feature (`EdgeKind::Joint(k)`: sets first, then explicit
    /// joints, then Voronoi grain boundaries).
    pub feature: Vec<u32>,
    /// Joint material of each hole's wall: a staged excavation's fill, an inclusion's interface,
    /// `NO_MATERIAL` for a hole from the start.
    pub hole: Vec<u32>,
}

impl JointCatalogue {
    pub fn of(scene: &Scene, meshed: &Meshed) -> JointCatalogue {
        let mut names: Vec<String> = scene.joint_materials.keys().cloned().collect();
        let mut laws: Vec<Box<dyn JointLaw>> =
            scene.joint_materials.values().map(joint_law).collect();
        let index = |name: &str| names.iter().position(|n| n == name).expect("validated") as u32;
        let feature: Vec<u32> = scene
            .joint_sets
            .iter()
            .map(|s| index(&s.material))
            .chain(scene.joints.iter().map(|j| index(&j.material)))
            .chain(scene.voronoi.iter().map(|v| index(&v.material)))
            .collect();
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
                    let e = scene.materials[&scene.region.material].young;
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
            let e = scene
                .inclusions
                .iter()
                .map(|i| &i.material)
                .chain([&scene.region.material])
                .map(|m| scene.materials[m].young)
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
        JointCatalogue {
            names,
            laws,
            feature,
            hole,
        }
    }
}
