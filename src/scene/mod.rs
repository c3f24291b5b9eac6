//! Scene files: the JSON description of a model (materials, geometry, zoning, in-situ stress,
//! boundary conditions, solve criterion, output). Every field is documented in
//! `docs/scene-format.md`; unknown fields are errors.

mod json_path;
mod limits;
mod magnitudes;
mod names;
mod realization;
mod supports;
mod typed;
mod unique;
mod validate;

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

pub use limits::{
    MAX_BOLT_SEGMENTS, MAX_BOLTS, MAX_GRAINS, MAX_JOINTS, MAX_POLYGON_VERTICES, MAX_REGION_VERTICES,
};
pub use realization::Scatter;
pub use supports::{BoltLine, BoltPattern, BoltSpec, LinerCapacitySpec, LinerSpec};
pub use typed::{
    BoltLayout, Condition, HoekBrownConstants, JointLawSpec, Load, Shape, ZoneLawSpec,
};
pub use validate::SceneError;

/// A whole scene, as read from JSON.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Name used for output files.
    pub name: String,
    /// Zone materials by name.
    #[serde(deserialize_with = "unique::unique_keys")]
    pub materials: BTreeMap<String, Material>,
    pub region: Region,
    #[serde(default)]
    pub excavations: Vec<Excavation>,
    /// Regions of another material inside the region (a stiff dyke, a soft fault zone), bonded to
    /// the rock around them.
    #[serde(default)]
    pub inclusions: Vec<Inclusion>,
    pub zoning: ZoningSpec,
    /// Joint materials by name.
    #[serde(default, deserialize_with = "unique::unique_keys")]
    pub joint_materials: BTreeMap<String, JointMaterial>,
    /// Sets of parallel joints cutting the region into blocks.
    #[serde(default)]
    pub joint_sets: Vec<JointSetSpec>,
    /// Which realization of the joint sets' `scatter` to build (default 0: the sets as written).
    #[serde(default)]
    pub realization: u64,
    /// Explicit joint segments.
    #[serde(default)]
    pub joints: Vec<JointLine>,
    /// Voronoi grains: the region cut by the Voronoi tessellation of jittered seeds.
    #[serde(default)]
    pub(crate) voronoi: Option<VoronoiSpec>,
    #[serde(default)]
    pub contacts: ContactSpec,
    /// Block modes: deformable, simple or rigid, for all blocks or by region.
    #[serde(default)]
    pub blocks: BlocksSpec,
    #[serde(default)]
    pub in_situ: InSitu,
    /// Gravitational acceleration (m/s²), as a vector; default none.
    #[serde(default)]
    pub gravity: [f64; 2],
    #[serde(default)]
    pub boundary: Vec<BoundaryCondition>,
    #[serde(default)]
    pub solve: SolveSpec,
    /// Fully grouted rock bolts (installed by a stage's `install`, else from the start).
    #[serde(default)]
    pub bolts: Vec<BoltSpec>,
    /// Liners on excavation walls (installed by a stage's `install`, else from the start).
    #[serde(default)]
    pub liners: Vec<LinerSpec>,
    /// Stages solved in order (default: one stage, solved with `solve`). Excavations named in a
    /// stage's `excavate` are filled with rock until that stage.
    #[serde(default)]
    pub stages: Vec<Stage>,
    /// Monitoring points: a quantity at a point, recorded every monitor step into
    /// `histories.csv` (UDEC's and FLAC's `history`).
    #[serde(default)]
    pub histories: Vec<HistorySpec>,
    #[serde(default)]
    pub output: OutputSpec,
}

/// One monitoring point: what is recorded where.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HistorySpec {
    /// Name, the start of its column in `histories.csv`.
    pub name: String,
    /// The point, m: the node nearest it (displacement, velocity), the zone holding it (stress),
    /// the bolt segment or liner element whose middle is nearest it (support forces); none for
    /// the energy balance's terms (`HistoryQuantity::is_energy`).
    #[serde(default)]
    pub at: Option<[f64; 2]>,
    /// What is recorded.
    pub quantity: HistoryQuantity,
}

/// A quantity a monitoring point records (tension positive; displacements since the last
/// `reset_displacements`, as the output shows them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HistoryQuantity {
    /// Displacement components and magnitude, m.
    DisplacementX,
    DisplacementY,
    Displacement,
    /// Velocity components, m/s.
    VelocityX,
    VelocityY,
    /// A node's acceleration over the last step of a dynamic stage, m/s² (0 in static stages).
    AccelerationX,
    AccelerationY,
    /// Zone stress components, Pa.
    StressXx,
    StressYy,
    StressXy,
    /// A bolt segment's axial force per bolt, N (tension positive).
    BoltForce,
    /// A liner element's thrust per set, N (compression positive), and its mean bending moment
    /// per set, N·m.
    LinerThrust,
    LinerMoment,
    /// The energy balance of a dynamic stage, J/m, of the whole model (no `at`): kinetic
    /// energy, strain energy since the stage began, work of the applied loads, net energy out
    /// through quiet boundaries, and the work less the rest (`dynamics::Energy`); 0 in static
    /// stages.
    KineticEnergy,
    StrainEnergy,
    BoundaryWork,
    QuietEnergy,
    /// The energy the joints took (their springs, friction and viscosity) and the supports took
    /// (bolts and liners: stored, yielded and their own motion), J/m.
    JointEnergy,
    SupportEnergy,
    /// The energy damping took (local, Rayleigh mass- and stiffness-proportional), J/m.
    DampingEnergy,
    EnergyError,
}

impl HistoryQuantity {
    /// Its name and unit as a column of `histories.csv` (`displacement_x_m`, …).
    pub fn column(self) -> &'static str {
        match self {
            HistoryQuantity::DisplacementX => "displacement_x_m",
            HistoryQuantity::DisplacementY => "displacement_y_m",
            HistoryQuantity::Displacement => "displacement_m",
            HistoryQuantity::VelocityX => "velocity_x_m_per_s",
            HistoryQuantity::VelocityY => "velocity_y_m_per_s",
            HistoryQuantity::AccelerationX => "acceleration_x_m_per_s2",
            HistoryQuantity::AccelerationY => "acceleration_y_m_per_s2",
            HistoryQuantity::StressXx => "stress_xx_pa",
            HistoryQuantity::StressYy => "stress_yy_pa",
            HistoryQuantity::StressXy => "stress_xy_pa",
            HistoryQuantity::BoltForce => "bolt_force_n",
            HistoryQuantity::LinerThrust => "liner_thrust_n",
            HistoryQuantity::LinerMoment => "liner_moment_n_m",
            HistoryQuantity::KineticEnergy => "kinetic_energy_j_per_m",
            HistoryQuantity::StrainEnergy => "strain_energy_j_per_m",
            HistoryQuantity::BoundaryWork => "boundary_work_j_per_m",
            HistoryQuantity::QuietEnergy => "quiet_energy_j_per_m",
            HistoryQuantity::JointEnergy => "joint_energy_j_per_m",
            HistoryQuantity::SupportEnergy => "support_energy_j_per_m",
            HistoryQuantity::DampingEnergy => "damping_energy_j_per_m",
            HistoryQuantity::EnergyError => "energy_error_j_per_m",
        }
    }

    /// Whether it is a term of the energy balance (read of the whole model, without `at`).
    pub fn is_energy(self) -> bool {
        matches!(
            self,
            HistoryQuantity::KineticEnergy
                | HistoryQuantity::StrainEnergy
                | HistoryQuantity::BoundaryWork
                | HistoryQuantity::QuietEnergy
                | HistoryQuantity::JointEnergy
                | HistoryQuantity::SupportEnergy
                | HistoryQuantity::DampingEnergy
                | HistoryQuantity::EnergyError
        )
    }
}

/// One stage: what changes, then a solve; each stage ends with an output step.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stage {
    /// Name, reported in the summary.
    pub name: String,
    /// Excavations removed at the start of this stage (by name).
    #[serde(default)]
    pub excavate: Vec<String>,
    /// Fraction of the in-situ traction left on the walls of every excavation made so far
    /// (fictitious support pressure of the convergence–confinement method), in [0, 1]; default 0.
    #[serde(default)]
    pub support_fraction: f64,
    /// Bolt groups and liners installed at the start of this stage (by name), after its
    /// excavations.
    #[serde(default)]
    pub install: Vec<String>,
    /// Zone materials changed at the start of this stage (by name, each given whole, as in
    /// `materials`; the density must stay): every zone, rigid and simple block of that material
    /// takes the new law and keeps its stress, yield state and plastic strain.
    #[serde(default, deserialize_with = "unique::unique_keys")]
    pub materials: BTreeMap<String, Material>,
    /// Gravitational acceleration from this stage on, m/s² (default: unchanged).
    #[serde(default)]
    pub gravity: Option<[f64; 2]>,
    /// Joint materials changed at the start of this stage (by name, each given whole, as in
    /// `joint_materials`): every contact of that material takes the new properties and keeps its
    /// state (stresses, displacements, whether it has failed), as UDEC's `change` between solves.
    #[serde(default, deserialize_with = "unique::unique_keys")]
    pub joint_materials: BTreeMap<String, JointMaterial>,
    /// Blocks that take another zone material at the start of this stage (UDEC's `change mat`
    /// over a range), in order: later regions override earlier ones.
    #[serde(default)]
    pub regions: Vec<MaterialRegion>,
    /// The boundary conditions from this stage on, given whole as the top-level `boundary`, which
    /// they replace (default: unchanged): fixities the new list drops are released, loads it drops
    /// are removed, and its own applied.
    #[serde(default)]
    pub boundary: Option<Vec<BoundaryCondition>>,
    /// Measure displacements from the start of this stage on (default false).
    #[serde(default)]
    pub reset_displacements: bool,
    /// How to solve this stage (default: the scene's `solve`).
    #[serde(default)]
    pub solve: Option<SolveSpec>,
    /// After its solve, search the stage's factor of safety by strength reduction
    /// (`strength_reduction`); default none.
    #[serde(default)]
    pub factor_of_safety: Option<FactorOfSafetySpec>,
}

