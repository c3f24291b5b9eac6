//! Semantic checks of a parsed scene: every error names the field (as a JSON path) and the reason.

use thiserror::Error;

use super::{
    BoundaryCondition, Fix, HoekBrownConstants, JointLawSpec, JointMaterial, Material,
    PlasticDepth, Rayleigh, Scene, Shape, SolveMethod, SolveMode, SolveSpec, ZoneLawSpec,
};

/// Why a scene cannot be used.
#[derive(Debug, Error)]
pub enum SceneError {
    #[error("cannot read {path}: {message}")]
    Io { path: String, message: String },
    /// Malformed JSON, an unknown field, or a value of the wrong type.
    #[error("{source_name}: line {line}, column {column}{}: {message}", at_path(.path))]
    Parse {
        source_name: String,
        line: usize,
        column: usize,
        /// The JSON path of the value there (`materials.rock.young`), empty at the top level.
        path: String,
        message: String,
    },
    /// A well-formed value that is not allowed.
    #[error("{path}: {reason}")]
    Invalid { path: String, reason: String },
}

/// `, at materials.rock.young` for a parse error's path; nothing at the top level.
fn at_path(path: &str) -> String {
    if path.is_empty() {
        String::new()
    } else {
        format!(", at {path}")
    }
}

/// A number as a message shows it: plainly between 1e-4 and 1e9 in size, else in scientific
/// notation with five digits (Rust writes 1e300 with all its 301 digits).
pub(super) struct Num(pub f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let x = self.0;
        if x == 0.0 || !x.is_finite() || (1e-4..1e9).contains(&x.abs()) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:.4e}")
        }
    }
}

/// A stage's factor-of-safety search: its tolerance and largest factor in range, on a static
/// solve (equilibrium is what a trial factor is judged by).
fn validate_factor_of_safety(
    p: &str,
    fos: &super::FactorOfSafetySpec,
    mode: SolveMode,
) -> Result<(), SceneError> {
    if !(fos.tolerance > 0.0 && fos.tolerance <= 0.5) {
        return Err(invalid(
            format!("{p}.tolerance"),
            format!("must be in (0, 0.5], got {}", Num(fos.tolerance)),
        ));
    }
    if !(fos.max_factor > 1.0 && fos.max_factor <= 1000.0) {
        return Err(invalid(
            format!("{p}.max_factor"),
            format!("must be in (1, 1000], got {}", Num(fos.max_factor)),
        ));
    }
    if let Some(limit) = fos.displacement_limit
        && !(limit > 0.0 && limit.is_finite())
    {
        return Err(invalid(
            format!("{p}.displacement_limit"),
            format!("must be positive, got {}", Num(limit)),
        ));
    }
    if mode != SolveMode::Static {
        return Err(invalid(
            p,
            "a factor of safety is searched on a static solve (each trial factor is judged by \
             whether the stage reaches equilibrium); this stage's `solve.mode` is dynamic",
        ));
    }
    Ok(())
}

pub(super) fn invalid(path: impl Into<String>, reason: impl Into<String>) -> SceneError {
    SceneError::Invalid {
        path: path.into(),
        reason: reason.into(),
    }
}

/// A zone material at `p` (top level or a stage's change).
fn validate_material(p: &str, m: &Material) -> Result<(), SceneError> {
    positive(&format!("{p}.density"), m.density)?;
    positive(&format!("{p}.young"), m.young)?;
    if !(m.poisson > -1.0 && m.poisson < 0.5) {
        return Err(invalid(
            format!("{p}.poisson"),
            format!(
                "must satisfy -1 < ν < 0.5 (0.5 is incompressible), got {}",
                Num(m.poisson)
            ),
        ));
    }
    validate_strength(p, m)?;
    match &m.weak_plane {
        Some(w) => validate_weak_plane(&format!("{p}.weak_plane"), w),
        None => Ok(()),
    }
}

/// An angle of friction or dilation at `path`: in [0, 90) degrees.
fn angle_below_90(path: &str, v: f64) -> Result<(), SceneError> {
    if (0.0..90.0).contains(&v) {
        Ok(())
    } else {
        Err(invalid(
            path,
            format!("must be in [0, 90) degrees, got {}", Num(v)),
        ))
    }
}

/// A tensile strength at `path`, if given: zero or positive (infinite allowed).
fn tensile(path: &str, t: Option<f64>) -> Result<(), SceneError> {
    match t {
        Some(t) if t.is_nan() || t < 0.0 => Err(invalid(
            path,
            format!("must be zero or positive, got {}", Num(t)),
        )),
        _ => Ok(()),
    }
}

/// A Coulomb criterion's fields at `p` (a Mohr–Coulomb material, a weak plane): cohesion ≥ 0
/// and finite, friction in [0, 90) degrees, dilation in [0, friction], tensile strength ≥ 0.
fn validate_coulomb(
    p: &str,
    (cohesion, friction, dilation): (f64, f64, f64),
    tension: Option<f64>,
) -> Result<(), SceneError> {
    if !(cohesion >= 0.0 && cohesion.is_finite()) {
        return Err(invalid(
            format!("{p}.cohesion"),
            format!("must be zero or positive, got {}", Num(cohesion)),
        ));
    }
    angle_below_90(&format!("{p}.friction"), friction)?;
    if !(0.0..=friction).contains(&dilation) {
        return Err(invalid(
            format!("{p}.dilation"),
            format!("must be in [0, friction] degrees, got {}", Num(dilation)),
        ));
    }
    tensile(&format!("{p}.tensile_strength"), tension)
}

/// The CWFS fields of a Mohr–Coulomb material at `p`: a residual cohesion ≥ 0, a mobilized
/// friction in [0, 90) degrees, both strains positive.
fn validate_cwfs(p: &str, w: &crate::scene::CwfsSpec) -> Result<(), SceneError> {
    if !(w.residual_cohesion >= 0.0 && w.residual_cohesion.is_finite()) {
        return Err(invalid(
            format!("{p}.residual_cohesion"),
            format!("must be zero or positive, got {}", Num(w.residual_cohesion)),
        ));
    }
    angle_below_90(&format!("{p}.mobilized_friction"), w.mobilized_friction)?;
    for (field, e) in [
        ("cohesion_strain", w.cohesion_strain),
        ("friction_strain", w.friction_strain),
    ] {
        if !(e > 0.0 && e.is_finite()) {
            return Err(invalid(
                format!("{p}.{field}"),
                format!("must be a positive plastic shear strain, got {}", Num(e)),
            ));
        }
    }
    Ok(())
}