/// How a stage's factor of safety is searched (`stages[i].factor_of_safety`).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FactorOfSafetySpec {
    /// The search stops when the smallest unstable factor exceeds the largest stable one by at
    /// most this fraction of it (dimensionless, in (0, 0.5]; default 0.005).
    #[serde(default = "FactorOfSafetySpec::default_tolerance")]
    pub tolerance: f64,
    /// The largest factor tried (dimensionless, in (1, 1000]; default 100); its inverse is the
    /// smallest. A stage stable at it reports a factor of at least this.
    #[serde(default = "FactorOfSafetySpec::default_max_factor")]
    pub max_factor: f64,
    /// A trial in which a block moved further than this beyond the rock around it (every node of
    /// it, beyond the farthest node of the blocks it touched at the stage's equilibrium) is
    /// unstable though its solve converged (a block that slid off and came to rest elsewhere),
    /// m (positive; default 1 % of the region's size).
    #[serde(default)]
    pub displacement_limit: Option<f64>,
}

impl FactorOfSafetySpec {
    fn default_tolerance() -> f64 {
        0.005
    }
    fn default_max_factor() -> f64 {
        100.0
    }
}

/// A zone material: isotropic elasticity, and the strength of the Mohr–Coulomb or the
/// generalized Hoek–Brown law.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Mass density, kg/m³.
    pub density: f64,
    /// Young's modulus, Pa.
    pub young: f64,
    /// Poisson's ratio (dimensionless, −1 < ν < 0.5).
    pub poisson: f64,
    /// Zone law: `elastic` (default), `mohr_coulomb` or `hoek_brown`.
    #[serde(default)]
    pub law: ZoneLawKind,
    /// Mohr–Coulomb: cohesion c, Pa (required for that law).
    #[serde(default)]
    pub cohesion: Option<f64>,
    /// Mohr–Coulomb: friction angle φ, degrees (required for that law).
    #[serde(default)]
    pub friction: Option<f64>,
    /// Mohr–Coulomb: dilation angle ψ, degrees (default 0; at most φ).
    #[serde(default)]
    pub dilation: f64,
    /// Mohr–Coulomb: tensile strength σt, Pa (default and cap: c / tan φ).
    #[serde(default)]
    pub tensile_strength: Option<f64>,
    /// Mohr–Coulomb strain softening: cohesion and friction at increasing plastic shear strain
    /// (from `cohesion`, `friction` at 0; linear between points, constant after the last).
    #[serde(default)]
    pub softening: Vec<SofteningPoint>,
    /// Mohr–Coulomb cohesion weakening and friction strengthening (CWFS, brittle spalling):
    /// cohesion from `cohesion` to a residual, friction from `friction` to a mobilized angle,
    /// each over its own plastic shear strain.
    #[serde(default)]
    pub cwfs: Option<CwfsSpec>,
    /// Hoek–Brown: the intact rock's uniaxial compressive strength σci, Pa (required for that law).
    #[serde(default)]
    pub sigma_ci: Option<f64>,
    /// Hoek–Brown: geological strength index GSI (with `mi`; or give `mb`, `s`, `a`).
    #[serde(default)]
    pub gsi: Option<f64>,
    /// Hoek–Brown: the intact rock's constant mi (with `gsi`).
    #[serde(default)]
    pub mi: Option<f64>,
    /// Hoek–Brown: disturbance factor D in [0, 1] (with `gsi`; default 0).
    #[serde(default)]
    pub disturbance: Option<f64>,
    /// Hoek–Brown: the rock mass's mb, s and a given directly (instead of `gsi`, `mi`).
    #[serde(default)]
    pub mb: Option<f64>,
    #[serde(default)]
    pub s: Option<f64>,
    #[serde(default)]
    pub a: Option<f64>,
    /// Hoek–Brown strain softening: the residual constants and the plastic shear strain where
    /// they are reached.
    #[serde(default)]
    pub residual: Option<HoekBrownResidual>,
    /// Ubiquitous joints: one weak plane through every zone of the material, around a matrix of
    /// the material's own law.
    #[serde(default)]
    pub weak_plane: Option<WeakPlaneSpec>,
}

/// The residual strength of a softening Hoek–Brown material: `gsi` (with the peak's mi and D)
/// or `mb`, `s` and `a`, reached at `plastic_strain`.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HoekBrownResidual {
    #[serde(default)]
    pub gsi: Option<f64>,
    #[serde(default)]
    pub mb: Option<f64>,
    #[serde(default)]
    pub s: Option<f64>,
    #[serde(default)]
    pub a: Option<f64>,
    /// Plastic shear strain e^ps at which the residual constants hold (dimensionless, > 0).
    pub plastic_strain: f64,
}

/// The cohesion-weakening friction-strengthening model of a Mohr–Coulomb material
/// (Hajiabdolmajid, Kaiser & Martin 2002).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CwfsSpec {
    /// Cohesion reached at `cohesion_strain`, Pa.
    pub residual_cohesion: f64,
    /// Plastic shear strain e^ps over which cohesion falls (dimensionless, > 0).
    pub cohesion_strain: f64,
    /// Friction angle reached at `friction_strain`, degrees.
    pub mobilized_friction: f64,
    /// Plastic shear strain e^ps over which friction rises (dimensionless, > 0).
    pub friction_strain: f64,
}

impl CwfsSpec {
    /// The softening table (e^ps, c in Pa, φ in degrees) of cohesion falling linearly from `c0`
    /// and friction rising linearly from `phi0` (degrees), each constant past its own strain:
    /// both are linear between the two strains' points, so the table holds them exactly.
    pub fn table(&self, c0: f64, phi0: f64) -> Vec<(f64, f64, f64)> {
        let at = |e: f64| {
            let c = c0 + (self.residual_cohesion - c0) * (e / self.cohesion_strain).min(1.0);
            let phi = phi0 + (self.mobilized_friction - phi0) * (e / self.friction_strain).min(1.0);
            (e, c, phi)
        };
        let (lo, hi) = (
            self.cohesion_strain.min(self.friction_strain),
            self.cohesion_strain.max(self.friction_strain),
        );
        if lo == hi {
            vec![at(lo)]
        } else {
            vec![at(lo), at(hi)]
        }
    }
}

/// The weak plane of a ubiquitous-joint material.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WeakPlaneSpec {
    /// Dip of the plane's trace from the x axis, counter-clockwise, degrees.
    pub dip: f64,
    /// Cohesion cj, Pa.
    pub cohesion: f64,
    /// Friction angle φj, degrees.
    pub friction: f64,
    /// Dilation angle ψj, degrees (default 0; at most φj).
    #[serde(default)]
    pub dilation: f64,
    /// Tensile strength σtj across the plane, Pa (default and cap: cj / tan φj).
    #[serde(default)]
    pub tensile_strength: Option<f64>,
}

/// One point of a softening table.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SofteningPoint {
    /// Plastic shear strain e^ps (dimensionless), > 0 and increasing along the table.
    pub(crate) plastic_strain: f64,
    /// Cohesion there, Pa.
    pub cohesion: f64,
    /// Friction angle there, degrees.
    pub friction: f64,
}

/// Which zone law a material follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ZoneLawKind {
    #[default]
    Elastic,
    MohrCoulomb,
    HoekBrown,
}

/// The modelled region: one polygon, its edge names and its material.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Region {
    /// Vertices (m), in order, either orientation.
    pub polygon: Vec<[f64; 2]>,
    /// Name of each edge (edge i runs from vertex i to vertex i+1); default `edge0`, `edge1`, ….
    #[serde(default)]
    pub(crate) edge_names: Option<Vec<String>>,
    /// Name of the material that fills the region.
    pub material: String,
    /// An elastic far field outside the polygon (issue 18): the infinite medium beyond the
    /// region, by boundary elements on its outer boundary, which then carries the in-situ
    /// stress's traction plus the far field's response to the boundary's displacement.
    #[serde(default)]
    pub far_field: Option<FarFieldSpec>,
}

impl Region {
    /// The polygon's bounding box (min corner, max corner), m.
    pub(crate) fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        (self.polygon.iter()).fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        })
    }
}

/// `region.far_field`: the infinite elastic medium outside the region.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FarFieldSpec {
    /// How it is modelled: `boundary_elements` (the only kind).
    pub kind: FarFieldKind,
    /// Young's modulus of the far-field rock, Pa (default: the region material's).
    #[serde(default)]
    pub young: Option<f64>,
    /// Poisson's ratio of the far-field rock (default: the region material's).
    #[serde(default)]
    pub poisson: Option<f64>,
    /// Length of the boundary elements, m (default: one per boundary edge of the zones): each
    /// straight run of the outer boundary between corners and joints is split into elements of
    /// about this length, at its zones' edges, never shorter than one edge.
    #[serde(default)]
    pub element_size: Option<f64>,
    /// What the far-field rock is: `intact` (default; isotropic, `young` and `poisson`) or
    /// `jointed` (that rock cut by the scene's `joint_sets`, stuck, as an equivalent anisotropic
    /// continuum).
    #[serde(default)]
    pub rock_mass: RockMass,
    /// The ground surface's height, m (default: none, the far field is the whole plane): the far
    /// field is the half-plane below y = surface, free beyond the region (Melan's solution), and
    /// the region's edges on the surface are free too.
    #[serde(default)]
    pub surface: Option<f64>,
}

impl FarFieldSpec {
    /// Whether a half-plane far field's surface holds all of `points` (m): each within 1e-9 of
    /// `span` (m, the largest coordinate's size, at least 1) of y = surface. A region edge there
    /// stays free of the far field.
    pub fn on_surface(&self, points: &[[f64; 2]], span: f64) -> bool {
        (self.surface).is_some_and(|s| points.iter().all(|p| (p[1] - s).abs() <= 1e-9 * span))
    }
}

/// The size of the largest coordinate of `points` (m), at least 1: what position tolerances are
/// relative to.
pub fn coordinate_span<'a>(points: impl IntoIterator<Item = &'a [f64; 2]>) -> f64 {
    (points.into_iter().flatten()).fold(1.0f64, |m, v| m.max(v.abs()))
}

/// `region.far_field.rock_mass`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RockMass {
    /// Isotropic intact rock.
    #[default]
    Intact,
    /// Intact rock plus the scene's joint sets smeared over their spacing.
    Jointed,
}

/// The kinds of far field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FarFieldKind {
    BoundaryElements,
}

/// A hole in the region, present from the start of the run.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Excavation {
    /// Name, also the boundary part of its wall.
    pub name: String,
    #[serde(default)]
    pub circle: Option<Circle>,
    /// Vertices (m) of a polygonal excavation.
    #[serde(default)]
    pub polygon: Option<Vec<[f64; 2]>>,
    /// A horseshoe: semicircular crown on vertical walls and a flat invert.
    #[serde(default)]
    pub horseshoe: Option<Horseshoe>,
}

/// A region of another material, cut from the rock along its outline and glued to it (a bonded
/// interface: kn = max E / `zoning.edge_at_excavation`, ks = kn / 2, never slipping or opening).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Inclusion {
    /// Name, used in messages.
    pub name: String,
    #[serde(default)]
    pub circle: Option<Circle>,
    /// Vertices (m) of a polygonal inclusion.
    #[serde(default)]
    pub polygon: Option<Vec<[f64; 2]>>,
    /// Name of the material inside (a key of `materials`).
    pub material: String,
}

/// A horseshoe excavation: a semicircular crown of radius r centred on the springline at
/// `center`, vertical walls of height `wall_height` below it, and a flat invert; width 2r.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Horseshoe {
    /// Centre of the crown on the springline, m.
    pub center: [f64; 2],
    /// Crown radius (half the width), m.
    pub radius: f64,
    /// Height of the vertical walls from the invert to the springline, m.
    pub(crate) wall_height: f64,
    /// Segments of the crown arc (default 64).
    #[serde(default = "default_arc_segments")]
    pub segments: usize,
}

fn default_arc_segments() -> usize {
    64
}

impl Horseshoe {
    /// The outline, counter-clockwise from the right springline: crown, left wall, invert.
    pub fn polygon(&self) -> Vec<[f64; 2]> {
        let [cx, cy] = self.center;
        let n = self.segments;
        let mut v: Vec<[f64; 2]> = (0..=n)
            .map(|k| {
                let t = std::f64::consts::PI * k as f64 / n as f64;
                [cx + self.radius * t.cos(), cy + self.radius * t.sin()]
            })
            .collect();
        v.push([cx - self.radius, cy - self.wall_height]);
        v.push([cx + self.radius, cy - self.wall_height]);
        v
    }
}

/// A circle approximated by a regular polygon.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Circle {
    /// Centre (m).
    pub center: [f64; 2],
    /// Radius (m).
    pub radius: f64,
    /// Number of polygon segments (default 128).
    #[serde(default = "default_segments")]
    pub segments: usize,
}

fn default_segments() -> usize {
    128
}

/// A joint material: stiffnesses, strength, and the law that uses them.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointMaterial {
    /// Normal stiffness kn, Pa/m.
    pub normal_stiffness: f64,
    /// Shear stiffness ks, Pa/m.
    pub shear_stiffness: f64,
    /// Friction angle, degrees (default 30).
    #[serde(default = "default_friction")]
    pub friction: f64,
    /// Cohesion, Pa (default 0; falls to `residual_cohesion` once the joint fails).
    #[serde(default)]
    pub cohesion: f64,
    /// The Coulomb law's cohesion after failure, Pa (default 0; at most `cohesion`).
    #[serde(default)]
    pub residual_cohesion: f64,
    /// Tensile strength, Pa (default 0; lost once the joint fails).
    #[serde(default)]
    pub tensile_strength: f64,
    /// Dilation angle, degrees (default 0).
    #[serde(default)]
    pub dilation: f64,
    /// Joint law: `coulomb` (default), `continuously_yielding`, `barton_bandis` or `glued` (a
    /// construction joint: elastic springs that never slip or open).
    #[serde(default)]
    pub law: JointLawKind,
    /// Continuously yielding: initial bounding friction angle φm0, degrees (default `friction`).
    #[serde(default)]
    pub initial_friction: Option<f64>,
    /// Continuously yielding: roughness length R, m (required for that law).
    #[serde(default)]
    pub roughness: Option<f64>,
    /// Barton–Bandis: joint roughness coefficient JRC0 of the sample (required for that law).
    #[serde(default)]
    pub jrc: Option<f64>,
    /// Barton–Bandis: joint wall compressive strength JCS0 of the sample, Pa (required).
    #[serde(default)]
    pub jcs: Option<f64>,
    /// Barton–Bandis: maximum closure Vm of the normal hyperbola, m (required; `normal_stiffness`
    /// is its initial stiffness Kni).
    #[serde(default)]
    pub max_closure: Option<f64>,
    /// Barton–Bandis: length L0 of the sample JRC0 and JCS0 were measured on, m (default 0.1).
    #[serde(default)]
    pub sample_length: Option<f64>,
    /// Barton–Bandis: block size Ln, m, to scale JRC and JCS to (Barton & Bandis 1982; default:
    /// none, the sample's values).
    #[serde(default)]
    pub block_size: Option<f64>,
    /// Barton–Bandis: the largest normal stiffness Kmax, Pa/m, where the hyperbola ends and the
    /// time step is taken (default its tangent at σ′ = JCS; at least `normal_stiffness`).
    #[serde(default)]
    pub max_normal_stiffness: Option<f64>,
    /// Barton–Bandis: the divisor M of the mobilized dilation angle JRCmob log10(JCS/σ′)/M
    /// (default 2).
    #[serde(default)]
    pub dilation_divisor: Option<f64>,
}

/// Which joint law a joint material follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JointLawKind {
    #[default]
    Coulomb,
    ContinuouslyYielding,
    BartonBandis,
    Glued,
}

fn default_friction() -> f64 {
    30.0
}

/// A set of parallel joints.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSetSpec {
    /// Dip angle, degrees counter-clockwise from the +x axis.
    pub dip: f64,
    /// Perpendicular spacing, m.
    pub spacing: f64,
    /// A point one joint of the set passes through, m (default the origin).
    #[serde(default)]
    pub origin: [f64; 2],
    /// Trace length of non-persistent joints, m (default: persistent).
    #[serde(default)]
    pub trace: Option<f64>,
    /// Rock bridge between traces, m (with `trace`; default 0).
    #[serde(default)]
    pub gap: f64,
    /// Random spread of each joint's dip, ± degrees (default 0).
    #[serde(default)]
    pub spread_dip: f64,
    /// Random spread of each joint's position, ± m (default 0).
    #[serde(default)]
    pub spread_spacing: f64,
    /// Seed of the random spread (default 1).
    #[serde(default = "default_seed")]
    pub seed: u64,
    /// How far the whole set moves between realizations (`Scene::realization`; default none).
    #[serde(default)]
    pub scatter: Option<Scatter>,
    /// Joint material name.
    pub material: String,
}

fn default_seed() -> u64 {
    1
}

/// One explicit joint segment.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointLine {
    /// End points, m.
    pub from: [f64; 2],
    pub to: [f64; 2],
    /// Joint material name.
    pub material: String,
}

/// Grain-based blocks from a Voronoi tessellation.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VoronoiSpec {
    /// Mean grain size, m (one seed per `size` × `size` cell, jittered).
    pub size: f64,
    /// Seed of the jitter (default 1).
    #[serde(default = "default_seed")]
    pub seed: u64,
    /// Joint material of the grain boundaries.
    pub material: String,
}

/// Contact detection controls.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ContactSpec {
    /// Largest gap at which a node and an edge make a contact, m (default 5 % of
    /// `zoning.edge_at_excavation`); detection reruns once anything has moved half of it.
    pub tolerance: Option<f64>,
}

/// How blocks move: `deformable` (zones), `simple` (rigid motion plus one uniform strain, 6 DOF)
/// or `rigid` (3 DOF).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BlockMode {
    #[default]
    Deformable,
    Simple,
    Rigid,
}

/// Block modes of a scene: one for all blocks, overridden by region (later entries win).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct BlocksSpec {
    /// Mode of every block not in a listed region (default `deformable`).
    pub mode: BlockMode,
    /// Modes by region: blocks whose centroid lies inside `polygon`, or the block containing `at`.
    pub regions: Vec<ModeRegion>,
    /// Corner rounding radius of rigid and simple blocks, m (UDEC's `round`); default 1 % of their
    /// mean radius. Each corner's radius is capped so its arc spans at most a quarter of its edges.
    pub round: Option<f64>,
    /// Mode of a deformable block too thin to zone at the size asked for there (2 A / P, its area
    /// over half its perimeter, under half the zoning's edge length at its centroid): `simple` or
    /// `rigid` takes it out of the zoning; by default (`deformable`) it is zoned as finely as it
    /// needs, and a warning says so either way.
    pub(crate) thin: BlockMode,
}