/// The weak plane of a ubiquitous-joint material at `p`: a finite dip, cohesion ≥ 0, friction in
/// [0, 90) degrees, dilation in [0, friction], tensile strength ≥ 0.
fn validate_weak_plane(p: &str, w: &crate::scene::WeakPlaneSpec) -> Result<(), SceneError> {
    if !w.dip.is_finite() {
        return Err(invalid(
            format!("{p}.dip"),
            "must be a finite angle in degrees",
        ));
    }
    validate_coulomb(p, (w.cohesion, w.friction, w.dilation), w.tensile_strength)
}

/// The Mohr–Coulomb fields of material `m` (path `p`): required and in range for that law, absent
/// for the elastic one.
fn validate_strength(p: &str, m: &Material) -> Result<(), SceneError> {
    match m.law_spec(p)? {
        ZoneLawSpec::Elastic => Ok(()),
        ZoneLawSpec::HoekBrown {
            sigma_ci,
            constants,
            dilation,
            tensile_strength,
            residual,
        } => {
            validate_hoek_brown(p, sigma_ci, constants, dilation, tensile_strength)?;
            if let Some((constants, strain)) = residual {
                let q = format!("{p}.residual");
                validate_constants(&q, constants, tensile_strength)?;
                if !(strain > 0.0 && strain.is_finite()) {
                    return Err(invalid(
                        format!("{q}.plastic_strain"),
                        format!(
                            "must be a positive plastic shear strain, got {}",
                            Num(strain)
                        ),
                    ));
                }
            }
            Ok(())
        }
        ZoneLawSpec::MohrCoulomb {
            cohesion: c,
            friction: phi,
            ..
        } => {
            validate_coulomb(p, (c, phi, m.dilation), m.tensile_strength)?;
            if let Some(cwfs) = &m.cwfs {
                validate_cwfs(&format!("{p}.cwfs"), cwfs)?;
            }
            let mut last = 0.0;
            for (i, pt) in m.softening.iter().enumerate() {
                let q = format!("{p}.softening[{i}]");
                if !(pt.plastic_strain > last && pt.plastic_strain.is_finite()) {
                    return Err(invalid(
                        format!("{q}.plastic_strain"),
                        "must be positive and increase along the table",
                    ));
                }
                if !(pt.cohesion >= 0.0 && pt.cohesion.is_finite()) {
                    return Err(invalid(format!("{q}.cohesion"), "must be zero or positive"));
                }
                if !(0.0..90.0).contains(&pt.friction) {
                    return Err(invalid(
                        format!("{q}.friction"),
                        "must be in [0, 90) degrees",
                    ));
                }
                last = pt.plastic_strain;
            }
            Ok(())
        }
    }
}

/// The Hoek–Brown fields of a material at `p`.
fn validate_hoek_brown(
    p: &str,
    sigma_ci: f64,
    constants: HoekBrownConstants,
    dilation: f64,
    tensile_strength: Option<f64>,
) -> Result<(), SceneError> {
    positive(&format!("{p}.sigma_ci"), sigma_ci)?;
    validate_constants(p, constants, tensile_strength)?;
    angle_below_90(&format!("{p}.dilation"), dilation)?;
    tensile(&format!("{p}.tensile_strength"), tensile_strength)
}

/// Hoek–Brown constants at `p` (a material or its `residual`): GSI in [1, 100], mi > 0, D in
/// [0, 1]; or mb ≥ 0 (0 with s > 0 and a tensile strength), s in [0, 1], a in [0.5, 1].
fn validate_constants(
    p: &str,
    constants: HoekBrownConstants,
    tensile_strength: Option<f64>,
) -> Result<(), SceneError> {
    let within = |field: &str, v: f64, lo: f64, hi: f64, rule: &str| {
        if (lo..=hi).contains(&v) {
            Ok(())
        } else {
            Err(invalid(
                format!("{p}.{field}"),
                format!("must be {rule}, got {}", Num(v)),
            ))
        }
    };
    match constants {
        HoekBrownConstants::Gsi {
            gsi,
            mi,
            disturbance,
        } => {
            within("gsi", gsi, 1.0, 100.0, "in [1, 100]")?;
            positive(&format!("{p}.mi"), mi)?;
            within("disturbance", disturbance, 0.0, 1.0, "in [0, 1]")?;
        }
        HoekBrownConstants::Given { mb, s, a } => {
            if mb.is_nan() || mb < 0.0 {
                return Err(invalid(
                    format!("{p}.mb"),
                    format!("must be zero or positive, got {}", Num(mb)),
                ));
            }
            if mb == 0.0 && s == 0.0 {
                return Err(invalid(
                    format!("{p}.s"),
                    "must be positive with mb = 0 (the rock would have no strength)",
                ));
            }
            if mb == 0.0 && tensile_strength.is_none() {
                return Err(invalid(
                    format!("{p}.tensile_strength"),
                    "is required with mb = 0 (the criterion then has no apex to cut tension at)",
                ));
            }
            within("s", s, 0.0, 1.0, "in [0, 1]")?;
            within("a", a, 0.5, 1.0, "in [0.5, 1]")?;
        }
    }
    Ok(())
}

/// A joint material at `p` (top level or a stage's change).
fn validate_joint_material(p: &str, j: &JointMaterial) -> Result<(), SceneError> {
    positive(&format!("{p}.normal_stiffness"), j.normal_stiffness)?;
    positive(&format!("{p}.shear_stiffness"), j.shear_stiffness)?;
    angle_below_90(&format!("{p}.friction"), j.friction)?;
    angle_below_90(&format!("{p}.dilation"), j.dilation)?;
    if let JointLawSpec::BartonBandis {
        jrc,
        jcs,
        max_closure,
        max_normal_stiffness,
        sample_length,
        block_size,
        dilation_divisor,
    } = j.law_spec(p)?
    {
        if let Some(k) = max_normal_stiffness
            && !(k >= j.normal_stiffness && k.is_finite())
        {
            return Err(invalid(
                format!("{p}.max_normal_stiffness"),
                format!(
                    "must be at least normal_stiffness (the hyperbola's initial tangent), got {}",
                    Num(k)
                ),
            ));
        }
        if !(0.0..=20.0).contains(&jrc) {
            return Err(invalid(
                format!("{p}.jrc"),
                format!("must be in [0, 20] (Barton's scale), got {}", Num(jrc)),
            ));
        }
        positive(&format!("{p}.jcs"), jcs)?;
        positive(&format!("{p}.max_closure"), max_closure)?;
        positive(&format!("{p}.sample_length"), sample_length)?;
        if let Some(b) = block_size {
            positive(&format!("{p}.block_size"), b)?;
        }
        if !(dilation_divisor >= 1.0 && dilation_divisor.is_finite()) {
            return Err(invalid(
                format!("{p}.dilation_divisor"),
                format!("must be at least 1, got {}", Num(dilation_divisor)),
            ));
        }
    }
    if let JointLawSpec::ContinuouslyYielding { roughness, .. } = j.law_spec(p)? {
        positive(&format!("{p}.roughness"), roughness)?;
        if let Some(f) = j.initial_friction
            && !(f >= j.friction && f < 90.0)
        {
            return Err(invalid(
                format!("{p}.initial_friction"),
                format!("must be in [friction, 90) degrees, got {}", Num(f)),
            ));
        }
    }
    if j.residual_cohesion != 0.0 && j.law != super::JointLawKind::Coulomb {
        return Err(invalid(
            format!("{p}.residual_cohesion"),
            "belongs to the Coulomb law (`law: coulomb`)",
        ));
    }
    if j.residual_cohesion > j.cohesion {
        return Err(invalid(
            format!("{p}.residual_cohesion"),
            format!(
                "must be at most cohesion ({}), got {}",
                Num(j.cohesion),
                Num(j.residual_cohesion)
            ),
        ));
    }
    for (f, v) in [
        ("cohesion", j.cohesion),
        ("residual_cohesion", j.residual_cohesion),
        ("tensile_strength", j.tensile_strength),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            return Err(invalid(
                format!("{p}.{f}"),
                format!("must be zero or positive, got {}", Num(v)),
            ));
        }
    }
    Ok(())
}

/// A history: a pulse with its amplitude (finite; the field `amplitude` names, e.g. an incident
/// wave's `velocity`, in `unit`) and frequency (positive), or a table of increasing times, not
/// both; delay and cycles in range.
fn validate_history(
    p: &str,
    w: &super::SignalSpec,
    amplitude: &str,
    unit: &str,
) -> Result<(), SceneError> {
    match (&w.pulse, &w.table) {
        (Some(_), Some(_)) | (None, None) => {
            return Err(invalid(
                p,
                format!("give one of `pulse` (with `{amplitude}` and `frequency`) and `table`"),
            ));
        }
        (Some(_), None) => {
            let peak = w.amplitude.ok_or_else(|| {
                invalid(
                    format!("{p}.{amplitude}"),
                    format!("the pulse's peak value ({unit}) is required"),
                )
            })?;
            if !peak.is_finite() {
                return Err(invalid(format!("{p}.{amplitude}"), "must be finite"));
            }
            let f = w.frequency.ok_or_else(|| {
                invalid(
                    format!("{p}.frequency"),
                    "the pulse's frequency (Hz) is required",
                )
            })?;
            positive(&format!("{p}.frequency"), f)?;
        }
        (None, Some(table)) => {
            for (field, given) in [
                (amplitude, w.amplitude),
                ("frequency", w.frequency),
                ("delay", w.delay),
            ] {
                if given.is_some() {
                    return Err(invalid(
                        format!("{p}.{field}"),
                        "belongs to a `pulse`; a table gives the history itself",
                    ));
                }
            }
            if table.is_empty() {
                return Err(invalid(format!("{p}.table"), "needs at least one point"));
            }
            for (k, pt) in table.iter().enumerate() {
                if !(pt[0].is_finite() && pt[1].is_finite()) {
                    return Err(invalid(format!("{p}.table[{k}]"), "must be finite"));
                }
                if k > 0 && pt[0] <= table[k - 1][0] {
                    return Err(invalid(format!("{p}.table[{k}]"), "times must increase"));
                }
            }
        }
    }
    if let Some(d) = w.delay
        && !(d >= 0.0 && d.is_finite())
    {
        return Err(invalid(
            format!("{p}.delay"),
            format!("must be at least 0 and finite, got {}", Num(d)),
        ));
    }
    if let Some(c) = w.cycles {
        if w.pulse != Some(super::PulseKind::Sine) {
            return Err(invalid(format!("{p}.cycles"), "belongs to a `sine` pulse"));
        }
        positive(&format!("{p}.cycles"), c)?;
    }
    Ok(())
}

/// The most cycles of a sine acceleration that a motion integrates.
const MAX_INTEGRATED_CYCLES: f64 = 5000.0;

/// A prescribed motion at `p` of the condition `bc`: a part's, not quiet, its direction not also
/// fixed; one of a velocity and an acceleration history; a baseline correction only of an
/// acceleration, and an acceleration integrated over a record that ends (not an unending sine).
fn validate_motion(
    p: &str,
    bc: &BoundaryCondition,
    m: &super::MotionSpec,
) -> Result<(), SceneError> {
    if bc.part.is_none() {
        return Err(invalid(
            p,
            "a prescribed motion is a part's (`part`), not a point's",
        ));
    }
    if bc.quiet {
        return Err(invalid(
            p,
            "a quiet part moves under its dashpots; bring a wave in through it with `incident`",
        ));
    }
    let axis = match m.direction {
        super::Axis::X => Fix::X,
        super::Axis::Y => Fix::Y,
    };
    if bc.fix.is_some_and(|f| f == axis || f == Fix::XY) {
        return Err(invalid(
            format!("{p}.direction"),
            "the part's `fix` holds that component still: the motion holds it already",
        ));
    }
    match (&m.velocity, &m.acceleration) {
        (Some(v), None) => {
            validate_history(&format!("{p}.velocity"), v, "amplitude", "m/s")?;
            if m.baseline {
                return Err(invalid(
                    format!("{p}.baseline"),
                    "corrects an integrated acceleration; a velocity is followed as given",
                ));
            }
        }
        (None, Some(a)) => {
            let q = format!("{p}.acceleration");
            validate_history(&q, a, "amplitude", "m/s²")?;
            if a.pulse == Some(super::PulseKind::Sine) {
                match a.cycles {
                    None => {
                        return Err(invalid(
                            format!("{q}.cycles"),
                            "an acceleration is integrated over its record: give the sine its cycles",
                        ));
                    }
                    // Sampled 200 times a cycle (`dynamics::Integrated`).
                    Some(c) if c > MAX_INTEGRATED_CYCLES => {
                        return Err(invalid(
                            format!("{q}.cycles"),
                            format!(
                                "at most {MAX_INTEGRATED_CYCLES} cycles of an acceleration are \
                                 integrated (200 samples each), got {}",
                                Num(c)
                            ),
                        ));
                    }
                    Some(_) => {}
                }
            }
        }
        _ => return Err(invalid(p, "give one of `velocity` and `acceleration`")),
    }
    Ok(())
}