/// A block mode for the blocks of one region or the block at one point.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModeRegion {
    pub mode: BlockMode,
    /// Polygon (m): blocks whose centroid lies inside take the mode.
    #[serde(default)]
    pub polygon: Option<Vec<[f64; 2]>>,
    /// Point (m): the block containing it takes the mode.
    #[serde(default)]
    pub at: Option<[f64; 2]>,
}

/// The blocks of one region, or the block at one point, that take another zone material.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialRegion {
    /// Name of the material they take (one of `materials`).
    pub material: String,
    /// Polygon (m): blocks whose centroid lies inside.
    #[serde(default)]
    pub polygon: Option<Vec<[f64; 2]>>,
    /// Point (m): the block containing it.
    #[serde(default)]
    pub at: Option<[f64; 2]>,
}

/// Zoning controls.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ZoningSpec {
    /// Zone edge length on excavation walls, m.
    pub edge_at_excavation: f64,
    /// Zone edge length far from excavations, m.
    pub edge_far: f64,
    /// Growth of edge length per metre of distance from the excavation (default 0.2).
    #[serde(default = "default_grading")]
    pub grading: f64,
    /// Depth from each excavation wall over which zones keep `edge_at_excavation` before the
    /// grading starts, m (default 0): a plastic zone's depth, zoned as finely as the wall.
    #[serde(default)]
    pub fine_depth: f64,
    /// Depth from each excavation wall where the rock is expected to yield, zoned at half the
    /// graded size: `"auto"` estimates it from the closed form of a circular hole in the
    /// region's rock, a number gives it (m); default 0, no refinement.
    #[serde(default)]
    pub plastic_depth: PlasticDepth,
    /// Minimum zone angle, degrees (default 30).
    #[serde(default = "default_min_angle")]
    pub min_angle: f64,
    /// Largest zone count accepted (default 2 000 000).
    #[serde(default = "default_max_zones")]
    pub max_zones: usize,
    /// Smallest zone angle accepted, degrees (default 1): a sharper zone that a joint makes costs
    /// that joint's piece there (a warning), one no joint makes is refused (it would set a tiny
    /// time step); 0 accepts any.
    #[serde(default = "default_accept_angle")]
    pub accept_angle: f64,
    /// Distance within which the cutter merges vertices, m (default `None`: 0.3 ×
    /// `edge_at_excavation`); never more than 0.9 × the shortest region or wall edge (those
    /// vertices never move) nor 2 % of `voronoi.size`.
    #[serde(default)]
    pub merge_tolerance: Option<f64>,
    /// Mixed discretization: each zone takes the volumetric strain averaged over its nodes'
    /// patches instead of its own, so constant-strain triangles do not lock as ν → 0.5
    /// (default false).
    #[serde(default)]
    pub mixed: bool,
}

/// `zoning.plastic_depth`: estimated before meshing (`"auto"`, the default), or given in metres
/// (0: no refinement).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum PlasticDepth {
    #[default]
    Auto,
    Depth(f64),
}

impl PlasticDepth {
    /// No refinement: the zoning as written (`zoning.plastic_depth` 0).
    pub const OFF: PlasticDepth = PlasticDepth::Depth(0.0);
}

impl<'de> Deserialize<'de> for PlasticDepth {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Given {
            Depth(f64),
            Word(String),
        }
        match Given::deserialize(d)? {
            Given::Depth(v) => Ok(PlasticDepth::Depth(v)),
            Given::Word(w) if w == "auto" => Ok(PlasticDepth::Auto),
            Given::Word(w) => Err(serde::de::Error::custom(format!(
                "zoning.plastic_depth: expected \"auto\" or a depth in metres, got \"{w}\""
            ))),
        }
    }
}

/// `zoning.merge_tolerance` when the scene gives none, as a fraction of `edge_at_excavation`.
pub const DEFAULT_MERGE: f64 = 0.3;

fn default_grading() -> f64 {
    0.2
}
fn default_accept_angle() -> f64 {
    1.0
}
fn default_min_angle() -> f64 {
    30.0
}
fn default_max_zones() -> usize {
    2_000_000
}

/// In-situ stress, Pa, tension positive: σ(y) = σ_ref + gradient · (y − y_ref).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InSitu {
    #[serde(default)]
    pub sxx: f64,
    #[serde(default)]
    pub syy: f64,
    #[serde(default)]
    pub sxy: f64,
    /// Out-of-plane stress, Pa; default ν(σxx + σyy) of each zone's material (plane strain).
    #[serde(default)]
    pub szz: Option<f64>,
    /// Elevation where the reference values hold, m (default 0).
    #[serde(default)]
    pub(crate) y_ref: f64,
    /// Vertical gradients dσ/dy, Pa/m (for gravity equilibrium dσyy/dy = −ρ·g_y).
    #[serde(default)]
    pub gradient: StressGradient,
}

/// Vertical gradients of the in-situ stress, Pa/m.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StressGradient {
    #[serde(default)]
    pub sxx: f64,
    #[serde(default)]
    pub syy: f64,
    #[serde(default)]
    pub szz: f64,
}

/// A boundary condition on a named boundary part or at the boundary node nearest a point.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoundaryCondition {
    /// `outer` (whole region boundary), a region edge name, or an excavation name.
    #[serde(default)]
    pub part: Option<String>,
    /// Point (m): the condition applies to the boundary node nearest to it.
    #[serde(default)]
    pub at: Option<[f64; 2]>,
    /// Fixed velocity components: "x", "y" or "xy".
    #[serde(default)]
    pub fix: Option<Fix>,
    /// Applied stress tensor (Pa); the traction is σ·n with n the outward normal.
    #[serde(default)]
    pub stress: Option<StressTensor>,
    /// Apply the in-situ stress (with its gradient) as traction σ·n.
    #[serde(default)]
    pub(crate) in_situ_traction: bool,
    /// Applied normal stress, Pa (tension positive: negative pushes on the boundary).
    #[serde(default)]
    pub(crate) normal_stress: Option<f64>,
    /// Applied shear stress, Pa, along the tangent t = (−n_y, n_x).
    #[serde(default)]
    pub(crate) shear_stress: Option<f64>,
    /// A quiet (viscous) boundary on the part, in dynamic stages: dashpots ρCp and ρCs per
    /// unit length, normal to it and along it, from the rock beside it (`dynamics::quiet`);
    /// fixities the part had in the stage before become the constant forces they exerted.
    #[serde(default)]
    pub quiet: bool,
    /// A plane wave entering through the quiet part.
    #[serde(default)]
    pub incident: Option<IncidentSpec>,
    /// A free-field boundary on the quiet part (vertical sides): its dashpots act on the
    /// velocity relative to a one-dimensional column beside it, whose stress loads it
    /// (`dynamics::free_field`).
    #[serde(default)]
    pub free_field: bool,
    /// A prescribed motion of the part's nodes along x or y, in dynamic stages
    /// (`dynamics::motion`): the component is held and follows a velocity history, or the
    /// velocity integrated from an acceleration history.
    #[serde(default)]
    pub motion: Option<MotionSpec>,
    /// A load history, in dynamic stages: the condition's load (`stress`, `in_situ_traction`,
    /// `normal_stress`/`shear_stress`) times this dimensionless history h(t) (`dynamics::load`);
    /// without it the load is constant.
    #[serde(default)]
    pub history: Option<SignalSpec>,
}

/// A prescribed motion of a boundary part: one of `velocity` (m/s) and `acceleration` (m/s²)
/// along `direction`; an acceleration is integrated to the velocity the nodes follow, with its
/// baseline corrected when asked (`dynamics::Integrated`).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    /// `x` or `y`.
    pub direction: Axis,
    /// The velocity history, m/s.
    #[serde(default)]
    pub velocity: Option<SignalSpec>,
    /// The acceleration history, m/s².
    #[serde(default)]
    pub acceleration: Option<SignalSpec>,
    /// Subtract from the acceleration the straight line a₀ + a₁ t that brings the motion to rest
    /// where it started at the record's end (zero final velocity and displacement; default false).
    #[serde(default)]
    pub baseline: bool,
}

/// A coordinate axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    X,
    Y,
}

impl Axis {
    /// 0 for x, 1 for y.
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
        }
    }
}

/// A history of time, t in s from the start of the stage (`dynamics::History`): a pulse scaled
/// by `amplitude`, or a `table`; the unit is the quantity's (m/s for a velocity, m/s² for an
/// acceleration).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SignalSpec {
    /// Peak value of the pulse.
    #[serde(default)]
    pub amplitude: Option<f64>,
    /// `ricker`, `half_sine` or `sine`.
    #[serde(default)]
    pub pulse: Option<PulseKind>,
    /// The pulse's frequency, Hz (a Ricker wavelet's peak frequency).
    #[serde(default)]
    pub frequency: Option<f64>,
    /// When the pulse starts (the Ricker wavelet: peaks), s (default 1.2/f for a Ricker
    /// wavelet, 0 for the others).
    #[serde(default)]
    pub delay: Option<f64>,
    /// Cycles of a `sine` (default: unending).
    #[serde(default)]
    pub cycles: Option<f64>,
    /// The history itself, [[t s, value], ...], times increasing: linear between its points, 0
    /// outside them.
    #[serde(default)]
    pub table: Option<Vec<[f64; 2]>>,
}