/// A solve specification at `p`.
fn validate_solve(p: &str, v: &SolveSpec) -> Result<(), SceneError> {
    positive(&format!("{p}.ratio"), v.ratio)?;
    if let Some(d) = v.duration {
        positive(&format!("{p}.duration"), d)?;
        if v.mode != SolveMode::Dynamic {
            return Err(invalid(
                format!("{p}.duration"),
                "a static solve ends at equilibrium; `duration` is a dynamic solve's (`mode`: \"dynamic\")",
            ));
        }
    }
    if v.max_cycles == 0 {
        return Err(invalid(format!("{p}.max_cycles"), "must be at least 1"));
    }
    if let Some(d) = v.damping
        && !(0.0..1.0).contains(&d)
    {
        return Err(invalid(
            format!("{p}.damping"),
            format!("must be in [0, 1), got {}", Num(d)),
        ));
    }
    if !(v.safety_factor > 0.0 && v.safety_factor <= 1.0) {
        return Err(invalid(
            format!("{p}.safety_factor"),
            format!("must be in (0, 1], got {}", Num(v.safety_factor)),
        ));
    }
    if v.monitor_every == 0 {
        return Err(invalid(format!("{p}.monitor_every"), "must be at least 1"));
    }
    if v.ramp > 0 && v.mode == SolveMode::Dynamic {
        return Err(invalid(
            format!("{p}.ramp"),
            "only a static solve ramps its out-of-balance forces (a dynamic run follows real time)",
        ));
    }
    if let Some(r) = &v.rayleigh {
        validate_rayleigh(p, v, r)?;
    }
    if v.method == SolveMethod::Implicit && v.mode != SolveMode::Static {
        return Err(invalid(
            format!("{p}.method"),
            "an implicit solve finds static equilibrium (`mode`: \"static\"); a dynamic run cycles explicitly",
        ));
    }
    if v.max_iterations == 0 {
        return Err(invalid(format!("{p}.max_iterations"), "must be at least 1"));
    }
    if !(1..=MAX_LOAD_STEPS).contains(&v.load_steps) {
        return Err(invalid(
            format!("{p}.load_steps"),
            format!("must be from 1 to {MAX_LOAD_STEPS}, got {}", v.load_steps),
        ));
    }
    if v.load_steps > 1 && v.method == SolveMethod::Explicit {
        return Err(invalid(
            format!("{p}.load_steps"),
            "acts in implicit solves (`method`: \"implicit\" or \"auto\"); explicit cycling releases its forces over `ramp` cycles",
        ));
    }
    if v.ramp > 0 && v.method == SolveMethod::Implicit {
        return Err(invalid(
            format!("{p}.ramp"),
            "acts in explicit cycling; an implicit solve releases its out-of-balance forces in `load_steps`",
        ));
    }
    if v.ramp >= v.max_cycles {
        return Err(invalid(
            format!("{p}.ramp"),
            format!(
                "{} cycles leave none of max_cycles = {} to converge in",
                v.ramp, v.max_cycles
            ),
        ));
    }
    Ok(())
}

/// Most load steps of an implicit stage: each is a solve of up to `max_iterations` iterations.
pub const MAX_LOAD_STEPS: u64 = 1000;

/// Rayleigh damping at `p`.rayleigh: a dynamic solve's, in place of local damping.
fn validate_rayleigh(p: &str, v: &SolveSpec, r: &Rayleigh) -> Result<(), SceneError> {
    let q = format!("{p}.rayleigh");
    if v.mode != SolveMode::Dynamic {
        return Err(invalid(
            q,
            "acts in dynamic solves only (`mode`: \"dynamic\"); a static solve relaxes with local damping (`damping`)",
        ));
    }
    if let Some(d) = v.damping
        && d > 0.0
    {
        return Err(invalid(
            format!("{p}.damping"),
            format!(
                "local damping {} and `rayleigh` are alternatives: give one (local damping defaults to 0 with `rayleigh`)",
                Num(d)
            ),
        ));
    }
    if !(r.fraction > 0.0 && r.fraction < 1.0) {
        return Err(invalid(
            format!("{q}.fraction"),
            format!(
                "must be in (0, 1) (a fraction of critical damping), got {}",
                Num(r.fraction)
            ),
        ));
    }
    positive(&format!("{q}.frequency"), r.frequency)
}

/// A selection of blocks: exactly one of a polygon (at least 3 finite vertices) and a point.
fn validate_selection(
    p: &str,
    polygon: &Option<Vec<[f64; 2]>>,
    at: &Option<[f64; 2]>,
) -> Result<(), SceneError> {
    let finite = |v: &[f64; 2]| v.iter().all(|x| x.is_finite());
    match (polygon, at) {
        (Some(poly), None) if poly.len() >= 3 && poly.iter().all(finite) => Ok(()),
        (Some(_), None) => Err(invalid(
            format!("{p}.polygon"),
            "needs at least 3 vertices, all finite",
        )),
        (None, Some(v)) if finite(v) => Ok(()),
        (None, Some(_)) => Err(invalid(format!("{p}.at"), "must be finite")),
        _ => Err(invalid(p, "give exactly one of `polygon` and `at`")),
    }
}

fn positive(path: &str, v: f64) -> Result<(), SceneError> {
    if v > 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(invalid(
            path,
            format!("must be positive and finite, got {}", Num(v)),
        ))
    }
}

impl Scene {
    /// Check values that the JSON types alone cannot: signs, ranges, names that must exist.
    pub fn validate(&self) -> Result<(), SceneError> {
        self.validate_names()?;
        if self.materials.is_empty() {
            return Err(invalid("materials", "at least one material is needed"));
        }
        for (name, m) in &self.materials {
            validate_material(&format!("materials.{name}"), m)?;
        }
        if !self.materials.contains_key(&self.region.material) {
            return Err(invalid(
                "region.material",
                format!("no material named '{}' in materials", self.region.material),
            ));
        }
        self.validate_far_field()?;
        if let Some(names) = &self.region.edge_names
            && names.len() != self.region.polygon.len()
        {
            return Err(invalid(
                "region.edge_names",
                format!(
                    "{} names for {} edges",
                    names.len(),
                    self.region.polygon.len()
                ),
            ));
        }
        for (i, e) in self.excavations.iter().enumerate() {
            let p = format!("excavations[{i}]");
            match e.shape(&p)? {
                Shape::Circle(c) => {
                    positive(&format!("{p}.circle.radius"), c.radius)?;
                    if c.segments < 8 {
                        return Err(invalid(
                            format!("{p}.circle.segments"),
                            "at least 8 segments",
                        ));
                    }
                }
                Shape::Polygon(_) => {}
                Shape::Horseshoe(h) => {
                    positive(&format!("{p}.horseshoe.radius"), h.radius)?;
                    positive(&format!("{p}.horseshoe.wall_height"), h.wall_height)?;
                    if h.segments < 4 {
                        return Err(invalid(
                            format!("{p}.horseshoe.segments"),
                            "at least 4 segments",
                        ));
                    }
                }
            }
        }
        self.validate_inclusions()?;
        let z = &self.zoning;
        positive("zoning.edge_at_excavation", z.edge_at_excavation)?;
        positive("zoning.edge_far", z.edge_far)?;
        if z.edge_far < z.edge_at_excavation {
            return Err(invalid(
                "zoning.edge_far",
                "must be at least zoning.edge_at_excavation",
            ));
        }
        if !(z.grading > 0.0 && z.grading <= 2.0) {
            return Err(invalid(
                "zoning.grading",
                format!("must be in (0, 2], got {}", Num(z.grading)),
            ));
        }
        if let PlasticDepth::Depth(d) = z.plastic_depth
            && !(d >= 0.0 && d.is_finite())
        {
            return Err(invalid(
                "zoning.plastic_depth",
                format!(
                    "must be \"auto\" or finite and not negative, got {}",
                    Num(d)
                ),
            ));
        }
        if !(z.fine_depth >= 0.0 && z.fine_depth.is_finite()) {
            return Err(invalid(
                "zoning.fine_depth",
                format!("must be finite and not negative, got {}", Num(z.fine_depth)),
            ));
        }
        if let Some(m) = z.merge_tolerance
            && !(m > 0.0 && m <= z.edge_at_excavation)
        {
            return Err(invalid(
                "zoning.merge_tolerance",
                format!(
                    "must be positive and at most zoning.edge_at_excavation ({} m), got {}",
                    Num(z.edge_at_excavation),
                    Num(m)
                ),
            ));
        }
        if !(z.accept_angle >= 0.0 && z.accept_angle < z.min_angle) {
            return Err(invalid(
                "zoning.accept_angle",
                format!(
                    "must be at least 0 and below zoning.min_angle ({}°), got {}",
                    Num(z.min_angle),
                    Num(z.accept_angle)
                ),
            ));
        }
        if !(z.min_angle > 0.0 && z.min_angle <= 33.0) {
            return Err(invalid(
                "zoning.min_angle",
                format!("must be in (0, 33] degrees, got {}", Num(z.min_angle)),
            ));
        }
        for (name, j) in &self.joint_materials {
            validate_joint_material(&format!("joint_materials.{name}"), j)?;
        }
        let joint_material = |path: String, name: &str| {
            if self.joint_materials.contains_key(name) {
                Ok(())
            } else {
                Err(invalid(
                    path,
                    format!("no joint material named '{name}' in joint_materials"),
                ))
            }
        };
        for (i, js) in self.joint_sets.iter().enumerate() {
            let p = format!("joint_sets[{i}]");
            positive(&format!("{p}.spacing"), js.spacing)?;
            if let Some(t) = js.trace {
                positive(&format!("{p}.trace"), t)?;
            }
            if !(js.gap >= 0.0 && js.spread_dip >= 0.0 && js.spread_spacing >= 0.0) {
                return Err(invalid(&p, "gap and spreads must be zero or positive"));
            }
            joint_material(format!("{p}.material"), &js.material)?;
        }
        // (A region of fewer than 3 vertices is the meshing's to refuse, naming it.)
        let region = (self.region.polygon.len() >= 3)
            .then(|| adit_meshing::Polygon::new(self.region.polygon.clone()));
        for (i, j) in self.joints.iter().enumerate() {
            joint_material(format!("joints[{i}].material"), &j.material)?;
            if j.from == j.to {
                return Err(invalid(format!("joints[{i}]"), "`from` and `to` coincide"));
            }
            if region
                .as_ref()
                .is_some_and(|r| !r.meets_segment(j.from, j.to))
            {
                return Err(invalid(
                    format!("joints[{i}]"),
                    "lies wholly outside region.polygon, where it cuts nothing",
                ));
            }
        }
        if let Some(v) = &self.voronoi {
            positive("voronoi.size", v.size)?;
            joint_material("voronoi.material".into(), &v.material)?;
        }
        if let Some(t) = self.contacts.tolerance {
            positive("contacts.tolerance", t)?;
        }
        if let Some(r) = self.blocks.round {
            positive("blocks.round", r)?;
        }
        for (i, r) in self.blocks.regions.iter().enumerate() {
            validate_selection(&format!("blocks.regions[{i}]"), &r.polygon, &r.at)?;
            if let (Some(at), Some(region)) = (r.at, &region)
                && !region.contains(at)
            {
                return Err(invalid(
                    format!("blocks.regions[{i}].at"),
                    format!(
                        "({}, {}) m lies outside region.polygon, where no block is to take the mode",
                        Num(at[0]),
                        Num(at[1])
                    ),
                ));
            }
        }
        let s = &self.in_situ;
        for (f, v) in [
            ("sxx", s.sxx),
            ("syy", s.syy),
            ("sxy", s.sxy),
            ("y_ref", s.y_ref),
        ] {
            if !v.is_finite() {
                return Err(invalid(format!("in_situ.{f}"), "must be finite"));
            }
        }
        for (i, bc) in self.boundary.iter().enumerate() {
            self.validate_boundary(&format!("boundary[{i}]"), bc)?;
        }
        validate_solve("solve", &self.solve)?;
        self.validate_quiet_stages()?;
        self.validate_output_interval()?;
        let large = self.solve.large_strain
            || self
                .stages
                .iter()
                .any(|s| s.solve.as_ref().is_some_and(|s| s.large_strain));
        if self.zoning.mixed && large {
            return Err(invalid(
                "zoning.mixed",
                "the mixed discretization is not available with `large_strain` yet",
            ));
        }
        self.validate_supports()?;
        self.validate_histories()?;
        self.validate_stages()?;
        self.validate_realization()?;
        self.validate_stress_magnitudes()?;
        self.validate_feature_sizes()?;
        self.validate_limits()
    }