impl IncidentSpec {
    /// Its particle-velocity history as a history (`velocity` is its amplitude).
    pub fn history(&self) -> SignalSpec {
        SignalSpec {
            amplitude: self.velocity,
            pulse: self.pulse,
            frequency: self.frequency,
            delay: self.delay,
            cycles: self.cycles,
            table: self.table.clone(),
        }
    }
}

/// A plane wave entering through a quiet boundary part, as its particle velocity history
/// (`dynamics::History`): a pulse scaled by `velocity`, or a `table`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IncidentSpec {
    /// `p`: particle velocity along the part's inward normal; `s`: along its tangent
    /// t = (−n_y, n_x), n the outward normal.
    pub wave: WaveKind,
    /// Peak particle velocity of the pulse, m/s.
    #[serde(default)]
    pub velocity: Option<f64>,
    /// `ricker`, `half_sine` or `sine`.
    #[serde(default)]
    pub pulse: Option<PulseKind>,
    /// The pulse's frequency, Hz (a Ricker wavelet's peak frequency).
    #[serde(default)]
    pub frequency: Option<f64>,
    /// When the pulse starts (the Ricker wavelet: peaks), s from the start of the stage
    /// (default 1.2/f for a Ricker wavelet, 0 for the others).
    #[serde(default)]
    pub delay: Option<f64>,
    /// Cycles of a `sine` (default: unending).
    #[serde(default)]
    pub cycles: Option<f64>,
    /// The velocity history itself, [[t s, v m/s], ...], times increasing: linear between its
    /// points, 0 outside them.
    #[serde(default)]
    pub table: Option<Vec<[f64; 2]>>,
}

/// The kind of an incident plane wave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum WaveKind {
    P,
    S,
}

/// The shape of an incident pulse.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PulseKind {
    Ricker,
    HalfSine,
    Sine,
}

impl BoundaryCondition {
    /// How many kinds of load are given: `stress`, `in_situ_traction`, `normal_stress`/`shear_stress`.
    pub fn load_kinds(&self) -> u8 {
        self.stress.is_some() as u8
            + self.in_situ_traction as u8
            + (self.normal_stress.is_some() || self.shear_stress.is_some()) as u8
    }
}

/// Which velocity components are fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Fix {
    #[serde(rename = "x")]
    X,
    #[serde(rename = "y")]
    Y,
    #[serde(rename = "xy")]
    XY,
}

/// A plane stress tensor, Pa.
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StressTensor {
    #[serde(default)]
    pub sxx: f64,
    #[serde(default)]
    pub syy: f64,
    #[serde(default)]
    pub sxy: f64,
}

/// How to solve.
#[derive(Debug, Clone, Deserialize)]
#[serde(from = "SolveFields")]
pub struct SolveSpec {
    /// `static` (mass-scaled dynamic relaxation to equilibrium) or `dynamic` (real masses, real time).
    pub mode: SolveMode,
    /// Stop when the unbalanced-force ratio falls below this (default 1e-5).
    pub ratio: f64,
    /// Stop after this many cycles at the latest (default 200 000).
    pub max_cycles: u64,
    /// Local non-viscous damping coefficient α; 0 for none. Default (`None`): `DEFAULT_DAMPING`.
    pub damping: Option<f64>,
    /// Time step safety factor on the stability limit (default 0.8).
    pub safety_factor: f64,
    /// Cycles between unbalanced-force checks and history rows (default 10).
    pub monitor_every: u64,
    /// Large strain: zones use their current shape and their stress turns with them (objective
    /// rate), for large rotations and displacements; default false (small strain: zones keep
    /// their original shape, exact for small rotations and cheaper).
    pub large_strain: bool,
    /// Cycles over which a static solve releases the out-of-balance forces it starts with
    /// (default 0: at once). The model then passes through near-equilibrium states, the path a
    /// slowly applied change takes, which friction and plasticity remember; the solve cannot
    /// converge before the ramp ends.
    pub ramp: u64,
    /// Rayleigh damping of a dynamic solve (default none); local damping then defaults to 0.
    pub rayleigh: Option<Rayleigh>,
    /// How a static solve reaches equilibrium: `explicit` (damped cycling, as above), `implicit`
    /// (a sparse direct solve of the stiffness, iterated on the same unbalanced-force ratio), or
    /// `auto` (implicit where the model's features allow it, else explicit; a stage the
    /// iterations cannot settle is cycled on explicitly; the summary says which ran and why).
    /// Default `auto`, but `explicit` for a solve that gives `ramp` (the slow release it asks
    /// for is explicit cycling's: `SolveFields::method_or_default`).
    pub method: SolveMethod,
    /// Iterations of an implicit solve at the latest (default 500: the accelerated iterations of
    /// the report's cases take at most about 220).
    pub max_iterations: u64,
    /// Time a dynamic stage runs, s: it ends `completed` after it, without stopping on the
    /// ratio (default none: a dynamic stage stops on the ratio or `max_cycles`).
    pub duration: Option<f64>,
    /// Equal steps in which an implicit stage releases the out-of-balance force it starts with
    /// (default 1: at once), each solved and committed before the next; a step that does not
    /// converge within `max_iterations` is halved. The implicit path's `ramp`.
    pub load_steps: u64,
}

/// A scene's `solve` as written (its fields are [`SolveSpec`]'s, documented there), with
/// `method` absent told from `method` given.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct SolveFields {
    mode: SolveMode,
    ratio: f64,
    max_cycles: u64,
    damping: Option<f64>,
    safety_factor: f64,
    monitor_every: u64,
    large_strain: bool,
    ramp: u64,
    rayleigh: Option<Rayleigh>,
    method: Option<SolveMethod>,
    max_iterations: u64,
    duration: Option<f64>,
    load_steps: u64,
}

impl SolveFields {
    /// The method a solve that names none takes: `auto`, or `explicit` when it gives `ramp` (so
    /// a scene written when explicit was the default, releasing a stage slowly, is still
    /// released slowly: the implicit path's slow release is `load_steps`).
    fn method_or_default(&self) -> SolveMethod {
        match self.method {
            Some(m) => m,
            None if self.ramp > 0 => SolveMethod::Explicit,
            None => SolveMethod::Auto,
        }
    }
}

impl Default for SolveFields {
    fn default() -> Self {
        let d = SolveSpec::default();
        SolveFields {
            mode: d.mode,
            ratio: d.ratio,
            max_cycles: d.max_cycles,
            damping: d.damping,
            safety_factor: d.safety_factor,
            monitor_every: d.monitor_every,
            large_strain: d.large_strain,
            ramp: d.ramp,
            rayleigh: d.rayleigh,
            method: None,
            max_iterations: d.max_iterations,
            duration: d.duration,
            load_steps: d.load_steps,
        }
    }
}

impl From<SolveFields> for SolveSpec {
    fn from(f: SolveFields) -> Self {
        SolveSpec {
            method: f.method_or_default(),
            mode: f.mode,
            ratio: f.ratio,
            max_cycles: f.max_cycles,
            damping: f.damping,
            safety_factor: f.safety_factor,
            monitor_every: f.monitor_every,
            large_strain: f.large_strain,
            ramp: f.ramp,
            rayleigh: f.rayleigh,
            max_iterations: f.max_iterations,
            duration: f.duration,
            load_steps: f.load_steps,
        }
    }
}

/// How a static solve reaches equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SolveMethod {
    Explicit,
    Implicit,
    #[default]
    Auto,
}

impl SolveMethod {
    /// The method as a scene spells it.
    pub fn name(self) -> &'static str {
        match self {
            SolveMethod::Explicit => "explicit",
            SolveMethod::Implicit => "implicit",
            SolveMethod::Auto => "auto",
        }
    }
}

/// Rayleigh damping (UDEC's `damping rayleigh`): a viscous force −α_R m v at every mass and a
/// viscous stress β_R σ̇ on top of every zone's, simple block's and loaded contact's elastic one,
/// so that a mode of angular frequency ω is damped at the fraction of critical
/// ξ(ω) = ½ (α_R / ω + β_R ω) (Bathe, *Finite Element Procedures*, §9.3.3).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rayleigh {
    /// Fraction of critical damping ξ at `frequency` (dimensionless), in (0, 1).
    pub fraction: f64,
    /// Frequency f at which the damping is `fraction`, Hz.
    pub frequency: f64,
    /// Which terms act (default both).
    #[serde(default)]
    pub components: RayleighComponents,
}

/// The terms of Rayleigh damping.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RayleighComponents {
    /// α_R = ξ ω₀, β_R = ξ / ω₀: ξ at ω₀ is the minimum over frequencies.
    #[default]
    Both,
    /// β_R = 2ξ / ω₀ alone: rigid-body motion (a sliding block) is not resisted, higher
    /// frequencies are damped more.
    Stiffness,
    /// α_R = 2ξ ω₀ alone: every motion, rigid-body motion too, is resisted.
    Mass,
}

impl Rayleigh {
    /// (α_R, 1/s; β_R, s) giving ξ(ω₀) = `fraction` at ω₀ = 2π `frequency`.
    pub fn coefficients(&self) -> (f64, f64) {
        let (xi, w) = (self.fraction, std::f64::consts::TAU * self.frequency);
        match self.components {
            RayleighComponents::Both => (xi * w, xi / w),
            RayleighComponents::Stiffness => (0.0, 2.0 * xi / w),
            RayleighComponents::Mass => (2.0 * xi * w, 0.0),
        }
    }

    /// Fraction of critical damping ξ(ω) = ½ (α_R / ω + β_R ω) of a mode of angular frequency
    /// `omega`, rad/s.
    pub fn fraction_at(&self, omega: f64) -> f64 {
        let (a, b) = self.coefficients();
        0.5 * (a / omega + b * omega)
    }
}

/// Solution mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SolveMode {
    Static,
    Dynamic,
}