    /// Monitoring points: distinct names, a point within the region's bounds (none for the
    /// energy balance's terms), and a support of the kind a support quantity asks for.
    fn validate_histories(&self) -> Result<(), SceneError> {
        let (lo, hi) = self.region.bounds();
        for (i, h) in self.histories.iter().enumerate() {
            let p = format!("histories[{i}]");
            if self.histories[..i].iter().any(|o| o.name == h.name) {
                return Err(invalid(
                    format!("{p}.name"),
                    format!("'{}' is used twice", h.name),
                ));
            }
            let at = match (h.at, h.quantity.is_energy()) {
                (Some(_), true) => {
                    return Err(invalid(
                        format!("{p}.at"),
                        format!(
                            "'{}' is of the whole model: give no point",
                            h.quantity.column()
                        ),
                    ));
                }
                (None, false) => {
                    return Err(invalid(
                        format!("{p}.at"),
                        format!("'{}' is read at a point: give it", h.quantity.column()),
                    ));
                }
                (None, true) if !self.any_dynamic() => {
                    return Err(invalid(
                        format!("{p}.quantity"),
                        format!(
                            "'{}' is a dynamic stage's energy balance, and no solve is dynamic",
                            h.quantity.column()
                        ),
                    ));
                }
                (None, true) => continue,
                (Some(at), false) => at,
            };
            let inside = (0..2).all(|d| at[d] >= lo[d] && at[d] <= hi[d]);
            if !inside {
                return Err(invalid(
                    format!("{p}.at"),
                    format!(
                        "({}, {}) m is outside the region (x in [{}, {}], y in [{}, {}] m)",
                        Num(at[0]),
                        Num(at[1]),
                        Num(lo[0]),
                        Num(hi[0]),
                        Num(lo[1]),
                        Num(hi[1])
                    ),
                ));
            }
            use super::HistoryQuantity as Q;
            let missing = match h.quantity {
                Q::BoltForce if self.bolts.is_empty() => Some("bolts"),
                Q::LinerThrust | Q::LinerMoment if self.liners.is_empty() => Some("liners"),
                _ => None,
            };
            if let Some(kind) = missing {
                return Err(invalid(
                    format!("{p}.quantity"),
                    format!(
                        "'{}' needs {kind}, and the scene has none",
                        h.quantity.column()
                    ),
                ));
            }
        }
        Ok(())
    }

    fn validate_stages(&self) -> Result<(), SceneError> {
        let mut done: Vec<&str> = Vec::new();
        for (i, st) in self.stages.iter().enumerate() {
            let p = format!("stages[{i}]");
            for (k, name) in st.excavate.iter().enumerate() {
                let q = format!("{p}.excavate[{k}]");
                if !self.excavations.iter().any(|e| e.name == *name) {
                    return Err(invalid(q, format!("no excavation named '{name}'")));
                }
                if done.contains(&name.as_str()) {
                    return Err(invalid(q, format!("'{name}' is excavated twice")));
                }
                done.push(name);
            }
            if let Some(spec) = &st.solve {
                validate_solve(&format!("{p}.solve"), spec)?;
            }
            for (k, r) in st.regions.iter().enumerate() {
                let q = format!("{p}.regions[{k}]");
                validate_selection(&q, &r.polygon, &r.at)?;
                if !self.materials.contains_key(&r.material) {
                    return Err(invalid(
                        format!("{q}.material"),
                        format!("no material named '{}' in materials", r.material),
                    ));
                }
            }
            for (k, bc) in st.boundary.iter().flatten().enumerate() {
                self.validate_boundary(&format!("{p}.boundary[{k}]"), bc)?;
            }
            for (k, name) in st.install.iter().enumerate() {
                let q = format!("{p}.install[{k}]");
                self.validate_install(&q, name, &done)?;
            }
            for (name, m) in &st.materials {
                let q = format!("{p}.materials.{name}");
                let Some(before) = self.materials.get(name) else {
                    return Err(invalid(
                        q,
                        format!("no material named '{name}' in materials to change"),
                    ));
                };
                validate_material(&q, m)?;
                if m.density != before.density {
                    return Err(invalid(
                        format!("{q}.density"),
                        format!(
                            "a stage cannot change the density yet (it sets the masses of rigid \
                             and simple blocks): keep {}",
                            before.density
                        ),
                    ));
                }
            }
            if let Some(g) = st.gravity
                && !g.iter().all(|v| v.is_finite())
            {
                return Err(invalid(format!("{p}.gravity"), "must be finite"));
            }
            for (name, j) in &st.joint_materials {
                let q = format!("{p}.joint_materials.{name}");
                if !self.joint_materials.contains_key(name) {
                    return Err(invalid(
                        q,
                        format!("no joint material named '{name}' in joint_materials to change"),
                    ));
                }
                validate_joint_material(&q, j)?;
            }
            if !(0.0..=1.0).contains(&st.support_fraction) {
                return Err(invalid(
                    format!("{p}.support_fraction"),
                    format!("must be in [0, 1], got {}", Num(st.support_fraction)),
                ));
            }
            if let Some(fos) = &st.factor_of_safety {
                let mode = st.solve.as_ref().unwrap_or(&self.solve).mode;
                validate_factor_of_safety(&format!("{p}.factor_of_safety"), fos, mode)?;
            }
        }
        Ok(())
    }

    fn validate_inclusions(&self) -> Result<(), SceneError> {
        for (i, inc) in self.inclusions.iter().enumerate() {
            let p = format!("inclusions[{i}]");
            match inc.shape(&p)? {
                Shape::Circle(c) => {
                    positive(&format!("{p}.circle.radius"), c.radius)?;
                    if c.segments < 8 {
                        return Err(invalid(
                            format!("{p}.circle.segments"),
                            "at least 8 segments",
                        ));
                    }
                }
                Shape::Polygon(_) | Shape::Horseshoe(_) => {}
            }
            if !self.materials.contains_key(&inc.material) {
                return Err(invalid(
                    format!("{p}.material"),
                    format!("no material named '{}' in materials", inc.material),
                ));
            }
        }
        Ok(())
    }

    /// Names a boundary condition may use in `part`, each once (region edges sharing a name are
    /// one part), in scene order.
    pub fn part_names(&self) -> Vec<String> {
        let mut seen = std::collections::HashSet::new();
        std::iter::once("outer".to_string())
            .chain(self.edge_names())
            .chain(self.excavations.iter().map(|e| e.name.clone()))
            .filter(|n| seen.insert(n.clone()))
            .collect()
    }

    /// Edge names of the region polygon (given, or `edge0`, `edge1`, …).
    pub fn edge_names(&self) -> Vec<String> {
        match &self.region.edge_names {
            Some(n) => n.clone(),
            None => (0..self.region.polygon.len())
                .map(|i| format!("edge{i}"))
                .collect(),
        }
    }

    fn validate_boundary(&self, p: &str, bc: &BoundaryCondition) -> Result<(), SceneError> {
        if let (Some(name), None) = (&bc.part, &bc.at)
            && !self.part_names().contains(name)
        {
            return Err(invalid(
                format!("{p}.part"),
                format!(
                    "no boundary part '{name}' (known: {})",
                    self.part_names().join(", ")
                ),
            ));
        }
        if bc.quiet && bc.part.is_none() {
            return Err(invalid(
                format!("{p}.quiet"),
                "a quiet boundary is a part's (`part`), not a point's",
            ));
        }
        if bc.quiet && bc.fix.is_some() {
            return Err(invalid(
                format!("{p}.fix"),
                "a quiet part moves, its dashpots resisting: it cannot be fixed too",
            ));
        }
        if let Some(incident) = &bc.incident {
            if !bc.quiet {
                return Err(invalid(
                    format!("{p}.incident"),
                    "a wave enters through a quiet part: give `quiet`: true",
                ));
            }
            validate_history(
                &format!("{p}.incident"),
                &incident.history(),
                "velocity",
                "m/s",
            )?;
        }
        if bc.free_field && !bc.quiet {
            return Err(invalid(
                format!("{p}.free_field"),
                "a free field acts through a quiet part's dashpots: give `quiet`: true",
            ));
        }
        if bc.free_field && bc.incident.is_some() {
            return Err(invalid(
                format!("{p}.incident"),
                "a free-field side takes its motion from its column, which the quiet base's \
                 incident wave drives; bring the wave in through the base",
            ));
        }
        if let Some(motion) = &bc.motion {
            validate_motion(&format!("{p}.motion"), bc, motion)?;
        }
        if let Some(history) = &bc.history {
            if bc.load_kinds() == 0 {
                return Err(invalid(
                    format!("{p}.history"),
                    "scales the condition's load: give `stress`, `in_situ_traction` or \
                     `normal_stress`/`shear_stress`",
                ));
            }
            validate_history(&format!("{p}.history"), history, "amplitude", "–")?;
        }
        bc.condition(p)?;
        for (f, v) in [
            ("normal_stress", bc.normal_stress),
            ("shear_stress", bc.shear_stress),
        ] {
            if v.is_some_and(|v| !v.is_finite()) {
                return Err(invalid(format!("{p}.{f}"), "must be finite"));
            }
        }
        Ok(())
    }

    /// Whether any solve (the scene's or a stage's) is dynamic.
    fn any_dynamic(&self) -> bool {
        std::iter::once(&self.solve)
            .chain(self.stages.iter().filter_map(|s| s.solve.as_ref()))
            .any(|s| s.mode == SolveMode::Dynamic)
    }

    /// `output.interval`: positive and finite, and some solve dynamic (it times their output).
    fn validate_output_interval(&self) -> Result<(), SceneError> {
        let Some(i) = self.output.interval else {
            return Ok(());
        };
        positive("output.interval", i)?;
        if !self.any_dynamic() {
            return Err(invalid(
                "output.interval",
                "times the output of dynamic solves, and no solve is dynamic; `every` counts \
                 cycles of static ones",
            ));
        }
        Ok(())
    }

    /// A list of boundary conditions with a quiet part, a prescribed motion or a load history is
    /// in force only during dynamic stages: dashpots would damp a static solve's path, and a wave,
    /// a motion or a history has no time there.
    fn validate_quiet_stages(&self) -> Result<(), SceneError> {
        let quiet = |list: &[BoundaryCondition]| {
            (list.iter().enumerate()).find_map(|(k, c)| {
                if c.quiet {
                    Some(format!("[{k}].quiet"))
                } else if c.motion.is_some() {
                    Some(format!("[{k}].motion"))
                } else {
                    c.history.as_ref().map(|_| format!("[{k}].history"))
                }
            })
        };
        let mode = |i: usize| {
            let st = self.stages.get(i);
            st.and_then(|s| s.solve.as_ref())
                .unwrap_or(&self.solve)
                .mode
        };
        let mut in_force = quiet(&self.boundary).map(|k| format!("boundary{k}"));
        for i in 0..self.stages.len().max(1) {
            if let Some(list) = self.stages.get(i).and_then(|s| s.boundary.as_deref()) {
                in_force = quiet(list).map(|k| format!("stages[{i}].boundary{k}"));
            }
            if let Some(path) = &in_force
                && mode(i) == super::SolveMode::Static
            {
                let stage = match self.stages.get(i) {
                    Some(s) => format!("stages[{i}] ('{}') is static", s.name),
                    None => "the solve is static".to_string(),
                };
                return Err(invalid(
                    path.as_str(),
                    format!(
                        "acts in dynamic solves only, and {stage} while it is in force: give that stage `solve.mode` \"dynamic\", or a boundary list of its own"
                    ),
                ));
            }
        }
        Ok(())
    }
}