/// Local damping when the scene gives none.
pub const DEFAULT_DAMPING: f64 = 0.8;

impl SolveSpec {
    /// The local damping coefficient α of this solve: the scene's, else 0 with Rayleigh damping
    /// and `DEFAULT_DAMPING` without.
    pub fn damping_coefficient(&self) -> f64 {
        let default = if self.rayleigh.is_some() {
            0.0
        } else {
            DEFAULT_DAMPING
        };
        self.damping.unwrap_or(default)
    }
}

impl Default for SolveSpec {
    fn default() -> Self {
        SolveSpec {
            mode: SolveMode::Static,
            ratio: 1e-5,
            max_cycles: 200_000,
            damping: None,
            safety_factor: 0.8,
            monitor_every: 10,
            large_strain: false,
            ramp: 0,
            rayleigh: None,
            method: SolveMethod::Auto,
            max_iterations: 500,
            duration: None,
            load_steps: 1,
        }
    }
}

/// Where and how often to write results.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OutputSpec {
    /// Output folder; default `out/<name>`.
    pub folder: Option<String>,
    /// Cycles between intermediate output steps; 0 = only at the end (default 0).
    pub every: u64,
    /// Simulated seconds between intermediate output steps of dynamic stages (the nearest whole
    /// number of steps, at least one); `every` then counts for the static stages alone.
    pub interval: Option<f64>,
    /// Whether each stage that ends leaves its checkpoint (`checkpoints/stage_NN.ckpt`, what
    /// `adit run --from-stage` goes on from; default true). A run of many realizations that will
    /// not be restarted by stage can leave them out (`models/tunnel.json`: 1.1 MB a stage).
    pub checkpoints: bool,
}

impl Default for OutputSpec {
    fn default() -> Self {
        OutputSpec {
            folder: None,
            every: 0,
            interval: None,
            checkpoints: true,
        }
    }
}

impl OutputSpec {
    /// Cycles between intermediate output steps of a solve `spec` with time step `dt` (s): in
    /// a dynamic solve with an `interval`, interval/Δt rounded (at least 1), else `every`.
    pub fn cycles_between(&self, spec: &SolveSpec, dt: f64) -> u64 {
        match self.interval {
            Some(i) if spec.mode == SolveMode::Dynamic && dt > 0.0 => {
                ((i / dt).round() as u64).max(1)
            }
            _ => self.every,
        }
    }
}

impl Scene {
    /// Whether excavation `name` waits for a stage (filled with rock until then).
    pub fn is_staged(&self, name: &str) -> bool {
        self.stages
            .iter()
            .any(|st| st.excavate.iter().any(|e| e == name))
    }