impl Scene {
    /// `region.far_field.surface`: finite, an intact far field (Melan's half-plane is
    /// isotropic), the region below it but not a million times its size below, and an in-situ
    /// stress that leaves it free (σ_yy and σ_xy zero there, to a millionth of the stress's size):
    /// else the far field could not hold the model at rest.
    fn validate_surface(&self, surface: f64, rock_mass: super::RockMass) -> Result<(), SceneError> {
        let field = "region.far_field.surface";
        if !surface.is_finite() {
            return Err(invalid(field, "must be finite"));
        }
        if rock_mass == super::RockMass::Jointed {
            return Err(invalid(
                field,
                "a half-plane far field is isotropic: rock_mass \"jointed\" cannot be taken with it",
            ));
        }
        // The region's extent, from which the tolerances and the depth follow.
        let (lo, hi) = self.region.bounds();
        let span = (lo.iter().chain(&hi)).fold(surface.abs(), |m, v| m.max(v.abs()));
        let above = surface + 1e-9 * span.max(1.0);
        if let Some(p) = (self.region.polygon.iter()).find(|p| p[1] > above) {
            return Err(invalid(
                field,
                format!(
                    "region.polygon's vertex ({}, {}) m lies above the surface y = {} m",
                    Num(p[0]),
                    Num(p[1]),
                    Num(surface)
                ),
            ));
        }
        let size = (hi[1] - lo[1]).max(hi[0] - lo[0]);
        if surface - hi[1] > 1e6 * size {
            return Err(invalid(
                field,
                format!(
                    "lies {} m above the region, over a million times its size: the half-plane is \
                     the whole plane there (leave surface out)",
                    Num(surface - hi[1])
                ),
            ));
        }
        let s = &self.in_situ;
        let syy = s.syy + s.gradient.syy * (surface - s.y_ref);
        let depth = (surface - lo[1]).max(0.0);
        let stress = (s.sxx.abs() + s.syy.abs() + s.sxy.abs())
            .max((s.gradient.syy.abs() + s.gradient.sxx.abs()) * depth);
        if syy.abs() > 1e-6 * stress + 1e-3 || s.sxy.abs() > 1e-6 * stress + 1e-3 {
            return Err(invalid(
                field,
                format!(
                    "the in-situ stress loads the surface (σyy = {} Pa, σxy = {} Pa at y = {} m): \
                     a half-plane's surface is free, so in_situ must give σyy = σxy = 0 there \
                     (with gravity, syy and its gradient vanishing at the surface)",
                    Num(syy),
                    Num(s.sxy),
                    Num(surface)
                ),
            ));
        }
        Ok(())
    }

    /// `region.far_field`: its constants in range; a static model (the far field is a
    /// stiffness, radiating no waves); no load of the boundary conditions on the region's outer
    /// boundary, which the far field loads itself (fixities stay allowed: a point fixed holds
    /// the near field in place for the implicit solve, a translation costing the far field nothing).
    fn validate_far_field(&self) -> Result<(), SceneError> {
        let Some(f) = &self.region.far_field else {
            return Ok(());
        };
        if let Some(e) = f.young {
            positive("region.far_field.young", e)?;
        }
        if let Some(h) = f.element_size {
            positive("region.far_field.element_size", h)?;
        }
        if let Some(nu) = f.poisson
            && !(nu > -1.0 && nu < 0.5)
        {
            return Err(invalid(
                "region.far_field.poisson",
                format!("must lie in (−1, 0.5), got {}", Num(nu)),
            ));
        }
        if let Some(surface) = f.surface {
            self.validate_surface(surface, f.rock_mass)?;
        }
        if f.rock_mass == super::RockMass::Jointed && self.joint_sets.is_empty() {
            return Err(invalid(
                "region.far_field.rock_mass",
                "jointed: the scene has no joint_sets to smear into the far field",
            ));
        }
        let solves = std::iter::once(("solve.mode", &self.solve)).chain(
            (self.stages.iter())
                .filter_map(|s| s.solve.as_ref())
                .map(|s| ("stages[].solve.mode", s)),
        );
        for (path, s) in solves {
            if s.mode == super::SolveMode::Dynamic {
                return Err(invalid(
                    path,
                    "dynamic: the far field (region.far_field) is a static stiffness that \
                     radiates no waves, so they would reflect from it",
                ));
            }
        }
        let outer: Vec<String> = std::iter::once("outer".to_string())
            .chain(self.edge_names())
            .collect();
        let lists = std::iter::once(("boundary".to_string(), &self.boundary)).chain(
            (self.stages.iter().enumerate()).filter_map(|(i, s)| {
                s.boundary
                    .as_ref()
                    .map(|b| (format!("stages[{i}].boundary"), b))
            }),
        );
        // A half-plane's region edges on its surface stay free of the far field: a load there (a
        // surcharge) is the near field's, whose net force the far field carries.
        let poly = &self.region.polygon;
        let span = super::coordinate_span(poly);
        let on_surface: Vec<String> = (self.edge_names().into_iter().enumerate())
            .filter(|(i, _)| f.on_surface(&[poly[*i], poly[(i + 1) % poly.len()]], span))
            .map(|(_, name)| name)
            .collect();
        for (path, list) in lists {
            for (j, bc) in list.iter().enumerate() {
                let on_outer = (bc.part.as_ref())
                    .is_some_and(|p| outer.contains(p) && !on_surface.contains(p));
                if on_outer && bc.load_kinds() > 0 {
                    return Err(invalid(
                        format!("{path}[{j}]"),
                        format!(
                            "loads part '{}' of the region's outer boundary, which the far field \
                             (region.far_field) loads with the in-situ stress and its own response",
                            bc.part.as_deref().unwrap_or_default()
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