    /// Parse and validate a scene from JSON text; `source` names it in messages.
    pub fn from_json(text: &str, source: &str) -> Result<Scene, SceneError> {
        // A byte-order mark, as some Windows editors write, is not part of the JSON.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let parse_error = |e: serde_json::Error| SceneError::Parse {
            source_name: source.to_string(),
            line: e.line(),
            column: e.column(),
            path: json_path::path_at(text, e.line(), e.column()),
            message: json_path::plain_message(&e.to_string()),
        };
        let scene: Scene = serde_json::from_str(text).map_err(parse_error)?;
        let numbers: serde_json::Value = serde_json::from_str(text).map_err(parse_error)?;
        magnitudes::check_numbers(&numbers)?;
        scene.validate()?;
        Ok(scene)
    }

    /// Read, parse and validate a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let source = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| SceneError::Io {
            path: source.clone(),
            message: e.to_string(),
        })?;
        let text = String::from_utf8(bytes).map_err(|e| {
            let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
            let line = 1 + good.iter().filter(|&&b| b == b'\n').count();
            let column = 1 + good.iter().rev().take_while(|&&b| b != b'\n').count();
            SceneError::Parse {
                source_name: source.clone(),
                line,
                column,
                path: String::new(),
                message: "not UTF-8 text".into(),
            }
        })?;
        Self::from_json(&text, &source)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = r#"{
        "name": "t",
        "materials": { "rock": { "density": 2500, "young": 1e9, "poisson": 0.2 } },
        "region": { "polygon": [[0, 0], [10, 0], [10, 10], [0, 10]], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 2 }
    }"#;

    fn error_of(text: &str) -> String {
        Scene::from_json(text, "scene.json")
            .unwrap_err()
            .to_string()
    }

    /// Numbers in messages stay short: 1e300 is not written with its 301 digits, nor 1e25 with
    /// its 26.
    #[test]
    fn huge_numbers_are_shown_short() {
        let msg = error_of(&GOOD.replace("\"edge_far\": 2", "\"edge_far\": 2, \"grading\": 1e25"));
        assert_eq!(msg, "zoning.grading: must be in (0, 2], got 1.0000e25");
        let msg = error_of(&GOOD.replace("\"edge_far\": 2", "\"edge_far\": 2, \"grading\": 1e300"));
        assert!(
            msg.starts_with("zoning.grading: 1.0000e300 is outside"),
            "{msg}"
        );
        let msg = error_of(&GOOD.replace("\"poisson\": 0.2", "\"poisson\": 0.75"));
        assert!(msg.ends_with("got 0.75"), "{msg}");
    }

    /// `zoning.plastic_depth` defaults to `"auto"`, takes `"auto"` or a depth, and refuses a negative
    /// depth or another word, naming the field.
    #[test]
    fn plastic_depth_is_checked() {
        let with = |v: &str| {
            GOOD.replace(
                "\"edge_far\": 2",
                &format!("\"edge_far\": 2, \"plastic_depth\": {v}"),
            )
        };
        let s = Scene::from_json(GOOD, "scene.json").unwrap();
        assert_eq!(s.zoning.plastic_depth, PlasticDepth::Auto);
        let s = Scene::from_json(&with("0"), "scene.json").unwrap();
        assert_eq!(s.zoning.plastic_depth, PlasticDepth::OFF);
        let s = Scene::from_json(&with("1.5"), "scene.json").unwrap();
        assert_eq!(s.zoning.plastic_depth, PlasticDepth::Depth(1.5));
        let msg = error_of(&with("-1"));
        assert_eq!(
            msg,
            "zoning.plastic_depth: must be \"auto\" or finite and not negative, got -1"
        );
        let msg = error_of(&with("\"deep\""));
        assert!(
            msg.contains("plastic_depth") && msg.contains("\"auto\""),
            "{msg}"
        );
    }

    /// `zoning.fine_depth` defaults to 0 (grading from the wall) and refuses a negative depth.
    #[test]
    fn fine_depth_is_checked() {
        let s = Scene::from_json(GOOD, "scene.json").unwrap();
        assert_eq!(s.zoning.fine_depth, 0.0);
        let msg =
            error_of(&GOOD.replace("\"edge_far\": 2", "\"edge_far\": 2, \"fine_depth\": -0.5"));
        assert_eq!(
            msg,
            "zoning.fine_depth: must be finite and not negative, got -0.5"
        );
    }

    #[test]
    fn good_scene_parses_with_defaults() {
        let s = Scene::from_json(GOOD, "scene.json").unwrap();
        assert_eq!(s.solve.ratio, 1e-5);
        assert_eq!(s.zoning.min_angle, 30.0);
        assert_eq!(s.edge_names(), ["edge0", "edge1", "edge2", "edge3"]);
    }

    #[test]
    fn malformed_json_gives_line_and_column() {
        let msg = error_of("{\n  \"name\": \"t\",\n  \"materials\": {,\n}");
        assert!(msg.starts_with("scene.json: line 3, column"), "{msg}");
    }

    #[test]
    fn unknown_field_is_named() {
        let msg = error_of(&GOOD.replace("\"density\"", "\"densty\": 1, \"density\""));
        assert!(
            msg.contains("unknown field `densty`")
                && msg.contains("line 3")
                && msg.contains(", at materials.rock.densty:"),
            "{msg}"
        );
    }

    #[test]
    fn missing_material_is_named() {
        let msg = error_of(&GOOD.replace("\"material\": \"rock\"", "\"material\": \"granite\""));
        assert_eq!(
            msg,
            "region.material: no material named 'granite' in materials"
        );
    }

    #[test]
    fn inclusion_errors_name_the_field() {
        let with = |inc: &str| {
            GOOD.replace(
                "\"zoning\"",
                &format!("\"inclusions\": [{inc}], \"zoning\""),
            )
        };
        let circle = "\"circle\": { \"center\": [5, 5], \"radius\": 1 }";
        let msg = error_of(&with(&format!(
            "{{ \"name\": \"i\", {circle}, \"material\": \"granite\" }}"
        )));
        assert_eq!(
            msg,
            "inclusions[0].material: no material named 'granite' in materials"
        );
        let msg = error_of(&with("{ \"name\": \"i\", \"material\": \"rock\" }"));
        assert!(msg.starts_with("inclusions[0]: give exactly one"), "{msg}");
        let one = format!("{{ \"name\": \"i\", {circle}, \"material\": \"rock\" }}");
        let msg = error_of(&with(&format!("{one}, {one}")));
        assert!(msg.starts_with("inclusions[1].name:"), "{msg}");
        assert!(Scene::from_json(&with(&one), "scene.json").is_ok());
    }

    #[test]
    fn negative_modulus_is_named() {
        let msg = error_of(&GOOD.replace("1e9", "-1e9"));
        assert!(
            msg.starts_with("materials.rock.young: must be positive"),
            "{msg}"
        );
    }

    #[test]
    fn incompressible_poisson_is_rejected() {
        for nu in ["0.5", "0.7"] {
            let msg = error_of(&GOOD.replace("0.2", nu));
            assert!(
                msg.starts_with("materials.rock.poisson: must satisfy -1 < ν < 0.5"),
                "{msg}"
            );
        }
    }

    #[test]
    fn continuously_yielding_joint_needs_its_roughness() {
        let joint = |extra: &str| {
            GOOD.replace(
                "\"zoning\"",
                &format!(
                    r#""joint_materials": {{ "j": {{ "law": "continuously_yielding", "normal_stiffness": 1e10,
                       "shear_stiffness": 1e9{extra} }} }}, "zoning""#
                ),
            )
        };
        assert_eq!(
            error_of(&joint("")),
            "joint_materials.j.roughness: required by the continuously yielding law"
        );
        assert!(
            error_of(&joint(r#", "roughness": 1e-3, "initial_friction": 20"#))
                .starts_with("joint_materials.j.initial_friction: must be in [friction, 90)")
        );
        assert!(Scene::from_json(&joint(r#", "roughness": 1e-3"#), "t").is_ok());
    }

    #[test]
    fn mohr_coulomb_material_needs_its_strength() {
        let mc = |extra: &str| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(r#""poisson": 0.2, "law": "mohr_coulomb"{extra}"#),
            )
        };
        assert_eq!(
            error_of(&mc(r#", "friction": 30"#)),
            "materials.rock: `law: mohr_coulomb` needs `cohesion` and `friction`"
        );
        assert!(
            error_of(&mc(r#", "cohesion": 1e6, "friction": 30, "dilation": 40"#))
                .starts_with("materials.rock.dilation: must be in [0, friction]")
        );
        assert!(Scene::from_json(&mc(r#", "cohesion": 1e6, "friction": 30"#), "t").is_ok());
        let table = |points: &str| {
            mc(&format!(
                r#", "cohesion": 1e6, "friction": 30, "softening": [{points}]"#
            ))
        };
        assert!(
            Scene::from_json(
                &table(r#"{ "plastic_strain": 0.01, "cohesion": 2e5, "friction": 28 }"#),
                "t"
            )
            .is_ok()
        );
        assert_eq!(
            error_of(&table(
                r#"{ "plastic_strain": 0.01, "cohesion": 2e5, "friction": 28 },
                   { "plastic_strain": 0.005, "cohesion": 1e5, "friction": 28 }"#
            )),
            "materials.rock.softening[1].plastic_strain: must be positive and increase along the table"
        );
        assert_eq!(
            error_of(&GOOD.replace("\"poisson\": 0.2", r#""poisson": 0.2, "cohesion": 1e6"#)),
            "materials.rock.cohesion: belongs to `law: mohr_coulomb`, not this material's law"
        );
    }

    /// A Hoek–Brown material needs σci and either GSI and mi or mb, s and a; a field of another
    /// law is named, and each value's range is checked.
    #[test]
    fn hoek_brown_material_needs_its_strength() {
        let hb = |extra: &str| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(r#""poisson": 0.2, "law": "hoek_brown"{extra}"#),
            )
        };
        assert!(Scene::from_json(&hb(r#", "sigma_ci": 8e7, "gsi": 50, "mi": 12"#), "t").is_ok());
        let given = r#", "sigma_ci": 8e7, "mb": 2, "s": 0.004, "a": 0.5, "dilation": 10"#;
        assert!(Scene::from_json(&hb(given), "t").is_ok());
        assert_eq!(
            error_of(&hb(r#", "gsi": 50, "mi": 12"#)),
            "materials.rock: `law: hoek_brown` needs `sigma_ci`"
        );
        assert!(
            error_of(&hb(r#", "sigma_ci": 8e7, "gsi": 50, "mi": 12, "mb": 2"#))
                .contains("needs either `gsi` and `mi`")
        );
        assert_eq!(
            error_of(&hb(
                r#", "sigma_ci": 8e7, "gsi": 50, "mi": 12, "friction": 30"#
            )),
            "materials.rock.friction: belongs to `law: mohr_coulomb`, not this material's law"
        );
        assert!(
            error_of(&hb(r#", "sigma_ci": 8e7, "gsi": 150, "mi": 12"#))
                .starts_with("materials.rock.gsi: must be in [1, 100]")
        );
        assert!(
            error_of(&hb(
                r#", "sigma_ci": 8e7, "gsi": 50, "mi": 12, "disturbance": 2"#
            ))
            .starts_with("materials.rock.disturbance:")
        );
        assert!(
            error_of(&hb(r#", "sigma_ci": 8e7, "mb": 2, "s": 0.004, "a": 0.3"#))
                .starts_with("materials.rock.a:")
        );
        assert!(
            error_of(&GOOD.replace("\"poisson\": 0.2", r#""poisson": 0.2, "gsi": 50"#))
                .starts_with("materials.rock.gsi: belongs to `law: hoek_brown`")
        );
    }

    /// Hoek–Brown softening takes a residual GSI (with the peak's mi and D) or mb, s and a,
    /// each checked and named.
    #[test]
    fn hoek_brown_residual_is_checked() {
        let hb = |peak: &str, residual: &str| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(
                    r#""poisson": 0.2, "law": "hoek_brown", "sigma_ci": 8e7, {peak}, "residual": {{ {residual} }}"#
                ),
            )
        };
        let gsi = r#""gsi": 50, "mi": 12"#;
        let given = r#""mb": 2, "s": 0.004, "a": 0.5"#;
        assert!(Scene::from_json(&hb(gsi, r#""gsi": 30, "plastic_strain": 0.01"#), "t").is_ok());
        let residual = r#""mb": 1, "s": 0.001, "a": 0.55, "plastic_strain": 0.01"#;
        assert!(Scene::from_json(&hb(given, residual), "t").is_ok());
        assert!(
            error_of(&hb(given, r#""gsi": 30, "plastic_strain": 0.01"#))
                .starts_with("materials.rock.residual: give `gsi`")
        );
        assert!(
            error_of(&hb(gsi, r#""gsi": 300, "plastic_strain": 0.01"#))
                .starts_with("materials.rock.residual.gsi:")
        );
        assert!(
            error_of(&hb(gsi, r#""gsi": 30, "plastic_strain": 0"#))
                .starts_with("materials.rock.residual.plastic_strain:")
        );
        let mc = GOOD.replace(
            "\"poisson\": 0.2",
            r#""poisson": 0.2, "law": "mohr_coulomb", "cohesion": 1e6, "friction": 30, "residual": { "gsi": 30, "plastic_strain": 0.01 }"#,
        );
        assert!(error_of(&mc).starts_with("materials.rock.residual: belongs to `law: hoek_brown`"));
    }

    /// CWFS's table holds cohesion falling and friction rising each linearly over its own
    /// strain, exactly, in either order of the strains; its fields are checked.
    #[test]
    fn cwfs_is_two_linear_laws_in_one_table() {
        use crate::law::{Elastic, MohrCoulomb};
        for (ec, ef) in [(0.002, 0.005), (0.005, 0.002), (0.003, 0.003)] {
            let cwfs = CwfsSpec {
                residual_cohesion: 15e6,
                cohesion_strain: ec,
                mobilized_friction: 48.0,
                friction_strain: ef,
            };
            let mut law =
                MohrCoulomb::new(Elastic::from_young(60e9, 0.2, 2700.0), 50e6, 0.0, 0.0, 10e6);
            law.softening = (cwfs.table(50e6, 0.0).into_iter())
                .map(|(e, c, phi)| (e, c, f64::to_radians(phi)))
                .collect();
            for k in 0..=100 {
                let e = 1e-4 * k as f64;
                let (c, phi) = law.strength(e);
                let c_exact = 50e6 - 35e6 * (e / ec).min(1.0);
                let phi_exact = 48f64.to_radians() * (e / ef).min(1.0);
                assert!((c - c_exact).abs() < 1e-6, "{ec} {ef} at {e}: c {c}");
                assert!((phi - phi_exact).abs() < 1e-12, "{ec} {ef} at {e}: φ {phi}");
            }
        }
        let mc = |cwfs: &str| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(
                    r#""poisson": 0.2, "law": "mohr_coulomb", "cohesion": 5e7, "friction": 0, "tensile_strength": 1e7, "cwfs": {{ {cwfs} }}"#
                ),
            )
        };
        let ok = r#""residual_cohesion": 1.5e7, "cohesion_strain": 0.002, "mobilized_friction": 48, "friction_strain": 0.005"#;
        assert!(Scene::from_json(&mc(ok), "t").is_ok());
        assert!(
            error_of(&mc(&ok.replace("48", "95")))
                .starts_with("materials.rock.cwfs.mobilized_friction:")
        );
        assert!(
            error_of(&mc(&ok.replace("0.005", "0")))
                .starts_with("materials.rock.cwfs.friction_strain:")
        );
        let both = mc(ok).replace(
            r#""cwfs""#,
            r#""softening": [{ "plastic_strain": 0.01, "cohesion": 1e6, "friction": 30 }], "cwfs""#,
        );
        assert!(error_of(&both).starts_with("materials.rock.cwfs: give `cwfs` or a `softening`"));
    }

    /// A weak plane goes with any law and its fields are checked, each named.
    #[test]
    fn a_weak_plane_is_checked_field_by_field() {
        let plane = |law: &str, plane: &str| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(r#""poisson": 0.2{law}, "weak_plane": {{ {plane} }}"#),
            )
        };
        let ok = r#""dip": 30, "cohesion": 1e5, "friction": 25"#;
        assert!(Scene::from_json(&plane("", ok), "t").is_ok());
        let mc = r#", "law": "mohr_coulomb", "cohesion": 1e6, "friction": 35"#;
        assert!(Scene::from_json(&plane(mc, ok), "t").is_ok());
        for (fields, field) in [
            (r#""dip": 30, "cohesion": -1, "friction": 25"#, "cohesion"),
            (r#""dip": 30, "cohesion": 1e5, "friction": 95"#, "friction"),
            (
                r#""dip": 30, "cohesion": 1e5, "friction": 25, "dilation": 30"#,
                "dilation",
            ),
            (
                r#""dip": 30, "cohesion": 1e5, "friction": 25, "tensile_strength": -5"#,
                "tensile_strength",
            ),
        ] {
            assert!(
                error_of(&plane(mc, fields))
                    .starts_with(&format!("materials.rock.weak_plane.{field}:")),
                "{fields}: {}",
                error_of(&plane(mc, fields))
            );
        }
        assert!(error_of(&plane(mc, r#""cohesion": 1e5, "friction": 25"#)).contains("dip"));
    }

    /// Mixed zones take dilatant rock, at the top level and in a stage, with the default damping.
    #[test]
    fn mixed_zones_take_dilatant_rock() {
        let mixed = |dilation: f64| {
            GOOD.replace(
                "\"poisson\": 0.2",
                &format!(
                    r#""poisson": 0.2, "law": "mohr_coulomb", "cohesion": 1e6, "friction": 30, "dilation": {dilation}"#
                ),
            )
            .replace("\"edge_far\": 2 }", "\"edge_far\": 2, \"mixed\": true }")
        };
        let s = Scene::from_json(&mixed(10.0), "t").unwrap();
        assert!(s.zoning.mixed && s.solve.damping_coefficient() == DEFAULT_DAMPING);
        let staged = mixed(0.0).replace(
            "\"zoning\"",
            r#""stages": [{ "name": "dilatant", "materials": { "rock": { "density": 2500, "young": 1e9,
                "poisson": 0.2, "law": "mohr_coulomb", "cohesion": 1e6, "friction": 30, "dilation": 5 } } }],
               "zoning""#,
        );
        assert!(Scene::from_json(&staged, "t").is_ok());
    }

    /// A ramp is for static solves and must leave cycles to converge in.
    #[test]
    fn ramp_is_static_and_shorter_than_the_cycle_limit() {
        let with = |solve: &str| {
            let text = format!(
                r#"{{ "name": "r", "materials": {{ "rock": {{ "density": 2500, "young": 1e9, "poisson": 0.2 }} }},
                    "region": {{ "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock" }},
                    "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }}, "solve": {solve} }}"#
            );
            Scene::from_json(&text, "r").err().map(|e| e.to_string())
        };
        assert_eq!(with(r#"{ "ramp": 1000 }"#), None);
        let dynamic = with(r#"{ "mode": "dynamic", "ramp": 1000 }"#).unwrap();
        assert!(
            dynamic.starts_with("solve.ramp: only a static solve"),
            "{dynamic}"
        );
        let long = with(r#"{ "ramp": 1000, "max_cycles": 1000 }"#).unwrap();
        assert!(
            long.starts_with("solve.ramp: 1000 cycles leave none"),
            "{long}"
        );
        // Load steps are the implicit path's ramp: each is refused where it cannot act.
        assert_eq!(with(r#"{ "method": "implicit", "load_steps": 4 }"#), None);
        assert_eq!(
            with(r#"{ "method": "auto", "load_steps": 4, "ramp": 100 }"#),
            None
        );
        for (solve, start) in [
            (
                r#"{ "method": "explicit", "load_steps": 4 }"#,
                "solve.load_steps: acts in implicit solves",
            ),
            (
                r#"{ "ramp": 100, "load_steps": 4 }"#,
                "solve.load_steps: acts in implicit solves",
            ),
            (
                r#"{ "method": "implicit", "ramp": 100 }"#,
                "solve.ramp: acts in explicit",
            ),
            (
                r#"{ "method": "implicit", "load_steps": 0 }"#,
                "solve.load_steps: must be from 1 to 1000",
            ),
            (
                r#"{ "method": "implicit", "load_steps": 1001 }"#,
                "solve.load_steps: must be from 1 to 1000",
            ),
        ] {
            let e = with(solve).unwrap();
            assert!(e.starts_with(start), "{solve}: {e}");
        }
    }

    /// A solve that names no method is `auto`, or `explicit` when it gives a ramp (the slow
    /// release explicit cycling was asked for when explicit was the default); one named is kept.
    #[test]
    fn the_default_method_is_auto_but_a_ramp_asks_for_explicit_cycling() {
        let method = |solve: &str| {
            let text = GOOD.replace(
                "\"edge_far\": 2 }",
                &format!("\"edge_far\": 2 }}, \"solve\": {solve}"),
            );
            Scene::from_json(&text, "m").unwrap().solve.method
        };
        assert_eq!(
            Scene::from_json(GOOD, "m").unwrap().solve.method,
            SolveMethod::Auto
        );
        assert_eq!(method(r#"{ "ratio": 1e-6 }"#), SolveMethod::Auto);
        assert_eq!(method(r#"{ "ramp": 100 }"#), SolveMethod::Explicit);
        assert_eq!(
            method(r#"{ "ramp": 100, "method": "auto" }"#),
            SolveMethod::Auto
        );
        assert_eq!(method(r#"{ "method": "explicit" }"#), SolveMethod::Explicit);
        assert_eq!(method(r#"{ "method": "implicit" }"#), SolveMethod::Implicit);
        assert_eq!(SolveSpec::default().method, SolveMethod::Auto);
        let unknown = GOOD.replace(
            "\"edge_far\": 2 }",
            "\"edge_far\": 2 }, \"solve\": { \"ramps\": 1 }",
        );
        let e = Scene::from_json(&unknown, "m").unwrap_err().to_string();
        assert!(e.contains("unknown field `ramps`"), "{e}");
    }

    /// Rayleigh damping is a dynamic solve's, replaces local damping, and gives ξ at its frequency.
    #[test]
    fn rayleigh_damping_is_dynamic_and_alone() {
        let scene = |solve: &str| {
            let text = GOOD.replace(
                "\"edge_far\": 2 }",
                &format!("\"edge_far\": 2 }}, \"solve\": {solve}"),
            );
            Scene::from_json(&text, "r")
        };
        let ok =
            scene(r#"{ "mode": "dynamic", "rayleigh": { "fraction": 0.05, "frequency": 10 } }"#)
                .unwrap();
        let r = ok.solve.rayleigh.unwrap();
        assert_eq!(ok.solve.damping_coefficient(), 0.0);
        let w = std::f64::consts::TAU * 10.0;
        assert!((r.fraction_at(w) - 0.05).abs() < 1e-15);
        assert!(r.fraction_at(2.0 * w) > 0.05 && r.fraction_at(0.5 * w) > 0.05);
        let stiff = Rayleigh {
            components: RayleighComponents::Stiffness,
            ..r
        };
        assert!((stiff.fraction_at(w) - 0.05).abs() < 1e-15 && stiff.coefficients().0 == 0.0);
        let err = |solve: &str| scene(solve).unwrap_err().to_string();
        let s = err(r#"{ "rayleigh": { "fraction": 0.05, "frequency": 10 } }"#);
        assert!(
            s.starts_with("solve.rayleigh: acts in dynamic solves only"),
            "{s}"
        );
        let s = err(
            r#"{ "mode": "dynamic", "damping": 0.8, "rayleigh": { "fraction": 0.05, "frequency": 10 } }"#,
        );
        assert!(
            s.starts_with("solve.damping: local damping 0.8 and `rayleigh`"),
            "{s}"
        );
        let s = err(r#"{ "mode": "dynamic", "rayleigh": { "fraction": 1.5, "frequency": 10 } }"#);
        assert!(
            s.starts_with("solve.rayleigh.fraction: must be in (0, 1)"),
            "{s}"
        );
        let s = err(r#"{ "mode": "dynamic", "rayleigh": { "fraction": 0.1, "frequency": 0 } }"#);
        assert!(
            s.starts_with("solve.rayleigh.frequency: must be positive"),
            "{s}"
        );
    }

    #[test]
    fn damping_defaults_to_the_same_for_every_solve() {
        let mut spec = SolveSpec::default();
        assert_eq!(spec.damping_coefficient(), DEFAULT_DAMPING);
        spec.damping = Some(0.3);
        assert_eq!(spec.damping_coefficient(), 0.3);
    }

    #[test]
    fn block_mode_regions_need_one_shape() {
        let with = |region: &str| {
            GOOD.replace(
                "\"zoning\"",
                &format!(r#""blocks": {{ "regions": [{region}] }}, "zoning""#),
            )
        };
        assert_eq!(
            error_of(&with(
                r#"{ "mode": "rigid", "at": [1, 1], "polygon": [[0, 0], [1, 0], [1, 1]] }"#
            )),
            "blocks.regions[0]: give exactly one of `polygon` and `at`"
        );
        assert!(
            error_of(&with(r#"{ "mode": "stiff", "at": [1, 1] }"#))
                .contains("unknown variant `stiff`")
        );
        let s = Scene::from_json(&with(r#"{ "mode": "simple", "at": [1, 1] }"#), "t").unwrap();
        assert_eq!(s.blocks.regions[0].mode, BlockMode::Simple);
    }

    #[test]
    fn unknown_boundary_part_lists_the_known_ones() {
        let text = GOOD.replace(
            "\"zoning\"",
            "\"boundary\": [{ \"part\": \"roof\", \"fix\": \"y\" }], \"zoning\"",
        );
        let msg = error_of(&text);
        assert!(
            msg.starts_with("boundary[0].part: no boundary part 'roof'") && msg.contains("edge3"),
            "{msg}"
        );
    }
}
